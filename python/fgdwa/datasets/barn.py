"""BARN (Benchmark for Autonomous Robot Navigation) maps as occupancy grids.

Two halves:

* :func:`load_barn` reads a file in the ``barn.npz`` format (docs/barn.md) and
  checks it, key by key, before anything uses it; :class:`BarnDataset` then hands
  out one :class:`BarnWorld` (grid, start, goal, reference path, optimal time) per
  map, by position or by BARN world id, and :func:`parse_world_selection` turns
  "all", "0,6,12" or "0-49" into world ids.
* :func:`convert_barn_worlds` rebuilds that format from the challenge's own files
  (``world_<i>.world`` Gazebo worlds and ``path_<i>.npy`` reference paths), the
  same way the shared barn.npz was made, so that anyone holding the challenge's
  repository can make the file for all 300 worlds.

Frames. The map frame has x along the direction of travel (Gazebo +y) and
y = -(Gazebo x). ``grids[k, row, col]`` has row 0 at the bottom (lowest y), as
:class:`fgdwa.OccupancyGrid` wants it, with origin (0.0, -1.5) and 0.15 m cells.
``fields[k, r, c]`` is the 30x30 obstacle field in BARN's own [row, col] order,
which runs the other way in y: field cell [r, c] is grid cell [39 - r, 34 + c].
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator, List, NamedTuple, Optional, Sequence, Tuple, Union

import numpy as np

from fgdwa._core import FgdwaError, OccupancyGrid

# --- the format's constants (docs/barn.md) ----------------------------------------
RESOLUTION = 0.15  # m per cell; also the spacing of the challenge's cylinders
ORIGIN = (0.0, -1.5)  # map (x, y) of the lower-left corner of grid cell (0, 0)
GRID_SHAPE = (50, 100)  # (rows, cols): y in [-1.5, 6.0), x in [0, 15)
BARN_FIELD_SIZE = 30  # the obstacle field is 30x30 cells
START = (3.0, 2.25, 0.0)  # map (x, y, yaw)
GOAL = (13.0, 2.25)  # map (x, y)
GOAL_RADIUS = 1.0  # m
TIME_LIMIT = 100.0  # s
OPTIMAL_SPEED = 2.0  # m/s: the optimal time is the reference path's length at this speed

# --- the challenge's Gazebo frame ---------------------------------------------------
CYLINDER_RADIUS = 0.075  # m
GAZEBO_START = (-2.25, 3.0)  # the challenge's INIT_POSITION (x, y)
GAZEBO_GOAL = (-2.25, 13.0)  # INIT_POSITION + GOAL_POSITION (0, 10)
FIELD_MIN_GAZEBO_Y = 5.1  # cylinders at smaller Gazebo y are the side and back walls
FIELD_CELL0_GAZEBO = (-4.425, 5.175)  # Gazebo (x, y) of field cell [0, 0]'s cylinder

# Field cell [r, c] has its centre at map (5.175 + 0.15 c, 4.425 - 0.15 r):
FIELD_TOP_ROW = int(round((-FIELD_CELL0_GAZEBO[0] - ORIGIN[1]) / RESOLUTION - 0.5))  # 39
FIELD_LEFT_COL = int(round((FIELD_CELL0_GAZEBO[1] - ORIGIN[0]) / RESOLUTION - 0.5))  # 34

SHARED_KEYS = ("world_ids", "grids", "fields", "optimal_time", "resolution", "origin", "start", "goal",
               "goal_radius", "time_limit")
_PATH_KEY = re.compile(r"path_(\d+)\Z")
_ALIGN_TOL = 1e-3  # cells: how far a cylinder may sit from a cell centre


# =====================================================================================
# Scoring
# =====================================================================================

def barn_score(success: bool, time: float, optimal_time: float) -> float:
    """The challenge's score of one run: ``success * OT / clip(T, 2 OT, 8 OT)``.

    A failed run (collision, timeout, goal not reached) scores 0 whatever its time;
    a successful one scores at most 0.5 (at or under twice the optimal time) and at
    least 0.125 (at or over eight times it).
    """
    ot = float(optimal_time)
    if not (math.isfinite(ot) and ot > 0):
        raise FgdwaError(f"barn_score: optimal_time = {optimal_time!r}: must be a finite number > 0")
    if not success:
        return 0.0
    t = float(time)
    if math.isnan(t) or t < 0:
        raise FgdwaError(f"barn_score: time = {time!r}: a successful run needs a time >= 0")
    return ot / min(max(t, 2.0 * ot), 8.0 * ot)


# =====================================================================================
# Loading barn.npz
# =====================================================================================

@dataclass(frozen=True)
class BarnWorld:
    """One BARN map with its task.

    ``grid`` is the full 50x100 map (1 = obstacle) in the map frame; ``field`` the
    30x30 obstacle field in BARN's [row, col] order; ``path`` the official reference
    path, (n, 2) map metres from the field's first cell to its last (it does not
    include ``start`` and ``goal``); ``optimal_time`` the challenge's optimal time
    (s). Arrays are read-only views of the data set.
    """

    world_id: int
    grid: OccupancyGrid
    field: np.ndarray
    start: Tuple[float, float, float]
    goal: Tuple[float, float]
    path: np.ndarray
    optimal_time: float
    goal_radius: float
    time_limit: float

    def score(self, success: bool, time: float) -> float:
        """The challenge's score of a run on this world (see :func:`barn_score`)."""
        return barn_score(success, time, self.optimal_time)

    def __repr__(self) -> str:
        return (f"BarnWorld(world_id={self.world_id}, grid={self.grid.shape}, path={len(self.path)} points, "
                f"optimal_time={self.optimal_time:.3f})")


