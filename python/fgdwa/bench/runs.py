"""The table of a benchmark's runs, shared by ``fgdwa barn`` and ``fgdwa dynamic``:
one :class:`Run` per episode (its runs.csv row and what failures.png draws of
it), the per-planner summary and its terminal table, and the files
runs.csv, summary.json and failures.png.
"""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional, Sequence

import numpy as np

from fgdwa.bench.report import json_safe
from fgdwa.io.table import Table

OUTCOMES = ("success", "collision", "timeout")


@dataclass
class Run:
    """One run's row of runs.csv, plus the trace failures.png draws (a
    dynamic field's runs add the movers' routes and discs)."""

    row: dict
    cells: np.ndarray  # (rows, cols) the world's grid (1: on the map, 2: missing from it)
    extent: tuple  # (x0, x1, y0, y1) m, the grid's
    poses: np.ndarray  # (steps + 1, 3)
    paths: list  # (cycle, (n, 2) points) per global path followed
    scan_map: Optional[np.ndarray] = None  # scan mode: the robot's map at the end
    scan_extent: Optional[tuple] = None  # (x0, x1, y0, y1) m, scan_map's; None: the world grid's
    label: str = ""  # names the world in the figure; default "world <id>"
    routes: list = field(default_factory=list)  # (k, 2) waypoints of each moving obstacle's route, closed
    discs: list = field(default_factory=list)  # (x, y, radius) of each moving obstacle when the run ended

    @property
    def outcome(self) -> str:
        return self.row["outcome"]

    @property
    def title(self) -> str:
        return self.label or f"world {self.row['world']}"


def run_timing(wall: float, cycle_times) -> dict:
    """A run's cost per control cycle (ms): the Navigator's step (mean, 95th
    percentile) and the simulator's own share, everything else the run's wall
    time held (world, lidar, referee, set-up)."""
    cycle_times = np.asarray(cycle_times, dtype=float)
    if not len(cycle_times):
        return {"cycle_ms_mean": float("nan"), "cycle_ms_p95": float("nan"), "sim_ms_mean": float("nan")}
    return {"cycle_ms_mean": 1e3 * float(np.mean(cycle_times)),
            "cycle_ms_p95": 1e3 * float(np.percentile(cycle_times, 95)),
            "sim_ms_mean": 1e3 * max(0.0, wall - float(np.sum(cycle_times))) / len(cycle_times)}


def episode_columns(result, wall: float) -> dict:
    """The columns every benchmark takes from an episode (an EpisodeResult that
    ran ``wall`` seconds): simulated time, mileage, clearance, replans, cycles
    spent backing up, the cost per cycle, the wall time and why a failed run ended;
    and for failures.png the goal (``goal_x``, ``goal_y``, m) and, after a
    collision, the point of contact (``contact_x``, ``contact_y``, m; NaN
    otherwise), what was hit (``hit``: "a wall", "mover 3", ...; "" otherwise)
    and how far a mover that appeared on the robot had jumped within the step
    (``jumped``, m; 0 otherwise: referee.Contact)."""
    paths, contact, goal = result.context.paths, result.collision, result.context.goal
    goal = (float("nan"), float("nan")) if goal is None else goal
    return {"time": result.summary.sim_time, "mileage": result.summary.mileage,
            "min_clearance": result.summary.min_clearance, "replans": max(0, len(paths) - 1),
            "backing_up": result.trace.statuses.count("BackingUp"),
            **run_timing(wall, result.trace.cycle_times), "wall_time": wall, "reason": result.summary.reason,
            "goal_x": float(goal[0]), "goal_y": float(goal[1]),
            "contact_x": float("nan") if contact is None else contact.point[0],
            "contact_y": float("nan") if contact is None else contact.point[1],
            "hit": "" if contact is None else contact.what,
            "jumped": 0.0 if contact is None else contact.jumped}


def paths_followed(result) -> list:
    """(cycle, points) of every global path an episode followed; its one given path when it never replanned."""
    context = result.context
    if context.paths:
        return context.paths
    return [] if context.global_path is None else [(0, context.global_path)]


