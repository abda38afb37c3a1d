"""The DynaBARN benchmark ``fgdwa dynabarn``: planners among the challenge's
moving cylinders (:mod:`fgdwa.io.dynabarn_data`), scored as run.py scores and by time.

One run is one world, one planner, one trial. The robot is BARN's Jackal (the
``jackal`` preset's limits at its own top speed, 2 m/s, where BARN caps it at 1;
its footprint padded, its true outline as the referee's), with BARN's lidar and
the default body; the rollout horizon is the dynamic fields' (1.5 s: among
movers a longer one is mostly prediction). The walls are rasterised into
a grid of ``RESOLUTION`` reaching ``MAP_MARGIN`` beyond the walls, the start,
the goal and every mover's keyframes: the robot's map (``--map scan``, the
challenge's setting, builds it from the lidar; ``known`` hands the walls over).
The cylinders move as Gazebo animates them; the challenge's Gazebo clock runs
before run.py starts timing, so each trial draws the world's clock at the
start, one for all cylinders, uniformly over the longest animation, from its seed.

Two scores per run: ``score``, run.py's formula ``success * OT / clip(T, 2 OT,
8 OT)`` with its DynaBARN reference length ``goal_x - start_x`` (negative: every
success scores 0.125 whatever its time), and ``time_score``, the same formula
with the straight start-goal distance as reference length, which rewards speed.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import FgdwaError, OccupancyGrid, robot_preset
from fgdwa.bench.barn import BarnSetup, add_jackal_arguments, check_planners, run_jackal
from fgdwa.settings import benchmark_settings
from fgdwa.bench.options import (add_executor_arguments, add_output_arguments, add_sensing_arguments,
                                 add_settings_argument,
                                 check_executor_arguments)
from fgdwa.bench.recordings import (add_record_failures_argument, check_recording_possible, failure_entries,
                                    print_failures, run_benchmark)
from fgdwa.bench.runs import (Run, episode_columns, format_table, paths_followed, summarize, write_run_outputs,
                              written_files)
from fgdwa.io.barn_data import barn_score
from fgdwa.io.dynabarn_data import DynabarnDataset, DynabarnWorld, find_dynabarn_file, load_dynabarn
from fgdwa.io.dynamic_fields import ROLLOUT_TIME
from fgdwa.mapping import MAPPING_MODES, check_mapping
from fgdwa.sim.body import check_seed
from fgdwa.sim.world import World
from fgdwa.file_limits import short_repr

RESOLUTION = 0.1  # m per cell of the arena's grid
MAP_MARGIN = 5.0  # m of free grid beyond everything the world holds
# The Jackal at its own top speed: among cylinders at up to 1.9 m/s a robot held
# to BARN's 1 m/s cannot get out of the way (fgdwa, 20 worlds x 3 trials:
# hard 0.17 -> 0.61).
DYNABARN_SETUP = BarnSetup(sim_time=ROLLOUT_TIME, v_max=robot_preset("jackal").limits.v_max)
RUN_FIELDS = ("world", "barn_world_idx", "difficulty", "planner", "mapping", "trial", "seed", "clock", "outcome",
              "success", "time", "score", "time_score", "mileage", "min_clearance", "replans", "backing_up",
              "cycle_ms_mean", "cycle_ms_p95", "sim_ms_mean", "wall_time", "jumped", "reason")
FAILURE_KEYS = ("world", "planner", "trial")


def run_py_score(success: bool, time_s: float, path_length: float) -> float:
    """run.py's score, ``success * OT / clip(T, 2 OT, 8 OT)`` with ``OT = path_length / 2``,
    clipped as numpy clips (``min(max(T, 2 OT), 8 OT)``), a negative length included."""
    if not (isinstance(path_length, (int, float)) and math.isfinite(path_length)):
        raise FgdwaError(f"run_py_score: path_length = {short_repr(path_length)}: must be a finite number (m)")
    if not success:
        return 0.0
    if not (isinstance(time_s, (int, float)) and time_s >= 0 and math.isfinite(time_s)):
        raise FgdwaError(f"run_py_score: time = {short_repr(time_s)}: a successful run needs a finite time >= 0 (s)")
    if path_length == 0:
        return math.nan  # the formula is 0 / 0: run.py itself would fail on such a world
    optimal = path_length / 2.0
    return optimal / min(max(time_s, 2.0 * optimal), 8.0 * optimal)


def arena_grid(world: DynabarnWorld, resolution: float = RESOLUTION, margin: float = MAP_MARGIN) -> OccupancyGrid:
    """The walls as occupied cells (every cell a wall overlaps), on a grid reaching
    ``margin`` beyond the world's extent, its corner on a multiple of the resolution."""
    x0, x1, y0, y1 = world.extent
    ox = math.floor((x0 - margin) / resolution) * resolution
    oy = math.floor((y0 - margin) / resolution) * resolution
    cols = int(math.ceil((x1 + margin - ox) / resolution))
    rows = int(math.ceil((y1 + margin - oy) / resolution))
    cells = np.zeros((rows, cols), dtype=np.uint8)
    for wx0, wy0, wx1, wy1 in world.walls:
        c0, c1 = int(math.floor((wx0 - ox) / resolution + 1e-9)), int(math.ceil((wx1 - ox) / resolution - 1e-9))
        r0, r1 = int(math.floor((wy0 - oy) / resolution + 1e-9)), int(math.ceil((wy1 - oy) / resolution - 1e-9))
        cells[max(r0, 0):max(r1, 0), max(c0, 0):max(c1, 0)] = 1
    return OccupancyGrid(cells, resolution, (ox, oy))


