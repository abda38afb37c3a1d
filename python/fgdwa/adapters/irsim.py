"""fgdwa as an IR-SIM behavior (docs/irsim.md).

``import fgdwa.adapters.irsim`` registers the behavior ``fgdwa`` for IR-SIM's
differential-drive robots. A world YAML then names it::

    robot:
      - kinematics: {name: diff}
        shape: {name: circle, radius: 0.2}
        state: [1, 1, 0]
        goal: [9, 9, 0]
        behavior: {name: fgdwa, preset: fgdwa}
        sensors:
          - {type: lidar2d, range_max: 8, angle_range: 4.71, number: 271}

IR-SIM builds one :class:`FgdwaBehavior` per robot and calls it every step; the
behavior is the robot side only: each step it hands a :class:`fgdwa.Navigator`
the robot's lidar scan, pose, velocity and current goal, and returns the
navigator's command [v, omega]. The navigator takes the robot's velocity and
acceleration limits, its outline and its lidar from IR-SIM, the control period
from the world's ``step_time``, and the world's grid map when there is one
(otherwise it maps from its scans). Other robots and obstacles reach it only
through the lidar.

:func:`run_world` runs a world headless until every fgdwa robot has arrived or
collided (IR-SIM's own flags) and reports each robot; ``fgdwa irsim WORLD.yaml``
is its command line.
"""

from __future__ import annotations

import contextlib
import io
import math
import time as _time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping, Optional, Sequence

import numpy as np

from fgdwa._core import (
    DetectWindowParams,
    FgdwaError,
    Footprint,
    LidarParams,
    Navigator,
    NavigatorMode,
    NavigatorParams,
    OccupancyGrid,
    PlannerParams,
    RobotLimits,
    RobotState,
    Scan,
    SegmentParams,
    TrackerParams,
    planner_preset,
    preset_names,
)
from fgdwa.io.scenario_values import ValueReader, param_keys
from fgdwa.io.table import Table
from fgdwa.sim.scenario import init_keywords, params_with
from fgdwa.file_limits import short_repr

try:
    # IR-SIM prints every matplotlib backend it fails to load when imported;
    # in a headless process that is each interactive one.
    with contextlib.redirect_stdout(io.StringIO()):
        import irsim
        from irsim.lib import register_behavior_class
        from irsim.lib.behavior.behavior_registry import behaviors_class_map
except ImportError as error:  # pragma: no cover - depends on the environment
    raise ImportError(f"fgdwa.adapters.irsim needs IR-SIM: pip install 'fgdwa[irsim]' ({error})") from error

BEHAVIOR = "fgdwa"
MAPPINGS = ("auto", "known", "scan")
# Keys IR-SIM itself reads from a behavior's mapping.
IRSIM_KEYS = ("name", "target_roles", "wander", "loop", "range_low", "range_high")
OWN_KEYS = ("preset", "mapping", "resolution", "detect_window")
LIMIT_KEYS = ("v_max", "omega_max", "acc_v", "acc_omega")
# The control period is IR-SIM's step_time, so dt is not a key.
PLANNER_FIELDS = tuple(name for name in init_keywords(PlannerParams) if name != "dt")
PLANNER_KEYS = tuple(param_keys(PlannerParams, allowed=PLANNER_FIELDS))
NAVIGATOR_KEYS = tuple(param_keys(NavigatorParams))
KEYS = IRSIM_KEYS + OWN_KEYS + LIMIT_KEYS + PLANNER_KEYS + NAVIGATOR_KEYS
# m, cells of a map built from scans. Finer than fgdwa's own 0.1 m: the planner
# trusts the map for hits within half a cell (plus the noise) of its obstacles,
# and with 0.1 m cells the tips of IR-SIM's random polygons and edges seen at a
# grazing angle went missing from it often enough to be hit.
DEFAULT_RESOLUTION = 0.05
MAX_SCAN_CELLS = 2_000_000  # a large world gets coarser cells rather than more of them
MAP_MARGIN = 2.0  # m kept around the world (and the robot and its goals) by a map built from scans
# s of simulated time between warnings that a robot gave up again.
GIVE_UP_WARNING_PERIOD = 10.0
# The navigator stops this fraction inside IR-SIM's goal_threshold, where IR-SIM counts the robot arrived.
GOAL_TOLERANCE_SHARE = 0.9
# With arrive_mode "state" the heading counts too: the position is settled within this share, then the robot turns.
STATE_POSITION_SHARE = 0.5
LIDAR_TYPES = ("lidar2d", "fmcw_lidar2d")


