"""An episode as a Rerun recording (``fgdwa run ... --record run.rrd``) to scrub
through cycle by cycle: the true map and the robot's own, the true and the
believed pose with the true outline and the planner's footprint, the scan,
the movers (true and tracked, with the discs the planner predicted), the
global paths, the scored rollouts coloured by their total or by any one
critic's term, the chosen one, and time series of I, D, T (the time to the
nearest predicted contact with a mover, while there is one), beta, delta, the mode,
each critic's raw score and term for the chosen rollout with the spread of its
terms over every admissible sample, vetoes, reject counts and stage times.

It is written from the episode's records (``run_episode(record_cycles=True)``),
so the C++ side knows nothing of Rerun. Needs the optional ``rerun-sdk``
(``pip install "fgdwa[inspect]"``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from fgdwa._core import FgdwaError, NavigatorMode
from fgdwa.sim.referee import placed_outline

INSTALL_HINT = 'pip install "fgdwa[inspect]"'
# Entities, one place for the writer and the tests that read a recording back.
TIMELINE = "cycle"
FAN = "world/rollouts"  # FAN/total: coloured by the total; FAN/by_critic/<name>: by that critic's term


def require_rerun():
    """The rerun module, or FgdwaError naming the extra to install."""
    try:
        import rerun as rr
    except ImportError as error:
        raise FgdwaError(f"recordings need rerun-sdk: {INSTALL_HINT} ({error})") from error
    return rr


def _cells_image(grid) -> np.ndarray:
    """Occupied cells dark, free ones white, row 0 at the bottom as the map has it."""
    return np.where(np.flipud(np.asarray(grid.cells)) > 0, 40, 245).astype(np.uint8)


def _outline(footprint, pose, points: int = 32) -> np.ndarray:
    """The closed outline of a footprint placed at pose (x, y, theta)."""
    x, y, _ = pose
    if footprint.is_circle:
        a = np.linspace(0.0, 2.0 * np.pi, points + 1)
        return np.column_stack([x + footprint.radius * np.cos(a), y + footprint.radius * np.sin(a)])
    vertices = placed_outline(footprint.vertices, pose)
    return np.vstack([vertices, vertices[:1]])


def _log_map(rr, rec, path: str, grid, static: bool) -> None:
    """A grid as an image placed in the world frame (metres)."""
    rows, cols = np.asarray(grid.cells).shape
    rec.log(path, rr.Image(_cells_image(grid)), static=static)
    x0, y0 = grid.origin
    # The image's pixel (col, row) sits at x0 + col r, y0 + (rows - row) r.
    rec.log(path, rr.Transform3D(translation=[x0, y0 + rows * grid.resolution, 0.0],
                                 mat3x3=[[grid.resolution, 0, 0], [0, -grid.resolution, 0], [0, 0, 1]]),
            static=True)


def _shades(values: np.ndarray) -> np.ndarray:
    """Colours for scores, higher is better: dark purple (worst of the cycle) to yellow (best)."""
    from matplotlib import colormaps

    values = np.asarray(values, dtype=float)
    span = float(np.ptp(values)) if len(values) else 0.0
    scaled = (values - values.min()) / span if span > 0.0 else np.ones_like(values)
    return (colormaps["viridis"](scaled)[:, :3] * 255).astype(np.uint8)


def _blueprint(critics):
    """The layout the viewer opens with: the world (the fan by total; each
    critic's colouring listed but hidden, one click shows it) beside the time series."""
    import rerun.blueprint as rrb

    hidden = {f"{FAN}/by_critic/{critic}": rrb.EntityBehavior(visible=False) for critic in critics}
    spread = [f"critics/{critic}/{name}" for critic in critics for name in ("min", "mean", "max")]
    return rrb.Blueprint(
        rrb.Horizontal(
            rrb.Spatial2DView(origin="world", name="world", overrides=hidden),
            rrb.Vertical(
                rrb.TimeSeriesView(origin="weights", name="I, D, T, beta, delta"),
                rrb.Tabs(
                    rrb.TimeSeriesView(origin="critics", name="chosen: each critic's term",
                                       contents=[f"critics/{critic}/term" for critic in critics]),
                    rrb.TimeSeriesView(origin="critics", name="chosen: raw scores",
                                       contents=[f"critics/{critic}/raw" for critic in critics]),
                    rrb.TimeSeriesView(origin="critics", name="terms over all samples", contents=spread),
                    rrb.TimeSeriesView(origin="critics", name="vetoes",
                                       contents=[f"critics/{critic}/vetoes" for critic in critics]),
                    rrb.TimeSeriesView(origin="navigator/rejected", name="rejected samples"),
                ),
                rrb.TimeSeriesView(origin="navigator", name="mode", contents=["navigator/mode"]),
                rrb.TimeSeriesView(origin="times", name="stage times (ms)"),
                rrb.TextLogView(origin="log", name="why"),
            ),
            column_shares=[3, 2],
        ),
        collapse_panels=True,
    )


def write_recording(result, world, goal, footprint, path, title: str = "fgdwa run", outline=None) -> Path:
    """Write ``result`` (an EpisodeResult with its cycles recorded) as a Rerun
    recording at ``path``; returns the path. ``footprint`` is the planner's,
    ``outline`` the body the referee judged (the footprint when None)."""
    trace, motion, context = result.trace, result.motion, result.context
    if not trace.cycles:
        raise FgdwaError("write_recording: the episode kept no cycles; run it with record_cycles=True")
    outline = footprint if outline is None else outline
    dt = result.summary.sim_time / result.summary.steps  # s, the control period
    rr = require_rerun()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    rec = rr.RecordingStream(application_id="fgdwa", recording_id=title)
    rec.save(str(path))
    critics = trace.cycles[0].critics
    rec.send_blueprint(_blueprint(critics))
    truth = world.true_grid() if world.grid is not None else None
    if truth is not None:
        _log_map(rr, rec, "world/map/true", truth, static=True)
    rec.log("world/goal", rr.Points2D([goal], radii=0.08, colors=[[220, 40, 40]], labels=["goal"]), static=True)
    rec.log("world/start", rr.Points2D([motion.poses[0, :2]], radii=0.08, colors=[[40, 160, 40]], labels=["start"]),
            static=True)
    modes = ", ".join(f"{int(value)} {name}" for name, value in NavigatorMode.__members__.items())
    rec.log("navigator/mode", rr.SeriesLines(names=f"mode ({modes})"), static=True)
    for name in ("term", "raw", "min", "mean", "max", "vetoes"):
        for critic in critics:
            rec.log(f"critics/{critic}/{name}", rr.SeriesLines(names=f"{critic} {name}"), static=True)
    path_cycles = {cycle: points for cycle, points in context.paths}
    mode = trigger = failure = None
    for k, cycle in enumerate(trace.cycles):
        rec.set_time(TIMELINE, sequence=k)
        rec.set_time("sim_time", duration=k * dt)
        _log_world(rr, rec, k, k * dt, cycle, result, world, footprint, outline, path_cycles)
        _log_fan(rr, rec, cycle)
        rec.log("navigator/mode", rr.Scalars(float(int(NavigatorMode.__members__[cycle.mode]))))
        for reason, count in cycle.reject_counts.items():
            rec.log(f"navigator/rejected/{reason}", rr.Scalars(float(count)))
        if (cycle.mode, cycle.trigger, cycle.failure) != (mode, trigger, failure):
            mode, trigger, failure = cycle.mode, cycle.trigger, cycle.failure
            why = f"{cycle.mode}" + (f", recovering from {trigger}" if trigger != "None" else "")
            rec.log("log", rr.TextLog(why + (f", gave up: {failure}" if failure != "None" else ""),
                                      level="WARN" if failure != "None" else "INFO"))
        for name, series in (("density", trace.density), ("deviation", trace.deviation),
                             ("contact_time", trace.contact_time), ("beta", trace.beta), ("delta", trace.delta)):
            if k < len(series) and np.isfinite(series[k]):
                rec.log(f"weights/{name}", rr.Scalars(float(series[k])))
        if k < len(trace.cycle_times):
            rec.log("times/cycle_ms", rr.Scalars(1e3 * float(trace.cycle_times[k])))
        for stage, seconds in cycle.times.items():
            rec.log(f"times/{stage}_ms", rr.Scalars(1e3 * float(seconds)))
        _log_critics(rr, rec, cycle)
    if result.summary.reason:
        rec.log("log", rr.TextLog(result.summary.reason, level="ERROR"))
    rec.flush()
    return path


def _log_world(rr, rec, k, t, cycle, result, world, footprint, outline, path_cycles) -> None:
    motion = result.motion
    pose = motion.poses[k]
    rec.log("world/robot/true", rr.LineStrips2D([_outline(outline, pose)], colors=[[30, 30, 200]]))
    believed = motion.believed_poses[k] if len(motion.believed_poses) > k else pose
    rec.log("world/robot/believed", rr.LineStrips2D([_outline(footprint, believed)], colors=[[150, 150, 255]]))
    rec.log("world/robot/trail", rr.LineStrips2D([motion.poses[:k + 1, :2]], colors=[[30, 30, 200]]))
    if cycle.scan_map is not None:
        _log_map(rr, rec, "world/map/robot", cycle.scan_map, static=False)
    rec.log("world/scan", rr.Points2D(cycle.hits, radii=0.03, colors=[[255, 140, 0]]))
    movers = world.discs_at(t) if world.has_moving else []
    rec.log("world/movers/true", rr.Points2D([d.center for d in movers] or np.zeros((0, 2)),
                                              radii=[d.radius for d in movers] or 0.0, colors=[[120, 120, 120]]))
    tracked = cycle.tracked
    rec.log("world/movers/tracked", rr.Points2D(tracked[:, :2], radii=tracked[:, 2], colors=[[200, 0, 200]]))
    # Where each track is predicted one second on: the disc the planner steers around.
    rec.log("world/movers/predicted_1s", rr.Points2D(tracked[:, :2] + tracked[:, 3:5], radii=tracked[:, 2],
                                                      colors=[[200, 0, 200, 90]]))
    if k in path_cycles:
        rec.log("world/global_path", rr.LineStrips2D([path_cycles[k]], colors=[[0, 150, 0]]))
    rec.log("world/chosen", rr.LineStrips2D([cycle.chosen[:, :2]] if len(cycle.chosen) else [],
                                            colors=[[255, 0, 0]], radii=0.02))


def _log_fan(rr, rec, cycle) -> None:
    strips = list(cycle.rollouts[:, :, :2])
    rec.log(f"{FAN}/total", rr.LineStrips2D(strips, colors=_shades(cycle.totals) if strips else None))
    for j, critic in enumerate(cycle.critics):
        colours = _shades(cycle.terms[:, j]) if strips and cycle.terms.shape[1] > j else None
        rec.log(f"{FAN}/by_critic/{critic}", rr.LineStrips2D(strips, colors=colours))


def _log_critics(rr, rec, cycle) -> None:
    for j, critic in enumerate(cycle.critics):
        if j < len(cycle.chosen_terms):
            rec.log(f"critics/{critic}/term", rr.Scalars(float(cycle.chosen_terms[j])))
            rec.log(f"critics/{critic}/raw", rr.Scalars(float(cycle.chosen_raw[j])))
        if j < len(cycle.critic_stats):
            low, mean, high = cycle.critic_stats[j]
            rec.log(f"critics/{critic}/min", rr.Scalars(float(low)))
            rec.log(f"critics/{critic}/mean", rr.Scalars(float(mean)))
            rec.log(f"critics/{critic}/max", rr.Scalars(float(high)))
        if j < len(cycle.critic_vetoes):
            rec.log(f"critics/{critic}/vetoes", rr.Scalars(float(cycle.critic_vetoes[j])))


def read_recording(path, contents: str = "/**"):
    """The entities matching ``contents`` of a recording as a pandas DataFrame,
    one row per cycle (Rerun's dataframe API, through a catalog server on this
    machine that lives for the call)."""
    rr = require_rerun()
    if not Path(path).is_file():
        raise FgdwaError(f"{path}: no such recording")
    server = rr.server.Server(host="127.0.0.1", datasets={"run": [str(path)]})
    client = rr.catalog.CatalogClient(server.url())
    dataset = client.get_dataset("run")
    table = dataset.filter_contents(contents).reader(index=TIMELINE).to_pandas()
    return table.sort_values(TIMELINE).reset_index(drop=True)


def viewer_command(path, web: bool = False, web_port: int | None = None, grpc_port: int | None = None) -> list:
    """The command that opens a recording in Rerun's viewer, or serves it to a
    browser (``web``, or when there is no display) on ``web_port`` (default
    9090) with its data on ``grpc_port`` (default 9876)."""
    import os
    import shutil
    import sys

    require_rerun()
    path = Path(path)
    if not path.is_file():
        raise FgdwaError(f"{path}: no such recording")
    for name, port in (("web_port", web_port), ("grpc_port", grpc_port)):
        if port is not None and not 1 <= port <= 65535:
            raise FgdwaError(f"{name} = {port}: must lie in [1, 65535]")
    viewer = shutil.which("rerun") or str(Path(sys.executable).with_name("rerun"))
    command = [viewer, str(path)]
    if web or not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        command[1:1] = ["--web-viewer"] + (["--web-viewer-port", str(web_port)] if web_port else [])
    if grpc_port:
        command[1:1] = ["--port", str(grpc_port)]
    return command


def open_recording(path, web: bool = False, web_port: int | None = None) -> int:
    """Open a recording (see viewer_command); returns the viewer's exit code."""
    import subprocess

    return subprocess.call(viewer_command(path, web, web_port))