class BarnDataset:
    """The worlds of one barn.npz file (see :func:`load_barn`).

    ``dataset[k]`` is the k-th world in file order (negative k counts from the end);
    ``dataset.world(i)`` is BARN world ``i``; ``dataset.select("0-49")`` the worlds
    of a selection (:func:`parse_world_selection`). Iterating yields every world.
    """

    def __init__(self, source: str, arrays: dict):
        self.source = source
        self._ids = tuple(int(i) for i in arrays["world_ids"])
        self._index = {wid: k for k, wid in enumerate(self._ids)}
        self._grids = _read_only(arrays["grids"])
        self._fields = _read_only(arrays["fields"])
        self._optimal = arrays["optimal_time"].astype(float)
        self._paths = {wid: _read_only(arrays[f"path_{wid}"]) for wid in self._ids}
        self.resolution = float(arrays["resolution"])
        self.origin = tuple(float(v) for v in arrays["origin"])
        self.start = tuple(float(v) for v in arrays["start"])
        self.goal = tuple(float(v) for v in arrays["goal"])
        self.goal_radius = float(arrays["goal_radius"])
        self.time_limit = float(arrays["time_limit"])

    @property
    def world_ids(self) -> List[int]:
        """BARN world ids in file order."""
        return list(self._ids)

    def __len__(self) -> int:
        return len(self._ids)

    def __iter__(self) -> Iterator[BarnWorld]:
        return (self[k] for k in range(len(self)))

    def __contains__(self, world_id) -> bool:
        return isinstance(world_id, (int, np.integer)) and int(world_id) in self._index

    def __getitem__(self, index) -> BarnWorld:
        if not isinstance(index, (int, np.integer)) or isinstance(index, bool):
            raise FgdwaError(f"{self.source}: worlds are indexed by position (int), got {index!r}; "
                             f"use .world(world_id) for a BARN world id or .select(spec) for a selection")
        k = int(index)
        if not -len(self) <= k < len(self):
            raise FgdwaError(f"{self.source}: index {k} out of range for {len(self)} worlds")
        k %= len(self)
        wid = self._ids[k]
        return BarnWorld(
            world_id=wid,
            grid=OccupancyGrid(self._grids[k], self.resolution, self.origin),
            field=self._fields[k],
            start=self.start,
            goal=self.goal,
            path=self._paths[wid],
            optimal_time=float(self._optimal[k]),
            goal_radius=self.goal_radius,
            time_limit=self.time_limit,
        )

    def index_of(self, world_id: int) -> int:
        """Position in the file of BARN world ``world_id``."""
        try:
            return self._index[int(world_id)]
        except (KeyError, TypeError, ValueError):
            raise FgdwaError(f"{self.source}: world {world_id!r} is not in this data set "
                             f"({describe_world_ids(self._ids)})") from None

    def world(self, world_id: int) -> BarnWorld:
        """BARN world ``world_id``."""
        return self[self.index_of(world_id)]

    def select(self, selection: Union[str, int, Iterable[int]]) -> List[BarnWorld]:
        """The worlds of a selection: a string as :func:`parse_world_selection` reads
        it, one world id, or an iterable of world ids."""
        return [self.world(wid) for wid in self.select_ids(selection)]

    def select_ids(self, selection: Union[str, int, Iterable[int]]) -> List[int]:
        """World ids of a selection, checked against this data set."""
        if isinstance(selection, str):
            return parse_world_selection(selection, self._ids)
        if isinstance(selection, (int, np.integer)) and not isinstance(selection, bool):
            selection = [selection]
        try:
            ids = [int(i) for i in selection]
        except (TypeError, ValueError):
            raise FgdwaError(f"world selection {selection!r}: expected a string such as '0-49' or world ids") from None
        for wid in ids:
            self.index_of(wid)
        return list(dict.fromkeys(ids))

    def __repr__(self) -> str:
        return f"BarnDataset({self.source!r}: {describe_world_ids(self._ids)})"


