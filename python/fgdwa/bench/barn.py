"""The BARN benchmark: every planner on BARN worlds, scored as the challenge scores.

One run is one world, one planner, one trial, with the map known to the
planners (``mapping="known"``) or built by the robot from its lidar
(``"scan"``, the challenge's setting). All planners share the robot (the
``jackal`` preset, speed-capped by :class:`BarnSetup`), the sampler, the lidar
and the simulator. Outcomes follow the challenge (docs/barn.md): success is
ending within the goal radius without collision before the time limit; the
score is ``success * OT / clip(T, 2 OT, 8 OT)`` with T simulated time.

:func:`run_barn` returns one :class:`fgdwa.bench.runs.Run` per run;
:func:`write_barn_outputs` writes runs.csv, summary.json and failures.png
(docs/barn.md, "Running the benchmark"). ``fgdwa barn`` and ``fgdwa barn
import`` are registered by :func:`register_barn_commands`.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import (FgdwaError, LidarParams, NavigatorParams, OccupancyGrid, PlannerParams, RobotLimits,
                         planner_preset, preset_names, robot_preset)
from fgdwa.bench.options import (add_executor_arguments, add_output_arguments, add_sensing_arguments,
                                 add_settings_argument,
                                 check_executor_arguments, check_sensing, planner_list)
from fgdwa.bench.recordings import (RECORDED_ROLLOUTS, add_record_failures_argument, check_recording_possible,
                                    failure_entries, print_failures, run_benchmark)
from fgdwa.bench.runner import DEFAULT_WORKERS, run_tasks
from fgdwa.bench.runs import (OUTCOMES, Run, episode_columns, format_table, paths_followed, write_run_outputs,
                              written_files)
from fgdwa.io.barn_convert import convert_barn_worlds
from fgdwa.io.barn_data import BarnDataset, barn_score, describe_world_ids, find_barn_file, load_barn
from fgdwa.mapping import MAPPING_MODES, check_mapping
from fgdwa.sim.body import DEFAULT_BODY, body_profile
from fgdwa.sim.episode import check_map_resolution, run_episode, simulated_navigator
from fgdwa.sim.scenario import params_with
from fgdwa.settings import Settings, benchmark_settings, group_settings
from fgdwa.sim.world import World
from fgdwa.file_limits import short_repr

BARN_PLANNERS = ("dwa", "gdwa", "sgdwa", "fgdwa", "dwb")
RUN_FIELDS = ("world", "planner", "mapping", "trial", "seed", "outcome", "success", "time", "score", "optimal_time",
              "mileage", "min_clearance", "replans", "backing_up", "cycle_ms_mean", "cycle_ms_p95", "sim_ms_mean", "wall_time", "reason")


@dataclass(frozen=True)
class BarnSetup:
    """How every planner runs on BARN.

    The Jackal's own limits (``jackal`` robot preset: 2 m/s, 4 rad/s, 20 m/s^2,
    25 rad/s^2) with the forward speed capped at ``v_max``: the score stops
    growing once T <= 2 OT, i.e. at a mean speed of 1 m/s along the reference
    path, and a slower robot has more room to pick its way. The rollouts are
    shortened to ``sim_time`` at period ``dt`` because BARN's gaps are a few
    centimetres wider than the robot: a 3 s horizon at 1 m/s reaches through
    them into the next obstacle and leaves no curved rollout admissible.
    The lidar is the Jackal's Hokuyo UST-10LX class: 270 degrees, 0.5 degree
    steps, 10 m, ``noise_std`` Gaussian range noise and a ``dropout`` share of
    beams returning nothing, drawn from the trial's seed. A real scan is never
    exact, so neither is the default one: the robot's map (cells of
    ``map_resolution``) marks each hit's cell, and a hit that noise puts short of
    the surface marks the free cell before it, which narrows BARN's gaps as a
    real sensor would. ``latency`` control
    cycles pass between a scan and its command reaching the wheels.
    """

    v_max: float = 1.0  # m/s
    dt: float = 0.1  # s, control period and rollout step
    sim_time: float = 1.0  # s, rollout horizon
    lidar_beams: int = 541
    lidar_range: float = 10.0  # m
    noise_std: float = 0.03  # m, Gaussian range noise
    dropout: float = 0.01  # probability a beam returns nothing
    latency: int = 0  # control cycles from a scan to its command reaching the wheels
    body: str = DEFAULT_BODY  # a profile of fgdwa.sim.body.BODY_PROFILES
    # How the rollouts take a command (PlannerParams.wheels): "ramp", from the measured twist at the
    # Jackal's accelerations and through the body's lag (planner/response_time), as the wheels do
    wheels: str = "ramp"
    # m: the planner's footprint (BARN's box) grows by this on every side; 0.05 covers the Jackal's body
    footprint_padding: float = 0.05
    # m, the cells of the map the robot builds from its scans (the ROS node's BARN config too), not the world's
    # 15 cm, whose cells widen every obstacle a noisy hit lands beside by a whole cell and close BARN's gaps
    map_resolution: float = 0.1
    replan_period: float = 0.5  # s between replans of a blocked path at most
    stall_time: float = 3.0  # s without 0.1 m of progress before a recovery
    # The challenge's time limit ends a run: the navigator keeps recovering until then.
    max_recoveries: int = 1000
    # Parameters changed by name (fgdwa.settings: ("navigator/tracker/hypothesis_time", 0.5), ...), after the above
    settings: Settings = ()

    def __post_init__(self):
        for name in ("v_max", "dt", "sim_time", "lidar_range", "replan_period", "stall_time"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise FgdwaError(f"BarnSetup.{name} = {short_repr(value)}: must be a finite number > 0")
        check_sensing("BarnSetup", self.noise_std, self.dropout, self.latency)
        body_profile(self.body)
        try:
            params_with(PlannerParams(), wheels=self.wheels)  # the schema's choices, not a copy of them
        except FgdwaError as error:
            raise FgdwaError(f"BarnSetup.wheels: {error}") from None
        padding = self.footprint_padding
        if not (isinstance(padding, (int, float)) and not isinstance(padding, bool) and 0 <= padding <= 1):
            raise FgdwaError(f"BarnSetup.footprint_padding = {short_repr(padding)}: must be a number in [0, 1] (m)")
        check_map_resolution(self.map_resolution, "BarnSetup.map_resolution")
        for name in ("lidar_beams", "max_recoveries"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
                raise FgdwaError(f"BarnSetup.{name} = {short_repr(value)}: must be an integer >= 1")
        try:
            self.navigator()
            self.planner_params("fgdwa", 0.5)
        except FgdwaError as error:
            raise FgdwaError(f"BarnSetup.settings: {error}") from None

    def limits(self) -> RobotLimits:
        jackal = robot_preset("jackal").limits
        if self.v_max > jackal.v_max:
            raise FgdwaError(f"BarnSetup.v_max = {self.v_max}: above the Jackal's {jackal.v_max} m/s")
        return RobotLimits(v_min=jackal.v_min, v_max=self.v_max, omega_max=jackal.omega_max, acc_v=jackal.acc_v,
                           acc_omega=jackal.acc_omega)

    def navigator(self, mapping: str = "scan") -> NavigatorParams:
        params = params_with(simulated_navigator(mapping), footprint_padding=self.footprint_padding,
                             replan_period=self.replan_period, stall_time=self.stall_time,
                             max_recoveries=self.max_recoveries)
        return params_with(params, **group_settings(self.settings, "navigator"))

    def planner_params(self, planner: str, goal_radius: float) -> PlannerParams:
        """The preset's parameters as the setup runs them."""
        # The planner knows its robot's response, as a user who identified it does.
        setup = dict(dt=self.dt, sim_time=self.sim_time, goal_tolerance=goal_radius, wheels=self.wheels,
                     response_time=body_profile(self.body).actuation_lag)
        return params_with(planner_preset(planner).params, **{**setup, **group_settings(self.settings, "planner")})

    def lidar(self) -> LidarParams:
        return LidarParams(fov=270.0 * math.pi / 180.0, beams=self.lidar_beams, max_range=self.lidar_range,
                           noise_std=self.noise_std, dropout=self.dropout)


