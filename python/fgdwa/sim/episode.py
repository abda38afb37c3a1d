"""Episodes: a robot driven by the navigator through a world until it reaches
the goal, collides, falls, or runs out of steps (docs/algorithms.md, "Episodes
and metrics").

``run_episode`` is the world's side of every cycle: it scans the true world,
steps the :class:`fgdwa.Navigator`, moves the body (:mod:`fgdwa.sim.body`) and
the discs, and asks the referee (:mod:`fgdwa.sim.referee`) whether the step
touched anything. The planner sees the world through a fast ``FieldClearance``;
the referee judges with the exact FCL ``CollisionWorld``.
"""

from __future__ import annotations

import copy
import dataclasses
import time
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from fgdwa._core import (
    CollisionWorld,
    DetectWindowParams,
    DistanceField,
    FailureReason,
    FgdwaError,
    Footprint,
    GlobalPath,
    GlobalStatus,
    LaserScanner,
    LidarParams,
    Navigator,
    NavigatorMode,
    NavigatorParams,
    OccupancyGrid,
    PlannerPreset,
    PlannerParams,
    PlanResult,
    Pose2,
    RobotLimits,
    RobotState,
    Twist,
    planner_preset,
    unicycle_step,
)
from fgdwa.global_planning import method_params, plan_global
from fgdwa.mapping import check_mapping
from fgdwa.sim.body import DEFAULT_BODY, SCAN_SEED_STRIDE, Body, BodySettings, body_settings, check_seed
from fgdwa.sim.referee import (DANGER_MARGIN, Contact, collides_during_step, collision_contact,
                               danger_point_clearance, danger_points, falls, path_length, smoothness)
from fgdwa.sim.world import World
from fgdwa.file_limits import short_repr

OUTCOMES = ("success", "collision", "fall", "failed", "timeout")


@dataclass
class CycleTrace:
    """What one cycle saw and scored, kept with ``run_episode(record_cycles=True)``
    so that figures replay it instead of simulating it again."""

    mode: str  # the navigator's mode (NavigatorMode name)
    rollouts: np.ndarray  # (k, n_steps, 3) the best admissible rollouts the planner scored, best first
    totals: np.ndarray  # (k,) their total scores
    chosen: np.ndarray  # (n_steps, 3) the chosen rollout; (0, 3) when the planner chose none
    hits: np.ndarray  # (n, 2) the lidar's hits this cycle; (0, 2) without a scan
    # (m, 5) the moving obstacles the planner predicted: x, y, radius (m), vx, vy (m/s)
    tracked: np.ndarray = field(default_factory=lambda: np.zeros((0, 5)))
    critics: tuple = ()  # the planner's critics, the order of the per-critic columns below
    terms: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))  # (k, critics) each best rollout's terms
    chosen_raw: np.ndarray = field(default_factory=lambda: np.zeros(0))  # (critics,) the chosen sample's raw scores
    chosen_terms: np.ndarray = field(default_factory=lambda: np.zeros(0))  # (critics,) its terms; they sum to its total
    raw: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))  # (k, critics) each best rollout's raw scores
    # (critics, 3) min, mean, max of each critic's term over the admissible samples
    critic_stats: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    critic_vetoes: np.ndarray = field(default_factory=lambda: np.zeros(0, dtype=int))  # (critics,) samples vetoed
    reject_counts: dict = field(default_factory=dict)  # samples per reject reason (RejectReason names)
    trigger: str = "None"  # what started the recovery under way (RecoveryTrigger name)
    failure: str = "None"  # why the navigator gave up (FailureReason name)
    times: dict = field(default_factory=dict)  # s, wall clock per stage (tracking, map, global, perception, plan)
    # the robot's own map (OccupancyGrid) after this cycle, when the scan changed it (mapping="scan"); else None
    scan_map: Optional[OccupancyGrid] = None