def find_barn_file(path: Optional[Union[str, os.PathLike]] = None) -> Path:
    """Where barn.npz is: ``path`` (a file, or a directory holding barn.npz), else the
    ``FGDWA_BARN_DATA`` environment variable (same rules)."""
    source = "argument"
    if path is None:
        path = os.environ.get("FGDWA_BARN_DATA")
        source = "FGDWA_BARN_DATA"
        if not path:
            raise FgdwaError("no BARN data given: pass the path of barn.npz (or of its directory), "
                             "or set FGDWA_BARN_DATA; make the file with `fgdwa barn import WORLD_DIR --out FILE`")
    p = Path(path)
    if p.is_dir():
        p = p / "barn.npz"
    if not p.is_file():
        raise FgdwaError(f"BARN data {p} ({source}): no such file")
    return p


def load_barn(path: Union[str, os.PathLike]) -> BarnDataset:
    """Read and check a file in the barn.npz format (docs/barn.md).

    Raises FgdwaError naming the file and the key on a missing key, a wrong shape,
    dtype or value, or a world id without its ``path_<id>``.
    """
    name = str(path)
    not_barn = f"{name}: not a barn.npz file (expected an .npz archive with keys {', '.join(SHARED_KEYS)})"
    try:
        loaded = np.load(path, allow_pickle=False)
        if not isinstance(loaded, np.lib.npyio.NpzFile):  # a lone .npy array
            raise FgdwaError(not_barn)
        with loaded as npz:
            arrays = {key: npz[key] for key in npz.files}
    except FgdwaError:
        raise
    except FileNotFoundError:
        raise FgdwaError(f"{name}: no such file") from None
    except (OSError, ValueError, EOFError) as error:
        raise FgdwaError(f"{name}: not a readable .npz file ({error})") from None
    except Exception as error:  # zipfile.BadZipFile and friends from a damaged archive
        raise FgdwaError(f"{name}: not a readable .npz file ({type(error).__name__}: {error})") from None
    if not arrays:
        raise FgdwaError(not_barn)
    _check_arrays(name, arrays)
    return BarnDataset(name, arrays)


