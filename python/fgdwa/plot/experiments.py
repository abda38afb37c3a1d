"""Figures of experiments (PNG): executed paths on the map, box plots with p-values,
the fuzzy weights over time (the paper's Figure 20) and the control surfaces."""

from __future__ import annotations

import textwrap
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.transforms import blended_transform_factory  # noqa: E402

from fgdwa.bench.experiments import (METRIC_BY_KEY, ExperimentResult, TrialRecord, planner_label,  # noqa: E402
                                     resolve_scenario)
from fgdwa.bench.report import fmt_p  # noqa: E402
from fgdwa.bench.stats import finite  # noqa: E402
from fgdwa.plot.episode import draw_world, save_figure  # noqa: E402
from fgdwa.plot.fuzzy import plot_control_surfaces  # noqa: E402

DPI = 100
COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:purple", "tab:brown")
BOX_METRICS = ("planning_time", "steps", "mileage", "danger_clearance")


def _save(fig, path: Path) -> Path:
    return save_figure(fig, path, dpi=DPI, bbox_inches="tight")


def danger_points_of(scenario, global_path: np.ndarray) -> np.ndarray:
    """The global path's danger points, as the episodes compute them."""
    from fgdwa._core import DistanceField
    from fgdwa.sim.referee import DANGER_MARGIN, danger_points

    grid = scenario.world.true_grid()
    if grid is None or global_path is None:
        return np.zeros((0, 2))
    return danger_points(global_path, DistanceField(grid), scenario.footprint.radius + DANGER_MARGIN)


def paths_figure(result: ExperimentResult, path: Path, trial: int = 0, scenario=None) -> Path:
    """The map with the global path, its key nodes and danger points, and every planner's
    executed path: trial ``trial`` bold, the other trials faint."""
    from fgdwa.sim.scenario import trial_variation

    scenario = scenario if scenario is not None else resolve_scenario(result.spec.scenario)
    first = result.record(result.spec.proposed, trial)
    _, world, _ = trial_variation(scenario, first.seed)
    fig, ax = plt.subplots(figsize=(9, 6.5))
    world_entries = draw_world(ax, world, 0.0)
    routes = [mover.route for mover in world.movers if mover.route is not None]
    for k, route in enumerate(routes):
        ax.plot(*route.T, ":", color="tab:purple", linewidth=0.8, label="moving obstacles' routes" if k == 0 else None)
    reference = next((r for r in result.records if r.global_path is not None and r.trial == trial), None)
    if reference is not None:
        ax.plot(*reference.global_path.T, "--", color="tab:red", linewidth=1.2, label="global path")
        if reference.key_nodes is not None:
            ax.plot(*reference.key_nodes.T, "+", color="tab:blue", markersize=11, markeredgewidth=2,
                    label="key nodes")
        danger = danger_points_of(scenario, reference.global_path)
        if len(danger):
            ax.scatter(*danger.T, s=160, facecolors="none", edgecolors="gold", linewidths=1.8, label="danger points")
    for k, planner in enumerate(result.spec.planners):
        colour = COLOURS[k % len(COLOURS)]
        for r in result.planner_records(planner):
            if r.trial != trial:
                ax.plot(*r.poses[:, :2].T, color=colour, linewidth=0.6, alpha=0.25)
        r = result.record(planner, trial)
        ax.plot(*r.poses[:, :2].T, color=colour, linewidth=2.0,
                label=f"{planner_label(planner)} ({r.metrics['outcome']})")
        if r.metrics["outcome"] != "success":
            ax.plot(*r.poses[-1, :2], "x", color=colour, markersize=12, markeredgewidth=2.5)
    ax.plot(*first.poses[0, :2], "o", color="tab:green", markersize=9, label="start")
    ax.plot(*np.asarray(scenario.goal)[:2], "*", color="tab:orange", markersize=16, label="goal")
    ax.set_aspect("equal")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    if world.grid is not None:
        x0, x1, y0, y1 = world.grid.extent
        ax.set_xlim(x0, x1)
        ax.set_ylim(y0, y1)
    ax.set_title(f"{result.spec.name.upper()}: executed paths, trial {trial + 1} (seed {first.seed}) bold, "
                 f"the other {result.trials - 1} faint")
    ax.legend(handles=world_entries + ax.get_legend_handles_labels()[0], loc="upper left",
              bbox_to_anchor=(1.01, 1.0), fontsize=8)
    fig.tight_layout()
    return _save(fig, path)