def summarize(runs: Sequence[Run], outcomes: Sequence[str] = OUTCOMES) -> dict:
    """Per planner, in order of first appearance: n, the rate of each outcome,
    collision_jumped (when the rows have ``jumped``: the rate of collisions with
    a mover that appeared on the robot, jumping within one step), mean_time (s,
    successful runs; NaN when none), mean_score and mean_time_score (all runs;
    when the rows have a score, a time_score) and the mean planning cycle (ms)."""
    table = {}
    for planner in dict.fromkeys(run.row["planner"] for run in runs):
        rows = [run.row for run in runs if run.row["planner"] == planner]
        n = len(rows)
        times = [r["time"] for r in rows if r["success"]]
        entry = {
            "n": n,
            **{outcome: sum(r["outcome"] == outcome for r in rows) / n for outcome in outcomes},
            **({"collision_jumped": sum(r["outcome"] == "collision" and r["jumped"] > 0 for r in rows) / n}
               if all("jumped" in r for r in rows) else {}),
            "mean_time": float(np.mean(times)) if times else float("nan"),
        }
        for key in ("score", "time_score"):
            if all(key in r for r in rows):
                entry[f"mean_{key}"] = float(np.mean([r[key] for r in rows]))
        for key in ("cycle_ms_mean", "sim_ms_mean"):
            if all(key in r for r in rows):
                entry[key] = float(np.nanmean([r[key] for r in rows]))
        table[planner] = entry
    return table


def format_table(summary: dict, title: str, outcomes: Sequence[str] = OUTCOMES) -> str:
    """The terminal table of a :func:`summarize` summary: one line per planner."""
    columns = [("n", lambda s: str(s["n"]))] + [(o, lambda s, o=o: f"{s[o]:.3f}") for o in outcomes]
    # Movers that jump (a looping animation going back to its start) only where some did.
    if any(s.get("collision_jumped", 0.0) > 0 for s in summary.values()):
        columns.insert(outcomes.index("collision") + 2 if "collision" in outcomes else len(columns),
                       ("of them jumped", lambda s: f"{s.get('collision_jumped', 0.0):.3f}"))
    columns.append(("mean time", lambda s: "-" if math.isnan(s["mean_time"]) else f"{s['mean_time']:.1f} s"))
    for key, header in (("mean_score", "mean score"), ("mean_time_score", "time score")):
        if all(key in s for s in summary.values()):
            columns.append((header, lambda s, key=key: f"{s[key]:.3f}"))
    columns.append(("cycle ms", lambda s: f"{s['cycle_ms_mean']:.2f}"))
    if all("sim_ms_mean" in s for s in summary.values()):
        columns.append(("sim ms", lambda s: f"{s['sim_ms_mean']:.2f}"))
    rows = [[planner] + [cell(s) for _, cell in columns] for planner, s in summary.items()]
    return Table(["planner"] + [header for header, _ in columns], rows, title).text()


def write_run_outputs(runs: Sequence[Run], out_dir, fields: Sequence[str], head: dict, figure: bool = True,
                      outcomes: Sequence[str] = OUTCOMES) -> dict:
    """Write runs.csv (columns ``fields``), summary.json (``head`` then the
    per-planner summary) and (``figure``) failures.png into ``out_dir``;
    return the summary."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "runs.csv", "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(fields))
        writer.writeheader()
        for run in runs:
            writer.writerow({k: _csv_value(run.row[k]) for k in fields})
    summary = summarize(runs, outcomes)
    document = {**head, "planners": json_safe(summary)}
    (out / "summary.json").write_text(json.dumps(document, indent=2) + "\n")
    if figure:
        from fgdwa.plot.failures import plot_failures

        plot_failures(runs, out / "failures.png")
    return summary


def written_files(runs: Sequence[Run], wall: float, out_dir, figure: bool) -> str:
    """The closing line of a benchmark command: how many runs, how long, which files."""
    return (f"{len(runs)} runs in {wall:.1f} s; wrote {Path(out_dir) / 'runs.csv'}, summary.json"
            + (", failures.png" if figure else ""))


def _csv_value(value):
    if isinstance(value, float):
        return "" if math.isnan(value) else f"{value:.6g}"
    return value