def _check_arrays(name: str, a: dict) -> None:
    def fail(key, message):
        raise FgdwaError(f"{name}: key '{key}': {message}")

    for key in SHARED_KEYS:
        if key not in a:
            raise FgdwaError(f"{name}: missing key '{key}' (a barn.npz file holds {', '.join(SHARED_KEYS)} "
                             f"and path_<id> per world)")

    ids = a["world_ids"]
    if ids.ndim != 1 or len(ids) == 0:
        fail("world_ids", f"shape {ids.shape}: expected (n,) with n >= 1")
    if ids.dtype.kind not in "iu":
        fail("world_ids", f"dtype {ids.dtype}: expected integers")
    if np.any(ids < 0):
        fail("world_ids", f"negative world id {int(ids[ids < 0][0])}")
    unique, counts = np.unique(ids, return_counts=True)
    if np.any(counts > 1):
        fail("world_ids", f"world id {int(unique[counts > 1][0])} appears more than once")
    n = len(ids)

    for key, shape in (("grids", (n,) + GRID_SHAPE), ("fields", (n, BARN_FIELD_SIZE, BARN_FIELD_SIZE))):
        cells = a[key]
        if cells.shape != shape:
            fail(key, f"shape {cells.shape}: expected {shape} (one per world id)")
        if cells.dtype != np.uint8:
            fail(key, f"dtype {cells.dtype}: expected uint8 (1 = obstacle)")
        if np.any(cells > 1):
            fail(key, "values other than 0 and 1")

    _check_float(fail, a, "optimal_time", (n,))
    if np.any(a["optimal_time"] <= 0):
        fail("optimal_time", "values must be > 0 (seconds)")
    _check_float(fail, a, "resolution", ())
    _check_float(fail, a, "origin", (2,))
    _check_float(fail, a, "start", (3,))
    _check_float(fail, a, "goal", (2,))
    _check_float(fail, a, "goal_radius", ())
    _check_float(fail, a, "time_limit", ())
    for key in ("resolution", "goal_radius", "time_limit"):
        if float(a[key]) <= 0:
            fail(key, f"{float(a[key])!r}: must be > 0")

    id_set = set(int(i) for i in ids)
    for wid in ids:
        key = f"path_{int(wid)}"
        if key not in a:
            raise FgdwaError(f"{name}: missing key '{key}': world {int(wid)} is in world_ids but has no reference path")
        path = a[key]
        if path.ndim != 2 or path.shape[1] != 2 or path.shape[0] < 1:
            fail(key, f"shape {path.shape}: expected (n, 2) points (x, y) in map metres")
        if path.dtype.kind != "f":
            hint = (" (the challenge's path_<i>.npy holds [row, col] field cells; convert the challenge's files "
                    "with `fgdwa barn import`)" if path.dtype.kind in "iu" else "")
            fail(key, f"dtype {path.dtype}: expected float map metres{hint}")
        if not np.all(np.isfinite(path)):
            fail(key, "non-finite values")
    for key in a:
        match = _PATH_KEY.match(key)
        if match and int(match.group(1)) not in id_set:
            fail(key, f"world {int(match.group(1))} is not in world_ids")


def _check_float(fail, a: dict, key: str, shape: tuple) -> None:
    value = a[key]
    if value.shape != shape:
        fail(key, f"shape {value.shape}: expected {shape}")
    if value.dtype.kind != "f":
        fail(key, f"dtype {value.dtype}: expected a float type")
    if not np.all(np.isfinite(value)):
        fail(key, "non-finite values")


def _read_only(array: np.ndarray) -> np.ndarray:
    array = np.array(array, copy=True)
    array.setflags(write=False)
    return array


def describe_world_ids(ids: Sequence[int]) -> str:
    ids = sorted(ids)
    if not ids:
        return "no worlds"
    if len(ids) <= 8:
        return "worlds " + ", ".join(str(i) for i in ids)
    return f"{len(ids)} worlds, ids {ids[0]}..{ids[-1]}"


# =====================================================================================
# Selections
# =====================================================================================

_RANGE = re.compile(r"(\d+)\s*-\s*(\d+)(?:\s*:\s*(\d+))?\Z")


