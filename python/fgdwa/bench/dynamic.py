"""The dynamic benchmark ``fgdwa dynamic``: planners on DynaBARN-style fields
of moving discs (:mod:`fgdwa.io.dynamic_fields`), scored by outcome and time.

One run is one field (level, seed) and one planner label. Each run loads the
field's scenario document exactly as ``fgdwa run FILE`` loads the file, and
runs it with ``run_scenario(scenario, preset, seed)``: the seed that made the
field also draws the start's jitter, the discs' phases and the lidar's noise,
so ``fgdwa run FIELD.yaml --planner PRESET --seed SEED`` replays a run. The
outputs are those of ``fgdwa barn`` (:func:`fgdwa.bench.runs.write_run_outputs`):
runs.csv, summary.json, failures.png, plus the scenario file of every field a
run failed on (``fields/``).
"""

from __future__ import annotations

import dataclasses
import time
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import FgdwaError, NavigatorParams, PlannerParams
from fgdwa.bench.options import (add_executor_arguments, add_output_arguments, add_sensing_arguments,
                                 add_settings_argument,
                                 check_executor_arguments, check_sensing, planner_list)
from fgdwa.bench.recordings import (RECORDED_ROLLOUTS, add_record_failures_argument, check_recording_possible,
                                    print_failures, run_benchmark)
from fgdwa.bench.runner import DEFAULT_WORKERS, run_tasks
from fgdwa.bench.runs import Run, episode_columns, format_table, paths_followed, write_run_outputs, written_files
from fgdwa.io.barn_data import parse_world_selection
from fgdwa.io.dynamic_fields import (DROPOUT, LEVELS, NOISE_STD, check_field_seed, check_level, closed_route,
                                     field_name, generate_field, write_field)
from fgdwa.io.scenario_file import scenario_from_dict
from fgdwa.sim.body import DEFAULT_BODY, body_profile
from fgdwa.settings import Settings, benchmark_settings, describe_settings, group_settings
from fgdwa.sim.episode import simulated_navigator
from fgdwa.sim.scenario import params_with, run_scenario, trial_variation

# A planner label -> (planner preset, NavigatorParams overrides). A variant of a
# preset is one more row, e.g. "fgdwa-slow-replan": ("fgdwa", {"replan_period": 2.0}).
PLANNER_VARIANTS = MappingProxyType({
    "dwa": ("dwa", {}),
    "gdwa": ("gdwa", {}),
    "sgdwa": ("sgdwa", {}),
    "fgdwa": ("fgdwa", {}),
    # The ablation: every hit a static obstacle where it is now, nothing tracked or predicted.
    "fgdwa-notrack": ("fgdwa", {"track_moving": False}),
    # Movers tracked and predicted by the local planner, but the global path runs through them.
    "fgdwa-noroute": ("fgdwa", {"route_around_movers": False}),
    "dwb": ("dwb", {}),
})
OUTCOMES = ("success", "collision", "timeout", "failed")
RUN_FIELDS = ("level", "seed", "planner", "outcome", "success", "time", "mileage", "min_clearance", "replans",
              "backing_up", "cycle_ms_mean", "cycle_ms_p95", "sim_ms_mean", "wall_time", "jumped", "reason")


@dataclass(frozen=True)
class DynamicSetup:
    """What every run shares beyond its field: the lidar's range noise (m) and
    dropped-beam rate (written into each field's variability) and the command
    latency (control cycles)."""

    noise_std: float = NOISE_STD
    dropout: float = DROPOUT
    latency: int = 0
    body: str = DEFAULT_BODY  # a profile of fgdwa.sim.body.BODY_PROFILES
    # Parameters changed by name (fgdwa.settings: ("navigator/tracker/hypothesis_time", 0.5), ...)
    settings: Settings = ()

    def __post_init__(self):
        check_sensing("DynamicSetup", self.noise_std, self.dropout, self.latency)
        body_profile(self.body)
        try:
            params_with(NavigatorParams(), **group_settings(self.settings, "navigator"))
            params_with(PlannerParams(), **group_settings(self.settings, "planner"))
        except FgdwaError as error:
            raise FgdwaError(f"DynamicSetup.settings: {error}") from None


