"""The ``fgdwa barn`` command line: run the benchmark, and ``barn import`` to
make its data file from the challenge's world files."""

from __future__ import annotations

from typing import Optional

from fgdwa.barn_benchmark import BarnSetup, barn_command
from fgdwa.datasets.barn import describe_world_ids, load_barn
from fgdwa.datasets.barn_convert import convert_barn_worlds
from fgdwa.experiments import EXECUTORS
from fgdwa.mapping import MAPPING_MODES


def barn_import_command(world_dir: str, out: str, worlds: Optional[str] = None) -> int:
    """``fgdwa barn import WORLD_DIR --out FILE [--worlds IDS]``: convert the
    challenge's world and path files to a barn.npz-format file. Returns the exit
    status; errors are raised as FgdwaError (the CLI prints them)."""
    convert_barn_worlds(world_dir, out, worlds)
    dataset = load_barn(out)  # what was written must load
    print(f"wrote {out}: {len(dataset)} BARN worlds ({describe_world_ids(dataset.world_ids)}) from {world_dir}")
    return 0


def add_sensing_arguments(parser, defaults) -> None:
    """--noise, --dropout and --latency, defaulting to ``defaults``' noise_std, dropout and latency."""
    parser.add_argument("--noise", type=float, default=defaults.noise_std, metavar="STD",
                        help=f"lidar range noise std, m (default {defaults.noise_std:g})")
    parser.add_argument("--dropout", type=float, default=defaults.dropout, metavar="P",
                        help=f"probability a lidar beam returns nothing (default {defaults.dropout:g})")
    parser.add_argument("--latency", type=int, default=defaults.latency, metavar="CYCLES",
                        help=f"control cycles from a scan to its command reaching the wheels "
                             f"(default {defaults.latency})")


def add_executor_arguments(parser) -> None:
    """--executor, --scheduler and --workers, as fgdwa.experiments.run_tasks takes them."""
    parser.add_argument("--executor", choices=list(EXECUTORS), default="local",
                        help="local: a process pool (default); dask: a dask.distributed cluster; serial: this process")
    parser.add_argument("--scheduler", default=None, metavar="ADDRESS",
                        help="dask scheduler address (default: a LocalCluster on this machine)")
    parser.add_argument("--workers", type=int, default=2, help="worker processes (default 2)")


def add_output_arguments(parser, default_out: str, files: str) -> None:
    """--out (a directory for ``files``), --no-figures and --no-progress."""
    parser.add_argument("--out", default=default_out, metavar="DIR",
                        help=f"directory for {files} (default {default_out})")
    parser.add_argument("--no-figures", action="store_true", help="skip failures.png")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")


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