def parse_world_selection(text: str, available: Optional[Iterable[int]] = None) -> List[int]:
    """World ids of a selection, in the order written, without repeats.

    ``text`` is ``all`` or comma-separated items, each a world id (``12``) or an
    inclusive range of world ids (``0-49``) with an optional step (``0-299:6`` is the
    challenge's local test set 0, 6, ..., 294). With ``available`` (the ids a data
    set holds), ``all`` means all of them, a range keeps those it holds (and must
    keep one), and a single id it does not hold is an error; without it, ``all`` is
    an error.
    """
    if not isinstance(text, str):
        raise FgdwaError(f"world selection {text!r}: expected a string such as 'all', '0,6,12' or '0-49'")
    have = None if available is None else sorted(set(int(i) for i in available))
    have_set = None if have is None else set(have)
    spec = text.strip()
    if spec.lower() == "all":
        if have is None:
            raise FgdwaError("world selection 'all': needs a data set to say which worlds there are")
        return list(have)
    if not spec:
        raise FgdwaError("world selection '': empty (use 'all', ids such as '0,6,12' or a range such as '0-49')")
    ids: List[int] = []
    for item in spec.split(","):
        item = item.strip()
        if item.isdigit():
            wid = int(item)
            if have_set is not None and wid not in have_set:
                raise FgdwaError(f"world selection {text!r}: world {wid} is not in the data set "
                                 f"({describe_world_ids(have)})")
            ids.append(wid)
            continue
        match = _RANGE.match(item)
        if not match:
            raise FgdwaError(f"world selection {text!r}: cannot read {item!r} (expected 'all', a world id such as "
                             f"'12', or a range such as '0-49' or '0-299:6')")
        first, last = int(match.group(1)), int(match.group(2))
        step = int(match.group(3)) if match.group(3) else 1
        if last < first:
            raise FgdwaError(f"world selection {text!r}: range {item!r} runs backwards")
        if step < 1:
            raise FgdwaError(f"world selection {text!r}: range {item!r} needs a step >= 1")
        chosen = range(first, last + 1, step)
        if have_set is not None:
            chosen = [wid for wid in chosen if wid in have_set]
            if not chosen:
                raise FgdwaError(f"world selection {text!r}: no world of {item!r} is in the data set "
                                 f"({describe_world_ids(have)})")
        ids.extend(chosen)
    return list(dict.fromkeys(ids))


# =====================================================================================
# Converting the challenge's files
# =====================================================================================

class ConvertedWorld(NamedTuple):
    world_id: int
    grid: np.ndarray  # (50, 100) uint8
    field: np.ndarray  # (30, 30) uint8
    path: np.ndarray  # (n, 2) float64 map metres
    optimal_time: float


def fill_holes(cells: np.ndarray) -> np.ndarray:
    """Fill the free regions that do not reach the array's border (4-connected):
    ``scipy.ndimage.binary_fill_holes`` with its default structure; uint8."""
    solid = np.asarray(cells).astype(bool)
    if solid.ndim != 2:
        raise FgdwaError(f"fill_holes: expected a 2-D array, got shape {solid.shape}")
    from scipy import ndimage

    return ndimage.binary_fill_holes(solid).astype(np.uint8)


_MODEL = re.compile(r"<model\s+name\s*=\s*['\"](unit_cylinder_\d+)['\"]\s*>")
_POSE = re.compile(r"<pose\b[^>]*>([^<]*)</pose>")


def _cylinder_positions(world_file: Path) -> List[Tuple[str, float, float]]:
    """(model name, Gazebo x, Gazebo y) of every unit_cylinder_N model, read from the
    part of the world file before ``<state`` (the state block repeats the poses)."""
    try:
        text = world_file.read_text(encoding="utf-8", errors="replace")
    except OSError as error:
        raise FgdwaError(f"{world_file}: cannot read ({error})") from None
    head = text.split("<state", 1)[0]
    models = list(_MODEL.finditer(head))
    if not models:
        raise FgdwaError(f"{world_file}: no unit_cylinder_N model before <state: not a BARN world file")
    out = []
    for m, following in zip(models, models[1:] + [None]):
        block = head[m.end():following.start() if following is not None else len(head)]
        pose = _POSE.search(block)
        if pose is None:
            raise FgdwaError(f"{world_file}: model {m.group(1)} has no <pose>")
        try:
            values = [float(v) for v in pose.group(1).split()]
        except ValueError:
            values = []
        if len(values) < 2 or not all(math.isfinite(v) for v in values[:2]):
            raise FgdwaError(f"{world_file}: model {m.group(1)}: cannot read pose {pose.group(1).strip()!r}")
        out.append((m.group(1), values[0], values[1]))
    return out


def _cell_index(value: float, what: str, where: str) -> int:
    index = round(value)
    if abs(value - index) > _ALIGN_TOL:
        raise FgdwaError(f"{where}: {what} is not on a 0.15 m cell (index {value:.4f})")
    return int(index)


