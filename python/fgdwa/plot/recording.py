"""An episode as a Rerun recording (``fgdwa run ... --record run.rrd``) to scrub
through cycle by cycle: the true map and the robot's own, the true and the
believed pose, the footprint, the scan, the movers (true and tracked), the
global paths, the scored rollouts with the chosen one, and time series of I,
D, beta, delta, the mode and each critic's part of the chosen total.

It is written from the episode's records (``run_episode(record_cycles=True)``),
so the C++ side knows nothing of Rerun. Needs the optional ``rerun-sdk``
(``pip install "fgdwa[inspect]"``).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from fgdwa._core import FgdwaError

INSTALL_HINT = 'pip install "fgdwa[inspect]"'
# Entities, one place for the writer and the tests that read a recording back.
TIMELINE = "cycle"


def _rerun():
    try:
        import rerun as rr
    except ImportError as error:
        raise FgdwaError(f"recordings need rerun-sdk: {INSTALL_HINT} ({error})") from error
    return rr


def _cells_image(grid) -> np.ndarray:
    """Occupied cells dark, free ones white, row 0 at the bottom as the map has it."""
    return np.where(np.flipud(np.asarray(grid.cells)) > 0, 40, 245).astype(np.uint8)


def _outline(footprint, pose, points: int = 32) -> np.ndarray:
    x, y, theta = pose
    if footprint.is_circle:
        a = np.linspace(0.0, 2.0 * np.pi, points + 1)
        return np.column_stack([x + footprint.radius * np.cos(a), y + footprint.radius * np.sin(a)])
    c, s = np.cos(theta), np.sin(theta)
    vertices = np.asarray(footprint.vertices, dtype=float) @ np.array([[c, s], [-s, c]]) + (x, y)
    return np.vstack([vertices, vertices[:1]])


def _log_map(rr, rec, path: str, grid) -> None:
    """A grid as an image placed in the world frame (metres)."""
    rows, cols = np.asarray(grid.cells).shape
    rec.log(path, rr.Image(_cells_image(grid)), static=True)
    x0, y0 = grid.origin
    # The image's pixel (col, row) sits at x0 + col r, y0 + (rows - row) r.
    rec.log(path, rr.Transform3D(translation=[x0, y0 + rows * grid.resolution, 0.0],
                                 mat3x3=[[grid.resolution, 0, 0], [0, -grid.resolution, 0], [0, 0, 1]]),
            static=True)


def write_recording(result, world, goal, footprint, path, title: str = "fgdwa run") -> Path:
    """Write ``result`` (an EpisodeResult with its cycles recorded) as a Rerun
    recording at ``path``; returns the path."""
    trace, motion, context = result.trace, result.motion, result.context
    if not trace.cycles:
        raise FgdwaError("write_recording: the episode kept no cycles; run it with record_cycles=True")
    dt = result.summary.sim_time / result.summary.steps  # s, the control period
    rr = _rerun()
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    rec = rr.RecordingStream(application_id="fgdwa", recording_id=title)
    rec.save(str(path))
    truth = world.true_grid() if world.grid is not None else None
    if truth is not None:
        _log_map(rr, rec, "world/map/true", truth)
    rec.log("world/goal", rr.Points2D([goal], radii=0.08, colors=[[220, 40, 40]], labels=["goal"]), static=True)
    rec.log("world/start", rr.Points2D([motion.poses[0, :2]], radii=0.08, colors=[[40, 160, 40]], labels=["start"]),
            static=True)
    path_cycles = {cycle: points for cycle, points in context.paths}
    critics = trace.cycles[0].critics
    for k, cycle in enumerate(trace.cycles):
        rec.set_time(TIMELINE, sequence=k)
        rec.set_time("sim_time", duration=k * dt)
        pose = motion.poses[k]
        rec.log("world/robot/true", rr.LineStrips2D([_outline(footprint, pose)], colors=[[30, 30, 200]]))
        if len(motion.believed_poses) > k:
            believed = motion.believed_poses[k]
            rec.log("world/robot/believed", rr.LineStrips2D([_outline(footprint, believed)], colors=[[150, 150, 255]]))
        rec.log("world/robot/trail", rr.LineStrips2D([motion.poses[:k + 1, :2]], colors=[[30, 30, 200]]))
        rec.log("world/scan", rr.Points2D(cycle.hits, radii=0.03, colors=[[255, 140, 0]]))
        movers = world.discs_at(k * dt) if world.has_moving else []
        rec.log("world/movers/true", rr.Points2D([d.center for d in movers] or np.zeros((0, 2)),
                                                  radii=[d.radius for d in movers] or 0.0, colors=[[120, 120, 120]]))
        tracked = cycle.tracked
        rec.log("world/movers/tracked", rr.Points2D(tracked[:, :2], radii=tracked[:, 2], colors=[[200, 0, 200]]))
        if k in path_cycles:
            rec.log("world/global_path", rr.LineStrips2D([path_cycles[k]], colors=[[0, 150, 0]]))
        if len(cycle.rollouts):
            totals = cycle.totals
            span = max(float(np.ptp(totals)), 1e-12)
            shade = ((totals - totals.min()) / span * 200 + 55).astype(np.uint8)
            rec.log("world/rollouts", rr.LineStrips2D(list(cycle.rollouts[:, :, :2]),
                                                      colors=np.column_stack([shade, shade, 255 - shade])))
        rec.log("world/chosen", rr.LineStrips2D([cycle.chosen[:, :2]] if len(cycle.chosen) else [],
                                                colors=[[255, 0, 0]]))
        rec.log("mode", rr.TextLog(cycle.mode))
        for name, series in (("density", trace.density), ("deviation", trace.deviation), ("beta", trace.beta),
                             ("delta", trace.delta)):
            if k < len(series) and np.isfinite(series[k]):
                rec.log(f"weights/{name}", rr.Scalars(float(series[k])))
        if k < len(trace.cycle_times):
            rec.log("times/cycle_ms", rr.Scalars(1e3 * float(trace.cycle_times[k])))
        for j, critic in enumerate(critics):
            if j < len(cycle.chosen_terms):
                rec.log(f"critics/{critic}/term", rr.Scalars(float(cycle.chosen_terms[j])))
                rec.log(f"critics/{critic}/raw", rr.Scalars(float(cycle.chosen_raw[j])))
    rec.flush()
    return path


def read_recording(path, contents: str = "/**"):
    """The entities matching ``contents`` of a recording as a pandas DataFrame,
    one row per cycle (Rerun's dataframe API, through a catalog server on this
    machine that lives for the call)."""
    rr = _rerun()
    if not Path(path).is_file():
        raise FgdwaError(f"{path}: no such recording")
    server = rr.server.Server(host="127.0.0.1", datasets={"run": [str(path)]})
    client = rr.catalog.CatalogClient(server.url())
    dataset = client.get_dataset("run")
    table = dataset.filter_contents(contents).reader(index=TIMELINE).to_pandas()
    return table.sort_values(TIMELINE).reset_index(drop=True)


def open_recording(path, web: bool = False) -> int:
    """Open a recording in Rerun's viewer, or in its web viewer served on this
    machine (``web``, or when there is no display); returns the viewer's exit code."""
    import os
    import shutil
    import subprocess
    import sys

    _rerun()
    path = Path(path)
    if not path.is_file():
        raise FgdwaError(f"{path}: no such recording")
    viewer = shutil.which("rerun") or str(Path(sys.executable).with_name("rerun"))
    command = [viewer, str(path)]
    if web or not os.environ.get("DISPLAY") and not os.environ.get("WAYLAND_DISPLAY"):
        command.insert(1, "--web-viewer")
    return subprocess.call(command)