@dataclass(frozen=True)
class BarnTask:
    """One run, self-contained (the world's arrays travel with it) so a worker
    process or a dask worker needs nothing else."""

    world_id: int
    cells: np.ndarray  # (rows, cols) uint8
    resolution: float
    origin: tuple
    start: tuple
    goal: tuple
    goal_radius: float
    time_limit: float
    optimal_time: float
    planner: str
    mapping: str
    trial: int
    seed: int
    setup: BarnSetup = field(default_factory=BarnSetup)
    record: str = ""  # a path: keep every cycle and write the run there as a Rerun recording


def barn_tasks(dataset: BarnDataset, world_ids: Sequence[int], planners: Sequence[str], mapping: str,
               trials: int = 1, base_seed: int = 0, setup: Optional[BarnSetup] = None) -> list:
    """One task per world, planner and trial (world-major, so a progress bar
    sweeps the worlds); trial i of every run uses seed ``base_seed + i``."""
    check_mapping(mapping)
    planners = check_planners(planners)
    if isinstance(trials, bool) or not isinstance(trials, (int, np.integer)) or trials < 1:
        raise FgdwaError(f"trials = {short_repr(trials)}: must be an integer >= 1")
    setup = setup if setup is not None else BarnSetup()
    tasks = []
    for wid in world_ids:
        w = dataset.world(wid)
        for planner in planners:
            for trial in range(int(trials)):
                tasks.append(BarnTask(
                    world_id=w.world_id, cells=np.asarray(w.grid.cells), resolution=w.grid.resolution,
                    origin=tuple(w.grid.origin), start=tuple(w.start), goal=tuple(w.goal),
                    goal_radius=w.goal_radius, time_limit=w.time_limit, optimal_time=w.optimal_time,
                    planner=planner, mapping=mapping, trial=trial, seed=int(base_seed) + trial, setup=setup))
    return tasks