def read_barn_world(world_file: Union[str, os.PathLike], path_file: Union[str, os.PathLike],
                    world_id: Optional[int] = None) -> ConvertedWorld:
    """One world from the challenge's files: its grid, field, reference path (map
    metres) and optimal time, as barn.npz holds them (see docs/barn.md)."""
    world_file, path_file = Path(world_file), Path(path_file)
    if world_id is None:
        match = re.fullmatch(r"world_(\d+)\.world", world_file.name)
        if not match:
            raise FgdwaError(f"{world_file}: cannot tell the world id from the name (expected world_<i>.world)")
        world_id = int(match.group(1))

    grid = np.zeros(GRID_SHAPE, dtype=np.uint8)
    field = np.zeros((BARN_FIELD_SIZE, BARN_FIELD_SIZE), dtype=np.uint8)
    for model, gx, gy in _cylinder_positions(world_file):
        where = f"{world_file}: {model} at Gazebo ({gx:g}, {gy:g})"
        if gy >= FIELD_MIN_GAZEBO_Y:
            r = _cell_index((gx - FIELD_CELL0_GAZEBO[0]) / RESOLUTION, "field row", where)
            c = _cell_index((gy - FIELD_CELL0_GAZEBO[1]) / RESOLUTION, "field column", where)
            if not (0 <= r < BARN_FIELD_SIZE and 0 <= c < BARN_FIELD_SIZE):
                raise FgdwaError(f"{where}: outside the 30x30 obstacle field (cell [{r}, {c}])")
            field[r, c] = 1
        else:  # side and back walls: map (x, y) = (Gazebo y, -Gazebo x)
            x, y = gy, -gx
            row = _cell_index((y - ORIGIN[1]) / RESOLUTION - 0.5, "grid row", where)
            col = _cell_index((x - ORIGIN[0]) / RESOLUTION - 0.5, "grid column", where)
            if not (0 <= row < GRID_SHAPE[0] and 0 <= col < GRID_SHAPE[1]):
                raise FgdwaError(f"{where}: outside the {GRID_SHAPE[0]}x{GRID_SHAPE[1]} map (cell [{row}, {col}])")
            grid[row, col] = 1
    # The world writer leaves out cylinders whose 8 neighbours are all filled.
    field = fill_holes(field)
    rows = FIELD_TOP_ROW - np.arange(BARN_FIELD_SIZE)
    cols = FIELD_LEFT_COL + np.arange(BARN_FIELD_SIZE)
    grid[rows[:, None], cols[None, :]] |= field

    cells = _read_path_cells(path_file)
    path = np.stack([(FIELD_CELL0_GAZEBO[1] - ORIGIN[0]) + RESOLUTION * cells[:, 1],
                     -FIELD_CELL0_GAZEBO[0] - RESOLUTION * cells[:, 0]], axis=1).astype(np.float64)
    return ConvertedWorld(int(world_id), grid, field, path, _challenge_optimal_time(cells))


def _read_path_cells(path_file: Path) -> np.ndarray:
    try:
        cells = np.load(path_file, allow_pickle=False)
    except FileNotFoundError:
        raise FgdwaError(f"{path_file}: no such file (each world_<i>.world needs its path_<i>.npy)") from None
    except (OSError, ValueError, EOFError) as error:
        raise FgdwaError(f"{path_file}: not a readable .npy file ({error})") from None
    if not isinstance(cells, np.ndarray) or cells.ndim != 2 or cells.shape[1] != 2 or len(cells) < 1:
        raise FgdwaError(f"{path_file}: shape {getattr(cells, 'shape', None)}: expected (n, 2) [row, col] field cells")
    if cells.dtype.kind not in "iu":
        raise FgdwaError(f"{path_file}: dtype {cells.dtype}: expected integer [row, col] field cells")
    if np.any(cells < 0) or np.any(cells >= BARN_FIELD_SIZE):
        raise FgdwaError(f"{path_file}: cells outside the 30x30 field")
    return cells