@dataclass(frozen=True)
class BehaviorConfig:
    """What a world's ``behavior: {name: fgdwa, ...}`` asks for, checked."""

    preset: str = "fgdwa"  # a planner preset (fgdwa.preset_names())
    mapping: str = "auto"  # "known": the world's grid map; "scan": built from scans; "auto": known when there is one
    resolution: Optional[float] = None  # m, cells of a map built from scans (None: DEFAULT_RESOLUTION, or coarser)
    planner: dict = field(default_factory=dict)  # PlannerParams fields replacing the preset's
    navigator: dict = field(default_factory=dict)  # NavigatorParams fields replacing its defaults
    limits: dict = field(default_factory=dict)  # RobotLimits fields tightening the robot's IR-SIM limits
    window: Optional[DetectWindowParams] = None  # the detect window of the obstacle density (default its own)


def parse_config(config: Mapping[str, Any], where: str) -> BehaviorConfig:
    """The behavior's keys, each checked; a bad one raises FgdwaError naming it and its value."""
    reader = ValueReader(where, Path.cwd())
    reader.mapping(dict(config), "", KEYS)
    preset = reader.string(config.get("preset", "fgdwa"), "preset")
    if preset not in preset_names():
        reader.fail("preset", preset, f"expected one of {', '.join(preset_names())}")
    mapping = reader.string(config.get("mapping", "auto"), "mapping")
    if mapping not in MAPPINGS:
        reader.fail("mapping", mapping, f"expected one of {', '.join(MAPPINGS)}")
    resolution = None
    if config.get("resolution") is not None:
        resolution = reader.number(config["resolution"], "resolution", low=0.0, low_open=True)
    planner = _planner_overrides(reader, config, planner_preset(preset).params)
    navigator = _navigator_overrides(reader, config)
    limits = {name: reader.number(config[name], name, low=0.0, low_open=True)
              for name in LIMIT_KEYS if config.get(name) is not None}
    window = None
    if config.get("detect_window") is not None:
        fields = reader.param_fields(DetectWindowParams, config["detect_window"], "detect_window")
        window = reader.core("detect_window", config["detect_window"],
                             lambda: params_with(DetectWindowParams(), **fields))
    return BehaviorConfig(preset=preset, mapping=mapping, resolution=resolution, planner=planner,
                          navigator=navigator, limits=limits, window=window)


def _planner_overrides(reader: ValueReader, config: Mapping[str, Any], base: PlannerParams) -> dict:
    given = {name: value for name, value in config.items() if name in PLANNER_KEYS and value is not None}
    overrides = reader.param_fields(PlannerParams, given, "", allowed=PLANNER_FIELDS)
    # The core refuses a cycle of more rollout poses than it allows, naming the numbers.
    reader.core("", given, lambda: params_with(base, **overrides))
    return overrides


def _navigator_overrides(reader: ValueReader, config: Mapping[str, Any]) -> dict:
    given = {name: value for name, value in config.items() if name in NAVIGATOR_KEYS and value is not None}
    overrides = reader.param_fields(NavigatorParams, given, "")
    reader.core("", given, lambda: params_with(NavigatorParams(), **overrides))
    return overrides


# ---------------------------------------------------------------- reading IR-SIM's robot

def robot_footprint(robot, pad: float = 0.0) -> Footprint:
    """The robot's outline in its own frame, grown by ``pad`` metres: a circle about
    its origin as fgdwa's circle, any other shape as its convex hull (never smaller
    than the shape IR-SIM checks for collisions)."""
    from shapely.geometry import JOIN_STYLE
    from shapely.geometry.polygon import orient

    geometry = robot.original_geometry
    if robot.shape == "circle":
        centre = geometry.centroid
        if math.hypot(centre.x, centre.y) < 1e-9:
            # IR-SIM's circle is a polygon inscribed in it: the circle holds it.
            return Footprint.circle(float(robot.radius) + pad)
    hull = geometry.convex_hull
    if hull.geom_type != "Polygon" or hull.area <= 0.0:
        raise FgdwaError(f"robot {short_repr(robot.name)}: shape {short_repr(robot.shape)} has no area to plan with")
    if pad > 0.0:
        hull = hull.buffer(pad, join_style=JOIN_STYLE.mitre)
    vertices = np.asarray(orient(hull, 1.0).exterior.coords, dtype=float)[:-1]
    try:
        return Footprint.polygon(vertices)
    except FgdwaError as error:
        raise FgdwaError(f"robot {short_repr(robot.name)}: shape {short_repr(robot.shape)} as a footprint: {error}") from None