@dataclass(frozen=True)
class DynamicTask:
    """One run, self-contained: the worker regenerates the field from (level, seed)."""

    level: str
    seed: int
    planner: str  # a PLANNER_VARIANTS label
    setup: DynamicSetup = field(default_factory=DynamicSetup)
    record: str = ""  # a path: keep every cycle and write the run there as a Rerun recording


def check_variants(planners) -> list:
    """The planner labels (a list or comma-separated text), checked against PLANNER_VARIANTS, without repeats."""
    return planner_list(planners, PLANNER_VARIANTS)


def parse_seeds(text) -> list:
    """Seeds from '0-49', '3,7,9' or '0-99:10' (the syntax of BARN's world selections)."""
    if isinstance(text, (int, np.integer)) and not isinstance(text, bool):
        return [check_field_seed(text)]
    return parse_world_selection(text, what="seeds", noun="seed")


def describe_seeds(seeds: Sequence[int]) -> str:
    seeds = sorted(seeds)
    if len(seeds) <= 8:
        return "seeds " + ", ".join(str(s) for s in seeds)
    return f"{len(seeds)} seeds, {seeds[0]}..{seeds[-1]}"


def dynamic_tasks(level: str, seeds: Sequence[int], planners: Sequence[str],
                  setup: Optional[DynamicSetup] = None) -> list:
    """One task per seed and planner (seed-major)."""
    level = check_level(level)
    planners = check_variants(planners)
    setup = setup if setup is not None else DynamicSetup()
    return [DynamicTask(level, check_field_seed(seed), planner, setup) for seed in seeds for planner in planners]


def field_document(task: DynamicTask) -> dict:
    return generate_field(task.level, task.seed, task.setup.noise_std, task.setup.dropout)


def _episode(task: DynamicTask):
    """The task's scenario and its episode (every cycle kept, with the fan a recording shows, when ``task.record``)."""
    scenario = scenario_from_dict(field_document(task), where=field_name(task.level, task.seed))
    preset, overrides = PLANNER_VARIANTS[task.planner]
    # The variant's overrides, then the named settings over them.
    navigator = params_with(simulated_navigator(), **{**overrides, **group_settings(task.setup.settings, "navigator")})
    planner = group_settings(task.setup.settings, "planner")
    if planner:
        scenario = dataclasses.replace(scenario, overrides={**scenario.overrides, **planner})
    if task.record:
        navigator.record_top_k = RECORDED_ROLLOUTS
    return scenario, run_scenario(scenario, preset, task.seed, navigator=navigator, latency=task.setup.latency,
                                  body=task.setup.body, record_cycles=bool(task.record))


def dynamic_run_name(task: DynamicTask) -> str:
    """A run's name in file names: level, seed, planner."""
    return f"{field_name(task.level, task.seed)}_{task.planner}"


def run_dynamic_task(task: DynamicTask) -> Run:
    """Run one task (in whatever process calls it)."""
    tic = time.perf_counter()
    scenario, result = _episode(task)
    wall = time.perf_counter() - tic
    outcome = result.summary.outcome
    row = {"level": task.level, "seed": task.seed, "planner": task.planner, "outcome": outcome,
           "success": int(outcome == "success"), **episode_columns(result, wall)}
    _, world, _ = trial_variation(scenario, task.seed)
    if task.record:
        from fgdwa.plot.recording import write_recording

        write_recording(result, world, scenario.goal, scenario.footprint, task.record, title=dynamic_run_name(task))
    grid = world.grid
    cells = (np.asarray(grid.cells) != 0).astype(np.uint8)
    if world.hidden is not None:
        cells[(cells == 0) & (np.asarray(world.hidden.cells) != 0)] = 2
    return Run(row=row, cells=cells, extent=tuple(grid.extent), poses=result.motion.poses,
               paths=paths_followed(result), label=f"{task.level} seed {task.seed}",
               routes=[closed_route(m.waypoints, m.mode) for m in world.movers],
               discs=[(d.center[0], d.center[1], d.radius) for d in world.discs_at(result.summary.sim_time)])


