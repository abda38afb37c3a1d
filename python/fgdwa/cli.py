"""The ``fgdwa`` command: ``demo``, ``run`` (one episode, its figure and GIF),
``experiment`` (the paper's experiments E1-E3, docs/algorithms.md), ``irsim``
(an IR-SIM world driven by the fgdwa behavior), ``replay`` (fgdwa_node's
planner rerun on a ROS bag), ``params``, and the benchmarks ``barn`` and
``dynamic`` (registered by :mod:`fgdwa.bench.barn` and :mod:`fgdwa.bench.dynamic`)."""

from __future__ import annotations

import argparse
import importlib.metadata
import os
import shlex
import sys
import time
from pathlib import Path

import numpy as np

from fgdwa._core import FgdwaError, preset_names

DEFAULT_EXPERIMENT_OUT = "out/experiments"


def _format_metrics(metrics: dict) -> str:
    from fgdwa.sim.episode import METRIC_UNITS

    rows = []
    for key, value in metrics.items():
        if key == "reason" and not value:
            continue
        unit = METRIC_UNITS.get(key, "")
        text = f"{value:.4g}" if isinstance(value, float) else f"{value}"
        rows.append(f"  {key:<16} {text} {unit}".rstrip())
    return "\n".join(rows)


def _cycle_line(cycle_times) -> str:
    ms = 1e3 * np.asarray(cycle_times, dtype=float)
    if len(ms) == 0:
        return "  cycle time       (no cycle)"
    return (f"  cycle time       median {np.median(ms):.3f} ms, p95 {np.percentile(ms, 95):.3f} ms "
            f"over {len(ms)} cycles")


def cmd_demo(args: argparse.Namespace) -> int:
    """`fgdwa run demo --planner fgdwa`: the one demo, whichever command names it."""
    argv = ["run", "demo", "--planner", "fgdwa", "--out", args.out, "--seed", str(args.seed),
            "--max-steps", str(args.max_steps)]
    if args.gif:
        argv += ["--gif", args.gif]
    return main(argv)


def cmd_inspect(args: argparse.Namespace) -> int:
    from fgdwa.plot.recording import open_recording

    return open_recording(args.recording, web=args.web, web_port=args.web_port)


def file_stem(name: str) -> str:
    """A scenario's name as a file name inside the output directory: letters,
    digits, '.', '-' and '_' only, no leading dot, at most 100 characters."""
    stem = "".join(c if c.isascii() and (c.isalnum() or c in "._-") else "_" for c in name).lstrip(".")
    return stem[:100] or "scenario"


def output_file(path: str, suffix: str, option: str) -> Path:
    """``path`` checked before a run that ends by writing it: the suffix its
    format needs, and a directory that can be made and written."""
    out = Path(path)
    if out.suffix.lower() != suffix:
        raise FgdwaError(f"{option} {path}: the file is written as {suffix[1:].upper()}: name it *{suffix}")
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise FgdwaError(f"{option} {path}: cannot make its directory ({error.strerror})") from None
    if not os.access(out.parent, os.W_OK) or (out.exists() and not os.access(out, os.W_OK)):
        raise FgdwaError(f"{option} {path}: not writable")
    return out