def boxplot_figure(result: ExperimentResult, path: Path, metrics=BOX_METRICS) -> Path:
    """A box plot per metric over the successful runs, the p-values against the proposed planner in the title."""
    comparisons = {(c.metric, c.other): c for c in result.comparisons()}
    planners = result.spec.planners
    fig, axes = plt.subplots(1, len(metrics), figsize=(4.3 * len(metrics), 4.8))
    axes = np.atleast_1d(axes)
    for ax, key in zip(axes, metrics):
        data = [finite(result.values(p, key)) for p in planners]
        positions = np.arange(1, len(planners) + 1)
        filled = [(pos, d) for pos, d in zip(positions, data) if len(d)]
        if filled:
            box = ax.boxplot([d for _, d in filled], positions=[pos for pos, _ in filled], widths=0.55,
                             patch_artist=True)
            for patch, (pos, _) in zip(box["boxes"], filled):
                patch.set_facecolor(COLOURS[(pos - 1) % len(COLOURS)])
                patch.set_alpha(0.45)
            for pos, d in filled:
                jitter = np.linspace(-0.12, 0.12, len(d)) if len(d) > 1 else np.zeros(1)
                ax.plot(pos + jitter, d, ".", color="k", markersize=4)
        column = blended_transform_factory(ax.transData, ax.transAxes)
        for pos, d in zip(positions, data):
            if not len(d):
                ax.text(pos, 0.5, "no successful\nrun", transform=column, ha="center", va="center", fontsize=8,
                        color="0.4")
        ax.set_xticks(positions)
        ax.set_xlim(0.4, len(planners) + 0.6)
        ax.set_xticklabels([textwrap.fill(planner_label(p), 15) for p in planners], fontsize=8)
        lines = [METRIC_BY_KEY[key].label]
        for other in result.spec.others:
            c = comparisons[(key, other)]
            lines.append(f"vs {planner_label(other)}: t p={fmt_p(c.welch_p)}, U p={fmt_p(c.mwu_p)}")
        ax.set_title("\n".join(lines), fontsize=8)
        ax.grid(axis="y", alpha=0.3)
    fig.suptitle(f"{result.spec.name.upper()}: successful runs of {result.trials} trials per planner", fontsize=10)
    fig.tight_layout()
    return _save(fig, path)


def weights_figure(record: TrialRecord, path: Path, title: str = "") -> Path:
    """beta and delta over time (the paper's Figure 20), with the inputs I and D below."""
    t = np.arange(len(record.beta)) * (record.dt if np.isfinite(record.dt) else 1.0)
    fig, axes = plt.subplots(3, 1, figsize=(8, 7), sharex=True)
    axes[0].plot(t, record.beta, color="tab:blue")
    axes[0].set_ylabel("beta (safety weight)")
    axes[1].plot(t, record.delta, color="tab:green")
    axes[1].set_ylabel("delta (similarity weight)")
    axes[2].plot(t, record.density, color="tab:orange", label="I, obstacle density")
    axes[2].plot(t, record.deviation, color="tab:red", label="D, path deviation (m)")
    axes[2].set_ylabel("fuzzy inputs")
    axes[2].legend(fontsize=8, loc="upper right")
    axes[2].set_xlabel("simulated time [s]")
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(title or f"{planner_label(record.planner)} weights, trial {record.trial + 1} (seed {record.seed}): "
                          f"{record.metrics['outcome']}", fontsize=10)
    fig.tight_layout()
    return _save(fig, path)


def experiment_figures(result: ExperimentResult, directory: Path, trial: int = 0) -> dict:
    """Every figure of an experiment, as {caption: path}."""
    directory = Path(directory)
    name = result.spec.name
    scenario = resolve_scenario(result.spec.scenario)
    figures = {
        f"{name.upper()}: map, global path, key nodes and executed paths":
            paths_figure(result, directory / f"{name}_paths.png", trial, scenario),
        f"{name.upper()}: metrics of the successful runs, p-values against {planner_label(result.spec.proposed)}":
            boxplot_figure(result, directory / f"{name}_boxplots.png"),
    }
    fuzzy = [p for p in result.spec.planners if p == "fgdwa"]
    if fuzzy:
        record = result.record(fuzzy[0], trial)
        figures[f"{name.upper()}: FGDWA's beta and delta over one run (cf. the paper's Figure 20)"] = \
            weights_figure(record, directory / f"{name}_weights.png")
    return figures


def control_surfaces_figure(path: Path) -> Path:
    """The paper's fuzzy controller as control surfaces beta(I, D) and delta(I, D)."""
    return _save(plot_control_surfaces("paper", None, points=41), path)


CONTROL_SURFACES = "control surfaces"


@dataclass(frozen=True)
class FigureJob:
    """Figures one worker draws: an experiment's into ``directory`` (which exists), or without a
    result the fuzzy controller's control surfaces as ``directory``/control_surfaces.png."""

    directory: str
    result: Optional[ExperimentResult] = None


def draw_figures(job: FigureJob) -> dict:
    """A job's figures, as {caption: path} ({CONTROL_SURFACES: path} for the surfaces)."""
    if job.result is None:
        return {CONTROL_SURFACES: control_surfaces_figure(Path(job.directory) / "control_surfaces.png")}
    return experiment_figures(job.result, Path(job.directory))
