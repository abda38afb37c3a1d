"""Benchmarks and experiments. One runner (``runner.run_tasks``: worker
processes, a dask.distributed cluster or this process, with a progress bar)
runs the tasks of all of them; the BARN benchmark (``barn``) and the dynamic
fields (``dynamic``) share the runs table (``runs``: one ``Run`` per episode,
runs.csv, summary.json, the terminal table) and the command-line options
(``options``); the paper's experiments E1-E3 (``experiments``) add their
statistics (``stats``) and reports (``report``).
"""

from fgdwa.bench.barn import BARN_PLANNERS, BarnSetup, BarnTask, run_barn, run_barn_task, write_barn_outputs
from fgdwa.bench.dynamic import PLANNER_VARIANTS, DynamicSetup, DynamicTask, run_dynamic, run_dynamic_task
from fgdwa.bench.experiments import (
    EXPERIMENTS,
    ExperimentResult,
    ExperimentSpec,
    TrialRecord,
    TrialTask,
    run_experiment,
    run_experiments,
    run_trial,
)
from fgdwa.bench.runner import DEFAULT_WORKERS, EXECUTORS, run_tasks
from fgdwa.bench.runs import Run, format_table, run_timing, summarize, write_run_outputs

__all__ = [
    "BARN_PLANNERS",
    "BarnSetup",
    "BarnTask",
    "DEFAULT_WORKERS",
    "DynamicSetup",
    "DynamicTask",
    "EXECUTORS",
    "EXPERIMENTS",
    "ExperimentResult",
    "ExperimentSpec",
    "PLANNER_VARIANTS",
    "Run",
    "TrialRecord",
    "TrialTask",
    "format_table",
    "run_barn",
    "run_barn_task",
    "run_dynamic",
    "run_dynamic_task",
    "run_experiment",
    "run_experiments",
    "run_tasks",
    "run_timing",
    "run_trial",
    "summarize",
    "write_barn_outputs",
    "write_run_outputs",
]