def cmd_run(args: argparse.Namespace) -> int:
    from fgdwa.bench.experiments import resolve_scenario
    from fgdwa.plot.episode import plot_episode
    from fgdwa.sim import check_seed, run_scenario, trial_variation

    if args.record:
        from fgdwa.plot.recording import require_rerun

        require_rerun()  # before the run, not after it
    # Every output is checked before the run, not after it.
    check_seed(args.seed)
    if args.gif:
        output_file(args.gif, ".gif", "--gif")
    if args.record:
        output_file(args.record, ".rrd", "--record")
    try:
        Path(args.out).mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise FgdwaError(f"--out {args.out}: cannot make the directory ({error.strerror})") from None
    scenario = resolve_scenario(args.scenario)
    planner = args.planner or scenario.planner
    options = {"max_steps": args.max_steps} if args.max_steps is not None else {}
    if args.latency:
        options["latency"] = args.latency
    options["body"] = args.body
    tic = time.perf_counter()
    if args.gif or args.record:
        # The GIF and the recording replay the cycles; a wider fan of scored rollouts than the default 5
        # shows the choice.
        from fgdwa.bench.recordings import recorded_navigator

        options.update(record_cycles=True, navigator=recorded_navigator(options.get("mapping", "known")))
    result = run_scenario(scenario, planner, args.seed, **options)
    wall = time.perf_counter() - tic
    print(f"scenario {scenario.name}: {scenario.description}")
    print(f"planner {planner}, seed {args.seed}, body {args.body}")
    print(_format_metrics(result.metrics()))
    print(_cycle_line(result.trace.cycle_times))
    print(f"  episode wall     {wall:.2f} s")
    out = Path(args.out)
    _, world, _ = trial_variation(scenario, args.seed)
    png = out / f"{file_stem(scenario.name)}_{planner}.png"
    summary = result.summary
    plot_episode(result, world, scenario.goal, png, title=f"{scenario.name}, {planner}, seed {args.seed}: "
                 f"{summary.outcome}, {summary.steps} steps, {summary.mileage:.2f} m",
                 footprint=scenario.footprint)
    print(f"figure: {png}")
    if args.gif:
        from fgdwa.plot.animation import write_gif

        tic = time.perf_counter()
        gif = write_gif(result, scenario, args.gif, planner=planner, seed=args.seed, max_frames=args.frames)
        print(f"animation: {gif} ({time.perf_counter() - tic:.1f} s to draw)")
    if args.record:
        from fgdwa.plot.recording import write_recording

        rrd = write_recording(result, world, scenario.goal, scenario.footprint, args.record,
                              title=f"{scenario.name} {planner} seed {args.seed}")
        print(f"recording: {rrd} (fgdwa inspect {rrd})")
    return 0 if summary.outcome == "success" else 1


def cmd_experiment(args: argparse.Namespace, argv) -> int:
    from fgdwa.bench.experiments import EXPERIMENTS, run_experiments, trial_failures
    from fgdwa.bench.recordings import check_recording_possible, print_failures
    from fgdwa.bench.report import save_experiment, terminal_report, write_results
    from fgdwa.bench.runner import run_tasks

    names = list(EXPERIMENTS) if args.name == "all" else [args.name]
    check_recording_possible(args.record_failures)
    out = Path(args.out)
    options = {"max_steps": args.max_steps} if args.max_steps is not None else {}
    options["body"] = args.body
    command = "fgdwa " + " ".join(shlex.quote(a) for a in (argv if argv is not None else sys.argv[1:]))
    tic = time.perf_counter()
    print(f"{', '.join(n.upper() for n in names)}: {args.trials} trials per planner, seeds {args.seed}.."
          f"{args.seed + args.trials - 1}, executor {args.executor}", flush=True)
    results = run_experiments(names, trials=args.trials, base_seed=args.seed, executor=args.executor,
                              scheduler=args.scheduler, workers=args.workers, progress=not args.no_progress,
                              options=options)
    trials_wall = time.perf_counter() - tic
    recordings = {}
    if args.record_failures:
        from fgdwa.bench.experiments import record_failed_trials

        recordings = record_failed_trials(results, args.record_failures, executor=args.executor,
                                          scheduler=args.scheduler, workers=args.workers,
                                          progress=not args.no_progress)
    drawn = [{} for _ in results]
    surfaces = None
    if not args.no_figures:
        from fgdwa.plot.experiments import CONTROL_SURFACES, FigureJob, draw_figures

        jobs = []
        for result in results:
            (out / result.spec.name).mkdir(parents=True, exist_ok=True)
            jobs.append(FigureJob(str(out / result.spec.name), result))
        if any("fgdwa" in r.spec.planners for r in results):
            out.mkdir(parents=True, exist_ok=True)
            jobs.append(FigureJob(str(out)))
        # Drawn side by side by the local pool; a dask cluster would take longer to start than the figures take.
        # The box plots' p-values and the reports both need scipy's tests: loaded here (0.7 s) before the
        # pool starts, so that its forked workers share them instead of each loading them again.
        import scipy.stats  # noqa: F401

        figures_executor = "local" if args.executor == "local" else "serial"
        figures = run_tasks(jobs, draw_figures, executor=figures_executor, workers=args.workers,
                            progress=not args.no_progress, label="figures")
        drawn = figures[:len(results)]
        if len(figures) > len(results):
            surfaces = figures[-1][CONTROL_SURFACES]
    for result, paths in zip(results, drawn):
        d = save_experiment(result, out, paths)
        print()
        print(terminal_report(d))
        print_failures(trial_failures(result, recordings), ("planner", "trial"))
        print(f"files: {out / result.spec.name}/")
    written = []
    if len(names) > 1:
        written.append(write_results(out, names, command, out / "report.md", surfaces))
    results_md = args.results_md
    if results_md:
        written.append(write_results(out, list(EXPERIMENTS), command, Path(results_md),
                                     surfaces if surfaces is not None else _existing(out / "control_surfaces.png")))
    for path in written:
        print(f"report: {path}")
    wall = time.perf_counter() - tic
    cycles = np.concatenate([r.cycle_times for result in results for r in result.records])
    print()
    print(f"wall time: {wall:.1f} s ({trials_wall:.1f} s of trials, {wall - trials_wall:.1f} s of reports and "
          f"figures); {sum(len(r.records) for r in results)} episodes")
    for result in results:
        ms = 1e3 * np.concatenate([r.cycle_times for r in result.records])
        print(f"  {result.spec.name}: per-cycle planning time median {np.median(ms):.3f} ms, "
              f"p95 {np.percentile(ms, 95):.3f} ms over {len(ms)} cycles")
    if len(cycles):
        print(f"  all: per-cycle planning time median {1e3 * np.median(cycles):.3f} ms, "
              f"p95 {1e3 * np.percentile(cycles, 95):.3f} ms over {len(cycles)} cycles")
    return 0


