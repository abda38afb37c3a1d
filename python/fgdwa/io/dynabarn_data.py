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
import math
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, List, Optional, Union

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.file_limits import read_text
from fgdwa.io.barn_data import describe_world_ids, parse_world_selection
from fgdwa.sim.keyframes import KeyframedMover

DIFFICULTIES = ("easy", "medium", "hard")
MAX_MOVERS = 1000  # per world
MAX_KEYFRAMES = 100_000  # per mover
MAX_COORDINATE = 1e4  # m
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
            raise FgdwaError(f"DynaBARN world {world_id!r}: not in {self.source} "
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
    source = "argument"
    if path is None:
        path = os.environ.get("FGDWA_DYNABARN_DATA")
        source = "FGDWA_DYNABARN_DATA"
        if not path:
            raise FgdwaError("no DynaBARN data given: pass --data FILE (a JSON file in the format of "
                             "dynabarn_dev.json), or set FGDWA_DYNABARN_DATA")
    p = Path(path)
    if not p.is_file():
        raise FgdwaError(f"DynaBARN data {p} ({source}): no such file")
    return p


class _Reader:
    """Checks one world's values, naming the world and key in each error."""

    def __init__(self, where: str):
        self.where = where

    def fail(self, key: str, value, why: str):
        text = repr(value)
        if len(text) > 80:
            text = text[:77] + "..."
        raise FgdwaError(f"{self.where}: {key} = {text}: {why}")

    def number(self, value, key: str, low: Optional[float] = None, positive: bool = False,
               limit: float = MAX_COORDINATE) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            self.fail(key, value, "expected a number")
        value = float(value) if abs(value) < 1e300 else math.inf
        if not math.isfinite(value) or abs(value) > limit:
            self.fail(key, value, f"must be finite, within +-{limit:g}")
        if low is not None and (value <= low if positive else value < low):
            self.fail(key, value, f"must be {'>' if positive else '>='} {low:g}")
        return value

    def numbers(self, value, key: str, count: int) -> tuple:
        if not isinstance(value, list) or len(value) != count:
            self.fail(key, value, f"expected a list of {count} numbers")
        return tuple(self.number(v, f"{key}[{i}]") for i, v in enumerate(value))

    def items(self, value, key: str, limit: int) -> list:
        if not isinstance(value, list):
            self.fail(key, value, "expected a list")
        if len(value) > limit:
            self.fail(key, f"<{len(value)} items>", f"at most {limit}")
        return value


def _world(data, index: int) -> DynabarnWorld:
    if not isinstance(data, dict):
        raise FgdwaError(f"DynaBARN worlds[{index}]: expected a mapping, got {type(data).__name__}")
    read = _Reader(f"DynaBARN worlds[{index}]" + (f" (world {data.get('world')!r})" if "world" in data else ""))
    needed = ("world", "start", "goal", "time_limit", "success_radius", "walls", "movers")
    for key in needed:
        if key not in data:
            read.fail(key, None, "required")
    wid = data["world"]
    if isinstance(wid, bool) or not isinstance(wid, int) or wid < 0:
        read.fail("world", wid, "expected an integer >= 0")
    barn_idx = data.get("barn_world_idx", 300 + wid)
    if isinstance(barn_idx, bool) or not isinstance(barn_idx, int):
        read.fail("barn_world_idx", barn_idx, "expected an integer")
    difficulty = data.get("difficulty", "")
    if difficulty not in DIFFICULTIES + ("",):
        read.fail("difficulty", difficulty, f"expected one of {', '.join(DIFFICULTIES)}")
    start = read.numbers(data["start"], "start", 3)
    goal = read.numbers(data["goal"], "goal", 2)
    time_limit = read.number(data["time_limit"], "time_limit", 0.0, positive=True, limit=1e5)
    radius = read.number(data["success_radius"], "success_radius", 0.0, positive=True)
    walls = []
    for i, wall in enumerate(read.items(data["walls"], "walls", 10_000)):
        rect = read.numbers(wall.get("rect") if isinstance(wall, dict) else wall, f"walls[{i}].rect", 4)
        if not (rect[0] < rect[2] and rect[1] < rect[3]):
            read.fail(f"walls[{i}].rect", list(rect), "expected [x0, y0, x1, y1] with x0 < x1 and y0 < y1")
        walls.append(rect)
    movers = []
    for i, mover in enumerate(read.items(data["movers"], "movers", MAX_MOVERS)):
        key = f"movers[{i}]"
        if not isinstance(mover, dict):
            read.fail(key, mover, "expected a mapping with radius, loop, length_s and keyframes")
        frames = read.items(mover.get("keyframes"), f"{key}.keyframes", MAX_KEYFRAMES)
        for j, frame in enumerate(frames):
            read.numbers(frame, f"{key}.keyframes[{j}]", 3)
        loop = mover.get("loop", True)
        if not isinstance(loop, bool):
            read.fail(f"{key}.loop", loop, "expected true or false")
        length = mover.get("length_s")
        if length is not None:
            length = read.number(length, f"{key}.length_s", 0.0, positive=True, limit=1e5)
        radius_m = read.number(mover.get("radius"), f"{key}.radius", 0.0, positive=True)
        try:
            movers.append(KeyframedMover(radius_m, np.array(frames, dtype=float), loop=loop, length=length))
        except FgdwaError as error:
            raise FgdwaError(f"{read.where}: {key}: {error}") from None
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
    worlds = [_world(w, i) for i, w in enumerate(data["worlds"])]
    return DynabarnDataset(worlds, source=str(path), about=str(data.get("about", "")))