def run_dynamic(level: str, seeds: Sequence[int], planners: Sequence[str], setup: Optional[DynamicSetup] = None,
                executor: str = "local", scheduler: Optional[str] = None, workers: int = DEFAULT_WORKERS,
                progress: bool = True) -> list:
    """Every run, in task order (:func:`fgdwa.bench.runner.run_tasks` runs them)."""
    tasks = dynamic_tasks(level, seeds, planners, setup)
    return run_tasks(tasks, run_dynamic_task, executor=executor, scheduler=scheduler, workers=workers,
                     progress=progress)


def replay_command(path, planner: str, seed: int, latency: int, body: str = DEFAULT_BODY,
                   settings: Settings = ()) -> str:
    """The ``fgdwa run`` command that replays a run of the field in ``path`` (parameters
    that differ from its defaults named in a comment)."""
    preset, overrides = PLANNER_VARIANTS[planner]
    command = f"fgdwa run {path} --planner {preset} --seed {seed}"
    if latency:
        command += f" --latency {latency}"
    if body != DEFAULT_BODY:
        command += f" --body {body}"
    changed = [f"NavigatorParams({', '.join(f'{k}={v!r}' for k, v in overrides.items())})"] if overrides else []
    if settings:
        changed.append(describe_settings(settings).strip())
    if changed:
        command += "  # with " + " and ".join(changed)
    return command


def write_failed_fields(runs: Sequence[Run], out_dir, setup: DynamicSetup) -> list:
    """Write the scenario file of every field a run failed on into ``out_dir``/fields;
    return one entry per failed run: planner, seed, outcome, reason, file, replay command.
    Field files of the same levels that an earlier run left and no run failed on
    this time are removed, so that ``fields/`` holds this run's failures only."""
    failed = []
    written = set()
    levels = {run.row["level"] for run in runs}
    for stale in (Path(out_dir) / "fields").glob("*.yaml"):
        seed = stale.stem.rsplit("_", 1)[-1]
        if seed.isdigit() and any(stale.stem == field_name(level, int(seed)) for level in levels):
            stale.unlink()
    for run in runs:
        row = run.row
        if row["outcome"] == "success":
            continue
        task = DynamicTask(row["level"], row["seed"], row["planner"], setup)
        path = Path(out_dir) / "fields" / f"{field_name(task.level, task.seed)}.yaml"
        if path not in written:
            write_field(field_document(task), path, command=f"fgdwa dynamic generate --level {task.level} "
                        f"--seed {task.seed} --noise {setup.noise_std:g} --dropout {setup.dropout:g}")
            written.add(path)
        failed.append({"planner": row["planner"], "seed": row["seed"], "outcome": row["outcome"],
                       "reason": row["reason"], "file": str(path),
                       "replay": replay_command(path, row["planner"], row["seed"], setup.latency, setup.body,
                                                setup.settings)})
    return failed