def start_clock(world: DynabarnWorld, seed: int) -> float:
    """The world's animation clock (s) when the run starts, drawn from the trial's seed."""
    longest = max((m.period for m in world.movers), default=0.0)
    rng = np.random.default_rng([check_seed(seed), 0xD7BA])
    return float(rng.uniform(0.0, longest)) if longest > 0 else 0.0


@dataclass(frozen=True)
class DynabarnTask:
    """One run, self-contained (the world travels with it)."""

    world: DynabarnWorld
    planner: str
    mapping: str
    trial: int
    seed: int
    setup: BarnSetup = field(default_factory=lambda: DYNABARN_SETUP)
    record: str = ""  # a path: keep every cycle and write the run there as a Rerun recording


def dynabarn_tasks(dataset: DynabarnDataset, world_ids: Sequence[int], planners: Sequence[str], mapping: str,
                   trials: int = 1, base_seed: int = 0, setup: Optional[BarnSetup] = None) -> list:
    """One task per world, planner and trial (world-major); trial i uses seed ``base_seed + i``."""
    check_mapping(mapping)
    planners = check_planners(planners)
    if isinstance(trials, bool) or not isinstance(trials, (int, np.integer)) or trials < 1:
        raise FgdwaError(f"trials = {short_repr(trials)}: must be an integer >= 1")
    if isinstance(base_seed, bool) or not isinstance(base_seed, (int, np.integer)) or base_seed < 0:
        raise FgdwaError(f"seed = {short_repr(base_seed)}: must be an integer >= 0")
    setup = setup if setup is not None else DYNABARN_SETUP
    return [DynabarnTask(dataset.world(wid), planner, mapping, trial, int(base_seed) + trial, setup)
            for wid in world_ids for planner in planners for trial in range(int(trials))]


def dynabarn_run_name(task: DynabarnTask) -> str:
    return f"dynabarn_{task.world.world}_{task.planner}_{task.mapping}_trial{task.trial}"


def run_dynabarn_task(task: DynabarnTask) -> Run:
    """Run one task (in whatever process calls it)."""
    w = task.world
    clock = start_clock(w, task.seed)
    movers = tuple(dataclasses.replace(m, phase=m.phase + clock) for m in w.movers)
    grid = arena_grid(w)
    world = World(grid=grid, movers=movers, discs_known=False)
    result, outcome, wall = run_jackal(world, w.start, w.goal, w.success_radius, w.time_limit, task.planner,
                                       task.mapping, task.seed, task.setup, task.record, dynabarn_run_name(task))
    success = outcome == "success"
    t = result.summary.sim_time
    straight = math.hypot(w.goal[0] - w.start[0], w.goal[1] - w.start[1])
    row = {"world": w.world, "barn_world_idx": w.barn_world_idx, "difficulty": w.difficulty,
           "planner": task.planner, "mapping": task.mapping, "trial": task.trial, "seed": task.seed, "clock": clock,
           "outcome": outcome, "success": int(success),
           "score": run_py_score(success, t, w.goal[0] - w.start[0]),
           "time_score": barn_score(success, t, straight / 2.0) if straight > 0 else float(success),
           **episode_columns(result, wall)}
    return Run(row=row, cells=np.asarray(grid.cells).astype(np.uint8), extent=tuple(grid.extent),
               poses=result.motion.poses, paths=paths_followed(result),
               label=f"DynaBARN world {w.world} ({w.difficulty})", routes=[m.route for m in movers],
               discs=[(d.center[0], d.center[1], d.radius) for d in world.discs_at(t)],
               scan_map=result.context.scan_map, scan_extent=result.context.scan_extent)