def step_mismatch(limits: RobotLimits, step_time: float) -> float:
    """The farthest one IR-SIM step can land from the pose fgdwa predicts for the same
    command, m: IR-SIM moves along the old heading and then turns, fgdwa's model turns
    and then moves, so the two positions are v dt apart in direction by omega dt."""
    return limits.v_max * 2.0 * math.sin(0.5 * min(limits.omega_max * step_time, math.pi)) * step_time


def robot_limits(robot, overrides: Mapping[str, float]) -> RobotLimits:
    """fgdwa's limits from IR-SIM's vel_min, vel_max and acce.

    fgdwa plans forward motion (v_min 0) and symmetric turns (the smaller of the
    two angular limits). IR-SIM's default acce is unbounded; the planner then
    assumes fgdwa's default accelerations, which the robot can always follow.
    Behavior keys may tighten any limit, never loosen it.
    """
    vel_min = np.asarray(robot.vel_min, dtype=float).reshape(-1)
    vel_max = np.asarray(robot.vel_max, dtype=float).reshape(-1)
    acce = np.asarray(robot.info.acce, dtype=float).reshape(-1)
    v_max, omega_max = float(vel_max[0]), float(min(vel_max[1], -vel_min[1]))
    if not v_max > 0.0:
        raise FgdwaError(f"robot {short_repr(robot.name)}: vel_max = {vel_max.tolist()}: fgdwa needs a forward speed > 0")
    if not omega_max > 0.0:
        raise FgdwaError(f"robot {short_repr(robot.name)}: vel_min = {vel_min.tolist()}, vel_max = {vel_max.tolist()}: "
                         f"fgdwa needs turning both ways (vel_min[1] < 0 < vel_max[1])")
    defaults = RobotLimits()
    acc_v = float(acce[0]) if math.isfinite(acce[0]) else defaults.acc_v
    acc_omega = float(acce[1]) if math.isfinite(acce[1]) else defaults.acc_omega
    world = robot._world_param
    if world.collision_mode == "contact":
        # In contact mode the wheels' grip caps how fast the speed changes.
        acc_v = min(acc_v, robot.friction * world.gravity)
    values = {"v_max": v_max, "omega_max": omega_max, "acc_v": acc_v, "acc_omega": acc_omega}
    for name, value in overrides.items():
        if value > values[name] * (1.0 + 1e-9):
            raise FgdwaError(f"robot {short_repr(robot.name)}: {name} = {value:g}: may only tighten the robot's own "
                             f"limit ({values[name]:g}, from IR-SIM's vel_max, vel_min and acce)")
        values[name] = value
    if not all(value > 0.0 for value in values.values()):
        raise FgdwaError(f"robot {short_repr(robot.name)}: limits {values}: must all be > 0")
    return RobotLimits(v_min=0.0, **values)


def robot_lidar(robot):
    """The robot's first 2D lidar, or FgdwaError saying how to give it one."""
    lidar = robot.lidar
    if lidar is None or getattr(lidar, "sensor_type", None) not in LIDAR_TYPES:
        raise FgdwaError(f"robot {short_repr(robot.name)}: the fgdwa behavior senses with a 2D lidar, and this robot has "
                         f"none: add one under the robot's sensors, e.g. "
                         f"sensors: [{{type: lidar2d, range_max: 8, angle_range: 4.71, number: 271}}]")
    if lidar.number < 2:
        raise FgdwaError(f"robot {short_repr(robot.name)}: lidar number = {lidar.number}: fgdwa needs at least 2 beams")
    return lidar


def lidar_params(lidar) -> LidarParams:
    """fgdwa's description of IR-SIM's lidar: field of view, beams, range, range noise."""
    noise = float(lidar.std) if lidar.noise else 0.0
    return LidarParams(fov=float(lidar.angle_range), beams=int(lidar.number),
                       max_range=float(lidar.range_max), noise_std=noise)


