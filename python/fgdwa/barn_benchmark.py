"""The BARN benchmark: every planner on BARN worlds, scored as the challenge scores.

One run is one world, one planner, one trial, with the map known to the
planners (``mapping="known"``) or built by the robot from its lidar
(``"scan"``, the challenge's setting). All planners share the robot (the
``jackal`` preset, speed-capped by :class:`BarnSetup`), the sampler, the lidar
and the simulator. Outcomes follow the challenge (docs/barn.md): success is
ending within the goal radius without collision before the time limit; the
score is ``success * OT / clip(T, 2 OT, 8 OT)`` with T simulated time.

:func:`run_barn` returns one :class:`BarnRun` per run; :func:`summarize`
turns them into the per-planner table; :func:`write_barn_outputs` writes
runs.csv, summary.json and failures.png (docs/barn.md, "Running the benchmark").
"""

from __future__ import annotations

import csv
import dataclasses
import json
import math
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import (FgdwaError, LidarParams, NavigatorParams, OccupancyGrid, RobotLimits, planner_preset, preset_names,
                         robot_preset)
from fgdwa.datasets.barn import BarnDataset, barn_score
from fgdwa.experiments import run_tasks
from fgdwa.mapping import check_mapping
from fgdwa.report import json_safe
from fgdwa.scenario import params_with
from fgdwa.sim import run_episode
from fgdwa.world import World

BARN_PLANNERS = ("dwa", "gdwa", "sgdwa", "fgdwa", "dwb")
OUTCOMES = ("success", "collision", "timeout")
RUN_FIELDS = ("world", "planner", "mapping", "trial", "seed", "outcome", "success", "time", "score", "optimal_time",
              "mileage", "min_clearance", "replans", "backing_up", "cycle_ms_mean", "cycle_ms_p95", "sim_ms_mean", "wall_time")


def run_timing(wall: float, cycle_times) -> dict:
    """A run's cost per control cycle (ms): the Navigator's step (mean, 95th
    percentile) and the simulator's own share, everything else the run's wall
    time held (world, lidar, referee, set-up)."""
    cycle_times = np.asarray(cycle_times, dtype=float)
    if not len(cycle_times):
        return {"cycle_ms_mean": float("nan"), "cycle_ms_p95": float("nan"), "sim_ms_mean": float("nan")}
    return {"cycle_ms_mean": 1e3 * float(np.mean(cycle_times)),
            "cycle_ms_p95": 1e3 * float(np.percentile(cycle_times, 95)),
            "sim_ms_mean": 1e3 * max(0.0, wall - float(np.sum(cycle_times))) / len(cycle_times)}


