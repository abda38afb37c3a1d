"""The command-line options the benchmark commands share (``fgdwa barn``,
``fgdwa dynamic``, ``fgdwa experiment``): where the runs go (executor,
scheduler, workers), the outputs, the sensing settings, parameters changed by
name, and the planner list."""

from __future__ import annotations

import argparse
import math
from typing import Sequence

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.bench.runner import DEFAULT_WORKERS, EXECUTORS
from fgdwa.file_limits import short_repr


def positive(text: str) -> int:
    """An argparse type: an integer >= 1."""
    value = int(text)
    if value < 1:
        raise argparse.ArgumentTypeError(f"{text}: must be an integer >= 1")
    return value


def add_executor_arguments(parser) -> None:
    """--executor, --scheduler and --workers, as fgdwa.bench.runner.run_tasks takes them."""
    parser.add_argument("--executor", choices=list(EXECUTORS), default="local",
                        help="local: a process pool on this machine (default); dask: a dask.distributed cluster; "
                             "serial: this process")
    parser.add_argument("--scheduler", default=None, metavar="ADDRESS",
                        help="dask scheduler address (default: a LocalCluster on this machine)")
    parser.add_argument("--workers", type=positive, default=DEFAULT_WORKERS,
                        help=f"worker processes (default {DEFAULT_WORKERS})")


def check_executor_arguments(args) -> None:
    """FgdwaError when --scheduler is given without --executor dask."""
    if args.scheduler is not None and args.executor != "dask":
        raise FgdwaError("--scheduler needs --executor dask")


def add_output_arguments(parser, default_out: str, files: str, figures: str = "failures.png") -> None:
    """--out (a directory for ``files``), --no-figures (skips ``figures``) and --no-progress."""
    parser.add_argument("--out", default=default_out, metavar="DIR",
                        help=f"directory for {files} (default {default_out})")
    parser.add_argument("--no-figures", action="store_true", help=f"skip {figures}")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")


def add_body_argument(parser, default: str = "default") -> None:
    """--body NAME: a profile of fgdwa.sim.body.BODY_PROFILES."""
    from fgdwa.sim.body import BODY_PROFILES

    parser.add_argument("--body", choices=list(BODY_PROFILES), default=default,
                        help="the robot's body: default (wheels that ramp at the acceleration limits, command noise, "
                             "odometry that drifts) or ideal (each command at once, the pose known); "
                             f"default {default}")


def add_sensing_arguments(parser, defaults) -> None:
    """--noise, --dropout, --latency (defaulting to ``defaults``' noise_std, dropout and latency) and --body."""
    parser.add_argument("--noise", type=float, default=defaults.noise_std, metavar="STD",
                        help=f"lidar range noise std, m (default {defaults.noise_std:g})")
    parser.add_argument("--dropout", type=float, default=defaults.dropout, metavar="P",
                        help=f"probability a lidar beam returns nothing (default {defaults.dropout:g})")
    parser.add_argument("--latency", type=int, default=defaults.latency, metavar="CYCLES",
                        help=f"control cycles from a scan to its command reaching the wheels "
                             f"(default {defaults.latency})")
    add_body_argument(parser, defaults.body)


def add_settings_argument(parser) -> None:
    """--set NAME=VALUE (repeatable): a planner or navigator parameter changed for every run (fgdwa.settings)."""
    parser.add_argument("--set", action="append", default=[], dest="settings", metavar="NAME=VALUE",
                        help="change a parameter for every run, by its name in docs/parameters.md, e.g. "
                             "planner/sim_time=1.5 or navigator/tracker/hypothesis_time=0.5 (repeatable)")


def check_sensing(owner: str, noise_std, dropout, latency) -> None:
    """Checks a benchmark's lidar range noise (m), dropped-beam rate and command latency (cycles)."""
    def number(value) -> bool:
        return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool) \
            and math.isfinite(value)

    if not (number(noise_std) and noise_std >= 0):
        raise FgdwaError(f"{owner}.noise_std = {short_repr(noise_std)}: must be a finite number >= 0 (m)")
    if not (number(dropout) and 0 <= dropout < 1):
        raise FgdwaError(f"{owner}.dropout = {short_repr(dropout)}: must be in [0, 1) (a probability)")
    if isinstance(latency, bool) or not isinstance(latency, (int, np.integer)) or latency < 0:
        raise FgdwaError(f"{owner}.latency = {short_repr(latency)}: must be an integer >= 0 (control cycles)")


def planner_list(planners, known: Sequence[str]) -> list:
    """Planner names (a list or comma-separated text), each one of ``known``, without repeats."""
    if isinstance(planners, str):
        planners = [p.strip() for p in planners.split(",") if p.strip()]
    planners = list(dict.fromkeys(planners))
    if not planners:
        raise FgdwaError("planners: name at least one (e.g. fgdwa,dwb)")
    for name in planners:
        if name not in known:
            raise FgdwaError(f"planner {short_repr(name)} unknown (known: {', '.join(known)})")
    return planners