def check_planners(planners: Sequence[str]) -> list:
    """The planner names, checked against the presets, without repeats."""
    return planner_list(planners, preset_names())


def run_jackal(world: World, start, goal, goal_radius: float, time_limit: float, planner: str, mapping: str,
               seed: int, setup: BarnSetup, record: str = "", title: str = "") -> tuple:
    """One episode of the BARN Challenge's Jackal in ``world``: the setup's
    limits, lidar, body and navigator, the preset's critics, the time limit as
    steps. With ``record``, every cycle is kept and the run written there as a
    Rerun recording (``title``). Returns (result, outcome, wall time in s):
    the challenge knows three outcomes, so running out of steps is a timeout."""
    preset = planner_preset(planner)
    params = setup.planner_params(planner, goal_radius)
    robot = robot_preset("jackal")
    navigator = setup.navigator(mapping)
    if record:
        navigator.record_top_k = RECORDED_ROLLOUTS
    tic = time.perf_counter()
    result = run_episode(world, start, goal, limits=setup.limits(), footprint=robot.footprint,
                         outline=robot.outline, body=setup.body, params=params,
                         max_steps=int(math.floor(time_limit / setup.dt + 1e-9)), goal_tolerance=goal_radius,
                         lidar=setup.lidar(), weight_policy=preset.weight_policy(), seed=seed, mapping=mapping,
                         navigator=navigator, latency=setup.latency, record_cycles=bool(record),
                         map_resolution=setup.map_resolution if mapping == "scan" else None)
    wall = time.perf_counter() - tic
    if record:
        from fgdwa.plot.recording import write_recording

        write_recording(result, world, goal, robot.footprint, record, title=title)
    outcome = result.summary.outcome if result.summary.outcome in OUTCOMES else "timeout"
    return result, outcome, wall


