"""failures.png: the failed runs of ``fgdwa barn`` or ``fgdwa dynamic``, one small map each."""

from __future__ import annotations

import math
import textwrap
from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

from fgdwa.plot.episode import save_figure  # noqa: E402

OUTCOME_COLOURS = {"collision": "tab:red", "timeout": "tab:orange", "failed": "tab:brown", "success": "tab:green"}
MAX_PANELS = 30
CELLS = ("Greys", 2.5)  # colour map and top of the range of the grid's values (1: on the map, 2: missing from it)
SEEN = "winter"  # the robot's own map, with --map scan
MOVERS = "tab:blue"


def plot_failures(runs: Sequence, path, max_panels: int = MAX_PANELS) -> Path:
    """Write :func:`failures_figure` of ``runs`` to ``path``."""
    return save_figure(failures_figure(runs, max_panels), path)


def failures_figure(runs: Sequence, max_panels: int = MAX_PANELS):
    """Each failed run's map (grey, obstacles missing from the map darker; with
    ``--map scan`` what the robot had mapped in blue over it), its last global
    path (dashed), the moving obstacles' routes (dotted) and discs where they
    were at the end (numbered as the reasons name them), start and goal, and the
    executed path, ending in a cross where it stopped; a collision's point of
    contact is marked and named. Each panel has axes in metres and the run's
    reason under its title; one legend explains every mark. At most
    ``max_panels`` runs, in run order; with none failed, one panel says so."""
    failed = [run for run in runs if run.outcome != "success"]
    if not failed:
        fig, ax = plt.subplots(figsize=(6, 2))
        ax.axis("off")
        ax.text(0.5, 0.5, f"no failed run among {len(runs)}", ha="center", va="center", fontsize=12)
        return fig
    shown = failed[:max_panels]
    cols = min(4, len(shown))
    rows = math.ceil(len(shown) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.4 * cols, 3.8 * rows + 0.9), squeeze=False, layout="constrained")
    fig.get_layout_engine().set(h_pad=0.2)  # inches: room for a three-line title under the row above
    for ax in axes.flat:
        ax.axis("off")
    for ax, run in zip(axes.flat, shown):
        _draw_run(ax, run)
    title = f"{len(failed)} failed run(s) of {len(runs)}"
    if len(failed) > len(shown):
        title += f" (first {len(shown)} shown)"
    fig.suptitle(title)
    fig.legend(handles=legend_entries(shown), loc="outside lower center", ncols=min(5, 2 * cols), fontsize=8)
    return fig


def legend_entries(runs: Sequence) -> list:
    """One legend entry per kind of mark the panels of ``runs`` show."""
    cells = np.concatenate([np.unique(np.asarray(run.cells)) for run in runs])
    cmap, top = plt.get_cmap(CELLS[0]), CELLS[1]
    entries = [Patch(facecolor=cmap(1 / top), label="map")]
    if np.any(cells == 2):
        entries.append(Patch(facecolor=cmap(2 / top), label="obstacles missing from the map"))
    if any(run.scan_map is not None for run in runs):
        entries.append(Patch(facecolor=plt.get_cmap(SEEN)(1.0), alpha=0.6, label="what the robot mapped"))
    if any(run.paths for run in runs):
        entries.append(Line2D([], [], linestyle="--", color="tab:purple", lw=0.8, label="last global path"))
    if any(run.routes for run in runs):
        entries.append(Line2D([], [], linestyle=":", color=MOVERS, lw=0.8, label="moving obstacles' routes"))
    if any(run.discs for run in runs):
        entries.append(Line2D([], [], marker="o", linestyle="none", color=MOVERS, alpha=0.5, markersize=9,
                              label="moving obstacles at the end, numbered"))
    for outcome in dict.fromkeys(run.outcome for run in runs):
        entries.append(Line2D([], [], color=OUTCOME_COLOURS.get(outcome, "k"), marker="x", mew=2,
                              label=f"path driven, x where it ended ({outcome})"))
    entries.append(Line2D([], [], marker="o", linestyle="none", color="tab:green", label="start"))
    entries.append(Line2D([], [], marker="*", linestyle="none", color="tab:orange", markersize=11, label="goal"))
    if any(_contact(run) is not None for run in runs):
        entries.append(Line2D([], [], marker="X", linestyle="none", color="red", markeredgecolor="k", markersize=10,
                              label="point of contact (what was hit)"))
    return entries


