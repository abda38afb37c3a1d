"""Figures of episodes: map, executed path and the last cycle's rollout fan; and
the drawing pieces every other figure shares (:func:`save_figure`,
:func:`draw_world`, :func:`footprint_patch`)."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402

from fgdwa._core import Footprint  # noqa: E402
from fgdwa.sim.episode import EpisodeResult  # noqa: E402
from fgdwa.sim.world import World  # noqa: E402


def save_figure(fig, path, dpi: int = 120, **options) -> Path:
    """Writes ``fig`` to ``path`` (its folder made as needed) and closes it."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi, **options)
    plt.close(fig)
    return path


def draw_world(ax, world: World, t: float = 0.0) -> None:
    """Terrain grades in browns, the map in grey, obstacles missing from it in
    orange, moving obstacles as circles at time ``t``."""
    if world.terrain is not None:
        grades = np.ma.masked_equal(world.terrain.grades, 0)
        ax.imshow(grades, cmap="copper_r", vmin=0, vmax=5, origin="lower", extent=world.terrain.extent,
                  interpolation="nearest", alpha=0.6)
    if world.grid is not None:
        cells = np.ma.masked_equal(world.grid.cells, 0) if world.terrain is not None else world.grid.cells
        ax.imshow(cells, cmap="Greys", vmin=0, vmax=1.6, origin="lower",
                  extent=world.grid.extent, interpolation="nearest")
    if world.hidden is not None:
        hidden = np.ma.masked_equal(world.hidden.cells, 0)
        ax.imshow(hidden, cmap="Oranges", vmin=0, vmax=1.3, origin="lower", extent=world.hidden.extent,
                  interpolation="nearest")
    for disc in world.discs_at(t):
        ax.add_patch(plt.Circle(disc.center, max(disc.radius, 0.05), color="tab:purple", alpha=0.7))


def draw_rollout_fan(ax, rollouts: np.ndarray, totals: np.ndarray, best_index: int) -> None:
    """Every sample's rollout, coloured by its total score; rejected ones dashed grey."""
    if rollouts is None or len(rollouts) == 0:
        return
    admissible = np.isfinite(totals)
    segments = [r[:, :2] for r in rollouts]
    rejected = [s for s, ok in zip(segments, admissible) if not ok]
    if rejected:
        ax.add_collection(LineCollection(rejected, colors="0.6", linewidths=0.5, linestyles="dashed"))
    if admissible.any():
        kept = [s for s, ok in zip(segments, admissible) if ok]
        lines = LineCollection(kept, cmap="viridis", linewidths=0.8)
        lines.set_array(totals[admissible])
        ax.add_collection(lines)
        plt.colorbar(lines, ax=ax, shrink=0.7, label="score of the last cycle's samples")
    if best_index >= 0:
        ax.plot(*rollouts[best_index, :, :2].T, color="red", linewidth=2.0, label="chosen rollout")


def placed_outline(vertices: np.ndarray, pose) -> np.ndarray:
    """A polygon footprint's (n, 2) vertices (robot frame) placed at pose (x, y, theta)."""
    x, y, theta = pose
    c, s = np.cos(theta), np.sin(theta)
    return np.asarray(vertices, dtype=float) @ np.array([[c, s], [-s, c]]) + (x, y)


def footprint_patch(footprint, pose, **style):
    """The footprint as it is, placed at pose: a circle or the polygon."""
    if footprint.is_circle:
        return plt.Circle(tuple(pose[:2]), footprint.radius, **style)
    return plt.Polygon(placed_outline(footprint.vertices, pose), closed=True, **style)


def plot_episode(result: EpisodeResult, world: World, goal, path: Optional[Path] = None,
                 title: str = "", footprint=None):
    """Map, executed path, start and goal, the footprint (default a 0.25 m circle) at
    the end, and the rollouts the planner scored in its last cycle."""
    fig, ax = plt.subplots(figsize=(9, 6.5))
    context, poses = result.context, result.motion.poses
    draw_world(ax, world, result.summary.sim_time)
    if context.global_path is not None:
        ax.plot(*context.global_path.T, color="tab:red", linewidth=1.0, linestyle="--", label="global path")
        ax.plot(*context.key_nodes.T, "+", color="tab:red", markersize=10, markeredgewidth=2, label="key nodes")
    ax.plot(*poses[:, :2].T, color="tab:blue", linewidth=1.8, label="executed path")
    ax.add_patch(footprint_patch(footprint if footprint is not None else Footprint.circle(0.25), poses[-1],
                                 fill=False, color="tab:blue"))
    if context.last_plan is not None:
        draw_rollout_fan(ax, context.last_rollouts, np.asarray(context.last_plan.total),
                         context.last_plan.best_index)
    ax.plot(*poses[0, :2], "o", color="tab:green", markersize=9, label="start")
    ax.plot(*np.asarray(goal)[:2], "*", color="tab:orange", markersize=15, label="goal")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    m = result.metrics()
    ax.set_title(title or f"{m['outcome']}: {m['steps']} steps, {m['mileage']:.2f} m, "
                          f"min clearance {m['min_clearance']:.2f} m")
    ax.legend(loc="upper left", fontsize=8)
    if world.grid is not None:
        x0, x1, y0, y1 = world.grid.extent
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    fig.tight_layout()
    if path is not None:
        save_figure(fig, path)
    return fig
