"""Converting the BARN challenge's files (Gazebo world_<i>.world and path_<i>.npy) into
the barn.npz format that :mod:`fgdwa.io.barn_data` loads."""

from __future__ import annotations

import math
import os
import re
from pathlib import Path
from typing import Iterable, List, NamedTuple, Optional, Tuple, Union

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.file_limits import load_npy, short_repr
from fgdwa.io.barn_data import (
    _ALIGN_TOL,
    BARN_FIELD_SIZE,
    CYLINDER_RADIUS,
    FIELD_CELL0_GAZEBO,
    FIELD_LEFT_COL,
    FIELD_MIN_GAZEBO_Y,
    FIELD_TOP_ROW,
    GAZEBO_GOAL,
    GAZEBO_START,
    GOAL,
    GOAL_RADIUS,
    GRID_SHAPE,
    OPTIMAL_SPEED,
    ORIGIN,
    RESOLUTION,
    START,
    TIME_LIMIT,
    parse_world_selection,
)


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
            raise FgdwaError(f"{world_file}: model {m.group(1)}: cannot read pose "
                             f"{short_repr(pose.group(1).strip())}")
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
    if not path_file.is_file():
        raise FgdwaError(f"{path_file}: no such file (each world_<i>.world needs its path_<i>.npy)")
    cells = load_npy(path_file, str(path_file))  # its size read from the header first
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