def irsim_scan(lidar, body=None) -> Scan:
    """The lidar's last scan as a fgdwa Scan, placed where the lidar was (IR-SIM's
    lidar_origin: the robot's pose with the lidar's mounting offset). A beam that hit
    nothing reads +inf; a return inside the blind zone (IR-SIM reports range_min, not
    valid) stays a hit at range_min, the nearest the obstacle can be placed.

    A return inside ``body`` (the robot's outline as a shapely geometry in the
    world) deeper than the range noise can carry a hit reads +inf too: nothing
    stands inside the robot that has not already collided with it, so it is the
    robot's own body or a ray-casting artifact (IR-SIM 2.12 returns one for the
    zero-length edges of grid maps, and a single such point inside the robot
    stops every motion of the planner). A noisy hit on an obstacle beside the
    robot can land just inside its outline: those stay."""
    ranges = np.array(lidar.range_data, dtype=float)
    valid = np.asarray(lidar.valid, dtype=bool)
    ranges[~valid & (ranges > lidar.range_min)] = np.inf
    pose = np.asarray(lidar.lidar_origin, dtype=float).reshape(-1)[:3]
    noise = float(lidar.std) if getattr(lidar, "noise", False) else 0.0
    if body is not None and noise > 0.0:
        body = body.buffer(-3.0 * noise)
    if body is not None and not body.is_empty:
        import shapely

        finite = np.flatnonzero(np.isfinite(ranges))
        angles = pose[2] + np.asarray(lidar.angle_list, dtype=float)[finite]
        x = pose[0] + ranges[finite] * np.cos(angles)
        y = pose[1] + ranges[finite] * np.sin(angles)
        ranges[finite[shapely.contains_xy(body, x, y)]] = np.inf
    return Scan(ranges, float(lidar.angle_min), float(lidar.angle_inc), float(lidar.range_max), pose)


def world_grid(objects) -> Optional[OccupancyGrid]:
    """The world's grid map (``obstacle_map``) as fgdwa's OccupancyGrid, None without one.

    IR-SIM counts a robot colliding with an occupied cell (value > 50) when it
    meets the cell's box or comes within half a cell of its centre. On square
    cells that is the cell itself; on cells of unequal sides the grid is resampled
    onto square cells of half the shorter side, each one occupied when it meets an
    occupied cell's box or disc: the map then holds every place IR-SIM collides
    with and reaches at most one of its (small) cells beyond.
    """
    maps = [obj for obj in objects if obj.shape == "map" and getattr(obj, "grid_map", None) is not None]
    if not maps:
        return None
    source = maps[0]
    grid = np.asarray(source.grid_map, dtype=float)
    rx, ry = (float(v) for v in np.asarray(source.grid_reso, dtype=float).reshape(-1)[:2])
    ox, oy = (float(v) for v in np.asarray(source.world_offset, dtype=float).reshape(-1)[:2])
    occupied = grid > 50.0
    if abs(rx - ry) <= 1e-9 * max(rx, ry):
        # IR-SIM indexes [x, y]; fgdwa's rows are y, row 0 at the bottom.
        return OccupancyGrid(np.ascontiguousarray(occupied.T, dtype=np.uint8), rx, (ox, oy))
    # Cells of the shorter side would stand up to a whole cell proud of what
    # IR-SIM collides with: enough to wedge a polygon robot in a doorway.
    res = 0.5 * min(rx, ry)
    cols = int(math.ceil(grid.shape[0] * rx / res - 1e-9))
    rows = int(math.ceil(grid.shape[1] * ry / res - 1e-9))
    cells = np.zeros((rows, cols), dtype=np.uint8)
    ix, iy = np.nonzero(occupied)
    cx, cy = ox + (ix + 0.5) * rx, oy + (iy + 0.5) * ry
    radius = 0.5 * max(rx, ry)
    reach = int(math.ceil(radius / res)) + 1
    col0, row0 = np.floor((cx - ox) / res).astype(int), np.floor((cy - oy) / res).astype(int)
    for dc in range(-reach, reach + 1):
        for dr in range(-reach, reach + 1):
            col, row = col0 + dc, row0 + dr
            inside = (col >= 0) & (col < cols) & (row >= 0) & (row < rows)
            x0, y0 = ox + col * res, oy + row * res
            # Distance from the occupied cell's centre to this square, and whether the boxes overlap.
            dx = np.maximum(np.maximum(x0 - cx, cx - (x0 + res)), 0.0)
            dy = np.maximum(np.maximum(y0 - cy, cy - (y0 + res)), 0.0)
            meets_disc = np.hypot(dx, dy) < radius * (1.0 - 1e-9)
            meets_box = (dx < 0.5 * rx * (1.0 - 1e-9)) & (dy < 0.5 * ry * (1.0 - 1e-9))
            hit = inside & (meets_disc | meets_box)
            cells[row[hit], col[hit]] = 1
    return OccupancyGrid(cells, res, (ox, oy))


