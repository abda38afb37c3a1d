"""The ``fgdwa`` command."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from fgdwa._core import FgdwaError, PlannerParams
from fgdwa.builtin import demo_scenario
from fgdwa.plotting import plot_episode
from fgdwa.sim import run_episode


def _format_metrics(metrics: dict) -> str:
    rows = []
    for key, value in metrics.items():
        rows.append(f"  {key:<16} {value:.4g}" if isinstance(value, float) else f"  {key:<16} {value}")
    return "\n".join(rows)


def cmd_demo(args: argparse.Namespace) -> int:
    scenario = demo_scenario()
    result = run_episode(scenario.world, scenario.start, scenario.goal, params=PlannerParams(),
                         max_steps=args.max_steps)
    print(f"scenario {scenario.name}: {scenario.description}")
    print("planner dwa (classic dynamic window, heading to the goal)")
    print(_format_metrics(result.metrics()))
    if len(result.cycle_times):
        print(f"  cycle time       median {1e3 * float(sorted(result.cycle_times)[len(result.cycle_times) // 2]):.3f} ms")
    png = Path(args.out) / "demo.png"
    plot_episode(result, scenario.world, scenario.goal, png)
    print(f"figure: {png}")
    return 0 if result.outcome == "success" else 1


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="fgdwa", description="fgdwa: dynamic window local planning.")
    sub = parser.add_subparsers(dest="command", required=True)
    demo = sub.add_parser("demo", help="run the classic DWA on the built-in demo scenario")
    demo.add_argument("--out", default="out/demo", help="directory for the figure (default: out/demo)")
    demo.add_argument("--max-steps", type=int, default=1000)
    demo.set_defaults(func=cmd_demo)
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except FgdwaError as error:
        print(f"fgdwa: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