def _contact(run):
    """((x, y), what) of a run's collision, from its row; None without one."""
    x, y = run.row.get("contact_x", math.nan), run.row.get("contact_y", math.nan)
    if not (np.isfinite(x) and np.isfinite(y)):
        return None
    return (x, y), run.row.get("hit", "")


def _draw_run(ax, run) -> None:
    row = run.row
    cells = np.asarray(run.cells)
    extent = run.extent
    ax.imshow(cells, origin="lower", extent=extent, cmap=CELLS[0], vmin=0, vmax=CELLS[1], interpolation="nearest")
    if run.scan_map is not None:
        seen = np.ma.masked_where(np.asarray(run.scan_map) == 0, run.scan_map)
        ax.imshow(seen, origin="lower", extent=run.scan_extent or extent, cmap=SEEN, alpha=0.6, interpolation="nearest")
    if run.paths:
        points = np.asarray(run.paths[-1][1])
        ax.plot(points[:, 0], points[:, 1], "--", color="tab:purple", lw=0.8)
    for route in run.routes:
        route = np.asarray(route)
        ax.plot(route[:, 0], route[:, 1], ":", color=MOVERS, lw=0.8)
    for index, (x, y, radius) in enumerate(run.discs):
        ax.add_patch(plt.Circle((x, y), radius, color=MOVERS, alpha=0.5))
        ax.text(x, y, str(index), ha="center", va="center", fontsize=6, color="white", clip_on=True)
    poses = np.asarray(run.poses)
    colour = OUTCOME_COLOURS.get(row["outcome"], "k")
    ax.plot(poses[:, 0], poses[:, 1], color=colour, lw=1.2)
    ax.plot(poses[-1, 0], poses[-1, 1], "x", color=colour, ms=7, mew=2)
    ax.plot(poses[0, 0], poses[0, 1], "o", color="tab:green", ms=5)
    goal = np.array([row.get("goal_x", math.nan), row.get("goal_y", math.nan)], dtype=float)
    if np.all(np.isfinite(goal)):
        ax.plot(*goal, "*", color="tab:orange", ms=10, markeredgecolor="k", markeredgewidth=0.4)
    contact = _contact(run)
    if contact is not None:
        (x, y), what = contact
        ax.plot(x, y, "X", color="red", markeredgecolor="k", ms=9, zorder=5)
        ax.annotate(what, (x, y), xytext=(6, 6), textcoords="offset points", fontsize=7, color="darkred",
                    bbox=dict(boxstyle="round,pad=0.15", facecolor="white", edgecolor="none", alpha=0.8))
    # Frame the obstacles, the run and its goal, not the empty rest of the map.
    occupied = np.argwhere(cells != 0)
    resolution = (extent[1] - extent[0]) / cells.shape[1]
    ys = np.concatenate([extent[2] + (occupied[:, 0] + 0.5) * resolution, poses[:, 1],
                         goal[1:] if np.isfinite(goal[1]) else []])
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(ys.min() - 0.3, ys.max() + 0.3)
    ax.set_aspect("equal")
    title = f"{run.title} {row['planner']}: {row['outcome']} ({row['time']:.0f} s)"
    reason = row.get("reason", "")
    if reason:
        title += "\n" + textwrap.fill(reason, 62)
    ax.set_title(title, fontsize=7)
    ax.axis("on")
    ax.tick_params(labelsize=6)
    ax.set_xlabel("x [m]", fontsize=7, labelpad=1)
    ax.set_ylabel("y [m]", fontsize=7, labelpad=1)