def _world_rect(robot) -> Optional[tuple]:
    """(x0, y0, x1, y1) of the robot's IR-SIM world, None when it is not in an environment."""
    env = getattr(robot, "_env", None)
    world = getattr(env, "_world", None)
    if world is None:
        return None
    return float(world.x_range[0]), float(world.y_range[0]), float(world.x_range[1]), float(world.y_range[1])


def scan_layout(robot, goals: Sequence, resolution: Optional[float]) -> OccupancyGrid:
    """An empty map to build from scans: the world, the robot and its goals, with a
    margin; cells of ``resolution``, by default DEFAULT_RESOLUTION unless that
    takes more than MAX_SCAN_CELLS; a given resolution that takes more is refused."""
    points = [np.asarray(robot.state, dtype=float).reshape(-1)[:2]] + [np.asarray(g, dtype=float)[:2]
                                                                        for g in goals]
    low, high = np.min(points, axis=0), np.max(points, axis=0)
    rect = _world_rect(robot)
    if rect is not None:
        low, high = np.minimum(low, rect[:2]), np.maximum(high, rect[2:])
    low, high = low - MAP_MARGIN, high + MAP_MARGIN
    coarsest = math.sqrt(float(np.prod(high - low)) / MAX_SCAN_CELLS)
    if resolution is None:
        resolution = max(DEFAULT_RESOLUTION, coarsest)
    cells = float(np.prod(np.ceil((high - low) / resolution)))
    if cells > MAX_SCAN_CELLS:
        raise FgdwaError(f"resolution = {resolution:g}: the map of the world ({high[0] - low[0]:g} m x "
                         f"{high[1] - low[1]:g} m with its margin) would take {cells:.3g} cells, more than "
                         f"{MAX_SCAN_CELLS}: give {coarsest:.3g} m or more (or leave resolution out)")
    cols, rows = (int(v) for v in np.ceil((high - low) / resolution))
    return OccupancyGrid(np.zeros((rows, cols), dtype=np.uint8), resolution, (float(low[0]), float(low[1])))


def _goals(robot) -> list:
    queue = getattr(robot, "_goal", None)
    if not queue:
        return []
    return [np.asarray(g, dtype=float).reshape(-1) for g in queue]


# ---------------------------------------------------------------- the behavior

