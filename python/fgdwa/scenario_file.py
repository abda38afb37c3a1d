"""Scenarios read from YAML (the format is described in docs/scenarios.md).

``load_scenario(source)`` takes a path to a ``.yaml`` file, YAML text, or the
name of a scenario shipped with the package (``shipped_scenarios()``), and
returns a ``fgdwa.scenario.Scenario``. Every problem in the input raises
``FgdwaError`` naming the file (``<text>`` for text), the key path (for example
``moving_obstacles[1].speed``) and the offending value, so a user can fix a file
without reading a traceback.

Units: metres, seconds, and degrees for angles in positions and headings (the
key says so: ``theta_deg``, ``fov_deg``). Angular rates and their accelerations
(``omega_max``, ``acc_omega``) stay in rad/s and rad/s^2, like ``RobotLimits``.
"""

from __future__ import annotations

import difflib
import math
import os
import re
from pathlib import Path
from typing import Any, Optional, Sequence, Union

import numpy as np
import yaml

from fgdwa._core import (
    CollisionWorld,
    DetectWindowParams,
    FgdwaError,
    Footprint,
    LidarParams,
    OccupancyGrid,
    PlannerParams,
    RobotLimits,
    TerrainGrid,
    critic_names,
    planner_preset,
    preset_names,
)
from fgdwa.scenario import PARAM_FIELDS, Scenario, Variability, params_with
from fgdwa.world import MOVER_MODES, MovingObstacle, World

SHIPPED_DIR = Path(__file__).resolve().parent / "scenarios"
TEXT = "<text>"

_TOP_KEYS = ("name", "description", "map", "terrain", "unknown_obstacles", "moving_obstacles", "start", "goal",
             "robot", "planner", "global_planner", "lidar", "detect_window", "variability", "max_steps",
             "goal_tolerance")
_MAP_SOURCES = ("ascii", "png", "npy", "size")
_LIMIT_FIELDS = ("v_min", "v_max", "omega_max", "acc_v", "acc_omega", "brake_v", "brake_omega")
# The type of each planner override, from the bound PlannerParams' defaults.
_OVERRIDE_TYPES = {name: type(getattr(PlannerParams(), name)) for name in PARAM_FIELDS}


def shipped_scenarios() -> list:
    """Names of the scenarios shipped with the package (``e1``, ``e2``, ``e3``, ``demo``, ...)."""
    if not SHIPPED_DIR.is_dir():
        return []
    return sorted(p.stem for p in SHIPPED_DIR.glob("*.yaml"))


def shipped_scenario_path(name: str) -> Path:
    """The YAML file of a shipped scenario."""
    names = shipped_scenarios()
    if name not in names:
        raise FgdwaError(f"scenario {name!r}: not a shipped scenario (shipped: {', '.join(names) or 'none'})")
    return SHIPPED_DIR / f"{name}.yaml"


def load_scenario(source: Union[str, os.PathLike], base_dir: Union[str, os.PathLike, None] = None) -> Scenario:
    """A Scenario from a YAML file, YAML text, or a shipped scenario's name.

    ``source`` is tried in this order: a shipped name (``shipped_scenarios()``),
    a path (a ``Path``, or a one-line string ending in .yaml/.yml or naming an
    existing file), else YAML text. Files a scenario refers to (png, npy) are
    found relative to its YAML file; for text, relative to ``base_dir`` (default:
    the current directory).
    """
    if isinstance(source, str) and source in shipped_scenarios():
        return _load_file(SHIPPED_DIR / f"{source}.yaml")
    if isinstance(source, os.PathLike):
        return _load_file(Path(source))
    if not isinstance(source, str):
        raise FgdwaError(f"load_scenario: source = {source!r}: expected a path, YAML text or a shipped scenario "
                         f"name ({', '.join(shipped_scenarios())})")
    one_line = "\n" not in source
    if one_line and (source.strip().endswith((".yaml", ".yml")) or Path(source).is_file()):
        return _load_file(Path(source))
    if one_line and ":" not in source:
        raise FgdwaError(f"load_scenario: source = {source!r}: neither a shipped scenario "
                         f"({', '.join(shipped_scenarios())}), an existing file, nor YAML text")
    return _load_text(source, TEXT, Path(base_dir) if base_dir is not None else Path.cwd())


def scenario_from_dict(data: Any, where: str = "<dict>", base_dir: Union[str, os.PathLike, None] = None) -> Scenario:
    """A Scenario from an already parsed YAML document (a dict); ``where`` names it in error messages."""
    return _Reader(where, Path(base_dir) if base_dir is not None else Path.cwd()).scenario(data)


def _load_file(path: Path) -> Scenario:
    where = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise FgdwaError(f"{where}: no such scenario file") from None
    except (OSError, UnicodeDecodeError) as error:
        raise FgdwaError(f"{where}: cannot read the scenario file ({error})") from None
    return _load_text(text, where, path.resolve().parent, default_name=path.stem)


def _load_text(text: str, where: str, base_dir: Path, default_name: str = "scenario") -> Scenario:
    data = _parse_yaml(text, where)
    return _Reader(where, base_dir, default_name).scenario(data)


