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
import zipfile
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator, List, Optional, Sequence, Tuple, Union

import numpy as np

from fgdwa import file_limits as limits
from fgdwa._core import FgdwaError, OccupancyGrid
from fgdwa.file_limits import npz_names, read_npz_member, unreadable_as_error, short_repr

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
        raise FgdwaError(f"barn_score: optimal_time = {short_repr(optimal_time)}: must be a finite number > 0")
    if not success:
        return 0.0
    t = float(time)
    if math.isnan(t) or t < 0:
        raise FgdwaError(f"barn_score: time = {short_repr(time)}: a successful run needs a time >= 0")
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
            raise FgdwaError(f"{self.source}: worlds are indexed by position (int), got {short_repr(index)}; "
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
            raise FgdwaError(f"{self.source}: world {short_repr(world_id)} is not in this data set "
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
            raise FgdwaError(f"world selection {short_repr(selection)}: expected a string such as '0-49' or world ids") from None
        for wid in ids:
            self.index_of(wid)
        return list(dict.fromkeys(ids))

    def __repr__(self) -> str:
        return f"BarnDataset({self.source!r}: {describe_world_ids(self._ids)})"


def find_data_file(path: Optional[Union[str, os.PathLike]], variable: str, what: str, missing: str,
                   name_in_directory: Optional[str] = None) -> Path:
    """A data set's file: ``path``, else the environment variable ``variable``;
    a directory stands for its ``name_in_directory``. ``what`` names the data
    in errors, ``missing`` says how to give it when neither is set."""
    source = "argument"
    if path is None:
        path = os.environ.get(variable)
        source = variable
        if not path:
            raise FgdwaError(f"no {what} data given: {missing}")
    p = Path(path)
    if name_in_directory is not None and p.is_dir():
        p = p / name_in_directory
    if not p.is_file():
        raise FgdwaError(f"{what} data {p} ({source}): no such file")
    return p


def find_barn_file(path: Optional[Union[str, os.PathLike]] = None) -> Path:
    """Where barn.npz is: ``path`` (a file, or a directory holding barn.npz), else the
    ``FGDWA_BARN_DATA`` environment variable (same rules)."""
    return find_data_file(path, "FGDWA_BARN_DATA", "BARN",
                          "pass the path of barn.npz (or of its directory), or set FGDWA_BARN_DATA; make the file "
                          "with `fgdwa barn import WORLD_DIR --out FILE`", name_in_directory="barn.npz")


def load_barn(path: Union[str, os.PathLike]) -> BarnDataset:
    """Read and check a file in the barn.npz format (docs/barn.md).

    Only the format's keys are read (SHARED_KEYS and ``path_<id>`` of each world
    id), each refused before it is decompressed when the zip directory or its
    .npy header says it holds more than ``fgdwa.file_limits.MAX_ARRAY_BYTES``.
    Raises FgdwaError naming the file and the key on a missing key, a wrong shape,
    dtype or value (a resolution, origin or time limit beyond the limits of
    fgdwa.file_limits; a start or goal off the map or on an obstacle of a world;
    a goal radius holding the start), or a world id without its ``path_<id>``.
    """
    name = str(path)
    not_barn = f"{name}: not a barn.npz file (expected an .npz archive with keys {', '.join(SHARED_KEYS)})"
    # Exception: zipfile.BadZipFile, zlib.error and friends from a damaged archive.
    with unreadable_as_error(name, ".npz file", also=(Exception,)):
        if not zipfile.is_zipfile(path):
            with open(path, "rb") as handle:
                npy = handle.read(len(np.lib.format.MAGIC_PREFIX)) == np.lib.format.MAGIC_PREFIX
            if npy:  # a lone .npy array
                raise FgdwaError(not_barn)
            raise FgdwaError(f"{name}: not a readable .npz file (not a zip archive)")
        with zipfile.ZipFile(path) as archive:
            keys = npz_names(archive)
            if not keys:
                raise FgdwaError(not_barn)
            for key in SHARED_KEYS:
                if key not in keys:
                    raise FgdwaError(f"{name}: missing key '{key}' (a barn.npz file holds {', '.join(SHARED_KEYS)} "
                                     f"and path_<id> per world)")
            arrays = {key: read_npz_member(archive, key, name) for key in SHARED_KEYS}
            ids = arrays["world_ids"]
            _check_world_ids(name, ids)
            for wid in ids:
                key = f"path_{int(wid)}"
                if key not in keys:
                    raise FgdwaError(f"{name}: missing key '{key}': world {int(wid)} is in world_ids but has no "
                                     f"reference path")
                arrays[key] = read_npz_member(archive, key, name)
    _check_arrays(name, arrays, keys)
    return BarnDataset(name, arrays)


def _check_world_ids(name: str, ids: np.ndarray) -> None:
    def fail(message):
        raise FgdwaError(f"{name}: key 'world_ids': {message}")

    if ids.ndim != 1 or len(ids) == 0:
        fail(f"shape {ids.shape}: expected (n,) with n >= 1")
    if ids.dtype.kind not in "iu":
        fail(f"dtype {ids.dtype}: expected integers")
    if np.any(ids < 0):
        fail(f"negative world id {int(ids[ids < 0][0])}")
    unique, counts = np.unique(ids, return_counts=True)
    if np.any(counts > 1):
        fail(f"world id {int(unique[counts > 1][0])} appears more than once")


def _check_arrays(name: str, a: dict, keys: Sequence[str]) -> None:
    def fail(key, message):
        raise FgdwaError(f"{name}: key '{key}': {message}")

    ids = a["world_ids"]
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
    _check_float(fail, a, "resolution", ())
    _check_float(fail, a, "origin", (2,))
    _check_float(fail, a, "start", (3,))
    _check_float(fail, a, "goal", (2,))
    _check_float(fail, a, "goal_radius", ())
    _check_float(fail, a, "time_limit", ())
    for key in ("resolution", "goal_radius", "time_limit"):
        if float(a[key]) <= 0:
            fail(key, f"{short_repr(float(a[key]))}: must be > 0")
    if np.any(a["optimal_time"] <= 0):
        fail("optimal_time", "values must be > 0 (seconds)")

    # Numbers the simulation can hold: a cell the distance field can size, a
    # finite run, positions that keep their precision.
    resolution = float(a["resolution"])
    if not limits.MIN_RESOLUTION <= resolution <= limits.MAX_RESOLUTION:
        fail("resolution", f"{short_repr(resolution)}: must be within [{limits.MIN_RESOLUTION:g}, {limits.MAX_RESOLUTION:g}] "
                           f"m per cell (fgdwa.file_limits.MIN_RESOLUTION, MAX_RESOLUTION)")
    origin = tuple(float(v) for v in a["origin"])
    x0, y0 = origin
    x1, y1 = x0 + GRID_SHAPE[1] * resolution, y0 + GRID_SHAPE[0] * resolution
    if max(abs(x0), abs(y0), abs(x1), abs(y1)) > limits.MAX_COORDINATE:
        fail("origin", f"{origin}: the map spans x {x0:g} to {x1:g}, y {y0:g} to {y1:g}; its corners must lie "
                       f"within +-{limits.MAX_COORDINATE:g} m (fgdwa.file_limits.MAX_COORDINATE)")
    time_limit = float(a["time_limit"])
    if time_limit > limits.MAX_DURATION:
        fail("time_limit", f"{short_repr(time_limit)}: must be <= {limits.MAX_DURATION:g} s of simulated time "
                           f"(fgdwa.file_limits.MAX_DURATION)")
    slowest = float(np.max(a["optimal_time"]))
    if slowest > time_limit:
        fail("optimal_time", f"{short_repr(slowest)} s is over the time limit {time_limit:g} s: every run that succeeded "
                             f"would score the best 0.5 however slow")
    if abs(float(a["start"][2])) > limits.MAX_MAGNITUDE:
        fail("start", f"yaw {short_repr(float(a['start'][2]))}: must be within +-{limits.MAX_MAGNITUDE:g} rad")

    # The task must be one: start and goal on the map, apart by more than the goal radius.
    def inside(point):
        return x0 <= point[0] < x1 and y0 <= point[1] < y1

    start, goal = a["start"][:2], a["goal"]
    for key, point in (("start", start), ("goal", goal)):
        if not inside(point):
            fail(key, f"({point[0]:g}, {point[1]:g}) is off the map (x {x0:g} to {x1:g}, y {y0:g} to {y1:g})")
    distance = float(np.hypot(*(goal - start)))
    goal_radius = float(a["goal_radius"])
    if goal_radius >= distance:
        fail("goal_radius", f"{short_repr(goal_radius)} m holds the start ({distance:g} m from the goal): every run would "
                            f"succeed before the robot moved")
    for key, point in (("start", start), ("goal", goal)):
        row = min(int((point[1] - y0) / resolution), GRID_SHAPE[0] - 1)
        col = min(int((point[0] - x0) / resolution), GRID_SHAPE[1] - 1)
        blocked = np.flatnonzero(a["grids"][:, row, col])
        if len(blocked):
            k = int(blocked[0])
            fail(key, f"({point[0]:g}, {point[1]:g}) lies on an obstacle cell [{row}, {col}] of world "
                      f"{int(ids[k])} (grids[{k}])")

    id_set = set(int(i) for i in ids)
    for wid in ids:
        key = f"path_{int(wid)}"
        path = a[key]
        if path.ndim != 2 or path.shape[1] != 2 or path.shape[0] < 1:
            fail(key, f"shape {path.shape}: expected (n, 2) points (x, y) in map metres")
        if path.dtype.kind != "f":
            hint = (" (the challenge's path_<i>.npy holds [row, col] field cells; convert the challenge's files "
                    "with `fgdwa barn import`)" if path.dtype.kind in "iu" else "")
            fail(key, f"dtype {path.dtype}: expected float map metres{hint}")
        if not np.all(np.isfinite(path)):
            fail(key, "non-finite values")
        off = ~((path[:, 0] >= x0) & (path[:, 0] < x1) & (path[:, 1] >= y0) & (path[:, 1] < y1))
        if np.any(off):
            i = int(np.flatnonzero(off)[0])
            fail(key, f"point {i} ({path[i, 0]:g}, {path[i, 1]:g}) of world {int(wid)} is off the map "
                      f"(x {x0:g} to {x1:g}, y {y0:g} to {y1:g})")
    for key in keys:
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


def parse_world_selection(text: str, available: Optional[Iterable[int]] = None, what: str = "world selection",
                          noun: str = "world id") -> List[int]:
    """World ids of a selection, in the order written, without repeats.

    ``text`` is ``all`` or comma-separated items, each a world id (``12``) or an
    inclusive range of world ids (``0-49``) with an optional step (``0-299:6`` is the
    challenge's local test set 0, 6, ..., 294). With ``available`` (the ids a data
    set holds), ``all`` means all of them, a range keeps those it holds (and must
    keep one), and a single id it does not hold is an error; without it, ``all`` is
    an error. ``what`` and ``noun`` name the selection and its items in errors
    (the dynamic benchmark's seeds use the same syntax).
    """
    if not isinstance(text, str):
        raise FgdwaError(f"{what} {short_repr(text)}: expected a string such as 'all', '0,6,12' or '0-49'")
    have = None if available is None else sorted(set(int(i) for i in available))
    have_set = None if have is None else set(have)
    spec = text.strip()
    if spec.lower() == "all":
        if have is None:
            raise FgdwaError(f"{what} 'all': needs a data set to say which worlds there are")
        return list(have)
    if not spec:
        raise FgdwaError(f"{what} '': empty (use ids such as '0,6,12' or a range such as '0-49')")
    ids: List[int] = []
    for item in spec.split(","):
        item = item.strip()
        if item.isdigit():
            wid = int(item)
            if have_set is not None and wid not in have_set:
                raise FgdwaError(f"{what} {short_repr(text)}: world {wid} is not in the data set "
                                 f"({describe_world_ids(have)})")
            ids.append(wid)
            continue
        match = _RANGE.match(item)
        if not match:
            raise FgdwaError(f"{what} {short_repr(text)}: cannot read {short_repr(item)} (expected 'all', a {noun} such as "
                             f"'12', or a range such as '0-49' or '0-299:6')")
        first, last = int(match.group(1)), int(match.group(2))
        step = int(match.group(3)) if match.group(3) else 1
        if last < first:
            raise FgdwaError(f"{what} {short_repr(text)}: range {short_repr(item)} runs backwards")
        if step < 1:
            raise FgdwaError(f"{what} {short_repr(text)}: range {short_repr(item)} needs a step >= 1")
        chosen = range(first, last + 1, step)
        if have_set is not None:
            chosen = [wid for wid in chosen if wid in have_set]
            if not chosen:
                raise FgdwaError(f"{what} {short_repr(text)}: no world of {short_repr(item)} is in the data set "
                                 f"({describe_world_ids(have)})")
        ids.extend(chosen)
    return list(dict.fromkeys(ids))