class FgdwaBehavior:
    """The fgdwa behavior of one IR-SIM differential-drive robot.

    Lifecycle: IR-SIM constructs it once per robot with the robot's ObjectInfo
    and the behavior's keys (checked now; an error is raised at the first step,
    since IR-SIM would only log it here), then calls it every step. The first call
    builds the Navigator from the robot; a world reset (time going back) builds
    it again. Read-only after a step: ``navigator``, ``record`` (the last
    CycleRecord), ``cycle_times`` (s of each Navigator step), ``failures``.
    """

    def __init__(self, object_info=None, **config):
        self.name = str(getattr(object_info, "name", None) or "robot")
        self.where = f"IR-SIM robot {self.name!r}, behavior {BEHAVIOR}"
        self.error: Optional[FgdwaError] = None
        self.config = BehaviorConfig()
        try:
            self.config = parse_config(config, self.where)
        except FgdwaError as error:
            # IR-SIM logs an exception raised here and then reports only that no behavior exists.
            self.error = error
        self.navigator: Optional[Navigator] = None
        self.record = None
        self.lidar = None
        self.limits: Optional[RobotLimits] = None
        self.mapping = ""
        self.cycle_times: list = []
        self.failures = 0
        self._warned = (None, -math.inf)  # the last give-up warned of: (failure, time)
        self._goal: Optional[np.ndarray] = None
        self._time = -math.inf
        self._dt = 0.0

    def prepare(self, robot) -> None:
        """Builds the navigator for ``robot`` now: every problem with the robot or the
        keys raises FgdwaError here instead of at the first step."""
        if self.error is not None:
            raise self.error
        if robot.kinematics != "diff":
            raise FgdwaError(f"{self.where}: fgdwa drives differential-drive robots (kinematics diff), "
                             f"not {short_repr(robot.kinematics)}")
        config = self.config
        lidar = robot_lidar(robot)
        step_time = float(robot._world_param.step_time)
        limits = robot_limits(robot, config.limits)
        # Grown by what one step of IR-SIM's integration can differ from fgdwa's model,
        # so the step the planner finds clear is clear in IR-SIM too.
        footprint = robot_footprint(robot, pad=step_mismatch(limits, step_time))
        preset = planner_preset(config.preset)
        planner = dict(config.planner)
        threshold = float(robot.goal_threshold)
        share = STATE_POSITION_SHARE if robot.arrive_mode == "state" else GOAL_TOLERANCE_SHARE
        if "goal_tolerance" in planner:
            if planner["goal_tolerance"] >= threshold:
                raise FgdwaError(f"{self.where}: goal_tolerance = {planner['goal_tolerance']:g}: must be less than "
                                 f"the robot's goal_threshold ({threshold:g}), or it stops before IR-SIM counts "
                                 f"it arrived")
        else:
            planner["goal_tolerance"] = share * threshold
        try:
            params = params_with(preset.params, dt=step_time, **planner)
        except FgdwaError as error:
            raise FgdwaError(f"{self.where}: {error} (the control period dt is the world's step_time)") from None
        lidar_model = lidar_params(lidar)
        navigator = self._navigator_params(robot, lidar_model)
        grid = world_grid(robot.external_objects)
        mapping = config.mapping
        if mapping == "auto":
            mapping = "known" if grid is not None else "scan"
        if mapping == "known" and grid is None:
            raise FgdwaError(f"{self.where}: mapping = 'known' needs the world's grid map (world: obstacle_map)")
        if mapping == "scan":
            # On the grid's layout when the world has one, else on the world's.
            grid = scan_layout(robot, _goals(robot), config.resolution) if grid is None else \
                OccupancyGrid(np.zeros((grid.rows, grid.cols), dtype=np.uint8), grid.resolution, grid.origin)
        self.navigator = Navigator(limits, footprint, params, grid, mapping=mapping, lidar=lidar_model,
                                   policy=preset.weight_policy(), navigator=navigator,
                                   window=config.window if config.window is not None else DetectWindowParams())
        self.lidar, self.limits, self.mapping, self._dt = lidar, limits, mapping, step_time
        self._goal = None
        self.record = None

    def _navigator_params(self, robot, lidar: LidarParams) -> NavigatorParams:
        values = dict(self.config.navigator)
        # The navigator hands the lidar's range noise to its map; the scan's
        # segmentation and the tracker are set for 3 cm of noise (fgdwa's own
        # lidar): a noisier lidar scales their noise-bound settings alike.
        segment, tracker = SegmentParams(), TrackerParams()
        scale = lidar.noise_std / segment.range_noise
        if scale > 1.0:
            if not any(name.startswith("segment.") for name in values):
                values["segment.range_noise"] = scale * segment.range_noise
            if not any(name.startswith("tracker.") for name in values):
                values["tracker.measurement_std"] = scale * tracker.measurement_std
                values["tracker.free_margin"] = scale * tracker.free_margin
        # The recovery backs up only as fast as the robot may reverse.
        reverse = max(0.0, -float(np.asarray(robot.vel_min, dtype=float).reshape(-1)[0]))
        defaults = NavigatorParams()
        speed = values.get("backup_speed", defaults.backup_speed)
        if reverse <= 0.0:
            if values.get("backup_distance", 0.0) > 0.0:
                raise FgdwaError(f"{self.where}: backup_distance = {values['backup_distance']:g}: the robot cannot "
                                 f"reverse (vel_min[0] = 0)")
            values["backup_distance"] = 0.0
        elif speed > reverse:
            if "backup_speed" in values:
                raise FgdwaError(f"{self.where}: backup_speed = {speed:g}: faster than the robot may reverse "
                                 f"({reverse:g}, from vel_min)")
            values["backup_speed"] = reverse
        return params_with(NavigatorParams(), **values)

    def __call__(self, ego_object=None, external_objects=None, **_config) -> np.ndarray:
        robot = ego_object
        if self.error is not None:
            raise self.error
        now = int(robot._world_param.count) * float(robot._world_param.step_time)
        if self.navigator is None or now < self._time:
            self.prepare(robot)
        self._time = now
        goal = robot.goal
        if goal is None or robot.arrive_flag:
            return self._stop(robot)
        goal = np.asarray(goal, dtype=float).reshape(-1)
        if self._goal is None or not np.array_equal(goal[:2], self._goal[:2]):
            self.navigator.set_goal(goal[:2])
            self._goal = goal
        velocity = np.asarray(robot.velocity, dtype=float).reshape(-1)
        state = RobotState(np.asarray(robot.state, dtype=float).reshape(-1)[:3], (velocity[0], velocity[1]))
        tic = _time.perf_counter()
        record = self.navigator.step(state, irsim_scan(self.lidar, robot.geometry), now)
        self.cycle_times.append(_time.perf_counter() - tic)
        self.record = record
        if record.mode == NavigatorMode.Failed:
            # IR-SIM has no way to give up: the robot stops and tries again from here.
            self.failures += 1
            # A robot may give up cycle after cycle (a goal another robot holds): the first time, when the
            # reason changes, and then every GIVE_UP_WARNING_PERIOD seconds, with the count.
            if (record.failure.name != self._warned[0] or now - self._warned[1] >= GIVE_UP_WARNING_PERIOD):
                robot.logger.warning(f"{self.name}: fgdwa gave up ({record.failure.name}); trying again "
                                     f"({self.failures} time{'s' if self.failures > 1 else ''} so far)")
                self._warned = (record.failure.name, now)
            self.navigator.set_goal(goal[:2])
            return self._stop(robot)
        command = np.array([[record.command.v], [record.command.omega]])
        if record.mode == NavigatorMode.GoalReached and robot.arrive_mode == "state" and len(goal) > 2:
            command = self._turn_to(robot, float(goal[2]), velocity)
        low, high = robot.get_vel_range()
        return np.clip(command, low, high)

    def _turn_to(self, robot, heading: float, velocity) -> np.ndarray:
        """On the goal's position, turn in place to its heading (arrive_mode "state"),
        no faster than the robot can stop on it."""
        error = math.remainder(heading - float(np.asarray(robot.state).reshape(-1)[2]), 2.0 * math.pi)
        limits = self.limits
        target = math.copysign(min(limits.omega_max, math.sqrt(2.0 * limits.acc_omega * abs(error)),
                                   abs(error) / self._dt), error)
        step = limits.acc_omega * self._dt
        omega = float(np.clip(target, velocity[1] - step, velocity[1] + step))
        return np.array([[0.0], [omega]])

    def _stop(self, robot) -> np.ndarray:
        low, high = robot.get_vel_range()
        return np.clip(np.zeros((2, 1)), low, high)


