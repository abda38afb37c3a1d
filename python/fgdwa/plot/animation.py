"""An animated GIF of one episode: the robot's footprint as it is, the path driven
so far, the rollouts the planner scored and the one it chose, the lidar's hits,
the detect window and the moving obstacles.

Every frame replays what the episode recorded (``run_episode(record_cycles=True)``):
nothing of the robot's side is simulated again.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import PillowWriter  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.patches import Circle, Wedge  # noqa: E402

from fgdwa._core import FgdwaError  # noqa: E402
from fgdwa.plot.episode import draw_world, footprint_patch, placed_outline  # noqa: E402
from fgdwa.sim.episode import EpisodeResult  # noqa: E402
from fgdwa.sim.scenario import Scenario, scenario_params, trial_variation  # noqa: E402


def frame_indices(steps: int, max_frames: int = 150) -> np.ndarray:
    """Up to ``max_frames`` cycle indices from 0 to ``steps`` (the final pose), evenly spread."""
    if max_frames < 2:
        raise ValueError(f"max_frames = {max_frames!r}: must be >= 2")
    count = min(int(max_frames), steps + 1)
    return np.unique(np.linspace(0, steps, count).round().astype(int))


def write_gif(result: EpisodeResult, scenario: Scenario, path, planner=None, seed: int = 0,
              max_frames: int = 150, dpi: int = 70, fps: int = 10) -> Path:
    """Animate ``result``, the run of ``planner`` on ``scenario`` with ``seed`` recorded
    with ``record_cycles=True``, into a GIF at ``path``."""
    trace, paths = result.trace, result.context.paths
    if len(trace.cycles) != result.summary.steps:
        raise FgdwaError("write_gif replays the recorded cycles: run the episode with record_cycles=True")
    _, params = scenario_params(scenario, planner)
    _, world, _ = trial_variation(scenario, seed)
    footprint = scenario.footprint
    radius = footprint.radius
    window = scenario.window
    steps = result.summary.steps
    frames = frame_indices(steps, max_frames)

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    draw_world(ax, dataclasses.replace(world, discs=(), movers=()), 0.0)
    # The global path in force at each frame (the navigator replans), from the recorded paths.
    (global_line,) = ax.plot([], [], "--", color="tab:red", linewidth=1.0)
    path_starts = [cycle for cycle, _ in paths]
    ax.plot(*np.asarray(scenario.goal)[:2], "*", color="tab:orange", markersize=13)
    ax.set_aspect("equal")
    if world.grid is not None:
        x0, x1, y0, y1 = world.grid.extent
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    ax.tick_params(labelsize=7)

    fan_lines = LineCollection([], colors="0.55", linewidths=0.5, alpha=0.7)
    ax.add_collection(fan_lines)
    (chosen,) = ax.plot([], [], color="red", linewidth=1.6)
    (driven,) = ax.plot([], [], color="tab:blue", linewidth=1.5)
    hits = ax.scatter([], [], s=2, color="tab:red", zorder=4)
    sector = Wedge((0, 0), window.radius, 0, 0, facecolor="tab:cyan", edgecolor="tab:blue", alpha=0.18,
                   linestyle="--")
    ax.add_patch(sector)
    body = footprint_patch(footprint, result.motion.poses[0], facecolor="tab:blue", edgecolor="k", alpha=0.6, zorder=5)
    ax.add_patch(body)
    (heading,) = ax.plot([], [], color="k", linewidth=1.2, zorder=6)
    discs = [Circle((0, 0), max(d.radius, 0.05), color="tab:purple", alpha=0.7, zorder=3)
             for d in world.discs_at(0.0)]
    for patch in discs:
        ax.add_patch(patch)
    label = ax.set_title("", fontsize=8)
    fig.tight_layout()

    poses, dt = result.motion.poses, params.dt

    def draw(k):
        x, y, theta = poses[k]
        t = k * dt
        driven.set_data(poses[: k + 1, 0], poses[: k + 1, 1])
        if footprint.is_circle:
            body.center = (x, y)
        else:
            body.set_xy(placed_outline(footprint.vertices, poses[k]))
        heading.set_data([x, x + 1.4 * radius * np.cos(theta)], [y, y + 1.4 * radius * np.sin(theta)])
        sector.set_center((x, y))
        sector.set_theta1(np.degrees(theta - window.half_angle))
        sector.set_theta2(np.degrees(theta + window.half_angle))
        for patch, disc in zip(discs, world.discs_at(t)):
            patch.center = tuple(disc.center)
        held = np.searchsorted(path_starts, k, side="right") - 1
        points = np.asarray(paths[held][1]) if held >= 0 else np.zeros((0, 2))
        global_line.set_data(points[:, 0], points[:, 1]) if len(points) else global_line.set_data([], [])
        if k < steps:
            cycle = trace.cycles[k]
            hits.set_offsets(cycle.hits if len(cycle.hits) else np.zeros((0, 2)))
            fan_lines.set_segments([np.vstack([[x, y], r[:, :2]]) for r in cycle.rollouts])
            best = np.vstack([[x, y], cycle.chosen[:, :2]]) if len(cycle.chosen) else np.zeros((0, 2))
            chosen.set_data(best[:, 0], best[:, 1])
        else:
            hits.set_offsets(np.zeros((0, 2)))
            fan_lines.set_segments([])
            chosen.set_data([], [])
        text = f"t = {t:5.2f} s  step {k}/{steps}"
        if k < steps and trace.cycles[k].mode not in ("Following", "Replanning"):
            text += f"  {trace.cycles[k].mode}"
        for name, values in (("beta", trace.beta), ("delta", trace.delta), ("I", trace.density)):
            if k < len(values) and np.isfinite(values[k]):
                text += f"  {name} {values[k]:.2f}"
        if k == steps:
            text += f"  {result.summary.outcome}"
        label.set_text(text)
        return [fan_lines, chosen, driven, hits, sector, body, heading, label, global_line, *discs]

    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    # One draw per frame: PillowWriter's own loop (FuncAnimation.save) draws each frame three times.
    writer = PillowWriter(fps=fps)
    with writer.saving(fig, str(path), dpi):
        for k in frames:
            draw(int(k))
            writer.grab_frame()
    plt.close(fig)
    return path
