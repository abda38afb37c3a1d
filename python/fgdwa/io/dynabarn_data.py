"""DynaBARN worlds from a JSON data file (the format of dynabarn_dev.json).

The file is ``{"about": str, "worlds": [world, ...]}``; each world holds
``world`` (its id), ``barn_world_idx`` (run.py's ``--world_idx``),
``difficulty``, ``start`` [x, y, yaw rad], ``goal`` [x, y], ``time_limit`` (s),
``success_radius`` (m), ``walls`` (``{"name", "rect": [x0, y0, x1, y1]}``, m)
and ``movers`` (``{"radius", "loop", "length_s", "keyframes": [[t, x, y], ...]}``,
moved as Gazebo's PoseAnimation moves them: :mod:`fgdwa.sim.keyframes`).
Every value is checked on loading; an error names the world and the key.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, List, Optional, Union

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.file_limits import read_text, short_repr
from fgdwa.io.barn_data import describe_world_ids, find_data_file, parse_world_selection
from fgdwa.io.scenario_values import ValueReader, join_key
from fgdwa.sim.keyframes import KeyframedMover

DIFFICULTIES = ("easy", "medium", "hard")
MAX_FILE_BYTES = 64 * 2**20


@dataclass(frozen=True)
class DynabarnWorld:
    world: int
    barn_world_idx: int
    difficulty: str
    start: tuple  # (x, y, yaw rad)
    goal: tuple  # (x, y)
    time_limit: float  # s
    success_radius: float  # m
    walls: tuple  # ((x0, y0, x1, y1), ...) m
    movers: tuple  # KeyframedMover, ...

    @property
    def extent(self) -> tuple:
        """(x0, x1, y0, y1) m: the walls, the start, the goal and every mover's keyframes."""
        xs = [self.start[0], self.goal[0]] + [v for r in self.walls for v in (r[0], r[2])]
        ys = [self.start[1], self.goal[1]] + [v for r in self.walls for v in (r[1], r[3])]
        for m in self.movers:
            xs += [float(m.keyframes[:, 1].min() - m.radius), float(m.keyframes[:, 1].max() + m.radius)]
            ys += [float(m.keyframes[:, 2].min() - m.radius), float(m.keyframes[:, 2].max() + m.radius)]
        return min(xs), max(xs), min(ys), max(ys)


class DynabarnDataset:
    """The worlds of one data file, by world id."""

    def __init__(self, worlds: List[DynabarnWorld], source: str = "", about: str = ""):
        self.source = source
        self.about = about
        self._worlds = {w.world: w for w in worlds}
        if len(self._worlds) != len(worlds):
            raise FgdwaError(f"DynaBARN data {source}: a world id appears twice")

    def __len__(self) -> int:
        return len(self._worlds)

    @property
    def world_ids(self) -> list:
        return sorted(self._worlds)

    def world(self, world_id: int) -> DynabarnWorld:
        if world_id not in self._worlds:
            raise FgdwaError(f"DynaBARN world {short_repr(world_id)}: not in {self.source} "
                             f"({describe_world_ids(self.world_ids)})")
        return self._worlds[world_id]

    def select_ids(self, selection: Union[str, int, Iterable[int]]) -> List[int]:
        """World ids of a selection ('all', '0,3,6', '0-59:3'), checked against this data set."""
        if isinstance(selection, str):
            return parse_world_selection(selection, self.world_ids)
        if isinstance(selection, (int, np.integer)) and not isinstance(selection, bool):
            selection = [selection]
        ids = list(dict.fromkeys(int(i) for i in selection))
        for wid in ids:
            self.world(wid)
        return ids

    def __repr__(self) -> str:
        return f"DynabarnDataset({self.source!r}: {describe_world_ids(self.world_ids)})"


def find_dynabarn_file(path: Optional[Union[str, os.PathLike]] = None) -> Path:
    """``path``, else the ``FGDWA_DYNABARN_DATA`` environment variable: a JSON data file."""
    return find_data_file(path, "FGDWA_DYNABARN_DATA", "DynaBARN",
                          "pass --data FILE (a JSON file in the format of dynabarn_dev.json), or set "
                          "FGDWA_DYNABARN_DATA")


