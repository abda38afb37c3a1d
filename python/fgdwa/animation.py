"""An animated GIF of one episode: the robot's footprint, the path driven so far, the
dynamic window's rollout fan and the chosen rollout, the lidar's hits, the
detect window and the moving obstacles.

The episode records poses and commands, not every cycle's scan or samples, so
each frame rebuilds them: the scan by scanning the trial's world again at the
recorded pose with the episode's own noise seed (``run_episode`` seeds cycle k
with ``seed * 1_000_003 + k``), the fan by rolling out a grid of the commands
reachable from the recorded command, and the chosen rollout from the command
the robot executed.
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

from fgdwa._core import DistanceField, LaserScanner, Pose2, dynamic_window, rollout, sample_window  # noqa: E402
from fgdwa.plotting import draw_world  # noqa: E402
from fgdwa.scenario import Scenario, scenario_params, trial_variation  # noqa: E402
from fgdwa.sim import SCAN_SEED_STRIDE, EpisodeResult  # noqa: E402


def frame_indices(steps: int, max_frames: int = 150) -> np.ndarray:
    """Up to ``max_frames`` cycle indices from 0 to ``steps`` (the final pose), evenly spread."""
    if max_frames < 2:
        raise ValueError(f"max_frames = {max_frames!r}: must be >= 2")
    count = min(int(max_frames), steps + 1)
    return np.unique(np.linspace(0, steps, count).round().astype(int))


def write_gif(result: EpisodeResult, scenario: Scenario, path, planner=None, seed: int = 0,
              max_frames: int = 150, dpi: int = 70, fps: int = 10, fan: tuple = (7, 9)) -> Path:
    """Animate ``result``, the run of ``planner`` on ``scenario`` with ``seed``, into a GIF at ``path``.

    ``fan`` = (velocities, turn rates) of the rollout grid drawn each frame."""
    _, params = scenario_params(scenario, planner)
    _, world, lidar = trial_variation(scenario, seed)
    true_grid = world.true_grid()
    scanner = LaserScanner(lidar, DistanceField(true_grid)) if true_grid is not None else None
    n_steps = params.n_steps
    limits = scenario.limits
    radius = scenario.footprint.radius
    window = scenario.window
    steps = result.steps
    frames = frame_indices(steps, max_frames)

    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    draw_world(ax, dataclasses.replace(world, discs=(), movers=()), 0.0)
    if result.global_path is not None:
        ax.plot(*result.global_path.T, "--", color="tab:red", linewidth=1.0)
        if result.key_nodes is not None:
            ax.plot(*result.key_nodes.T, "+", color="tab:blue", markersize=8, markeredgewidth=1.5)
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
    body = Circle((0, 0), radius, facecolor="tab:blue", edgecolor="k", alpha=0.6, zorder=5)
    ax.add_patch(body)
    (heading,) = ax.plot([], [], color="k", linewidth=1.2, zorder=6)
    discs = [Circle((0, 0), max(d.radius, 0.05), color="tab:purple", alpha=0.7, zorder=3)
             for d in world.discs_at(0.0)]
    for patch in discs:
        ax.add_patch(patch)
    label = ax.set_title("", fontsize=8)
    fig.tight_layout()

    poses, commands, dt = result.poses, result.commands, params.dt

    def draw(k):
        x, y, theta = poses[k]
        t = k * dt
        driven.set_data(poses[: k + 1, 0], poses[: k + 1, 1])
        body.center = (x, y)
        heading.set_data([x, x + 1.4 * radius * np.cos(theta)], [y, y + 1.4 * radius * np.sin(theta)])
        sector.set_center((x, y))
        sector.set_theta1(np.degrees(theta) - window.half_angle_deg)
        sector.set_theta2(np.degrees(theta) + window.half_angle_deg)
        discs_now = world.discs_at(t)
        for patch, disc in zip(discs, discs_now):
            patch.center = tuple(disc.center)
        if scanner is not None:
            scan = scanner.scan(Pose2(x, y, theta), discs_now, 0.0, seed=int(seed) * SCAN_SEED_STRIDE + k)
            points = scan.hit_points
            hits.set_offsets(points if len(points) else np.zeros((0, 2)))
        current = tuple(commands[k - 1]) if k > 0 else (0.0, 0.0)
        if k < steps:
            candidates = sample_window(dynamic_window(limits, current, dt), current, fan[0], fan[1])
            fan_lines.set_segments([np.vstack([[x, y], rollout((x, y, theta), tuple(c), dt, n_steps)[:, :2]])
                                    for c in candidates])
            best = np.vstack([[x, y], rollout((x, y, theta), tuple(commands[k]), dt, n_steps)[:, :2]])
            chosen.set_data(best[:, 0], best[:, 1])
        else:
            fan_lines.set_segments([])
            chosen.set_data([], [])
        text = f"t = {t:5.2f} s  step {k}/{steps}"
        for name, values in (("beta", result.beta), ("delta", result.delta), ("I", result.density)):
            if k < len(values) and np.isfinite(values[k]):
                text += f"  {name} {values[k]:.2f}"
        if k == steps:
            text += f"  {result.outcome}"
        label.set_text(text)
        return [fan_lines, chosen, driven, hits, sector, body, heading, label, *discs]

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
