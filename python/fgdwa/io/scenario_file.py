"""Scenarios read from YAML (the format is described in docs/scenarios.md).

``load_scenario(source)`` takes a path to a ``.yaml`` file, YAML text, or the
name of a scenario shipped with the package (``shipped_scenarios()``), and
returns a ``fgdwa.sim.scenario.Scenario``. Every problem in the input raises
``FgdwaError`` naming the file (``<text>`` for text), the key path (for example
``moving_obstacles[1].speed``) and the offending value, so a user can fix a file
without reading a traceback.

Units: metres, seconds, and degrees for angles in positions and headings (the
key says so: ``theta_deg``, ``fov_deg``). Angular rates and their accelerations
(``omega_max``, ``acc_omega``) stay in rad/s and rad/s^2, like ``RobotLimits``.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any, Union

from fgdwa._core import (
    DetectWindowParams,
    FgdwaError,
    Footprint,
    LidarParams,
    PlannerParams,
    RobotLimits,
    planner_preset,
    preset_names,
)
from fgdwa.file_limits import clip, is_file, read_text
from fgdwa.io.scenario_checks import FeasibilityChecks
from fgdwa.io.scenario_maps import MapReader
from fgdwa.io.scenario_values import join_key, parse_yaml, short_repr
from fgdwa.sim.keyframes import KeyframedMover
from fgdwa.sim.scenario import Scenario, Variability, params_with
from fgdwa.sim.world import MOVER_MODES, MovingObstacle, World

SHIPPED_DIR = Path(__file__).resolve().parents[1] / "scenarios"  # fgdwa/scenarios
TEXT = "<text>"

_TOP_KEYS = ("name", "description", "map", "terrain", "unknown_obstacles", "moving_obstacles", "start", "goal",
             "robot", "planner", "global_planner", "lidar", "detect_window", "variability", "max_steps",
             "goal_tolerance")
_LIMIT_FIELDS = ("v_min", "v_max", "omega_max", "acc_v", "acc_omega", "brake_v", "brake_omega")
# The limit (a constant of fgdwa.file_limits) of each RobotLimits field.
_LIMIT_BOUNDS = {"v_min": "MAX_SPEED", "v_max": "MAX_SPEED", "omega_max": "MAX_ANGULAR_RATE",
                 "acc_v": "MAX_ACCELERATION", "acc_omega": "MAX_ACCELERATION", "brake_v": "MAX_ACCELERATION",
                 "brake_omega": "MAX_ACCELERATION"}


def shipped_scenarios() -> list:
    """Names of the scenarios shipped with the package (``e1``, ``e2``, ``e3``, ``demo``, ...)."""
    if not SHIPPED_DIR.is_dir():
        return []
    return sorted(p.stem for p in SHIPPED_DIR.glob("*.yaml"))


def shipped_scenario_path(name: str) -> Path:
    """The YAML file of a shipped scenario."""
    names = shipped_scenarios()
    if name not in names:
        raise FgdwaError(f"scenario {short_repr(name)}: not a shipped scenario (shipped: {', '.join(names) or 'none'})")
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
        raise FgdwaError(f"load_scenario: source = {short_repr(source)}: expected a path, YAML text or a shipped "
                         f"scenario name ({', '.join(shipped_scenarios())})")
    one_line = "\n" not in source
    if one_line and (source.strip().endswith((".yaml", ".yml")) or is_file(source)):
        return _load_file(Path(source))
    if one_line and ":" not in source:
        raise FgdwaError(f"load_scenario: source = {short_repr(source)}: neither a shipped scenario "
                         f"({', '.join(shipped_scenarios())}), an existing file, nor YAML text")
    return _load_text(source, TEXT, Path(base_dir) if base_dir is not None else Path.cwd())


def scenario_from_dict(data: Any, where: str = "<dict>", base_dir: Union[str, os.PathLike, None] = None) -> Scenario:
    """A Scenario from an already parsed YAML document (a dict); ``where`` names it in error messages."""
    return _Reader(where, Path(base_dir) if base_dir is not None else Path.cwd()).scenario(data)


def _load_file(path: Path) -> Scenario:
    where = clip(str(path), 4096)  # a longer name is no file's (PATH_MAX)
    try:
        text = read_text(path, where)
    except FileNotFoundError:
        raise FgdwaError(f"{where}: no such scenario file") from None
    except (OSError, ValueError) as error:  # ValueError: not UTF-8, or a NUL in the name
        raise FgdwaError(f"{where}: cannot read the scenario file ({clip(error)})") from None
    return _load_text(text, where, path.resolve().parent, default_name=path.stem)


def _load_text(text: str, where: str, base_dir: Path, default_name: str = "scenario") -> Scenario:
    data = parse_yaml(text, where)
    return _Reader(where, base_dir, default_name).scenario(data)

class _Reader(MapReader, FeasibilityChecks):
    """Reads one YAML document into a Scenario; every error names ``where``, the key path and the value."""

    def scenario(self, data: Any) -> Scenario:
        if data is None:
            raise FgdwaError(f"{self.where}: the scenario is empty")
        try:
            return self._scenario(data)
        except FgdwaError:
            raise
        except Exception as error:  # a bug here must still say which file it was reading
            raise FgdwaError(f"{self.where}: could not read the scenario "
                             f"({type(error).__name__}: {clip(error)})") from error

    def _scenario(self, data: Any) -> Scenario:
        if not isinstance(data, dict):
            raise FgdwaError(f"{self.where}: expected a mapping of scenario keys at the top level, "
                             f"got {short_repr(data)}")
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

        limits, footprint, outline = self.robot(data.get("robot"))
        start = self.start(data["start"])
        goal = self.point(data["goal"], "goal")
        self.check_start(start, data["start"], world, footprint, layout)
        self.check_goal(goal, data["goal"], world, footprint, layout)

        planner, overrides = self.planner(data.get("planner"))
        method, options = self.global_planner(data.get("global_planner"))
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
            options_kw["max_steps"] = self.integer(data["max_steps"], "max_steps", low=1, limit="MAX_STEPS")
        if data.get("goal_tolerance") is not None:
            options_kw["goal_tolerance"] = self.length(data["goal_tolerance"], "goal_tolerance")
        if options_kw.get("goal_tolerance") is not None:
            self.check_not_at_goal(start, goal, options_kw["goal_tolerance"], "goal_tolerance", data["goal_tolerance"])
        elif "goal_tolerance" in overrides:
            self.check_not_at_goal(start, goal, overrides["goal_tolerance"], "planner.overrides.goal_tolerance",
                                   overrides["goal_tolerance"])
        else:
            self.check_not_at_goal(start, goal, planner_preset(planner).params.goal_tolerance, "goal", data["goal"])
        return self.core("scenario", data.get("name"), lambda: Scenario(
            name=name, world=world, start=start, goal=goal, description=description, limits=limits,
            footprint=footprint, outline=outline, planner=planner, overrides=overrides, global_method=method,
            global_options=options, **options_kw))

    def moving_obstacles(self, value: Any) -> tuple:
        key = "moving_obstacles"
        movers, known, known_from = [], None, None
        for i, item in enumerate(self.list_of(value, key)):
            ikey = join_key(key, i)
            self.mapping(item, ikey, ("radius", "waypoints", "speed", "mode", "start", "velocity", "start_delay",
                                      "phase", "known", "keyframes", "loop", "length"), required=("radius",))
            radius = self.length(item["radius"], join_key(ikey, "radius"), positive=True)
            phase = self.number(item.get("phase", 0.0), join_key(ikey, "phase"), limit="MAX_DURATION")
            if item.get("keyframes") is not None:
                movers.append(self.keyframed(item, ikey, radius, phase))
            else:
                for other in ("loop", "length"):
                    if item.get(other) is not None:
                        self.fail(join_key(ikey, other), item[other], "applies with keyframes only")
                start_delay = self.duration(item.get("start_delay", 0.0), join_key(ikey, "start_delay"))
                mover = self.routed(item, ikey, radius)
                movers.append(self.core(ikey, item, lambda: MovingObstacle(start_delay=start_delay, phase=phase,
                                                                             **mover)))
            if item.get("known") is not None:
                flag = self.boolean(item["known"], join_key(ikey, "known"))
                if known is not None and flag != known:
                    self.fail(join_key(ikey, "known"), flag, f"every moving obstacle must share one value "
                                                          f"({known_from} is {str(known).lower()})")
                known, known_from = flag, join_key(ikey, "known")
        return movers, bool(known)

    def routed(self, item: dict, key: str, radius: float) -> dict:
        """A MovingObstacle's keywords: waypoints + speed + mode, or start + velocity."""
        if item.get("waypoints") is not None:
            for other in ("start", "velocity"):
                if item.get(other) is not None:
                    self.fail(join_key(key, other), item[other], "give waypoints + speed or start + velocity, "
                                                                "not both")
            points = self.points(item["waypoints"], join_key(key, "waypoints"), 2)
            if item.get("speed") is None:
                self.fail(join_key(key, "speed"), None, "required with waypoints (m/s)")
            speed = self.number(item["speed"], join_key(key, "speed"), low=0.0, low_open=True, limit="MAX_SPEED")
            mode = self.string(item.get("mode", "loop"), join_key(key, "mode"))
            if mode not in MOVER_MODES:
                self.fail(join_key(key, "mode"), mode, f"expected one of {', '.join(MOVER_MODES)}")
            return dict(radius=radius, waypoints=points, speed=speed, mode=mode)
        for other in ("speed", "mode"):
            if item.get(other) is not None:
                self.fail(join_key(key, other), item[other], "applies with waypoints only")
        if item.get("start") is None:
            self.fail(join_key(key, "start"), None, "required without waypoints (or give waypoints + speed, "
                                                    "or keyframes)")
        start = self.point(item["start"], join_key(key, "start"))
        velocity = self.point(item.get("velocity", [0.0, 0.0]), join_key(key, "velocity"), limit="MAX_SPEED")
        return dict(radius=radius, start=start, velocity=velocity)

    def keyframed(self, item: dict, key: str, radius: float, phase: float) -> KeyframedMover:
        """A mover given as timed keyframes [t, x, y], moved as Gazebo animates one."""
        for other in ("waypoints", "speed", "mode", "start", "velocity", "start_delay"):
            if item.get(other) is not None:
                self.fail(join_key(key, other), item[other], "give keyframes or waypoints + speed or start + "
                                                             "velocity, not two of them")
        frames = self.keyframes(item["keyframes"], join_key(key, "keyframes"))
        loop = self.boolean(item.get("loop", True), join_key(key, "loop"))
        length = None
        if item.get("length") is not None:
            length = self.duration(item["length"], join_key(key, "length"), positive=True)
        return self.core(key, item, lambda: KeyframedMover(radius, frames, loop=loop, length=length, phase=phase))

    def robot(self, value: Any) -> tuple:
        """(limits, footprint, outline): outline, the body the referee judges, is the footprint unless given."""
        limits, footprint = RobotLimits(), Footprint.circle(0.25)
        if value is None:
            return limits, footprint, None
        key = "robot"
        self.mapping(value, key, ("limits", "footprint", "outline"))
        if value.get("limits") is not None:
            lkey = join_key(key, "limits")
            raw = self.mapping(value["limits"], lkey, _LIMIT_FIELDS)
            fields = {}
            for name, item in raw.items():
                positive = name in ("v_max", "omega_max", "acc_v", "acc_omega")
                fields[name] = self.number(item, join_key(lkey, name), low=0.0, low_open=positive,
                                           limit=_LIMIT_BOUNDS[name])
            if fields.get("v_min", 0.0) > fields.get("v_max", limits.v_max):
                self.fail(join_key(lkey, "v_min"), fields["v_min"],
                          f"must be <= v_max ({fields.get('v_max', limits.v_max):g})")
            limits = self.core(lkey, raw, lambda: RobotLimits(**fields))
            self.core(lkey, raw, limits.validate)
        if value.get("footprint") is not None:
            footprint = self.shape(value["footprint"], join_key(key, "footprint"))
        outline = self.shape(value["outline"], join_key(key, "outline")) if value.get("outline") is not None else None
        return limits, footprint, outline

    def shape(self, value: Any, key: str) -> Footprint:
        """A footprint or outline: {radius: m} or {polygon: [[x, y], ...]}."""
        raw = self.mapping(value, key, ("radius", "polygon"))
        if (raw.get("radius") is None) == (raw.get("polygon") is None):
            self.fail(key, raw, "give exactly one of radius (m) or polygon ([[x, y], ...] m, robot frame)")
        if raw.get("radius") is not None:
            radius = self.length(raw["radius"], join_key(key, "radius"), positive=True)
            return self.core(join_key(key, "radius"), radius, lambda: Footprint.circle(radius))
        vertices = self.points(raw["polygon"], join_key(key, "polygon"), 3)
        return self.core(join_key(key, "polygon"), raw["polygon"], lambda: Footprint.polygon(vertices))

    def start(self, value: Any) -> tuple:
        key = "start"
        if isinstance(value, dict):
            self.mapping(value, key, ("x", "y", "theta_deg", "theta"), required=("x", "y"))
            if value.get("theta_deg") is not None and value.get("theta") is not None:
                self.fail(key, value, "give theta_deg (degrees) or theta (radians), not both")
            x, y = (self.number(value["x"], join_key(key, "x"), limit="MAX_COORDINATE"),
                    self.number(value["y"], join_key(key, "y"), limit="MAX_COORDINATE"))
            if value.get("theta") is not None:
                theta = self.number(value["theta"], join_key(key, "theta"))
            else:
                theta = math.radians(self.number(value.get("theta_deg", 0.0), join_key(key, "theta_deg")))
            return x, y, theta
        if not isinstance(value, (list, tuple)) or len(value) not in (2, 3):
            self.fail(key, value, "expected [x, y] or [x, y, theta_deg] (metres, degrees)")
        numbers = [self.number(v, join_key(key, i), limit="MAX_COORDINATE" if i < 2 else "MAX_MAGNITUDE")
                   for i, v in enumerate(value)]
        return numbers[0], numbers[1], math.radians(numbers[2]) if len(numbers) == 3 else 0.0

    def planner(self, value: Any) -> tuple:
        if value is None:
            return "fgdwa", {}
        key = "planner"
        self.mapping(value, key, ("preset", "overrides"))
        preset = self.string(value.get("preset", "fgdwa"), join_key(key, "preset"))
        if preset not in preset_names():
            self.fail(join_key(key, "preset"), preset, f"expected one of {', '.join(preset_names())}")
        base = planner_preset(preset).params
        okey = join_key(key, "overrides")
        overrides = self.param_fields(PlannerParams, value.get("overrides") or {}, okey)
        # The core refuses a cycle of more rollout poses than it allows, naming the numbers.
        self.core(okey, value.get("overrides"), lambda: params_with(base, **overrides))
        return preset, overrides

    def global_planner(self, value: Any) -> tuple:
        from fgdwa import global_planning

        if value is None:
            return "astar", {}
        key = "global_planner"
        self.mapping(value, key, ("method", "options"))
        method = self.string(value.get("method", "astar"), join_key(key, "method"))
        methods = global_planning.global_methods()
        if method not in methods:
            self.fail(join_key(key, "method"), method, f"expected one of {', '.join(methods)}")
        okey = join_key(key, "options")
        raw = value.get("options") or {}
        cls = global_planning.method_params(method)
        # OMPL's planner is the method's name.
        allowed = [entry["name"] for entry in cls.schema() if "." not in entry["name"] and entry["name"] != "planner"]
        fields = self.param_fields(cls, raw, okey, allowed=allowed)
        self.core(okey, raw, lambda: params_with(cls(), **fields))
        options: dict = {}
        for name, item in fields.items():
            *groups, leaf = name.split(".")
            target = options
            for group in groups:
                target = target.setdefault(group, {})
            target[leaf] = item
        return method, options

    def lidar(self, value: Any) -> LidarParams:
        # The noise and the dropped beams are the trials' variability.
        fields = self.param_fields(LidarParams, value, "lidar", allowed=("fov", "beams", "max_range"))
        return self.core("lidar", value, lambda: params_with(LidarParams(), **fields))

    def detect_window(self, value: Any) -> DetectWindowParams:
        fields = self.param_fields(DetectWindowParams, value, "detect_window")
        return self.core("detect_window", value, lambda: params_with(DetectWindowParams(), **fields))

    def variability(self, value: Any) -> Variability:
        key = "variability"
        self.mapping(value, key, ("start_xy_std", "start_theta_std_deg", "start_theta_std", "mover_phase",
                                  "lidar_noise_std", "lidar_dropout"))
        default = Variability()
        if value.get("start_theta_std_deg") is not None and value.get("start_theta_std") is not None:
            self.fail(key, value, "give start_theta_std_deg (degrees) or start_theta_std (radians), not both")
        theta_std = default.start_theta_std
        if value.get("start_theta_std_deg") is not None:
            theta_std = math.radians(self.number(value["start_theta_std_deg"], join_key(key, "start_theta_std_deg"),
                                                 low=0.0))
        elif value.get("start_theta_std") is not None:
            theta_std = self.number(value["start_theta_std"], join_key(key, "start_theta_std"), low=0.0)
        dropout = self.number(value.get("lidar_dropout", default.lidar_dropout), join_key(key, "lidar_dropout"),
                              low=0.0)
        if dropout >= 1.0:
            self.fail(join_key(key, "lidar_dropout"), dropout, "must be < 1 (the probability a beam returns nothing)")
        return Variability(
            start_xy_std=self.length(value.get("start_xy_std", default.start_xy_std), join_key(key, "start_xy_std")),
            start_theta_std=theta_std,
            mover_phase=self.boolean(value.get("mover_phase", default.mover_phase), join_key(key, "mover_phase")),
            lidar_noise_std=self.length(value.get("lidar_noise_std", default.lidar_noise_std),
                                        join_key(key, "lidar_noise_std")),
            lidar_dropout=dropout)
