"""failures.png: the failed runs of ``fgdwa barn`` or ``fgdwa dynamic``, one small map each."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Sequence

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from fgdwa.plot.episode import save_figure  # noqa: E402

OUTCOME_COLOURS = {"collision": "tab:red", "timeout": "tab:orange", "failed": "tab:brown", "success": "tab:green"}
MAX_PANELS = 30


def plot_failures(runs: Sequence, path, max_panels: int = MAX_PANELS) -> Path:
    """Each failed run's map (grey, obstacles missing from the map darker; with
    ``--map scan`` what the robot had mapped in blue over it), its last global
    path (dashed), the moving obstacles' routes (dotted) and discs where they
    were at the end, and the executed path, ending in a cross where it collided
    or stopped. At most ``max_panels`` runs, in run
    order; with none failed, one panel says so."""
    failed = [run for run in runs if run.outcome != "success"]
    if not failed:
        fig, ax = plt.subplots(figsize=(6, 2))
        ax.axis("off")
        ax.text(0.5, 0.5, f"no failed run among {len(runs)}", ha="center", va="center", fontsize=12)
        return save_figure(fig, path)
    shown = failed[:max_panels]
    cols = min(5, len(shown))
    rows = math.ceil(len(shown) / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(3.6 * cols, 2.2 * rows + 0.6), squeeze=False)
    for ax in axes.flat:
        ax.axis("off")
    for ax, run in zip(axes.flat, shown):
        _draw_run(ax, run)
    title = f"{len(failed)} failed run(s) of {len(runs)}"
    if len(failed) > len(shown):
        title += f" (first {len(shown)} shown)"
    fig.suptitle(title)
    fig.tight_layout()
    return save_figure(fig, path)


def _draw_run(ax, run) -> None:
    row = run.row
    cells = np.asarray(run.cells)
    extent = run.extent
    ax.imshow(cells, origin="lower", extent=extent, cmap="Greys", vmin=0, vmax=2.5, interpolation="nearest")
    if run.scan_map is not None:
        seen = np.ma.masked_where(np.asarray(run.scan_map) == 0, run.scan_map)
        ax.imshow(seen, origin="lower", extent=extent, cmap="winter", alpha=0.6, interpolation="nearest")
    if run.paths:
        points = np.asarray(run.paths[-1][1])
        ax.plot(points[:, 0], points[:, 1], "--", color="tab:purple", lw=0.8)
    for route in run.routes:
        route = np.asarray(route)
        ax.plot(route[:, 0], route[:, 1], ":", color="tab:blue", lw=0.8)
    for x, y, radius in run.discs:
        ax.add_patch(plt.Circle((x, y), radius, color="tab:blue", alpha=0.5))
    poses = np.asarray(run.poses)
    colour = OUTCOME_COLOURS.get(row["outcome"], "k")
    ax.plot(poses[:, 0], poses[:, 1], color=colour, lw=1.2)
    ax.plot(poses[-1, 0], poses[-1, 1], "x", color=colour, ms=7, mew=2)
    # Frame the obstacles and the run, not the empty rest of the map.
    occupied = np.argwhere(cells != 0)
    resolution = (extent[1] - extent[0]) / cells.shape[1]
    ys = np.concatenate([extent[2] + (occupied[:, 0] + 0.5) * resolution, poses[:, 1]])
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(ys.min() - 0.3, ys.max() + 0.3)
    ax.set_aspect("equal")
    ax.set_title(f"{run.title} {row['planner']}: {row['outcome']} ({row['time']:.0f} s)", fontsize=8)
    ax.axis("on")
    ax.set_xticks([])
    ax.set_yticks([])