@dataclass
class EpisodeSummary:
    """The scalar metrics of a run; ``EpisodeResult.metrics()`` is this as a dict."""

    outcome: str  # one of OUTCOMES
    steps: int
    sim_time: float = field(metadata={"unit": "s"})  # simulated
    planning_time: float = field(metadata={"unit": "s"})  # wall clock spent choosing commands
    mileage: float = field(metadata={"unit": "m"})  # length of the executed path
    min_clearance: float = field(metadata={"unit": "m"})  # exact (FCL) clearance along the executed path
    mean_clearance: float = field(metadata={"unit": "m"})
    # mean obstacle distance at the global path's danger points
    danger_clearance: float = field(default=float("nan"), metadata={"unit": "m"})
    mean_deviation: float = field(default=float("nan"), metadata={"unit": "m"})  # from the global path
    max_deviation: float = field(default=float("nan"), metadata={"unit": "m"})
    # sum of |change of omega| between cycles
    smoothness: float = field(default=0.0, metadata={"unit": "rad/s"})
    reason: str = ""  # why a run that did not succeed ended, in a line ("" on success)


# The unit of each metric (EpisodeResult.metrics()' keys), "" for a count or a word.
METRIC_UNITS = {f.name: f.metadata.get("unit", "") for f in dataclasses.fields(EpisodeSummary)}


@dataclass
class Motion:
    """What the robot did, step by step."""

    poses: np.ndarray  # (steps + 1, 3) x, y, theta, start included: where the robot was
    commands: np.ndarray  # (steps, 2) v, omega the wheels got (after latency, actuation noise, terrain)
    clearances: np.ndarray  # (steps + 1,) m
    twists: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))  # (steps, 2) mean v, omega driven per cycle
    believed_poses: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))  # (steps + 1, 3) the odometry's


@dataclass
class PlannerTrace:
    """What the navigator read and decided, cycle by cycle."""

    statuses: list = field(default_factory=list)  # the planner's status, or the navigator's mode when it did not plan
    modes: list = field(default_factory=list)  # the navigator's mode (NavigatorMode names)
    cycle_times: np.ndarray = field(default_factory=lambda: np.zeros(0))  # s
    targets: Optional[np.ndarray] = None  # (steps, 2) the heading's target
    density: np.ndarray = field(default_factory=lambda: np.zeros(0))  # (steps,) I (nan unsensed)
    deviation: np.ndarray = field(default_factory=lambda: np.zeros(0))  # (steps,) D, m (nan without path)
    beta: np.ndarray = field(default_factory=lambda: np.zeros(0))  # (steps,) clearance weight
    delta: np.ndarray = field(default_factory=lambda: np.zeros(0))  # (steps,) similarity weight (nan without)
    # (steps,) s, T: when the nearest tracked or known mover would first touch the robot, both keeping their
    # velocities (inf: none)
    contact_time: np.ndarray = field(default_factory=lambda: np.zeros(0))
    cycles: list = field(default_factory=list)  # CycleTrace per cycle, with record_cycles=True


@dataclass
class NavigationContext:
    """The goal, the paths and the map the navigator worked with, and its last cycle."""

    mapping: str = "known"  # "known": the planners had the map; "scan": they had the robot's own map
    global_path: Optional[np.ndarray] = None  # (n, 2), the path followed at the end, when the planner followed one
    key_nodes: Optional[np.ndarray] = None  # (k, 2) its key-node positions
    paths: list = field(default_factory=list)  # (cycle, (n, 2) points) per global path followed, in order
    scan_map: Optional[np.ndarray] = None  # (rows, cols) the robot's map at the end, with mapping="scan"
    scan_extent: Optional[tuple] = None  # (x0, x1, y0, y1) m, scan_map's
    last_plan: Optional[PlanResult] = None
    last_rollouts: Optional[np.ndarray] = None  # (samples, n_steps, 3)
    last_scan: Optional[object] = None  # the last cycle's Scan, when sensing
    goal: Optional[np.ndarray] = None  # (2,) where it was sent, m


@dataclass
class EpisodeResult:
    """The executed run: its metrics (``summary``), the robot's steps
    (``motion``), the navigator's cycles (``trace``), what it navigated by
    (``context``) and, after a collision, what it touched where (``collision``)."""

    summary: EpisodeSummary
    motion: Motion
    trace: PlannerTrace = field(default_factory=PlannerTrace)
    context: NavigationContext = field(default_factory=NavigationContext)
    collision: Optional[Contact] = None

    def metrics(self) -> dict:
        """The scalar metrics, as plain Python numbers."""
        return {f.name: getattr(self.summary, f.name) for f in dataclasses.fields(EpisodeSummary)}