# --- YAML -----------------------------------------------------------------------------------------------------------


class _StrictLoader(yaml.SafeLoader):
    """SafeLoader that refuses duplicate keys and reads 1e-3 as a number (YAML 1.1 wants 1.0e-3)."""

    def construct_mapping(self, node, deep=False):
        if isinstance(node, yaml.MappingNode):
            self.flatten_mapping(node)
            seen = set()
            for key_node, _ in node.value:
                key = self.construct_object(key_node, deep=True)
                try:
                    duplicate = key in seen
                except TypeError:
                    raise yaml.constructor.ConstructorError(None, None, f"unhashable key {key!r}",
                                                            key_node.start_mark) from None
                if duplicate:
                    raise yaml.constructor.ConstructorError(None, None, f"duplicate key {key!r}",
                                                            key_node.start_mark)
                seen.add(key)
        return super().construct_mapping(node, deep=deep)


_StrictLoader.add_implicit_resolver(
    "tag:yaml.org,2002:float",
    re.compile(r"""^[-+]?(?:[0-9][0-9_]*)(?:\.[0-9_]*)?[eE][-+]?[0-9]+$"""),
    list("-+0123456789"))


def _parse_yaml(text: str, where: str) -> Any:
    try:
        return yaml.load(text, Loader=_StrictLoader)  # noqa: S506 (a SafeLoader subclass)
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        problem = error.problem or error.context or "malformed YAML"
        if mark is None:
            raise FgdwaError(f"{where}: malformed YAML: {problem}") from None
        lines = text.splitlines()
        line = lines[mark.line] if 0 <= mark.line < len(lines) else ""
        raise FgdwaError(f"{where}: malformed YAML at line {mark.line + 1}, column {mark.column + 1}: {problem} "
                         f"(line {mark.line + 1} = {line.strip()!r})") from None
    except yaml.YAMLError as error:
        raise FgdwaError(f"{where}: malformed YAML: {error}") from None


# --- reading --------------------------------------------------------------------------------------------------------


def _short(value: Any, limit: int = 80) -> str:
    text = repr(value)
    return text if len(text) <= limit else text[:limit - 3] + "..."


def _join(parent: str, child: Union[str, int]) -> str:
    if isinstance(child, int):
        return f"{parent}[{child}]"
    return f"{parent}.{child}" if parent else str(child)


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


class _Layout:
    """The map's cells: shape, resolution, origin, and how many cells one ASCII character stands for."""

    def __init__(self, shape: tuple, resolution: float, origin: tuple, cells_per_char: int):
        self.shape = shape
        self.resolution = resolution
        self.origin = origin
        self.cells_per_char = cells_per_char

    @property
    def extent(self) -> tuple:
        rows, cols = self.shape
        x0, y0 = self.origin
        return x0, x0 + cols * self.resolution, y0, y0 + rows * self.resolution

    def describe(self) -> str:
        rows, cols = self.shape
        text = f"{rows} x {cols} cells"
        if self.cells_per_char > 1 and rows % self.cells_per_char == 0 and cols % self.cells_per_char == 0:
            text += f" = {rows // self.cells_per_char} rows x {cols // self.cells_per_char} characters " \
                    f"at cells_per_char {self.cells_per_char}"
        return text