def dynabarn_command(args) -> int:
    """``fgdwa dynabarn``: run, print the table per difficulty, write the outputs."""
    check_executor_arguments(args)
    check_recording_possible(args.record_failures)
    dataset = load_dynabarn(find_dynabarn_file(args.data))
    world_ids = dataset.select_ids(args.worlds)
    planners = check_planners(args.planners)
    setup = dataclasses.replace(DYNABARN_SETUP, noise_std=args.noise, dropout=args.dropout, latency=args.latency,
                                body=args.body, footprint_padding=args.footprint_padding,
                                map_resolution=args.map_resolution, settings=benchmark_settings(args.settings))
    tasks = dynabarn_tasks(dataset, world_ids, planners, args.mapping, args.trials, args.seed, setup)
    runs, wall, recordings = run_benchmark(tasks, run_dynabarn_task, args, dynabarn_run_name)
    failed = failure_entries(runs, FAILURE_KEYS, recordings)
    meta = {"data": dataset.source, "worlds": world_ids, "mapping": args.mapping, "trials": args.trials,
            "seed": args.seed, "setup": dataclasses.asdict(setup), "wall_time": wall, "failed": failed}
    summary = write_run_outputs(runs, args.out, RUN_FIELDS, meta, figure=not args.no_figures)
    print(format_table(summary, f"DynaBARN, map {args.mapping}, {len(world_ids)} worlds, all levels"))
    for level in ("easy", "medium", "hard"):
        subset = [run for run in runs if run.row["difficulty"] == level]
        if subset and len(subset) < len(runs):
            print(format_table(summarize(subset), f"  {level}: {len({r.row['world'] for r in subset})} worlds"))
    print_failures(failed, FAILURE_KEYS)
    print(written_files(runs, wall, args.out, figure=not args.no_figures))
    return 0


def register_dynabarn_commands(subparsers) -> None:
    """Add ``dynabarn`` to an argparse sub-parser set; the handler is stored as ``func(args, argv) -> int``."""
    p = subparsers.add_parser(
        "dynabarn", help="run planners on DynaBARN worlds (the BARN Challenge's moving cylinders)",
        description="Run planners on DynaBARN worlds from a data file in the format of dynabarn_dev.json, with "
                    "the cylinders moved as Gazebo animates them, and score each run with run.py's formula "
                    "(0.125 for every success on these worlds) and with a time-based score.")
    p.add_argument("--data", default=None, metavar="FILE",
                   help="the DynaBARN JSON data file; default: $FGDWA_DYNABARN_DATA")
    p.add_argument("--worlds", default="all", metavar="IDS", help="world ids: 'all' (default), '0,3,6', '0-59:3'")
    p.add_argument("--planners", default="fgdwa,dwb", metavar="LIST",
                   help="comma-separated planner presets (default fgdwa,dwb)")
    p.add_argument("--map", dest="mapping", choices=list(MAPPING_MODES), default="scan",
                   help="scan: the robot maps the walls from its lidar, as in the challenge (default); "
                        "known: the planners get the walls")
    p.add_argument("--trials", type=int, default=1, help="runs per world and planner (default 1)")
    p.add_argument("--seed", type=int, default=0,
                   help="base seed: trial i uses seed + i (the movers' clock at the start, lidar noise, body)")
    add_sensing_arguments(p, DYNABARN_SETUP)
    add_executor_arguments(p)
    add_output_arguments(p, "out/dynabarn", "runs.csv, summary.json, failures.png")
    add_record_failures_argument(p)
    add_jackal_arguments(p, DYNABARN_SETUP)
    add_settings_argument(p)
    p.set_defaults(func=lambda args, *_: dynabarn_command(args))