def dynamic_command(args) -> int:
    """``fgdwa dynamic``: run, print the table, write the outputs."""
    check_executor_arguments(args)
    check_recording_possible(args.record_failures)
    level = check_level(args.level)
    seeds = parse_seeds(args.seeds)
    planners = check_variants(args.planners)
    setup = DynamicSetup(noise_std=args.noise, dropout=args.dropout, latency=args.latency, body=args.body,
                         settings=benchmark_settings(args.settings))
    tasks = dynamic_tasks(level, seeds, planners, setup)
    runs, wall, recordings = run_benchmark(tasks, run_dynamic_task, args, dynamic_run_name)
    failed = write_failed_fields(runs, args.out, setup)
    if recordings is not None:
        for entry, path in zip(failed, [p for p in recordings if p is not None]):
            entry["recording"] = str(path)
    head = {"level": level, "seeds": seeds, "setup": dataclasses.asdict(setup), "wall_time": wall,
            "failed": failed}
    summary = write_run_outputs(runs, args.out, RUN_FIELDS, head, figure=not args.no_figures, outcomes=OUTCOMES)
    print(format_table(summary, f"dynamic fields, level {level}, {describe_seeds(seeds)}", OUTCOMES))
    print_failures(failed, ("seed", "planner"))
    print(written_files(runs, wall, args.out, figure=not args.no_figures)
          + (f", {len({f['file'] for f in failed})} field file(s) of failed runs in {Path(args.out) / 'fields'}"
             if failed else ""))
    return 0


def generate_command(args) -> int:
    """``fgdwa dynamic generate``: write one field's scenario file."""
    document = generate_field(check_level(args.level), check_field_seed(args.seed), args.noise, args.dropout)
    path = write_field(document, args.out, command=f"fgdwa dynamic generate --level {args.level} --seed {args.seed} "
                       f"--noise {args.noise:g} --dropout {args.dropout:g}")
    print(f"wrote {path}: {document['description']}")
    print(f"run it: fgdwa run {path} --seed {args.seed} --gif out/run/{document['name']}.gif")
    return 0


def register_dynamic_commands(subparsers) -> None:
    """Add ``dynamic`` (run the benchmark) and ``dynamic generate`` to an argparse
    sub-parser set; the handlers are stored as ``func(args, argv) -> int``."""
    dynamic = subparsers.add_parser(
        "dynamic", help="run planners on DynaBARN-style fields of moving discs (or: dynamic generate)",
        description="Run planners on fields of discs moving across the robot's way, unknown to the planner "
                    "(seen only by the lidar), with boxes missing from the map; `fgdwa dynamic generate` writes "
                    "one field as a scenario file.")
    dynamic.add_argument("--level", choices=list(LEVELS), default="medium",
                         help="easy: 2 discs at 0.2-0.4 m/s; medium: 4 at 0.3-0.6 m/s; hard: 6 at 0.4-0.8 m/s "
                              "(default medium)")
    dynamic.add_argument("--seeds", default="0-49", metavar="SEEDS",
                         help="field seeds: '0-49' (default), '3,7,9', '0-99:10'")
    dynamic.add_argument("--planners", default="fgdwa,dwb", metavar="LIST",
                         help=f"comma-separated planner labels (default fgdwa,dwb; known: "
                              f"{', '.join(PLANNER_VARIANTS)})")
    add_sensing_arguments(dynamic, DynamicSetup())
    add_settings_argument(dynamic)
    add_executor_arguments(dynamic)
    add_output_arguments(dynamic, "out/dynamic", "runs.csv, summary.json, failures.png and fields/")
    add_record_failures_argument(dynamic)
    dynamic.set_defaults(func=lambda args, *_: dynamic_command(args))
    sub = dynamic.add_subparsers(dest="dynamic_command", required=False, metavar="{generate}")
    gen = sub.add_parser("generate", help="write one field (level, seed) as a scenario file for `fgdwa run`")
    gen.add_argument("--level", choices=list(LEVELS), required=True)
    gen.add_argument("--seed", type=int, required=True, help="field seed (an integer >= 0)")
    gen.add_argument("--noise", type=float, default=NOISE_STD, metavar="STD",
                     help=f"lidar range noise std written into the field, m (default {NOISE_STD:g})")
    gen.add_argument("--dropout", type=float, default=DROPOUT, metavar="P",
                     help=f"probability a lidar beam returns nothing, written into the field (default {DROPOUT:g})")
    gen.add_argument("--out", required=True, metavar="FILE", help="the scenario YAML to write")
    gen.set_defaults(func=lambda args, *_: generate_command(args))