def _challenge_optimal_time(cells: np.ndarray) -> float:
    """The challenge's optimal time, computed as its run.py does (same operations in
    the same order, so the float is the same): path cells to Gazebo
    (0.15 r - 4.575, 0.15 c + 5.075), from the start through them to the goal, length
    over 2 m/s."""
    radius = CYLINDER_RADIUS
    r_shift = -radius - (BARN_FIELD_SIZE * radius * 2)
    c_shift = radius + 5
    points = [(r * (radius * 2) + r_shift, c * (radius * 2) + c_shift) for r, c in cells]
    points = np.insert(points, 0, GAZEBO_START, axis=0)
    points = np.insert(points, len(points), GAZEBO_GOAL, axis=0)
    length = 0
    for p1, p2 in zip(points[:-1], points[1:]):
        length += ((p1[0] - p2[0]) ** 2 + (p1[1] - p2[1]) ** 2) ** 0.5
    return float(length / OPTIMAL_SPEED)


def _world_files(world_dir: Path) -> dict:
    found = {}
    for entry in world_dir.iterdir():
        match = re.fullmatch(r"world_(\d+)\.world", entry.name)
        if match:
            found[int(match.group(1))] = entry
    return found


def _path_file(world_dir: Path, world_id: int) -> Path:
    """path_<i>.npy beside the world file, or in path_files/ as the challenge keeps it
    (jackal_helper/worlds/BARN/path_files/)."""
    name = f"path_{world_id}.npy"
    for candidate in (world_dir / name, world_dir / "path_files" / name):
        if candidate.is_file():
            return candidate
    raise FgdwaError(f"{world_dir}: no {name} for world_{world_id}.world (looked beside it and in path_files/)")


def convert_barn_worlds(world_dir: Union[str, os.PathLike], out_path: Union[str, os.PathLike],
                        world_ids: Optional[Union[str, Iterable[int]]] = None) -> None:
    """Write a barn.npz-format file from the challenge's ``world_<i>.world`` and
    ``path_<i>.npy`` files in ``world_dir`` (path files beside the worlds or in its
    ``path_files/``, as in the challenge's jackal_helper/worlds/BARN).

    ``world_ids``: which worlds (ids, or a selection string such as "0-299:6");
    default every world_<i>.world in the directory. Worlds are written in increasing
    id order. ``out_path`` is written as given (no .npz is appended) and replaced
    only once the whole file is written.
    """
    world_dir = Path(world_dir)
    if not world_dir.is_dir():
        raise FgdwaError(f"{world_dir}: not a directory (expected the challenge's worlds: world_<i>.world "
                         f"and path_<i>.npy)")
    files = _world_files(world_dir)
    if world_ids is None:
        ids = sorted(files)
        if not ids:
            raise FgdwaError(f"{world_dir}: no world_<i>.world files")
    else:
        ids = parse_world_selection(world_ids, files) if isinstance(world_ids, str) else [int(i) for i in world_ids]
        ids = sorted(set(ids))
        if not ids:
            raise FgdwaError(f"{world_dir}: no worlds selected")
        missing = [i for i in ids if i not in files]
        if missing:
            raise FgdwaError(f"{world_dir}: no world_{missing[0]}.world (asked for worlds {missing})")

    worlds = [read_barn_world(files[i], _path_file(world_dir, i), i) for i in ids]
    arrays = {
        "world_ids": np.array(ids, dtype=np.int64),
        "grids": np.stack([w.grid for w in worlds]).astype(np.uint8),
        "fields": np.stack([w.field for w in worlds]).astype(np.uint8),
        "optimal_time": np.array([w.optimal_time for w in worlds], dtype=np.float64),
        "resolution": np.float64(RESOLUTION),
        "origin": np.array(ORIGIN, dtype=np.float64),
        "start": np.array(START, dtype=np.float64),
        "goal": np.array(GOAL, dtype=np.float64),
        "goal_radius": np.float64(GOAL_RADIUS),
        "time_limit": np.float64(TIME_LIMIT),
    }
    for w in worlds:
        arrays[f"path_{w.world_id}"] = w.path

    out_path = Path(out_path)
    if out_path.parent and not out_path.parent.exists():
        out_path.parent.mkdir(parents=True, exist_ok=True)
    partial = out_path.with_name(out_path.name + ".partial")
    try:
        with open(partial, "wb") as handle:
            np.savez_compressed(handle, **arrays)
        os.replace(partial, out_path)
    except OSError as error:
        partial.unlink(missing_ok=True)
        raise FgdwaError(f"{out_path}: cannot write ({error})") from None