def cmd_irsim(args: argparse.Namespace) -> int:
    try:
        from fgdwa.adapters.irsim import format_run, run_world
    except ImportError as error:
        raise FgdwaError(str(error)) from None

    run = run_world(args.world, max_steps=args.max_steps, seed=args.seed, render=args.render)
    print(format_run(run))
    robots = run.fgdwa_robots()
    return 0 if all(r.arrived and not r.collided for r in robots) else 1


def cmd_replay(args: argparse.Namespace) -> int:
    from fgdwa.adapters.replay import replay_command

    return replay_command(args)


def _existing(path: Path):
    return path if path.exists() else None


def build_parser() -> argparse.ArgumentParser:
    from fgdwa.bench.barn import register_barn_commands
    from fgdwa.bench.dynabarn import register_dynabarn_commands
    from fgdwa.bench.dynamic import register_dynamic_commands
    from fgdwa.bench.options import add_body_argument, add_executor_arguments, add_output_arguments, positive
    from fgdwa.bench.recordings import add_record_failures_argument

    parser = argparse.ArgumentParser(prog="fgdwa", description="fgdwa: dynamic window local planning.")
    parser.add_argument("--version", action="version", version=f"fgdwa {importlib.metadata.version('fgdwa')}")
    sub = parser.add_subparsers(dest="command", required=True)

    demo = sub.add_parser("demo", help="FGDWA on the shipped demo scenario: the same as `fgdwa run demo --planner fgdwa`")
    demo.add_argument("--out", default="out/demo", help="directory for the figure (default: out/demo)")
    demo.add_argument("--gif", default=None, metavar="FILE", help="also write an animation of the run (.gif)")
    demo.add_argument("--seed", type=int, default=0, help="seed of the run (default 0)")
    demo.add_argument("--max-steps", type=positive, default=1000)
    demo.set_defaults(func=lambda args, argv: cmd_demo(args))

    run = sub.add_parser("run", help="run one episode of a scenario: metrics, a PNG and optionally a GIF")
    run.add_argument("scenario", help="a shipped scenario name (demo, e1, e2, e3) or a scenario YAML file")
    run.add_argument("--planner", default=None, choices=preset_names(),
                     help="planner preset (default: the scenario's)")
    run.add_argument("--seed", type=int, default=0, help="trial seed: start jitter, obstacle phases, lidar noise")
    run.add_argument("--out", default="out/run", help="directory for the PNG (default: out/run)")
    run.add_argument("--gif", default=None, metavar="FILE", help="also write an animated GIF of the run")
    run.add_argument("--frames", type=positive, default=150, help="at most this many GIF frames (default 150)")
    run.add_argument("--record", default=None, metavar="FILE.rrd",
                     help="also write a Rerun recording of every cycle (needs rerun-sdk: pip install 'fgdwa[inspect]')")
    run.add_argument("--max-steps", type=positive, default=None, help="override the scenario's max_steps")
    run.add_argument("--latency", type=int, default=0, metavar="CYCLES",
                     help="control cycles from a scan to its command reaching the wheels (default 0)")
    add_body_argument(run)
    run.set_defaults(func=lambda args, argv: cmd_run(args))

    exp = sub.add_parser("experiment", help="run the paper's experiments E1-E3 and write tables, figures "
                                            "and reports")
    exp.add_argument("name", choices=["e1", "e2", "e3", "all"])
    exp.add_argument("--trials", type=positive, default=15, help="trials per planner (default 15)")
    exp.add_argument("--seed", type=int, default=0, help="base seed: trial i uses seed + i (default 0)")
    exp.add_argument("--max-steps", type=positive, default=None, help="override every scenario's max_steps")
    exp.add_argument("--results-md", default=None, metavar="PATH",
                     help="also write the results page there (the repository's: docs/RESULTS.md, with "
                          "--out docs/results)")
    add_executor_arguments(exp)
    add_output_arguments(exp, DEFAULT_EXPERIMENT_OUT, "the tables, figures and reports, one folder per experiment",
                         figures="the PNG figures")
    add_record_failures_argument(exp)
    add_body_argument(exp)
    exp.set_defaults(func=cmd_experiment)
    ins = sub.add_parser("inspect", help="open a recording (fgdwa run ... --record FILE.rrd) in Rerun's viewer, "
                                         "or its web viewer when there is no display")
    ins.add_argument("recording", help="a .rrd file")
    ins.add_argument("--web", action="store_true", help="the web viewer even with a display")
    ins.add_argument("--web-port", type=int, default=None, metavar="PORT",
                     help="the web viewer's port (default 9090); open http://localhost:PORT")
    ins.set_defaults(func=lambda args, argv: cmd_inspect(args))
    irs = sub.add_parser("irsim", help="run an IR-SIM world whose robots name behavior fgdwa (needs ir-sim: "
                                       "pip install 'fgdwa[irsim]'); prints each robot's outcome by IR-SIM's flags")
    irs.add_argument("world", help="an IR-SIM world YAML file")
    irs.add_argument("--max-steps", type=positive, default=1000, help="steps before giving up (default 1000)")
    irs.add_argument("--seed", type=int, default=None, help="IR-SIM's random seed (lidar noise, random placements)")
    irs.add_argument("--render", action="store_true", help="draw the world in a window while it runs")
    irs.set_defaults(func=lambda args, argv: cmd_irsim(args))
    rep = sub.add_parser("replay", help="rerun fgdwa_node's planner on a ROS bag's scans and odometry and show "
                                        "where its commands differ from the recorded ones (docs/ros.md)")
    rep.add_argument("bag", help="a ROS 1 bag, or a ROS 2 bag's directory or .db3/.mcap file, recorded from "
                                 "fgdwa_node: the scan, odometry, cmd_vel, /diagnostics and /fgdwa_node/events")
    rep.add_argument("--out", default="out/replay", help="directory for replay.csv, .json, .png (default out/replay)")
    rep.add_argument("--scan-topic", default=None, help="the LaserScan topic, when the bag has several")
    rep.add_argument("--odom-topic", default=None, help="the Odometry topic, when the bag has several")
    rep.add_argument("--set", action="append", metavar="NAME=VALUE",
                     help="replay with a setting changed, by fgdwa_node's parameter name (e.g. planner/sim_time=1.5)")
    rep.set_defaults(func=lambda args, argv: cmd_replay(args))
    par = sub.add_parser("params", help="list every parameter: name, unit, bounds, default, meaning "
                                        "(docs/parameters.md)")
    par.set_defaults(func=lambda args, argv: cmd_params())
    register_barn_commands(sub)
    register_dynamic_commands(sub)
    register_dynabarn_commands(sub)
    return parser


def cmd_params() -> int:
    from fgdwa.params_doc import parameter_reference

    print(parameter_reference())
    return 0


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command == "experiment" and args.scheduler is not None and args.executor != "dask":
        parser.error("--scheduler needs --executor dask")
    try:
        return args.func(args, argv)
    except FgdwaError as error:
        print(f"fgdwa: {error}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