def _world(data, index: int, source: str) -> DynabarnWorld:
    wid = data.get("world") if isinstance(data, dict) else None
    read = ValueReader(f"DynaBARN data {source}, worlds[{index}]" + (f" (world {wid!r})" if wid is not None else ""),
                       Path(source).parent)
    # Keys it does not read are let be: other files in this format may carry more.
    if not isinstance(data, dict):
        read.fail("world", data, "expected a mapping")
    for name in ("world", "start", "goal", "time_limit", "success_radius", "walls", "movers"):
        if name not in data:
            read.fail(name, None, "required")
    wid = read.integer(data["world"], "world", low=0)
    barn_idx = read.integer(data.get("barn_world_idx", 300 + wid), "barn_world_idx")
    difficulty = read.string(data.get("difficulty", ""), "difficulty")
    if difficulty not in DIFFICULTIES + ("",):
        read.fail("difficulty", difficulty, f"expected one of {', '.join(DIFFICULTIES)}")
    start = data["start"]
    if not isinstance(start, list) or len(start) != 3:
        read.fail("start", start, "expected [x, y, yaw] (m, m, rad)")
    start = (*read.point(start[:2], "start"), read.number(start[2], "start[2]"))
    goal = read.point(data["goal"], "goal")
    time_limit = read.duration(data["time_limit"], "time_limit", positive=True)
    radius = read.length(data["success_radius"], "success_radius", positive=True)
    walls = []
    for i, wall in enumerate(read.list_of(data["walls"], "walls")):
        key = join_key(join_key("walls", i), "rect")
        rect = wall.get("rect") if isinstance(wall, dict) else wall
        if not isinstance(rect, list) or len(rect) != 4:
            read.fail(key, rect, "expected [x0, y0, x1, y1] (m)")
        rect = (*read.point(rect[:2], key), *read.point(rect[2:], key))
        if not (rect[0] < rect[2] and rect[1] < rect[3]):
            read.fail(key, list(rect), "expected [x0, y0, x1, y1] with x0 < x1 and y0 < y1")
        walls.append(rect)
    movers = []
    for i, mover in enumerate(read.list_of(data["movers"], "movers")):
        key = join_key("movers", i)
        if not isinstance(mover, dict):
            read.fail(key, mover, "expected a mapping with radius, loop, length_s and keyframes")
        frames = read.keyframes(mover.get("keyframes"), join_key(key, "keyframes"))
        loop = read.boolean(mover.get("loop", True), join_key(key, "loop"))
        length = mover.get("length_s")
        if length is not None:
            length = read.duration(length, join_key(key, "length_s"), positive=True)
        radius_m = read.length(mover.get("radius"), join_key(key, "radius"), positive=True)
        movers.append(read.core(key, mover, lambda: KeyframedMover(radius_m, frames, loop=loop, length=length)))
    return DynabarnWorld(world=wid, barn_world_idx=barn_idx, difficulty=difficulty, start=start, goal=goal,
                         time_limit=time_limit, success_radius=radius, walls=tuple(walls), movers=tuple(movers))


def load_dynabarn(path: Union[str, os.PathLike]) -> DynabarnDataset:
    """The worlds of a DynaBARN data file; FgdwaError names what is wrong with it."""
    path = Path(path)
    try:
        data = json.loads(read_text(path, f"DynaBARN data {path}", max_bytes=MAX_FILE_BYTES))
    except UnicodeDecodeError:
        raise FgdwaError(f"DynaBARN data {path}: not UTF-8 text") from None
    except json.JSONDecodeError as error:
        raise FgdwaError(f"DynaBARN data {path}: not JSON ({error.msg} at line {error.lineno})") from None
    if not isinstance(data, dict) or not isinstance(data.get("worlds"), list) or not data["worlds"]:
        raise FgdwaError(f"DynaBARN data {path}: expected {{\"about\": ..., \"worlds\": [...]}} with one world "
                         "or more")
    worlds = [_world(w, i, str(path)) for i, w in enumerate(data["worlds"])]
    return DynabarnDataset(worlds, source=str(path), about=str(data.get("about", "")))