def _as_pose(value, name: str) -> np.ndarray:
    pose = np.asarray(value, dtype=float)
    if pose.shape != (3,) or not np.all(np.isfinite(pose)):
        raise FgdwaError(f"{name}: expected a finite (x, y, theta), got {short_repr(value)}")
    return pose


def _as_point(value, name: str) -> np.ndarray:
    point = np.asarray(value, dtype=float)
    if point.shape != (2,) or not np.all(np.isfinite(point)):
        raise FgdwaError(f"{name}: expected a finite (x, y), got {short_repr(value)}")
    return point


@dataclass(frozen=True)
class EpisodeOptions:
    """How ``run_episode`` runs an episode; every field is optional (see run_episode)."""

    limits: Optional[RobotLimits] = None  # default RobotLimits()
    footprint: Optional[Footprint] = None  # default a circle of 0.25 m
    params: Optional[PlannerParams] = None  # default PlannerParams()
    max_steps: int = 1000  # cycles before a timeout
    goal_tolerance: Optional[float] = None  # m; default the planner's
    global_path: Optional[object] = None  # a GlobalPath or (n, 2) points to follow
    global_method: str = "astar"  # "astar" or "ompl:NAME", for a path planned before the run
    global_options: Optional[dict] = None  # options of plan_global
    lidar: Optional[LidarParams] = None  # None: no scans (known map only)
    window: Optional[DetectWindowParams] = None  # the detect window of I
    weight_policy: Optional[object] = None  # a WeightPolicy; needs a lidar
    seed: int = 0  # every random draw of the run: lidar noise and dropped beams, actuation noise, odometry drift
    danger_clearance: Optional[float] = None  # m; default footprint radius + 0.3 m
    mapping: str = "known"  # or "scan"
    # m, the cells of the map the robot builds with mapping "scan" (the ROS node's ~map_resolution), over the
    # world grid's extent; None: the world grid's own cells
    map_resolution: Optional[float] = None
    navigator: Optional[NavigatorParams] = None  # default NavigatorParams()
    record_cycles: bool = False  # keep a CycleTrace per cycle
    # The body: a profile of fgdwa.sim.body.BODY_PROFILES ("default": wheels that ramp, command noise,
    # odometry drift; "ideal") or a BodySettings; the fields below, when not None, replace the profile's.
    body: object = DEFAULT_BODY
    latency: Optional[int] = None  # cycles from a scan to its command reaching the wheels
    actuation_noise: Optional[tuple] = None  # (m/s, rad/s) std of Gaussian noise on the command the wheels get
    actuation_lag: Optional[float] = None  # s, time constant of the first-order lag of (v, omega) toward the command
    odometry_drift: Optional[tuple] = None  # (m, rad) std of the believed pose's random walk after 1 m, 1 rad
    motor_rate: Optional[float] = None  # Hz, the motor controller's rate: the wheels ramp at the acceleration limits
    # The body the referee judges (the true outline); None: the footprint the planner is given.
    outline: Optional[Footprint] = None
    # m the navigator's goal tolerance is tighter than the referee's (at most half of it goes): what a user
    # whose pose is an estimate asks of the robot. None: half the referee's tolerance when the odometry drifts
    # or scans are matched, else 0.
    goal_margin: Optional[float] = None


EPISODE_OPTIONS = tuple(f.name for f in dataclasses.fields(EpisodeOptions))
GOAL_MARGIN_SHARE = 0.5  # of the referee's goal tolerance: goal_margin's default with a drifting body or scan matching


def simulated_navigator(mapping: str = "known") -> NavigatorParams:
    """The navigator's parameters a simulated robot runs with unless it is given
    its own: the defaults, and with the map given whole each scan matched to it
    (``scan_match.enabled``), as a robot with a map runs a localiser. The map's
    walls are the true ones, so the drifting odometry is corrected: on the
    default body E1-E3 went from 14 and 15, 15, 14 and 8, 13 and 11 successes of
    15 to 15 and 15, 15, 15 and 10, 15 and 15 (on the ideal body the same), and
    BARN with the map known had one collision in 250 runs without it, none with
    it; the fields stayed within their spread. On a map built from scans the
    odometry stands: matched to its own map the pose measured worse (BARN from
    scans, seeds 0-1: 241 and 230 successes of 250 with 7 collisions, against 247
    and 245 with 3)."""
    check_mapping(mapping)
    params = NavigatorParams()
    params.scan_match.enabled = mapping == "known"
    return params