def run_barn_task(task: BarnTask) -> Run:
    """Run one task (in whatever process calls it)."""
    world = World(grid=OccupancyGrid(task.cells, task.resolution, task.origin))
    result, outcome, wall = run_jackal(world, task.start, task.goal, task.goal_radius, task.time_limit, task.planner,
                                       task.mapping, task.seed, task.setup, task.record, barn_run_name(task))
    success = outcome == "success"
    row = {
        "world": task.world_id, "planner": task.planner, "mapping": task.mapping, "trial": task.trial,
        "seed": task.seed, "outcome": outcome, "success": int(success),
        "score": barn_score(success, result.summary.sim_time, task.optimal_time), "optimal_time": task.optimal_time,
        **episode_columns(result, wall),
    }
    return Run(row=row, cells=task.cells, extent=tuple(world.grid.extent), poses=result.motion.poses,
               paths=paths_followed(result), scan_map=result.context.scan_map, scan_extent=result.context.scan_extent)


# What names a failed run in the terminal and in summary.json.
FAILURE_KEYS = ("world", "planner", "trial")


def barn_run_name(task: BarnTask) -> str:
    """A run's name in file names: world, planner, mapping, trial."""
    return f"barn_{task.world_id}_{task.planner}_{task.mapping}_trial{task.trial}"


def run_barn(dataset: BarnDataset, worlds="all", planners: Sequence[str] = BARN_PLANNERS, mapping: str = "known",
             trials: int = 1, base_seed: int = 0, setup: Optional[BarnSetup] = None, executor: str = "local",
             scheduler: Optional[str] = None, workers: int = DEFAULT_WORKERS, progress: bool = True) -> list:
    """Every run of the selection, in task order (see :func:`barn_tasks` and
    :func:`fgdwa.bench.runner.run_tasks` for the executors)."""
    tasks = barn_tasks(dataset, dataset.select_ids(worlds), planners, mapping, trials, base_seed, setup)
    return run_tasks(tasks, run_barn_task, executor=executor, scheduler=scheduler, workers=workers,
                     progress=progress)


def format_summary(summary: dict, mapping: str) -> str:
    """The BARN terminal table."""
    return format_table(summary, f"BARN, map {mapping}")


def write_barn_outputs(runs: Sequence[Run], out_dir, mapping: str, meta: Optional[dict] = None,
                       figure: bool = True) -> dict:
    """Write runs.csv, summary.json and (``figure``) failures.png into ``out_dir``;
    return the summary."""
    return write_run_outputs(runs, out_dir, RUN_FIELDS, {"mapping": mapping, **(meta or {})}, figure)


def add_jackal_arguments(parser, setup: BarnSetup) -> None:
    """The options of the Jackal's footprint and map that `fgdwa barn` and `fgdwa dynabarn` share."""
    parser.add_argument("--footprint-padding", type=float, default=setup.footprint_padding, metavar="M",
                        help="grow the planner's footprint (BARN's 0.42 m x 0.33 m box) by this on every side; the "
                             "referee judges the Jackal's body, 0.508 m x 0.430 m "
                             f"(default {setup.footprint_padding:g})")
    parser.add_argument("--map-resolution", type=float, default=setup.map_resolution, metavar="M",
                        help="cells of the map the robot builds with --map scan, whatever the world's cells "
                             f"(default {setup.map_resolution:g})")


