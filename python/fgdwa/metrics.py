"""Metrics of executed runs that need more than the run itself (docs/algorithms.md, "Episodes and metrics")."""

from __future__ import annotations

import numpy as np

from fgdwa._core import DistanceField

DANGER_MARGIN = 0.3  # m beyond the footprint's radius: the default danger clearance


def danger_points(path: np.ndarray, static: DistanceField, danger_clearance: float, spacing: float = 1.0,
                  step: float = 0.05) -> np.ndarray:
    """Points of the global path whose static clearance is below ``danger_clearance`` (m).

    The path is walked every ``step`` metres; of the points that qualify, one is
    kept per ``spacing`` metres of path (Figures 17-18's circled spots).
    """
    path = np.asarray(path, dtype=float)
    if len(path) < 2:
        return np.zeros((0, 2))
    legs = np.diff(path, axis=0)
    lengths = np.hypot(legs[:, 0], legs[:, 1])
    ends = np.concatenate([[0.0], np.cumsum(lengths)])
    s = np.arange(0.0, ends[-1] + 1e-12, step)
    x = np.interp(s, ends, path[:, 0])
    y = np.interp(s, ends, path[:, 1])
    points = np.column_stack([x, y])
    near = static.distance(points) < danger_clearance
    kept, last = [], -np.inf
    for arc, point, flag in zip(s, points, near):
        if flag and arc - last >= spacing:
            kept.append(point)
            last = arc
    return np.array(kept).reshape(-1, 2)


def danger_point_clearance(executed: np.ndarray, points: np.ndarray, static: DistanceField) -> float:
    """Mean, over danger points, of the obstacle distance at the executed position nearest to each."""
    executed = np.asarray(executed, dtype=float)[:, :2]
    if len(points) == 0 or len(executed) == 0:
        return float("nan")
    nearest = np.argmin(np.hypot(executed[None, :, 0] - points[:, None, 0], executed[None, :, 1] - points[:, None, 1]),
                        axis=1)
    return float(np.mean(static.distance(executed[nearest])))


def smoothness(commands: np.ndarray) -> float:
    """Sum of |change of omega| between consecutive commands (rad/s)."""
    commands = np.asarray(commands, dtype=float).reshape(-1, 2)
    return float(np.sum(np.abs(np.diff(commands[:, 1])))) if len(commands) > 1 else 0.0