def default_goal_margin(body: BodySettings, navigator: NavigatorParams, tolerance: float) -> float:
    """goal_margin's default (m) for a referee's goal ``tolerance`` (m): where the
    navigator's pose is an estimate (odometry that drifts, or scans matched to
    the map), the robot aims for the inner half of the goal region, since after
    tens of metres the estimate may be off by tenths of a metre and a robot
    that stops on the region's rim believing it has arrived may stand outside
    it; else 0."""
    estimated = max(body.odometry_drift) > 0 or navigator.scan_match.enabled
    return GOAL_MARGIN_SHARE * tolerance if estimated else 0.0


def run_episode(world: World, start, goal, options: Optional[EpisodeOptions] = None, **settings) -> EpisodeResult:
    """Drive from ``start`` (x, y, theta, at rest) to ``goal`` (x, y), run as
    ``options`` say (an EpisodeOptions) with any of its fields given as keywords
    on top (an unknown keyword is an error naming it).

    The robot side is one :class:`fgdwa.Navigator` (map, global path, local
    planner, recovery; ``navigator`` its NavigatorParams); this function is the
    world: every cycle it scans the true world, steps the navigator, moves the
    robot by the command and the discs by ``dt``, and referees. The episode
    ends on success (within ``goal_tolerance`` of the goal, default the
    planner's), collision (exact footprint contact anywhere along a step, the
    turn included, whoever moves into whom), a fall (the centre entering grade-4 terrain), the
    navigator giving up ("failed"), or ``max_steps`` cycles (timeout).

    A path-following planner (``heading_target == "key_nodes"`` or a critic
    that reads the path) follows ``global_path`` ((n, 2) points) when given, a
    path planned once by ``plan_global(method=global_method, **global_options)``
    when those are not A* with its defaults, else the navigator's own A* path
    (obstacles inflated by the footprint's radius plus NavigatorParams.path_margin,
    then the radius, then the inscribed radius); the navigator replans on its
    map when the path ahead is blocked or after a stall.

    With ``lidar`` the robot scans the true world every cycle (noise drawn from
    ``seed``; ``lidar.dropout`` of the beams read nothing): hits the map does not explain become obstacles for the local
    planner, and the obstacle density I of the detect window (``window``) is
    recorded with the path deviation D. A ``weight_policy`` (``FuzzyWeights``,
    ``FixedWeights`` or a Python subclass of ``WeightPolicy``) then sets the
    clearance weight beta and, when the planner has one, the similarity weight
    delta each cycle.

    Terrain (``world.terrain``) is known to the navigator: its planner keeps
    the footprint off grade 4 and its speed within the passing factor of the
    grade under the robot; the world holds the robot to that speed as well.
    Danger points are the global path's points whose static clearance is below
    ``danger_clearance`` (default: footprint radius + 0.3 m).

    ``mapping="scan"`` hides the map: the navigator starts with an empty one of
    the same layout and marks what the lidar (``lidar``, default
    ``LidarParams()``) hits.

    The robot's body is a real robot's by default (``body="default"``;
    ``body="ideal"`` applies each command at once and knows the pose; see
    :mod:`fgdwa.sim.body`): ``motor_rate`` (Hz) is how often the wheels step
    toward the command within the acceleration limits, ``latency`` cycles pass
    before a command reaches the wheels (they keep the previous one meanwhile),
    ``actuation_noise`` (std_v m/s, std_omega rad/s) perturbs the command they
    get, ``actuation_lag`` (s) is the time constant with which what they aim at
    follows it, and ``odometry_drift`` (std per metre travelled, per radian
    turned) makes the pose the navigator believes wander from the true one: it
    gets the believed pose, its scans are taken from the true pose but placed at
    the believed one (so its map takes the error), while the referee (goal,
    collision, fall, clearances, ``motion.poses``) always uses the true pose;
    ``motion.believed_poses`` holds the odometry's. The referee judges
    ``outline``, the robot's true body (default: the planner's ``footprint``).
    Every random draw (lidar noise and
    dropped beams, actuation, odometry) comes from ``seed``: the same seed gives
    the same episode, bit for bit.

    ``record_cycles`` keeps a :class:`CycleTrace` per cycle in ``trace.cycles`` (the
    scored rollouts, the chosen one, the scan's hits): what the GIF replays.
    About 10 kB a cycle with a 541-beam lidar, so it is off for experiments.
    """
    options = options if options is not None else EpisodeOptions()
    unknown = sorted(set(settings) - set(EPISODE_OPTIONS))
    if unknown:
        raise FgdwaError(f"run_episode: unknown setting(s) {unknown} (known: {', '.join(EPISODE_OPTIONS)})")
    options = dataclasses.replace(options, **settings)
    limits, footprint, params, max_steps = options.limits, options.footprint, options.params, options.max_steps
    goal_tolerance, global_path, lidar, window = options.goal_tolerance, options.global_path, options.lidar, options.window
    weight_policy, mapping, navigator = options.weight_policy, options.mapping, options.navigator
    seed = check_seed(options.seed)
    settings_of_body = body_settings(options)
    limits = limits if limits is not None else RobotLimits()
    footprint = footprint if footprint is not None else Footprint.circle(0.25)
    outline = options.outline if options.outline is not None else footprint  # what the referee judges
    params = params if params is not None else PlannerParams()
    navigator_params = navigator if navigator is not None else simulated_navigator(mapping)
    start_pose = _as_pose(start, "start")
    goal_point = _as_point(goal, "goal")
    if isinstance(max_steps, bool) or not isinstance(max_steps, (int, np.integer)) or max_steps < 1:
        raise FgdwaError(f"max_steps = {short_repr(max_steps)}: must be an integer >= 1")
    tolerance = params.goal_tolerance if goal_tolerance is None else float(goal_tolerance)
    if not np.isfinite(tolerance) or tolerance < 0:
        raise FgdwaError(f"goal_tolerance = {short_repr(goal_tolerance)}: must be >= 0")
    margin = options.goal_margin
    if margin is None:
        margin = default_goal_margin(settings_of_body, navigator_params, tolerance)
    if isinstance(margin, bool) or not isinstance(margin, (int, float, np.integer, np.floating)) \
            or not 0 <= margin <= 10:
        raise FgdwaError(f"goal_margin = {short_repr(margin)}: must be a number in [0, 10] (m)")
    if margin > 0:
        params = copy.copy(params)
        params.goal_tolerance = max(tolerance - margin, 0.5 * tolerance, 1e-3)

    if weight_policy is not None and lidar is None:
        raise FgdwaError("weight_policy: the obstacle density it reads needs a lidar")
    check_mapping(mapping)
    scanning = mapping == "scan"
    if scanning and lidar is None:
        lidar = LidarParams()
    if scanning and world.grid is None:
        raise FgdwaError("mapping = 'scan' builds a map on the world grid's layout: the world needs a grid")
    window = window if window is not None else DetectWindowParams()
    true_grid = world.true_grid()
    truth = CollisionWorld(true_grid, world.discs_at(0.0))
    if truth.in_collision(outline, start_pose, 0.0):
        raise FgdwaError(f"start = {tuple(start_pose)}: the robot's outline there overlaps an obstacle")
    # One field of what really stands there, for the lidar and the danger-point metric.
    true_field = DistanceField(true_grid) if true_grid is not None else None
    scanner = LaserScanner(lidar, true_field) if lidar is not None else None
    if options.map_resolution is not None and not scanning:
        raise FgdwaError("map_resolution: only the map the robot builds (mapping 'scan') has cells of its own")
    layout = _navigator_map(world, start_pose, goal_point, options.map_resolution)
    robot = Navigator(limits, footprint, params, layout, mapping=mapping,
                      lidar=lidar if lidar is not None else LidarParams(), policy=weight_policy,
                      navigator=navigator_params, terrain=world.terrain, passing_factors=world.passing_factors,
                      window=window)
    robot.set_goal(goal_point)
    given = _given_path(world, start_pose, goal_point, footprint, robot, global_path, options.global_method,
                        options.global_options)
    if given is not None:
        robot.set_global_path(given)

    dt = params.dt
    body = Body(settings_of_body, dt, seed, limits)
    pose = Pose2(*start_pose)  # where the robot is
    believed = start_pose.copy()  # where its odometry says it is
    poses = [start_pose.copy()]
    believed_poses = [believed.copy()]
    commands, twists = [], []
    clearances = [truth.clearance(outline, start_pose, 0.0)]
    statuses, modes, cycle_times, targets = [], [], [], []
    density, deviation, betas, deltas, contact_times = [], [], [], [], []
    paths = []
    path_version = 0
    planned = False  # whether the local planner ran in any cycle
    cycles = []
    outcome = "timeout"
    reason = ""
    contact = None
    scan = None
    for k in range(max_steps):
        position = np.array([pose.x, pose.y])
        if np.hypot(*(position - goal_point)) <= tolerance:
            outcome = "success"
            break
        t = k * dt
        discs_now = world.discs_at(t)
        if scanner is not None:
            # Taken from where the robot is, placed where it believes it is.
            scan = scanner.scan(pose, discs_now, 0.0, seed=seed * SCAN_SEED_STRIDE + k)
            if body.drifts:
                scan.pose = tuple(believed)
        tic = time.perf_counter()
        record = robot.step(RobotState(believed, body.twist), scan, t, discs_now if world.discs_known else [])
        cycle_times.append(time.perf_counter() - tic)
        if record.mode == NavigatorMode.Failed:
            outcome = "failed"
            reason = f"the navigator gave up: {record.failure.name}"
            if record.failure == FailureReason.RecoveriesExhausted:
                reason += f" ({record.recoveries} recoveries in a row, the last on {record.trigger.name})"
            break
        if record.path_version != path_version:
            path_version = record.path_version
            paths.append((k, record.path_points))
        density.append(record.density)
        deviation.append(record.deviation)
        betas.append(record.beta)
        deltas.append(record.delta)
        contact_times.append(record.contact_time)
        planned = planned or record.planned
        if options.record_cycles:
            changed = scanning and (not cycles or record.new_cells > 0)
            cycles.append(_trace(record, scan, params.n_steps, robot.map if changed else None))
        modes.append(record.mode.name)
        statuses.append(record.status.name if record.planned else record.mode.name)
        targets.append(record.target)
        command = body.wheels(record.command)
        # Steep ground slows the robot whatever it was told.
        factor = world.passing_factors[world.grade_at(position)]
        command = Twist(min(command.v, factor * limits.v_max), command.omega)
        driven = body.drive(command)
        pose = unicycle_step(pose, driven, dt)
        believed = body.odometry(believed, driven, pose)
        commands.append((command.v, command.omega))
        twists.append((driven.v, driven.omega))
        poses.append(np.array([pose.x, pose.y, pose.theta]))
        believed_poses.append(believed.copy())
        if world.has_moving:
            truth.discs = world.discs_at(t + dt)
        clearances.append(truth.clearance(outline, pose, 0.0))
        # In a world that stands still the clearance at the step's start is the one measured a step ago.
        if collides_during_step(truth, outline, poses[-2], poses[-1], t, dt,
                                discs_at=world.discs_at if world.has_moving else None,
                                start_clearance=None if world.has_moving else clearances[-2]):
            outcome = "collision"
            contact = collision_contact(truth, outline, poses[-1],
                                        (driven.v * np.cos(pose.theta), driven.v * np.sin(pose.theta)),
                                        grid=true_grid, hidden=world.hidden,
                                        before=world.discs_at(t) if world.has_moving else None, dt=dt)
            reason = contact.reason
            break
        if world.terrain is not None and falls(world, poses[-2], poses[-1]):
            outcome = "fall"
            reason = f"fall: the centre entered grade-4 terrain at ({pose.x:.2f}, {pose.y:.2f})"
            break
    else:
        position = np.array([pose.x, pose.y])
        if np.hypot(*(position - goal_point)) <= tolerance:
            outcome = "success"

    if outcome == "timeout":
        reason = (f"timeout: {np.hypot(pose.x - goal_point[0], pose.y - goal_point[1]):.2f} m from the goal after "
                  f"{len(commands) * dt:g} s" + (f", last mode {modes[-1]}" if modes else ""))
        if modes and modes[-1] == "GoalReached":
            off = np.hypot(believed[0] - pose.x, believed[1] - pose.y)
            reason += f" (it believed it had arrived: its odometry was {off:.2f} m off)"
    path = robot.path
    poses_arr = np.array(poses)
    clear_arr = np.array(clearances, dtype=float)
    deviations = np.array(deviation, dtype=float)
    deviations = deviations[np.isfinite(deviations)]
    danger = float("nan")
    if path is not None and true_grid is not None:
        threshold = footprint.radius + DANGER_MARGIN if options.danger_clearance is None else \
            float(options.danger_clearance)
        points = danger_points(path.points, true_field, threshold)
        danger = danger_point_clearance(poses_arr[:, :2], points, true_field)
    finite = clear_arr[np.isfinite(clear_arr)]
    steps = len(commands)
    summary = EpisodeSummary(
        outcome=outcome,
        steps=steps,
        sim_time=steps * dt,
        planning_time=float(np.sum(cycle_times)),
        mileage=path_length(poses_arr),
        min_clearance=float(np.min(clear_arr)) if len(clear_arr) else float("inf"),
        mean_clearance=float(np.mean(finite)) if len(finite) else float("inf"),
        danger_clearance=danger,
        mean_deviation=float(np.mean(deviations)) if len(deviations) else float("nan"),
        max_deviation=float(np.max(deviations)) if len(deviations) else float("nan"),
        smoothness=smoothness(np.array(commands, dtype=float).reshape(-1, 2)),
        reason=reason,
    )
    motion = Motion(
        poses=poses_arr,
        commands=np.array(commands, dtype=float).reshape(-1, 2),
        clearances=clear_arr,
        twists=np.array(twists, dtype=float).reshape(-1, 2),
        believed_poses=np.array(believed_poses),
    )
    trace = PlannerTrace(
        statuses=statuses,
        modes=modes,
        cycle_times=np.array(cycle_times),
        targets=np.array(targets, dtype=float).reshape(-1, 2),
        density=np.array(density, dtype=float),
        deviation=np.array(deviation, dtype=float),
        beta=np.array(betas, dtype=float),
        delta=np.array(deltas, dtype=float),
        contact_time=np.array(contact_times, dtype=float),
        cycles=cycles,
    )
    context = NavigationContext(
        goal=goal_point,
        mapping=mapping,
        global_path=None if path is None else path.points,
        key_nodes=None if path is None else path.points[robot.planner.key_nodes],
        paths=paths,
        scan_map=robot.map.cells if scanning else None,
        scan_extent=tuple(robot.map.extent) if scanning else None,
        last_plan=robot.plan_result if planned else None,
        # The planner keeps its last cycle's rollouts: copied once, not every cycle.
        last_rollouts=robot.planner.rollouts() if planned else None,
        last_scan=scan,
    )
    return EpisodeResult(summary, motion, trace, context, contact)