class _NotDifferential:
    """Registered for IR-SIM's other kinematics so that naming fgdwa there says why it cannot drive them."""

    def __init__(self, object_info=None, **_config):
        self.name = str(getattr(object_info, "name", None) or "robot")
        self.kinematics = getattr(object_info, "kinematics", "?")

    def __call__(self, ego_object=None, external_objects=None, **_config):
        raise FgdwaError(f"IR-SIM robot {short_repr(self.name)}, behavior {BEHAVIOR}: fgdwa drives differential-drive "
                         f"robots (kinematics diff), not {short_repr(self.kinematics)}")


def _register() -> None:
    """Registers the behavior with IR-SIM for every kinematics it names; a module
    reload replaces its own earlier classes, another package's "fgdwa" is left alone."""
    for kinematics in ("diff", "omni", "omni_angular", "acker"):
        cls = FgdwaBehavior if kinematics == "diff" else _NotDifferential
        existing = behaviors_class_map.get((kinematics, BEHAVIOR))
        if existing is None:
            register_behavior_class(kinematics, BEHAVIOR)(cls)
        elif getattr(existing, "__module__", None) == __name__:
            behaviors_class_map[(kinematics, BEHAVIOR)] = cls


_register()


def behavior_of(robot) -> Optional[FgdwaBehavior]:
    """The FgdwaBehavior IR-SIM built for ``robot``, None when it runs another behavior."""
    handler = getattr(getattr(robot, "obj_behavior", None), "_invoke_func", None)
    return handler if isinstance(handler, FgdwaBehavior) else None


# ---------------------------------------------------------------- running a world

@dataclass
class RobotOutcome:
    """How one robot of a world fared, by IR-SIM's own flags."""

    name: str
    behavior: str  # its behavior's name ("" without one)
    arrived: bool  # IR-SIM's arrive flag: its last goal reached
    collided: bool  # IR-SIM's collision flag was raised at some step
    steps: int  # steps until it arrived or first collided, else every step run
    time: float  # s of simulated time at that step
    cycle_ms_median: float = float("nan")  # ms, median Navigator step (fgdwa robots)
    cycle_ms_p95: float = float("nan")
    failures: int = 0  # times the navigator gave up and started again

    @property
    def outcome(self) -> str:
        if self.collided:
            return "collided"
        return "arrived" if self.arrived else "running"