def check_sensing(owner: str, noise_std, dropout, latency) -> None:
    """Checks a benchmark's lidar range noise (m), dropped-beam rate and command latency (cycles)."""
    def number(value) -> bool:
        return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool) \
            and math.isfinite(value)

    if not (number(noise_std) and noise_std >= 0):
        raise FgdwaError(f"{owner}.noise_std = {noise_std!r}: must be a finite number >= 0 (m)")
    if not (number(dropout) and 0 <= dropout < 1):
        raise FgdwaError(f"{owner}.dropout = {dropout!r}: must be in [0, 1) (a probability)")
    if isinstance(latency, bool) or not isinstance(latency, (int, np.integer)) or latency < 0:
        raise FgdwaError(f"{owner}.latency = {latency!r}: must be an integer >= 0 (control cycles)")


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
    exact, so neither is the default one: the robot's map marks each hit's cell,
    and a hit that noise puts short of the surface marks the free cell before
    it, which narrows BARN's gaps as a real sensor would. ``latency`` control
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
    replan_period: float = 0.5  # s between replans of a blocked path at most
    stall_time: float = 3.0  # s without 0.1 m of progress before a recovery
    # The challenge's time limit ends a run: the navigator keeps recovering until then.
    max_recoveries: int = 1000

    def __post_init__(self):
        for name in ("v_max", "dt", "sim_time", "lidar_range", "replan_period", "stall_time"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise FgdwaError(f"BarnSetup.{name} = {value!r}: must be a finite number > 0")
        check_sensing("BarnSetup", self.noise_std, self.dropout, self.latency)
        for name in ("lidar_beams", "max_recoveries"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 1:
                raise FgdwaError(f"BarnSetup.{name} = {value!r}: must be an integer >= 1")

    def limits(self) -> RobotLimits:
        jackal = robot_preset("jackal").limits
        if self.v_max > jackal.v_max:
            raise FgdwaError(f"BarnSetup.v_max = {self.v_max}: above the Jackal's {jackal.v_max} m/s")
        return RobotLimits(v_min=jackal.v_min, v_max=self.v_max, omega_max=jackal.omega_max, acc_v=jackal.acc_v,
                           acc_omega=jackal.acc_omega)

    def navigator(self) -> NavigatorParams:
        return NavigatorParams(replan_period=self.replan_period, stall_time=self.stall_time,
                               max_recoveries=self.max_recoveries)

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


@dataclass
class BarnRun:
    """One run's row of runs.csv, plus the trace failures.png draws (the
    dynamic benchmark's runs too: they add the movers' routes and discs)."""

    row: dict
    cells: np.ndarray  # (rows, cols) the world's grid (1: on the map, 2: missing from it)
    extent: tuple  # (x0, x1, y0, y1) m, the grid's
    poses: np.ndarray  # (steps + 1, 3)
    paths: list  # (cycle, (n, 2) points) per global path followed
    scan_map: Optional[np.ndarray] = None  # scan mode: the robot's map at the end
    label: str = ""  # names the world in the figure; default "world <id>"
    routes: list = field(default_factory=list)  # (k, 2) waypoints of each moving obstacle's route, closed
    discs: list = field(default_factory=list)  # (x, y, radius) of each moving obstacle when the run ended

    @property
    def outcome(self) -> str:
        return self.row["outcome"]

    @property
    def title(self) -> str:
        return self.label or f"world {self.row['world']}"


def barn_tasks(dataset: BarnDataset, world_ids: Sequence[int], planners: Sequence[str], mapping: str,
               trials: int = 1, base_seed: int = 0, setup: Optional[BarnSetup] = None) -> list:
    """One task per world, planner and trial (world-major, so a progress bar
    sweeps the worlds); trial i of every run uses seed ``base_seed + i``."""
    check_mapping(mapping)
    planners = check_planners(planners)
    if isinstance(trials, bool) or not isinstance(trials, (int, np.integer)) or trials < 1:
        raise FgdwaError(f"trials = {trials!r}: must be an integer >= 1")
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
    if isinstance(planners, str):
        planners = [p.strip() for p in planners.split(",") if p.strip()]
    planners = list(dict.fromkeys(planners))
    if not planners:
        raise FgdwaError("planners: name at least one (e.g. fgdwa,dwb)")
    known = preset_names()
    for name in planners:
        if name not in known:
            raise FgdwaError(f"planner {name!r} unknown (known: {', '.join(known)})")
    return planners


def run_barn_task(task: BarnTask) -> BarnRun:
    """Run one task (in whatever process calls it)."""
    setup = task.setup
    preset = planner_preset(task.planner)
    params = params_with(preset.params, dt=setup.dt, sim_time=setup.sim_time, goal_tolerance=task.goal_radius)
    robot = robot_preset("jackal")
    world = World(grid=OccupancyGrid(task.cells, task.resolution, task.origin))
    max_steps = int(math.floor(task.time_limit / setup.dt + 1e-9))
    tic = time.perf_counter()
    result = run_episode(world, task.start, task.goal, limits=setup.limits(), footprint=robot.footprint,
                         params=params, max_steps=max_steps, goal_tolerance=task.goal_radius, lidar=setup.lidar(),
                         weight_policy=preset.weight_policy(), seed=task.seed, mapping=task.mapping,
                         navigator=setup.navigator(), latency=setup.latency)
    wall = time.perf_counter() - tic
    # The challenge knows three outcomes; running out of steps is its timeout.
    outcome = result.outcome if result.outcome in OUTCOMES else "timeout"
    success = outcome == "success"
    paths = result.paths if result.paths else ([] if result.global_path is None else [(0, result.global_path)])
    row = {
        "world": task.world_id, "planner": task.planner, "mapping": task.mapping, "trial": task.trial,
        "seed": task.seed, "outcome": outcome, "success": int(success), "time": result.sim_time,
        "score": barn_score(success, result.sim_time, task.optimal_time), "optimal_time": task.optimal_time,
        "mileage": result.mileage, "min_clearance": result.min_clearance,
        "replans": max(0, len(result.paths) - 1), "backing_up": result.statuses.count("BackingUp"),
        **run_timing(wall, result.cycle_times), "wall_time": wall,
    }
    grid = world.grid
    return BarnRun(row=row, cells=task.cells, extent=tuple(grid.extent), poses=result.poses, paths=paths,
                   scan_map=result.scan_map)


def run_barn(dataset: BarnDataset, worlds="all", planners: Sequence[str] = BARN_PLANNERS, mapping: str = "known",
             trials: int = 1, base_seed: int = 0, setup: Optional[BarnSetup] = None, executor: str = "local",
             scheduler: Optional[str] = None, workers: int = 2, progress: bool = True) -> list:
    """Every run of the selection, in task order (see :func:`barn_tasks` and
    :func:`fgdwa.experiments.run_tasks` for the executors)."""
    tasks = barn_tasks(dataset, dataset.select_ids(worlds), planners, mapping, trials, base_seed, setup)
    return run_tasks(tasks, executor=executor, scheduler=scheduler, workers=workers, progress=progress,
                     runner=run_barn_task)


def summarize(runs: Sequence[BarnRun], outcomes: Sequence[str] = OUTCOMES) -> dict:
    """Per planner, in order of first appearance: n, the rate of each outcome,
    mean_time (s, successful runs; NaN when none), mean_score (all runs; when
    the rows have a score) and the mean planning cycle (ms)."""
    table = {}
    for planner in dict.fromkeys(run.row["planner"] for run in runs):
        rows = [run.row for run in runs if run.row["planner"] == planner]
        n = len(rows)
        times = [r["time"] for r in rows if r["success"]]
        entry = {
            "n": n,
            **{outcome: sum(r["outcome"] == outcome for r in rows) / n for outcome in outcomes},
            "mean_time": float(np.mean(times)) if times else float("nan"),
        }
        if all("score" in r for r in rows):
            entry["mean_score"] = float(np.mean([r["score"] for r in rows]))
        for key in ("cycle_ms_mean", "sim_ms_mean"):
            if all(key in r for r in rows):
                entry[key] = float(np.nanmean([r[key] for r in rows]))
        table[planner] = entry
    return table


def format_table(summary: dict, title: str, outcomes: Sequence[str] = OUTCOMES) -> str:
    """The terminal table of a :func:`summarize` summary: one line per planner."""
    scored = all("mean_score" in s for s in summary.values())
    header = f"{'planner':<14} {'n':>5}" + "".join(f" {o:>9}" for o in outcomes) + f" {'mean time':>10}"
    simulated = all("sim_ms_mean" in s for s in summary.values())
    header += f" {'mean score':>11}" * scored + f" {'cycle ms':>9}" + f" {'sim ms':>7}" * simulated
    lines = [title, header]
    for planner, s in summary.items():
        mean_time = "-" if math.isnan(s["mean_time"]) else f"{s['mean_time']:.1f} s"
        line = f"{planner:<14} {s['n']:>5}" + "".join(f" {s[o]:>9.3f}" for o in outcomes) + f" {mean_time:>10}"
        if scored:
            line += f" {s['mean_score']:>11.3f}"
        line += f" {s['cycle_ms_mean']:>9.2f}"
        if simulated:
            line += f" {s['sim_ms_mean']:>7.2f}"
        lines.append(line)
    return "\n".join(lines)


def format_summary(summary: dict, mapping: str) -> str:
    """The BARN terminal table."""
    return format_table(summary, f"BARN, map {mapping}")


def write_run_outputs(runs: Sequence[BarnRun], out_dir, fields: Sequence[str], head: dict, figure: bool = True,
                      outcomes: Sequence[str] = OUTCOMES) -> dict:
    """Write runs.csv (columns ``fields``), summary.json (``head`` then the
    per-planner summary) and (``figure``) failures.png into ``out_dir``;
    return the summary."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "runs.csv", "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(fields))
        writer.writeheader()
        for run in runs:
            writer.writerow({k: _csv_value(run.row[k]) for k in fields})
    summary = summarize(runs, outcomes)
    document = {**head, "planners": json_safe(summary)}
    (out / "summary.json").write_text(json.dumps(document, indent=2) + "\n")
    if figure:
        from fgdwa.barn_figures import plot_failures

        plot_failures(runs, out / "failures.png")
    return summary


def write_barn_outputs(runs: Sequence[BarnRun], out_dir, mapping: str, meta: Optional[dict] = None,
                       figure: bool = True) -> dict:
    """Write runs.csv, summary.json and (``figure``) failures.png into ``out_dir``;
    return the summary."""
    return write_run_outputs(runs, out_dir, RUN_FIELDS, {"mapping": mapping, **(meta or {})}, figure)


def _csv_value(value):
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.6g}"
    return value


def barn_command(args) -> int:
    """``fgdwa barn``: run, print the table, write the outputs."""
    from fgdwa.datasets.barn import find_barn_file, load_barn

    if args.scheduler is not None and args.executor != "dask":
        raise FgdwaError("--scheduler needs --executor dask")
    dataset = load_barn(find_barn_file(args.data))
    world_ids = dataset.select_ids(args.worlds)
    planners = check_planners(args.planners)
    setup = BarnSetup(noise_std=args.noise, dropout=args.dropout, latency=args.latency)
    tic = time.perf_counter()
    runs = run_barn(dataset, world_ids, planners, args.mapping, args.trials, args.seed, setup=setup,
                    executor=args.executor, scheduler=args.scheduler, workers=args.workers,
                    progress=not args.no_progress)
    wall = time.perf_counter() - tic
    meta = {"data": str(dataset.source), "worlds": world_ids, "trials": args.trials, "seed": args.seed,
            "setup": dataclasses.asdict(setup), "wall_time": wall}
    summary = write_barn_outputs(runs, args.out, args.mapping, meta, figure=not args.no_figures)
    print(format_summary(summary, args.mapping))
    print(f"{len(runs)} runs in {wall:.1f} s; wrote {Path(args.out) / 'runs.csv'}, summary.json"
          + ("" if args.no_figures else ", failures.png"))
    return 0