def _enum_name(value) -> str:
    """An enum value's C++ name ("None", not Python's "None_")."""
    return value.name.rstrip("_")


def _trace(record, scan, n_steps: int, scan_map=None) -> CycleTrace:
    best = record.best
    critics = len(record.critic_names)
    rollouts = np.array([b.poses for b in best], dtype=float).reshape(len(best), n_steps, 3)
    return CycleTrace(mode=record.mode.name, rollouts=rollouts, totals=np.array([b.total for b in best], dtype=float),
                      chosen=np.asarray(record.chosen_rollout, dtype=float).reshape(-1, 3),
                      hits=scan.hit_points if scan is not None else np.zeros((0, 2)),
                      tracked=np.array([[d.center[0], d.center[1], d.radius, d.velocity[0], d.velocity[1]]
                                        for d in record.tracked], dtype=float).reshape(-1, 5),
                      critics=tuple(record.critic_names),
                      terms=np.array([b.terms for b in best], dtype=float).reshape(len(best), critics),
                      chosen_raw=np.array(record.choice.raw, dtype=float),
                      chosen_terms=np.array(record.choice.terms, dtype=float),
                      raw=np.array([b.raw for b in best], dtype=float).reshape(len(best), critics),
                      critic_stats=np.array([(c.min, c.mean, c.max) for c in record.critic_stats],
                                            dtype=float).reshape(-1, 3),
                      critic_vetoes=np.array(record.critic_vetoes, dtype=int),
                      reject_counts=dict(record.reject_counts),
                      trigger=_enum_name(record.trigger), failure=_enum_name(record.failure), times=dict(record.times),
                      scan_map=scan_map)