@dataclass
class WorldRun:
    world: str
    steps: int  # steps run
    wall_time: float  # s
    robots: list  # RobotOutcome per robot, in IR-SIM's order

    def fgdwa_robots(self) -> list:
        return [r for r in self.robots if r.behavior == BEHAVIOR]


def make_env(world, seed: Optional[int] = None, render: bool = False, log_level: str = "WARNING"):
    """An IR-SIM environment of ``world`` (a YAML path) whose fgdwa robots are checked
    now: a bad key or a robot fgdwa cannot drive raises FgdwaError before any step.
    Headless unless ``render``."""
    path = Path(world)
    if not path.is_file():
        raise FgdwaError(f"world {world!r}: no such file")
    kwargs = dict(log_level=log_level, seed=seed)
    if render:
        env = irsim.make(str(path), display=True, **kwargs)
    else:
        env = irsim.make(str(path), display=False, headless=True, **kwargs)
    for robot in env.robot_list:
        behavior = behavior_of(robot)
        if behavior is not None:
            behavior.prepare(robot)
        elif robot.beh_config.get("name") == BEHAVIOR:
            handler = getattr(robot.obj_behavior, "_invoke_func", None)
            handler(ego_object=robot)  # the class registered for other kinematics says why
    return env


def run_world(world, max_steps: int = 1000, seed: Optional[int] = None, render: bool = False,
              log_level: str = "WARNING") -> WorldRun:
    """Run ``world`` until every fgdwa robot has arrived or collided, or ``max_steps``;
    IR-SIM's arrive and collision flags are the referee."""
    if isinstance(max_steps, bool) or not isinstance(max_steps, int) or max_steps < 1:
        raise FgdwaError(f"max_steps = {short_repr(max_steps)}: must be an integer >= 1")
    tic = _time.perf_counter()
    env = make_env(world, seed=seed, render=render, log_level=log_level)
    robots = list(env.robot_list)
    driven = [r for r in robots if behavior_of(r) is not None]
    if not driven:
        env.end(0)
        raise FgdwaError(f"world {world!r}: no robot has behavior {{name: {BEHAVIOR}}}")
    step_time = float(env.step_time)
    ended = {}  # robot index -> step at which it arrived or first collided
    collided = [False] * len(robots)
    watched = [i for i, r in enumerate(robots) if behavior_of(r) is not None]
    steps = 0
    try:
        for steps in range(1, max_steps + 1):
            env.step()
            if render:
                env.render(0.01)
            for i, robot in enumerate(robots):
                if robot.collision and not collided[i]:
                    collided[i] = True
                    ended.setdefault(i, steps)
                if robot.arrive:
                    ended.setdefault(i, steps)
            if all(i in ended for i in watched):
                break
    finally:
        env.end(0)
    outcomes = []
    for i, robot in enumerate(robots):
        behavior = behavior_of(robot)
        ms = 1e3 * np.asarray(behavior.cycle_times if behavior is not None else [], dtype=float)
        done = ended.get(i, steps)
        outcomes.append(RobotOutcome(
            name=robot.name, behavior=str(robot.beh_config.get("name", "")), arrived=bool(robot.arrive),
            collided=collided[i], steps=done, time=done * step_time,
            cycle_ms_median=float(np.median(ms)) if len(ms) else float("nan"),
            cycle_ms_p95=float(np.percentile(ms, 95)) if len(ms) else float("nan"),
            failures=behavior.failures if behavior is not None else 0))
    return WorldRun(world=str(world), steps=steps, wall_time=_time.perf_counter() - tic, robots=outcomes)


def format_run(run: WorldRun) -> str:
    """A table of the robots' outcomes."""
    rows = []
    for r in run.robots:
        finite = math.isfinite(r.cycle_ms_median)
        rows.append([r.name, r.behavior or "-", r.outcome, str(r.steps), f"{r.time:.1f}",
                     f"{r.cycle_ms_median:.2f}" if finite else "-", f"{r.cycle_ms_p95:.2f}" if finite else "-",
                     str(r.failures)])
    return Table(["robot", "behavior", "outcome", "step", "time s", "cycle median ms", "cycle p95 ms", "gave up"],
                 rows, f"world {run.world}: {run.steps} steps, {run.wall_time:.2f} s wall").text()