def barn_command(args) -> int:
    """``fgdwa barn``: run, print the table, write the outputs."""
    check_executor_arguments(args)
    check_recording_possible(args.record_failures)
    dataset = load_barn(find_barn_file(args.data))
    world_ids = dataset.select_ids(args.worlds)
    planners = check_planners(args.planners)
    setup = BarnSetup(noise_std=args.noise, dropout=args.dropout, latency=args.latency, body=args.body,
                      footprint_padding=args.footprint_padding, map_resolution=args.map_resolution,
                      settings=benchmark_settings(args.settings))
    tasks = barn_tasks(dataset, world_ids, planners, args.mapping, args.trials, args.seed, setup)
    runs, wall, recordings = run_benchmark(tasks, run_barn_task, args, barn_run_name)
    failed = failure_entries(runs, FAILURE_KEYS, recordings)
    meta = {"data": str(dataset.source), "worlds": world_ids, "trials": args.trials, "seed": args.seed,
            "setup": dataclasses.asdict(setup), "wall_time": wall, "failed": failed}
    summary = write_barn_outputs(runs, args.out, args.mapping, meta, figure=not args.no_figures)
    print(format_summary(summary, args.mapping))
    print_failures(failed, FAILURE_KEYS)
    print(written_files(runs, wall, args.out, figure=not args.no_figures))
    return 0


def barn_import_command(world_dir: str, out: str, worlds: Optional[str] = None) -> int:
    """``fgdwa barn import WORLD_DIR --out FILE [--worlds IDS]``: convert the
    challenge's world and path files to a barn.npz-format file. Returns the exit
    status; errors are raised as FgdwaError (the CLI prints them)."""
    convert_barn_worlds(world_dir, out, worlds)
    dataset = load_barn(out)  # what was written must load
    print(f"wrote {out}: {len(dataset)} BARN worlds ({describe_world_ids(dataset.world_ids)}) from {world_dir}")
    return 0


def register_barn_commands(subparsers) -> None:
    """Add ``barn`` (run the benchmark) and ``barn import`` to an argparse
    sub-parser set (``parser.add_subparsers()``); the handlers are stored as
    ``func(args, argv) -> int``, as fgdwa.cli expects."""
    barn = subparsers.add_parser(
        "barn", help="run planners on BARN worlds (or: barn import)",
        description="Run planners on BARN worlds and score them as the BARN challenge does; "
                    "`fgdwa barn import` makes the data file.")
    barn.add_argument("--data", default=None, metavar="FILE",
                      help="the barn.npz file (or its directory); default: $FGDWA_BARN_DATA")
    barn.add_argument("--worlds", default="all", metavar="IDS",
                      help="world ids: 'all' (default), '0,6,12', '0-49', '0-299:6'")
    barn.add_argument("--planners", default="fgdwa,dwb", metavar="LIST",
                      help="comma-separated planner presets (default fgdwa,dwb; the comparison set is "
                           "dwa,gdwa,sgdwa,fgdwa,dwb)")
    barn.add_argument("--map", dest="mapping", choices=list(MAPPING_MODES), default="known",
                      help="known: the planners get the whole grid; scan: the robot maps what its lidar hits "
                           "and replans on that (default known)")
    barn.add_argument("--trials", type=int, default=1, help="runs per world and planner (default 1)")
    barn.add_argument("--seed", type=int, default=0, help="base seed: trial i uses seed + i (lidar noise)")
    add_sensing_arguments(barn, BarnSetup())
    add_executor_arguments(barn)
    add_output_arguments(barn, "out/barn", "runs.csv, summary.json, failures.png")
    add_record_failures_argument(barn)
    add_jackal_arguments(barn, BarnSetup())
    add_settings_argument(barn)
    barn.set_defaults(func=lambda args, *_: barn_command(args))
    barn_sub = barn.add_subparsers(dest="barn_command", required=False, metavar="{import}")
    imp = barn_sub.add_parser(
        "import", help="convert the BARN challenge's world_<i>.world and path_<i>.npy files to a barn.npz file")
    imp.add_argument("world_dir", metavar="WORLD_DIR",
                     help="directory with world_<i>.world, and path_<i>.npy beside them or in path_files/ "
                          "(the challenge's jackal_helper/worlds/BARN)")
    imp.add_argument("--out", required=True, metavar="FILE", help="the barn.npz file to write")
    imp.add_argument("--worlds", default=None, metavar="IDS",
                     help="world ids to convert: 'all' (default), '0,6,12', '0-49' or '0-299:6'")
    imp.set_defaults(func=lambda args, *_: barn_import_command(args.world_dir, args.out, args.worlds))