def check_map_resolution(value, name: str = "map_resolution") -> None:
    """Refuses, naming ``name``, a map cell size that is not a number in [0.01, 1] m."""
    if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
            or not 0.01 <= value <= 1.0:
        raise FgdwaError(f"{name} = {short_repr(value)}: must be a number in [0.01, 1] (m)")


def _navigator_map(world: World, start, goal, resolution: Optional[float] = None) -> OccupancyGrid:
    """The map the navigator starts from: the world's known grid, or for a
    world without one an empty grid around start and goal (the robot knows
    nothing of its surroundings then). With ``resolution`` (mapping "scan"),
    an empty grid over the world grid's extent in cells of that size: the
    robot's map need not share the world's cells."""
    if resolution is not None:
        check_map_resolution(resolution)
        if world.terrain is not None:
            raise FgdwaError("map_resolution: a world with terrain keeps its grid's cells (the terrain is laid on them)")
        x0, x1, y0, y1 = world.grid.extent
        cols, rows = (int(np.ceil(span / resolution - 1e-9)) for span in (x1 - x0, y1 - y0))
        return OccupancyGrid(np.zeros((rows, cols), dtype=np.uint8), float(resolution), (x0, y0))
    if world.grid is not None:
        return world.grid
    margin, resolution = 10.0, 0.1
    low = np.minimum(start[:2], goal) - margin
    size = np.ceil((np.maximum(start[:2], goal) + margin - low) / resolution).astype(int)
    return OccupancyGrid(np.zeros((size[1], size[0]), dtype=np.uint8), resolution, tuple(low))