class _Reader:
    """Reads one YAML document into a Scenario; every error names ``where``, the key path and the value."""

    def __init__(self, where: str, base_dir: Path, default_name: str = "scenario"):
        self.where = where
        self.base_dir = base_dir
        self.default_name = default_name

    # errors and basic types

    def fail(self, key: str, value: Any, problem: str):
        raise FgdwaError(f"{self.where}: {key} = {_short(value)}: {problem}")

    def mapping(self, value: Any, key: str, allowed: Sequence[str], required: Sequence[str] = ()) -> dict:
        if not isinstance(value, dict):
            self.fail(key, value, f"expected a mapping with keys {', '.join(allowed)}")
        for name, item in value.items():
            if not isinstance(name, str) or name not in allowed:
                close = difflib.get_close_matches(str(name), allowed, n=1)
                hint = f"; did you mean {close[0]!r}?" if close else ""
                self.fail(_join(key, str(name)), item, f"unknown key (known here: {', '.join(allowed)}){hint}")
        for name in required:
            if value.get(name) is None:
                self.fail(_join(key, name), None, "required")
        return value

    def number(self, value: Any, key: str, low: Optional[float] = None, high: Optional[float] = None,
               low_open: bool = False) -> float:
        if not _is_number(value):
            self.fail(key, value, "expected a number")
        value = float(value)
        if not math.isfinite(value):
            self.fail(key, value, "must be finite")
        if low is not None and (value <= low if low_open else value < low):
            self.fail(key, value, f"must be {'>' if low_open else '>='} {low:g}")
        if high is not None and value > high:
            self.fail(key, value, f"must be <= {high:g}")
        return value

    def integer(self, value: Any, key: str, low: Optional[int] = None) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            self.fail(key, value, "expected an integer")
        if low is not None and value < low:
            self.fail(key, value, f"must be >= {low}")
        return int(value)

    def boolean(self, value: Any, key: str) -> bool:
        if not isinstance(value, bool):
            self.fail(key, value, "expected true or false")
        return value

    def string(self, value: Any, key: str) -> str:
        if not isinstance(value, str):
            self.fail(key, value, "expected a string")
        return value

    def point(self, value: Any, key: str) -> tuple:
        if isinstance(value, dict):
            self.mapping(value, key, ("x", "y"), required=("x", "y"))
            return self.number(value["x"], _join(key, "x")), self.number(value["y"], _join(key, "y"))
        if not isinstance(value, (list, tuple)) or len(value) != 2:
            self.fail(key, value, "expected [x, y] in metres")
        return tuple(self.number(v, _join(key, i)) for i, v in enumerate(value))

    def points(self, value: Any, key: str, minimum: int) -> np.ndarray:
        if not isinstance(value, (list, tuple)) or len(value) < minimum:
            self.fail(key, value, f"expected a list of at least {minimum} [x, y] points")
        return np.array([self.point(v, _join(key, i)) for i, v in enumerate(value)], dtype=float)

    def file(self, value: Any, key: str, suffixes: Sequence[str]) -> Path:
        name = self.string(value, key)
        path = Path(name).expanduser()
        if not path.is_absolute():
            path = self.base_dir / path
        if not path.is_file():
            self.fail(key, value, f"no such file ({path})")
        if path.suffix.lower() not in suffixes:
            self.fail(key, value, f"expected a {' or '.join(suffixes)} file")
        return path

    def core(self, key: str, value: Any, build):
        """Calls a core constructor; its complaint is reported at ``key``."""
        try:
            return build()
        except FgdwaError as error:
            self.fail(key, value, str(error))
        except (TypeError, ValueError, RuntimeError) as error:
            self.fail(key, value, f"rejected ({error})".splitlines()[0])

    # the document

    def scenario(self, data: Any) -> Scenario:
        if data is None:
            raise FgdwaError(f"{self.where}: the scenario is empty")
        try:
            return self._scenario(data)
        except FgdwaError:
            raise
        except Exception as error:  # a bug here must still say which file it was reading
            raise FgdwaError(f"{self.where}: could not read the scenario ({type(error).__name__}: {error})") from error

    def _scenario(self, data: Any) -> Scenario:
        if not isinstance(data, dict):
            raise FgdwaError(f"{self.where}: expected a mapping of scenario keys at the top level, "
                             f"got {_short(data)}")
        self.mapping(data, "", _TOP_KEYS, required=("map", "start", "goal"))
        name = self.string(data["name"], "name") if data.get("name") is not None else self.default_name
        description = self.string(data["description"], "description").strip() \
            if data.get("description") is not None else ""

        grid, layout = self.occupancy_map(data["map"])
        terrain, factors = self.terrain(data.get("terrain"), layout)
        hidden = self.unknown_obstacles(data.get("unknown_obstacles"), layout)
        movers, known = self.moving_obstacles(data.get("moving_obstacles"))
        world = self.core("map", data["map"], lambda: World(
            grid=grid, hidden=hidden, terrain=terrain, movers=tuple(movers), discs_known=known,
            passing_factors=factors))

        limits, footprint = self.robot(data.get("robot"))
        start = self.start(data["start"])
        goal = self.point(data["goal"], "goal")
        self.check_start(start, data["start"], world, footprint, layout)
        self.check_goal(goal, data["goal"], world, footprint, layout)

        planner, overrides = self.planner(data.get("planner"))
        method, options = self.global_planner(data.get("global_planner"), grid)
        if method == "astar":
            self.check_reachable(start, goal, data["goal"], world, footprint, options)
        options_kw = {}
        if data.get("lidar") is not None:
            options_kw["lidar"] = self.lidar(data["lidar"])
        if data.get("detect_window") is not None:
            options_kw["window"] = self.detect_window(data["detect_window"])
        if data.get("variability") is not None:
            options_kw["variability"] = self.variability(data["variability"])
        if data.get("max_steps") is not None:
            options_kw["max_steps"] = self.integer(data["max_steps"], "max_steps", low=1)
        if data.get("goal_tolerance") is not None:
            options_kw["goal_tolerance"] = self.number(data["goal_tolerance"], "goal_tolerance", low=0.0)
        return self.core("scenario", data.get("name"), lambda: Scenario(
            name=name, world=world, start=start, goal=goal, description=description, limits=limits,
            footprint=footprint, planner=planner, overrides=overrides, global_method=method,
            global_options=options, **options_kw))

    # map and layers

    def occupancy_map(self, value: Any) -> tuple:
        key = "map"
        self.mapping(value, key, _MAP_SOURCES + ("resolution", "origin", "cells_per_char", "threshold", "border",
                                                 "rectangles"))
        sources = [s for s in _MAP_SOURCES if value.get(s) is not None]
        if len(sources) != 1:
            self.fail(key, sorted(value), f"give exactly one of {', '.join(_MAP_SOURCES)} (got "
                                          f"{', '.join(sources) or 'none'})")
        source = sources[0]
        resolution = self.number(value.get("resolution", 0.1), _join(key, "resolution"), low=0.0, low_open=True)
        origin = self.point(value.get("origin", [0.0, 0.0]), _join(key, "origin"))
        per_char = self.integer(value.get("cells_per_char", 1), _join(key, "cells_per_char"), low=1)
        if value.get("threshold") is not None and source != "png":
            self.fail(_join(key, "threshold"), value["threshold"], "applies to a png map only")
        skey = _join(key, source)
        if source == "ascii":
            cells = self.ascii(value[source], skey, {"#": 1, ".": 0}, per_char)
        elif source == "png":
            threshold = self.number(value.get("threshold", 0.5), _join(key, "threshold"), low=0.0, high=1.0)
            cells = self.png(value[source], skey, threshold)
        elif source == "npy":
            cells = self.npy(value[source], skey, allowed=(0, 1), what="0 (free) or 1 (obstacle)")
        else:
            size = value[source]
            if not isinstance(size, list) or len(size) != 2:
                self.fail(skey, size, "expected [width, height] in metres")
            size = [self.number(v, _join(skey, i), low=0.0, low_open=True) for i, v in enumerate(size)]
            shape = tuple(int(round(s / resolution)) for s in reversed(size))
            if min(shape) < 1:
                self.fail(skey, value[source], f"[width, height] must each hold at least one cell of {resolution} m")
            cells = np.zeros(shape, dtype=np.uint8)
        layout = _Layout(cells.shape, resolution, origin, per_char)
        if self.boolean(value.get("border", False), _join(key, "border")):
            cells[0, :] = cells[-1, :] = 1
            cells[:, 0] = cells[:, -1] = 1
        for i, rect in enumerate(self.list_of(value.get("rectangles"), _join(key, "rectangles"))):
            self.paint(cells, layout, rect, _join(_join(key, "rectangles"), i), 1)
        grid = self.core(key, source, lambda: OccupancyGrid(cells, resolution, origin))
        return grid, layout

    def list_of(self, value: Any, key: str) -> list:
        if value is None:
            return []
        if not isinstance(value, list):
            self.fail(key, value, "expected a list")
        return value

    def ascii(self, text: Any, key: str, alphabet: dict, per_char: int) -> np.ndarray:
        """Rows of characters, the first text row the highest y: returned with row 0 at the bottom."""
        self.string(text, key)
        lines = [line.rstrip() for line in text.splitlines()]
        while lines and not lines[0]:
            lines.pop(0)
        while lines and not lines[-1]:
            lines.pop()
        if not lines:
            self.fail(key, text, "empty")
        width = len(lines[0])
        for r, line in enumerate(lines):
            if len(line) != width:
                self.fail(key, line, f"text row {r + 1} (from the top) has {len(line)} characters, "
                                     f"the first row {width}: every row must be as wide")
            for c, char in enumerate(line):
                if char not in alphabet:
                    self.fail(key, char, f"at text row {r + 1} (from the top), column {c + 1}: expected one of "
                                         f"{' '.join(repr(a) for a in alphabet)}")
        cells = np.array([[alphabet[ch] for ch in line] for line in lines], dtype=np.uint8)
        cells = np.flipud(cells)
        if per_char > 1:
            cells = np.kron(cells, np.ones((per_char, per_char), dtype=np.uint8))
        return np.ascontiguousarray(cells)

    def png(self, value: Any, key: str, threshold: float) -> np.ndarray:
        import matplotlib.image

        path = self.file(value, key, (".png",))
        try:
            image = np.asarray(matplotlib.image.imread(path), dtype=float)
        except Exception as error:  # matplotlib/PIL raise many kinds for a bad file
            self.fail(key, value, f"cannot read the image ({error})")
        if image.max(initial=0) > 1.0:
            image = image / 255.0
        if image.ndim == 2:
            luminance, alpha = image, None
        elif image.ndim == 3 and image.shape[2] in (3, 4):
            luminance = image[..., :3] @ np.array([0.299, 0.587, 0.114])
            alpha = image[..., 3] if image.shape[2] == 4 else None
        elif image.ndim == 3 and image.shape[2] in (1, 2):
            luminance = image[..., 0]
            alpha = image[..., 1] if image.shape[2] == 2 else None
        else:
            self.fail(key, value, f"unexpected image shape {image.shape}")
        dark = luminance < threshold
        if alpha is not None:
            dark &= alpha >= 0.5  # transparent pixels are free
        return np.ascontiguousarray(np.flipud(dark).astype(np.uint8))

    def npy(self, value: Any, key: str, allowed: tuple, what: str) -> np.ndarray:
        path = self.file(value, key, (".npy",))
        try:
            array = np.load(path, allow_pickle=False)
        except Exception as error:
            self.fail(key, value, f"cannot read the array ({error})")
        if array.ndim != 2 or min(array.shape) < 1:
            self.fail(key, value, f"expected a 2-D array, got shape {array.shape}")
        if array.dtype.kind not in "biuf":
            self.fail(key, value, f"expected numbers, got dtype {array.dtype}")
        bad = ~np.isin(array, allowed)
        if bad.any():
            r, c = np.argwhere(bad)[0]
            self.fail(key, value, f"cell [{r}, {c}] = {array[r, c]!r}: every cell must be {what}")
        return np.ascontiguousarray(array.astype(np.uint8))

    def same_layout(self, cells: np.ndarray, layout: _Layout, key: str, value: Any, per_char_text: bool):
        if cells.shape != layout.shape:
            if per_char_text:
                rows, cols = cells.shape[0] // layout.cells_per_char, cells.shape[1] // layout.cells_per_char
                got = f"{rows} rows x {cols} characters (= {cells.shape[0]} x {cells.shape[1]} cells)"
            else:
                got = f"shape {cells.shape[0]} x {cells.shape[1]}"
            self.fail(key, value, f"{got} differs from the map's layout ({layout.describe()})")

    def rect(self, value: Any, key: str, layout: _Layout, extra: int = 0) -> list:
        if not isinstance(value, (list, tuple)) or len(value) != 4 + extra:
            shape = "[x0, y0, x1, y1, grade]" if extra else "[x0, y0, x1, y1]"
            self.fail(key, value, f"expected {shape} (corners in metres)")
        x0, y0, x1, y1 = (self.number(v, _join(key, i)) for i, v in enumerate(value[:4]))
        if not (x0 < x1 and y0 < y1):
            self.fail(key, value, "expected x0 < x1 and y0 < y1")
        ex0, ex1, ey0, ey1 = layout.extent
        slack = 0.5 * layout.resolution
        if x0 < ex0 - slack or x1 > ex1 + slack or y0 < ey0 - slack or y1 > ey1 + slack:
            self.fail(key, value, f"outside the map (x {ex0:g} to {ex1:g}, y {ey0:g} to {ey1:g})")
        return [x0, y0, x1, y1]

    def paint(self, cells: np.ndarray, layout: _Layout, value: Any, key: str, fill: Optional[int]) -> None:
        """Sets the cells of a rectangle (the cells whose centres it covers; at least one per axis)."""
        extra = 1 if fill is None else 0
        x0, y0, x1, y1 = self.rect(value, key, layout, extra)
        if fill is None:
            fill = self.integer(value[4], _join(key, 4), low=0)
            if fill > 4:
                self.fail(_join(key, 4), fill, "a slope grade must be 0-4")
        ox, oy = layout.origin
        res = layout.resolution
        rows, cols = layout.shape
        c0, c1 = int(round((x0 - ox) / res)), int(round((x1 - ox) / res))
        r0, r1 = int(round((y0 - oy) / res)), int(round((y1 - oy) / res))
        c1, r1 = max(c1, c0 + 1), max(r1, r0 + 1)
        cells[max(r0, 0):min(r1, rows), max(c0, 0):min(c1, cols)] = fill

    def terrain(self, value: Any, layout: _Layout) -> tuple:
        default_factors = World.__dataclass_fields__["passing_factors"].default
        if value is None:
            return None, default_factors
        key = "terrain"
        self.mapping(value, key, ("ascii", "npy", "rectangles", "passing_factors"))
        if value.get("ascii") is not None and value.get("npy") is not None:
            self.fail(key, sorted(value), "give ascii or npy, not both")
        grades = np.zeros(layout.shape, dtype=np.uint8)
        if value.get("ascii") is not None:
            alphabet = {str(g): g for g in range(5)}
            alphabet["."] = 0
            grades = self.ascii(value["ascii"], _join(key, "ascii"), alphabet, layout.cells_per_char)
            self.same_layout(grades, layout, _join(key, "ascii"), value["ascii"], per_char_text=True)
        elif value.get("npy") is not None:
            grades = self.npy(value["npy"], _join(key, "npy"), allowed=(0, 1, 2, 3, 4), what="a slope grade 0-4")
            self.same_layout(grades, layout, _join(key, "npy"), value["npy"], per_char_text=False)
        for i, rect in enumerate(self.list_of(value.get("rectangles"), _join(key, "rectangles"))):
            self.paint(grades, layout, rect, _join(_join(key, "rectangles"), i), None)
        factors = default_factors
        if value.get("passing_factors") is not None:
            fkey = _join(key, "passing_factors")
            raw = value["passing_factors"]
            if not isinstance(raw, list) or len(raw) != 5:
                self.fail(fkey, raw, "expected 5 numbers in [0, 1], one per grade 0-4")
            factors = tuple(self.number(v, _join(fkey, i), low=0.0, high=1.0) for i, v in enumerate(raw))
        grid = self.core(key, "terrain", lambda: TerrainGrid(grades, layout.resolution, layout.origin))
        return grid, factors

    def unknown_obstacles(self, value: Any, layout: _Layout) -> Optional[OccupancyGrid]:
        if value is None:
            return None
        key = "unknown_obstacles"
        if isinstance(value, list):
            value = {"rectangles": value}
            rect_key = key
        else:
            self.mapping(value, key, ("rectangles", "ascii", "npy"))
            rect_key = _join(key, "rectangles")
        cells = np.zeros(layout.shape, dtype=np.uint8)
        if value.get("ascii") is not None:
            cells = self.ascii(value["ascii"], _join(key, "ascii"), {"#": 1, ".": 0}, layout.cells_per_char)
            self.same_layout(cells, layout, _join(key, "ascii"), value["ascii"], per_char_text=True)
        if value.get("npy") is not None:
            layer = self.npy(value["npy"], _join(key, "npy"), allowed=(0, 1), what="0 (free) or 1 (obstacle)")
            self.same_layout(layer, layout, _join(key, "npy"), value["npy"], per_char_text=False)
            cells |= layer
        for i, rect in enumerate(self.list_of(value.get("rectangles"), rect_key)):
            self.paint(cells, layout, rect, _join(rect_key, i), 1)
        return self.core(key, "unknown_obstacles", lambda: OccupancyGrid(cells, layout.resolution, layout.origin))

    def moving_obstacles(self, value: Any) -> tuple:
        key = "moving_obstacles"
        movers, known, known_from = [], None, None
        for i, item in enumerate(self.list_of(value, key)):
            ikey = _join(key, i)
            self.mapping(item, ikey, ("radius", "waypoints", "speed", "mode", "start", "velocity", "start_delay",
                                      "phase", "known"), required=("radius",))
            radius = self.number(item["radius"], _join(ikey, "radius"), low=0.0, low_open=True)
            start_delay = self.number(item.get("start_delay", 0.0), _join(ikey, "start_delay"), low=0.0)
            phase = self.number(item.get("phase", 0.0), _join(ikey, "phase"))
            if item.get("waypoints") is not None:
                for other in ("start", "velocity"):
                    if item.get(other) is not None:
                        self.fail(_join(ikey, other), item[other], "give waypoints + speed or start + velocity, "
                                                                   "not both")
                points = self.points(item["waypoints"], _join(ikey, "waypoints"), 2)
                if item.get("speed") is None:
                    self.fail(_join(ikey, "speed"), None, "required with waypoints (m/s)")
                speed = self.number(item["speed"], _join(ikey, "speed"), low=0.0, low_open=True)
                mode = self.string(item.get("mode", "loop"), _join(ikey, "mode"))
                if mode not in MOVER_MODES:
                    self.fail(_join(ikey, "mode"), mode, f"expected one of {', '.join(MOVER_MODES)}")
                mover = dict(radius=radius, waypoints=points, speed=speed, mode=mode)
            else:
                for other in ("speed", "mode"):
                    if item.get(other) is not None:
                        self.fail(_join(ikey, other), item[other], "applies with waypoints only")
                if item.get("start") is None:
                    self.fail(_join(ikey, "start"), None, "required without waypoints (or give waypoints + speed)")
                start = self.point(item["start"], _join(ikey, "start"))
                velocity = self.point(item.get("velocity", [0.0, 0.0]), _join(ikey, "velocity"))
                mover = dict(radius=radius, start=start, velocity=velocity)
            movers.append(self.core(ikey, item, lambda: MovingObstacle(start_delay=start_delay, phase=phase,
                                                                         **mover)))
            if item.get("known") is not None:
                flag = self.boolean(item["known"], _join(ikey, "known"))
                if known is not None and flag != known:
                    self.fail(_join(ikey, "known"), flag, f"every moving obstacle must share one value "
                                                          f"({known_from} is {str(known).lower()})")
                known, known_from = flag, _join(ikey, "known")
        return movers, bool(known)

    # robot and task

    def robot(self, value: Any) -> tuple:
        limits, footprint = RobotLimits(), Footprint.circle(0.25)
        if value is None:
            return limits, footprint
        key = "robot"
        self.mapping(value, key, ("limits", "footprint"))
        if value.get("limits") is not None:
            lkey = _join(key, "limits")
            raw = self.mapping(value["limits"], lkey, _LIMIT_FIELDS)
            fields = {}
            for name, item in raw.items():
                positive = name in ("v_max", "omega_max", "acc_v", "acc_omega")
                fields[name] = self.number(item, _join(lkey, name), low=0.0, low_open=positive)
            if fields.get("v_min", 0.0) > fields.get("v_max", limits.v_max):
                self.fail(_join(lkey, "v_min"), fields["v_min"],
                          f"must be <= v_max ({fields.get('v_max', limits.v_max):g})")
            limits = self.core(lkey, raw, lambda: RobotLimits(**fields))
            self.core(lkey, raw, limits.validate)
        if value.get("footprint") is not None:
            fkey = _join(key, "footprint")
            raw = self.mapping(value["footprint"], fkey, ("radius", "polygon"))
            if (raw.get("radius") is None) == (raw.get("polygon") is None):
                self.fail(fkey, raw, "give exactly one of radius (m) or polygon ([[x, y], ...] m, robot frame)")
            if raw.get("radius") is not None:
                radius = self.number(raw["radius"], _join(fkey, "radius"), low=0.0, low_open=True)
                footprint = self.core(_join(fkey, "radius"), radius, lambda: Footprint.circle(radius))
            else:
                vertices = self.points(raw["polygon"], _join(fkey, "polygon"), 3)
                footprint = self.core(_join(fkey, "polygon"), raw["polygon"], lambda: Footprint.polygon(vertices))
        return limits, footprint

    def start(self, value: Any) -> tuple:
        key = "start"
        if isinstance(value, dict):
            self.mapping(value, key, ("x", "y", "theta_deg", "theta"), required=("x", "y"))
            if value.get("theta_deg") is not None and value.get("theta") is not None:
                self.fail(key, value, "give theta_deg (degrees) or theta (radians), not both")
            x, y = self.number(value["x"], _join(key, "x")), self.number(value["y"], _join(key, "y"))
            if value.get("theta") is not None:
                theta = self.number(value["theta"], _join(key, "theta"))
            else:
                theta = math.radians(self.number(value.get("theta_deg", 0.0), _join(key, "theta_deg")))
            return x, y, theta
        if not isinstance(value, (list, tuple)) or len(value) not in (2, 3):
            self.fail(key, value, "expected [x, y] or [x, y, theta_deg] (metres, degrees)")
        numbers = [self.number(v, _join(key, i)) for i, v in enumerate(value)]
        return numbers[0], numbers[1], math.radians(numbers[2]) if len(numbers) == 3 else 0.0

    def inside(self, point, layout: _Layout) -> bool:
        x0, x1, y0, y1 = layout.extent
        return x0 <= point[0] < x1 and y0 <= point[1] < y1

    def check_start(self, start: tuple, value: Any, world: World, footprint: Footprint, layout: _Layout) -> None:
        if not self.inside(start, layout):
            x0, x1, y0, y1 = layout.extent
            self.fail("start", value, f"off the map (x {x0:g} to {x1:g}, y {y0:g} to {y1:g})")
        if CollisionWorld(world.grid).in_collision(footprint, start):
            self.fail("start", value, f"the robot's footprint ({footprint!r}) there overlaps an obstacle of the map")
        if CollisionWorld(world.true_grid()).in_collision(footprint, start):
            self.fail("start", value, f"the robot's footprint ({footprint!r}) there overlaps an unknown obstacle")
        if world.grade_at(start[:2]) >= 4:
            self.fail("start", value, "on impassable terrain (grade 4)")

    def check_goal(self, goal: tuple, value: Any, world: World, footprint: Footprint, layout: _Layout) -> None:
        if not self.inside(goal, layout):
            x0, x1, y0, y1 = layout.extent
            self.fail("goal", value, f"off the map (x {x0:g} to {x1:g}, y {y0:g} to {y1:g})")
        # The robot may arrive at any heading: the circle it always fills must fit.
        probe = Footprint.circle(footprint.inscribed_radius)
        if CollisionWorld(world.true_grid()).in_collision(probe, (goal[0], goal[1], 0.0)):
            self.fail("goal", value, f"inside an obstacle (a circle of the footprint's inscribed radius "
                                     f"{footprint.inscribed_radius:g} m there overlaps one)")
        if world.grade_at(goal) >= 4:
            self.fail("goal", value, "on impassable terrain (grade 4)")

    def check_reachable(self, start: tuple, goal: tuple, value: Any, world: World, footprint: Footprint,
                        options: dict) -> None:
        """A* on the map, obstacles inflated as the episode's last resort does (the footprint's radius)."""
        from fgdwa.global_planning import plan_global

        radius = options.get("inflation_radius", footprint.radius)
        extra = {k: v for k, v in options.items() if k != "inflation_radius"}
        try:
            plan = plan_global(world.grid, start[:2], goal, method="astar", terrain=world.terrain,
                               inflation_radius=radius, **extra)
            found = plan.status.name == "Found"
        except FgdwaError as error:
            self.fail("goal", value, f"the global planner cannot start ({error})")
        if not found:
            self.fail("goal", value, f"no global path from the start {tuple(round(v, 3) for v in start[:2])} on "
                                     f"the map (A*, obstacles and grade 4 inflated by {radius:g} m): the start or "
                                     f"the goal is walled off or nearer than that to an obstacle")

    # planners and sensors

    def planner(self, value: Any) -> tuple:
        if value is None:
            return "fgdwa", {}
        key = "planner"
        self.mapping(value, key, ("preset", "overrides"))
        preset = self.string(value.get("preset", "fgdwa"), _join(key, "preset"))
        if preset not in preset_names():
            self.fail(_join(key, "preset"), preset, f"expected one of {', '.join(preset_names())}")
        base = planner_preset(preset).params
        okey = _join(key, "overrides")
        raw = self.mapping(value.get("overrides") or {}, okey, PARAM_FIELDS)
        overrides = {}
        for name, item in raw.items():
            fkey = _join(okey, name)
            kind = _OVERRIDE_TYPES.get(name)
            if kind is float:
                item = self.number(item, fkey)
            elif kind is int:
                item = self.integer(item, fkey, low=1)
            elif kind is str:
                item = self.string(item, fkey)
            elif kind is bool:
                item = self.boolean(item, fkey)
            elif kind is list:
                item = self.critics(item, fkey)
            self.core(fkey, raw[name], lambda: params_with(base, **{name: item}))
            overrides[name] = item
        self.core(okey, raw, lambda: params_with(base, **overrides))
        return preset, overrides

    def critics(self, value: Any, key: str) -> list:
        if not isinstance(value, list) or not value:
            self.fail(key, value, "expected a list of critics: {name, weight, params}")
        known = critic_names()
        critics = []
        for i, item in enumerate(value):
            ckey = _join(key, i)
            self.mapping(item, ckey, ("name", "weight", "params"), required=("name",))
            name = self.string(item["name"], _join(ckey, "name"))
            if name not in known:
                self.fail(_join(ckey, "name"), name, f"unknown critic (known: {', '.join(known)})")
            weight = self.number(item.get("weight", 1.0), _join(ckey, "weight"), low=0.0)
            params = item.get("params") or {}
            if not isinstance(params, dict):
                self.fail(_join(ckey, "params"), params, "expected a mapping of numbers and words")
            for pname, pvalue in params.items():
                if not isinstance(pname, str) or not (_is_number(pvalue) or isinstance(pvalue, str)):
                    self.fail(_join(_join(ckey, "params"), str(pname)), pvalue, "expected a number or a word")
            critics.append({"name": name, "weight": weight, "params": dict(params)})
        return critics

    def global_planner(self, value: Any, grid: OccupancyGrid) -> tuple:
        from fgdwa import global_planning

        if value is None:
            return "astar", {}
        key = "global_planner"
        self.mapping(value, key, ("method", "options"))
        method = self.string(value.get("method", "astar"), _join(key, "method"))
        methods = global_planning.global_methods()
        if method not in methods:
            self.fail(_join(key, "method"), method, f"expected one of {', '.join(methods)}")
        okey = _join(key, "options")
        raw = value.get("options") or {}
        if not isinstance(raw, dict):
            self.fail(okey, raw, "expected a mapping of planner options")
        known = getattr(global_planning, "_ASTAR_OPTIONS" if method == "astar" else "_OMPL_OPTIONS", None)
        known = sorted(set(known) - {"terrain", "footprint"}) if known is not None else None
        if known is not None:
            self.mapping(raw, okey, known)
        probe = OccupancyGrid(np.zeros((4, 4), dtype=np.uint8), grid.resolution, grid.origin)
        for name, item in raw.items():
            fkey = _join(okey, name)
            if item is None or isinstance(item, dict):
                self.fail(fkey, item, "expected a number, a boolean or a list of numbers")
            if method == "astar":
                self.core(fkey, item, lambda: global_planning.AStarPlanner(probe, **{name: item}))
            else:
                self.core(fkey, item, lambda: global_planning.OmplPlanner(
                    probe, Footprint.circle(0.1), planner=method[len("ompl:"):], **{name: item}))
        return method, dict(raw)

    def lidar(self, value: Any) -> LidarParams:
        key = "lidar"
        self.mapping(value, key, ("fov_deg", "beams", "max_range"))
        default = LidarParams()
        fov = self.number(value.get("fov_deg", default.fov_deg), _join(key, "fov_deg"), low=0.0, high=360.0,
                          low_open=True)
        beams = self.integer(value.get("beams", default.beams), _join(key, "beams"), low=1)
        max_range = self.number(value.get("max_range", default.max_range), _join(key, "max_range"), low=0.0,
                                low_open=True)
        return self.core(key, value, lambda: LidarParams(fov_deg=fov, beams=beams, max_range=max_range))

    def detect_window(self, value: Any) -> DetectWindowParams:
        key = "detect_window"
        self.mapping(value, key, ("half_angle_deg", "radius", "base"))
        default = DetectWindowParams()
        half = self.number(value.get("half_angle_deg", default.half_angle_deg), _join(key, "half_angle_deg"),
                           low=0.0, high=180.0, low_open=True)
        radius = self.number(value.get("radius", default.radius), _join(key, "radius"), low=0.0, low_open=True)
        base = self.number(value.get("base", default.base), _join(key, "base"), low=0.0, high=1.0)
        return self.core(key, value, lambda: DetectWindowParams(half_angle_deg=half, radius=radius, base=base))

    def variability(self, value: Any) -> Variability:
        key = "variability"
        self.mapping(value, key, ("start_xy_std", "start_theta_std_deg", "start_theta_std", "mover_phase",
                                  "lidar_noise_std"))
        default = Variability()
        if value.get("start_theta_std_deg") is not None and value.get("start_theta_std") is not None:
            self.fail(key, value, "give start_theta_std_deg (degrees) or start_theta_std (radians), not both")
        theta_std = default.start_theta_std
        if value.get("start_theta_std_deg") is not None:
            theta_std = math.radians(self.number(value["start_theta_std_deg"], _join(key, "start_theta_std_deg"),
                                                 low=0.0))
        elif value.get("start_theta_std") is not None:
            theta_std = self.number(value["start_theta_std"], _join(key, "start_theta_std"), low=0.0)
        return Variability(
            start_xy_std=self.number(value.get("start_xy_std", default.start_xy_std), _join(key, "start_xy_std"),
                                     low=0.0),
            start_theta_std=theta_std,
            mover_phase=self.boolean(value.get("mover_phase", default.mover_phase), _join(key, "mover_phase")),
            lidar_noise_std=self.number(value.get("lidar_noise_std", default.lidar_noise_std),
                                        _join(key, "lidar_noise_std"), low=0.0))
