"""Figures of episodes: map, executed path and the last cycle's rollout fan; and
the drawing pieces every other figure shares (:func:`save_figure`,
:func:`draw_world`, :func:`footprint_patch`, :func:`world_legend`).

Every element drawn gets a legend entry: the map layers through proxy patches
(an image has none of its own), the colour bar through its label, which names
the score, the cycle it belongs to and which end is better.
"""

from __future__ import annotations

import textwrap
from pathlib import Path
from typing import Optional

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from fgdwa._core import Footprint  # noqa: E402
from fgdwa.sim.episode import EpisodeResult  # noqa: E402
from fgdwa.sim.referee import placed_outline  # noqa: E402,F401 (one formula, drawn here too)
from fgdwa.sim.world import World  # noqa: E402

# The map layers' colour maps and the value range each is drawn over; a cell of value 1 takes
# the colour the legend shows.
MAP_STYLE = ("Greys", 1.6)
HIDDEN_STYLE = ("Oranges", 1.3)
TERRAIN_STYLE = ("copper_r", 5.0)
MOVER_COLOUR = "tab:purple"
FAN_COLOURS = "viridis"


def save_figure(fig, path, dpi: int = 120, **options) -> Path:
    """Writes ``fig`` to ``path`` (its folder made as needed) and closes it."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=dpi, **options)
    plt.close(fig)
    return path


def _layer_colour(style, value: float = 1.0):
    cmap, vmax = style
    return plt.get_cmap(cmap)(value / vmax)


def world_legend(world: World, t: Optional[float] = 0.0) -> list:
    """Legend entries (proxy artists) of what :func:`draw_world` draws of ``world``:
    each terrain grade present, the map, the obstacles missing from it and, unless
    ``t`` is None, the moving obstacles at time ``t``."""
    handles = []
    if world.terrain is not None:
        grades = np.asarray(world.terrain.grades)
        for grade in range(1, 5):
            if np.any(grades == grade):
                factor = world.passing_factors[grade]
                what = "entering it is a fall" if grade == 4 else f"speed x{factor:g}"
                handles.append(Patch(facecolor=_layer_colour(TERRAIN_STYLE, grade), alpha=0.6,
                                     label=f"terrain grade {grade} ({what})"))
    if world.grid is not None:
        handles.append(Patch(facecolor=_layer_colour(MAP_STYLE), label="map (known to the robot)"))
    if world.hidden is not None and np.any(world.hidden.cells):
        handles.append(Patch(facecolor=_layer_colour(HIDDEN_STYLE), label="obstacles missing from the map"))
    if t is not None and world.has_moving:
        handles.append(Line2D([], [], marker="o", linestyle="none", markersize=10, color=MOVER_COLOUR, alpha=0.7,
                              label=f"moving obstacles at t = {t:.1f} s, numbered"))
    return handles


def draw_world(ax, world: World, t: Optional[float] = 0.0) -> list:
    """Terrain grades in browns, the map in grey, obstacles missing from it in
    orange, moving obstacles as circles at time ``t`` (none when ``t`` is None),
    each with its number (the index a collision's reason names). Returns the
    legend entries of what it drew (:func:`world_legend`)."""
    if world.terrain is not None:
        grades = np.ma.masked_equal(world.terrain.grades, 0)
        ax.imshow(grades, cmap=TERRAIN_STYLE[0], vmin=0, vmax=TERRAIN_STYLE[1], origin="lower",
                  extent=world.terrain.extent, interpolation="nearest", alpha=0.6)
    if world.grid is not None:
        cells = np.ma.masked_equal(world.grid.cells, 0) if world.terrain is not None else world.grid.cells
        ax.imshow(cells, cmap=MAP_STYLE[0], vmin=0, vmax=MAP_STYLE[1], origin="lower",
                  extent=world.grid.extent, interpolation="nearest")
    if world.hidden is not None:
        hidden = np.ma.masked_equal(world.hidden.cells, 0)
        ax.imshow(hidden, cmap=HIDDEN_STYLE[0], vmin=0, vmax=HIDDEN_STYLE[1], origin="lower",
                  extent=world.hidden.extent, interpolation="nearest")
    if t is not None:
        for index, disc in enumerate(world.discs_at(t)):
            ax.add_patch(plt.Circle(disc.center, max(disc.radius, 0.05), color=MOVER_COLOUR, alpha=0.7))
            ax.text(*disc.center, str(index), ha="center", va="center", fontsize=8, color="white", clip_on=True)
    return world_legend(world, t)


def score_label(cycle: str) -> str:
    """The colour bar's label of a fan coloured by total score, for ``cycle`` (e.g. "cycle 88, t = 13.20 s")."""
    return f"total score of each rollout, {cycle}\n(higher is better; the highest is chosen)"


def draw_rollout_fan(ax, rollouts: np.ndarray, totals: np.ndarray, best_index: int, cycle: str = "the last cycle",
                     detail: str = "") -> list:
    """Every sample's rollout of one cycle (``cycle`` names it in the legend,
    ``detail`` adds e.g. its number and time on the colour bar), coloured by its
    total score with a colour bar saying so; rejected ones dashed grey; the
    chosen one red. Returns the legend entries of what it drew."""
    handles = []
    if rollouts is None or len(rollouts) == 0:
        return handles
    admissible = np.isfinite(totals)
    segments = [r[:, :2] for r in rollouts]
    rejected = [s for s, ok in zip(segments, admissible) if not ok]
    if rejected:
        ax.add_collection(LineCollection(rejected, colors="0.6", linewidths=0.5, linestyles="dashed"))
        handles.append(Line2D([], [], color="0.6", linewidth=0.8, linestyle="--",
                              label=f"rollouts rejected in {cycle} ({len(rejected)})"))
    if admissible.any():
        kept = [s for s, ok in zip(segments, admissible) if ok]
        lines = LineCollection(kept, cmap=FAN_COLOURS, linewidths=0.8)
        lines.set_array(totals[admissible])
        ax.add_collection(lines)
        bar = plt.colorbar(lines, ax=ax, shrink=0.8, pad=0.02)
        bar.set_label(score_label(", ".join(filter(None, [cycle, detail]))), fontsize=8)
        handles.append(Line2D([], [], color=plt.get_cmap(FAN_COLOURS)(0.6), linewidth=1.2,
                              label=f"rollouts scored in {cycle} ({len(kept)}; colour: score)"))
    if best_index >= 0:
        (chosen,) = ax.plot(*rollouts[best_index, :, :2].T, color="red", linewidth=2.0,
                            label=f"rollout chosen in {cycle}")
        handles.append(chosen)
    return handles


def footprint_patch(footprint, pose, **style):
    """The footprint as it is, placed at pose: a circle or the polygon."""
    if footprint.is_circle:
        return plt.Circle(tuple(pose[:2]), footprint.radius, **style)
    return plt.Polygon(placed_outline(footprint.vertices, pose), closed=True, **style)


def plot_episode(result: EpisodeResult, world: World, goal, path: Optional[Path] = None,
                 title: str = "", footprint=None):
    """Map, executed path, start and goal, the footprint (default a 0.25 m circle) at
    the end, and the rollouts the planner scored in its last cycle, each with a
    legend entry; a collision's point of contact is marked."""
    fig, ax = plt.subplots(figsize=(12, 5.8), layout="constrained")
    context, poses = result.context, result.motion.poses
    summary = result.summary
    handles = draw_world(ax, world, summary.sim_time)
    if context.global_path is not None:
        handles += ax.plot(*context.global_path.T, color="tab:red", linewidth=1.0, linestyle="--",
                           label="global path (the last one followed)")
        handles += ax.plot(*context.key_nodes.T, "+", color="tab:red", markersize=10, markeredgewidth=2,
                           label="key nodes")
    handles += ax.plot(*poses[:, :2].T, color="tab:blue", linewidth=1.8, label="executed path")
    ax.add_patch(footprint_patch(footprint if footprint is not None else Footprint.circle(0.25), poses[-1],
                                 fill=False, color="tab:blue", linewidth=1.5))
    handles.append(Line2D([], [], marker="o", linestyle="none", markersize=10, markerfacecolor="none",
                          color="tab:blue", label="footprint at the end"))
    if context.last_plan is not None:
        last = max(summary.steps - 1, 0)
        dt = summary.sim_time / summary.steps if summary.steps else 0.0
        handles += draw_rollout_fan(ax, context.last_rollouts, np.asarray(context.last_plan.total),
                                    context.last_plan.best_index, detail=f"cycle {last} at t = {last * dt:.2f} s")
    handles += ax.plot(*poses[0, :2], "o", color="tab:green", markersize=9, label="start")
    handles += ax.plot(*np.asarray(goal)[:2], "*", color="tab:orange", markersize=15, label="goal")
    contact = result.collision
    if contact is not None:
        handles += ax.plot(*contact.point, "X", color="red", markeredgecolor="k", markersize=13, zorder=6,
                           label=f"point of contact ({contact.what})")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    m = result.metrics()
    heading = title or f"{m['outcome']}: {m['steps']} steps, {m['mileage']:.2f} m, " \
                       f"min clearance {m['min_clearance']:.2f} m"
    if summary.reason:
        heading += "\n" + textwrap.fill(summary.reason, 90)
    ax.set_title(heading, fontsize=9)
    fig.legend(handles=handles, loc="outside right upper", fontsize=8)
    if world.grid is not None:
        x0, x1, y0, y1 = world.grid.extent
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    if path is not None:
        save_figure(fig, path, bbox_inches="tight")
    return fig