def _given_path(world: World, start, goal, footprint: Footprint, robot: Navigator, given, method: str,
                options: Optional[dict]) -> Optional[GlobalPath]:
    """The path the navigator is handed instead of planning its own: ``given``,
    or one planned here when the method or options are not the navigator's A*."""
    method_params(method)  # an unknown method is refused by name, given path or not
    if given is not None:
        return given if isinstance(given, GlobalPath) else GlobalPath(np.asarray(given, dtype=float))
    if not robot.planner.needs_path or (method == "astar" and not options):
        return None
    if world.grid is None:
        raise FgdwaError("a path-following planner needs a global path: give global_path or a world with a grid")
    options = dict(options or {})
    if method.startswith("ompl:"):
        options.setdefault("footprint", footprint)
    # A path that keeps a margin beyond the footprint gives the local planner
    # room at the corners where key nodes sit; where the margin closes every
    # passage, the footprint's radius alone decides.
    radii = [options.pop("inflation_radius")] if "inflation_radius" in options else \
        [footprint.radius + robot.params.path_margin, footprint.radius]
    for radius in radii:
        plan = plan_global(world.grid, start[:2], goal, method=method, terrain=world.terrain,
                           inflation_radius=radius, **options)
        if plan.status == GlobalStatus.Found:
            break
    if plan.status != GlobalStatus.Found:
        raise FgdwaError(f"global planner {method}: no path from start to goal ({plan.status.name})")
    return GlobalPath(plan.path)


def run_preset(world: World, start, goal, planner="fgdwa", lidar: Optional[LidarParams] = None,
               **kwargs) -> EpisodeResult:
    """``run_episode`` with a named planner (``preset_names()``) or a PlannerPreset.

    A fuzzy preset senses with ``lidar`` (default ``LidarParams()``): the density
    I that sets its weights comes from the scan."""
    preset = planner if isinstance(planner, PlannerPreset) else planner_preset(planner)
    policy = preset.weight_policy()
    if policy is not None and lidar is None:
        lidar = LidarParams()
    return run_episode(world, start, goal, params=kwargs.pop("params", preset.params), lidar=lidar,
                       weight_policy=kwargs.pop("weight_policy", policy), **kwargs)
