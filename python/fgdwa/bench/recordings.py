"""Recordings of a benchmark's failed runs (``--record-failures DIR``): each
failed run's task is run again with its cycles kept and written as a Rerun
recording in the worker, through the same runner as the benchmark (so in
parallel, with a progress bar). A run depends on its task alone, so the second
time ends as the first did; that is checked, and a run that does not is an error.
"""

from __future__ import annotations

import dataclasses
import time
from pathlib import Path
from typing import Callable, Optional, Sequence

from fgdwa._core import FgdwaError, NavigatorParams
from fgdwa.bench.runner import run_tasks
from fgdwa.bench.runs import Run
from fgdwa.sim.episode import simulated_navigator

# The scored rollouts a recording keeps per cycle: recorded only, it changes no choice.
RECORDED_ROLLOUTS = 40


def recorded_navigator(mapping: str = "known") -> NavigatorParams:
    """The simulated robot's navigator (fgdwa.sim.episode.simulated_navigator)
    keeping RECORDED_ROLLOUTS scored rollouts a cycle, for a run replayed as a
    recording: the same run as without, with a wider fan to show."""
    navigator = simulated_navigator(mapping)
    navigator.record_top_k = RECORDED_ROLLOUTS
    return navigator


def record_failures(tasks: Sequence, outcomes: Sequence[str], runner: Callable, directory, name: Callable,
                    outcome_of: Callable = lambda run: run.row["outcome"], **executor) -> list:
    """For each task whose run failed (``outcomes[i]`` is not "success"),
    ``runner`` of the task with ``record`` set to ``directory/name(task).rrd``;
    returns each task's recording path (None for the runs that succeeded).
    ``outcome_of`` reads the outcome of what ``runner`` returns; ``executor``:
    run_tasks' executor options."""
    failed = [i for i, outcome in enumerate(outcomes) if outcome != "success"]
    again = [dataclasses.replace(tasks[i], record=str(Path(directory) / f"{name(tasks[i])}.rrd")) for i in failed]
    reruns = run_tasks(again, runner, label="recordings", **executor)
    paths: list = [None] * len(tasks)
    for i, task, rerun in zip(failed, again, reruns):
        if outcome_of(rerun) != outcomes[i]:
            raise FgdwaError(f"{name(task)}: ran again to be recorded it ended in {outcome_of(rerun)}, "
                             f"not {outcomes[i]}")
        paths[i] = Path(task.record)
    return paths


def run_outcomes(runs: Sequence[Run]) -> list:
    return [run.row["outcome"] for run in runs]


def run_benchmark(tasks: Sequence, runner: Callable, args, name: Callable) -> tuple:
    """A benchmark command's runs: ``tasks`` through ``runner`` with the
    command's executor options (``args``: --executor, --scheduler, --workers,
    --no-progress), then, with --record-failures, each failed one again as a
    recording named ``name(task)``. Returns (runs, wall time in s of the runs,
    each task's recording path or None; None without --record-failures)."""
    executor = dict(executor=args.executor, scheduler=args.scheduler, workers=args.workers,
                    progress=not args.no_progress)
    tic = time.perf_counter()
    runs = run_tasks(tasks, runner, **executor)
    wall = time.perf_counter() - tic
    recordings = None
    if args.record_failures:
        recordings = record_failures(tasks, run_outcomes(runs), runner, args.record_failures, name, **executor)
    return runs, wall, recordings


def failure_entries(runs: Sequence[Run], keys: Sequence[str], recordings: Optional[Sequence] = None) -> list:
    """One entry per failed run for summary.json: its ``keys`` columns, outcome,
    reason and (when recorded) its recording."""
    entries = []
    for i, run in enumerate(runs):
        if run.row["outcome"] == "success":
            continue
        entry = {key: run.row[key] for key in (*keys, "outcome", "reason")}
        if recordings is not None and recordings[i] is not None:
            entry["recording"] = str(recordings[i])
        entries.append(entry)
    return entries


def print_failures(entries: Sequence[dict], keys: Sequence[str], limit: int = 40) -> None:
    """A line per failed run: what it was, why it failed, and how to open its recording."""
    for entry in entries[:limit]:
        what = " ".join(f"{key} {entry[key]}" for key in keys)
        print(f"  {what}: {entry['reason']}" + (f" (fgdwa inspect {entry['recording']})" if "recording" in entry
                                                 else ""))
    if len(entries) > limit:
        print(f"  ... and {len(entries) - limit} more failed runs (summary.json, runs.csv)")


def check_recording_possible(directory) -> None:
    """Before a benchmark runs: FgdwaError when its failures could not be
    recorded (no rerun-sdk), rather than after the runs."""
    if directory:
        from fgdwa.plot.recording import require_rerun

        require_rerun()


def add_record_failures_argument(parser) -> None:
    parser.add_argument("--record-failures", default=None, metavar="DIR",
                        help="run each failed run again and write it as a Rerun recording into DIR "
                             "(needs rerun-sdk: pip install 'fgdwa[inspect]')")
