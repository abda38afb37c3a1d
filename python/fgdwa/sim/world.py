"""What exists in a simulated world, and what of it the planners know."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import Disc, FgdwaError, OccupancyGrid, TerrainGrid
from fgdwa.file_limits import short_repr

MOVER_MODES = ("loop", "back_and_forth", "once")


@dataclass(frozen=True)
class MovingObstacle:
    """A disc moving along waypoints at a constant speed, or at a constant velocity.

    ``waypoints`` ((k, 2), k >= 2, m) are followed at ``speed`` (m/s): ``loop``
    returns from the last to the first, ``back_and_forth`` reverses at the ends,
    ``once`` stops at the last. With no waypoints the disc starts at ``start``
    and moves at ``velocity`` (m/s). Before ``start_delay`` (s) it waits at its
    first position; ``phase`` (s) shifts its clock, so trials can start it at
    different points of its cycle.
    """

    radius: float
    waypoints: Optional[np.ndarray] = None
    speed: float = 0.0
    mode: str = "loop"
    start: Optional[tuple] = None
    velocity: tuple = (0.0, 0.0)
    start_delay: float = 0.0
    phase: float = 0.0

    def __post_init__(self):
        if not (np.isfinite(self.radius) and self.radius > 0):
            raise FgdwaError(f"moving obstacle radius = {short_repr(self.radius)}: must be > 0")
        if self.mode not in MOVER_MODES:
            raise FgdwaError(f"moving obstacle mode = {short_repr(self.mode)}: expected one of {MOVER_MODES}")
        for name in ("start_delay", "phase", "speed"):
            value = getattr(self, name)
            if not np.isfinite(value) or (name != "phase" and value < 0):
                raise FgdwaError(f"moving obstacle {name} = {short_repr(value)}: must be a finite number >= 0")
        if self.waypoints is not None:
            points = np.asarray(self.waypoints, dtype=float)
            if points.ndim != 2 or points.shape[1] != 2 or len(points) < 2 or not np.all(np.isfinite(points)):
                raise FgdwaError(f"moving obstacle waypoints: expected (k >= 2, 2) finite points, got {short_repr(self.waypoints)}")
            object.__setattr__(self, "waypoints", points)
            if self.speed <= 0:
                raise FgdwaError(f"moving obstacle speed = {short_repr(self.speed)}: must be > 0 to follow waypoints")
        else:
            start = np.asarray(self.start if self.start is not None else (np.nan, np.nan), dtype=float)
            velocity = np.asarray(self.velocity, dtype=float)
            if start.shape != (2,) or not np.all(np.isfinite(start)):
                raise FgdwaError(f"moving obstacle start = {short_repr(self.start)}: needed (x, y) when there are no waypoints")
            if velocity.shape != (2,) or not np.all(np.isfinite(velocity)):
                raise FgdwaError(f"moving obstacle velocity = {short_repr(self.velocity)}: expected (vx, vy)")

    @cached_property
    def route(self) -> np.ndarray:
        """The waypoints in travel order: closed for a loop, there and back for
        back_and_forth; None without waypoints. Computed once."""
        points = self.waypoints
        if points is None:
            return None
        if self.mode == "loop":
            return np.vstack([points, points[:1]])
        if self.mode == "back_and_forth":
            return np.vstack([points, points[-2::-1]])
        return points

    @cached_property
    def _legs(self) -> tuple:
        """(leg vectors, leg lengths, cumulative lengths) of the route."""
        legs = np.diff(self.route, axis=0)
        lengths = np.hypot(legs[:, 0], legs[:, 1])
        return legs, lengths, np.cumsum(lengths)

    @property
    def period(self) -> float:
        """Time (s) to come back to where it was: one pass of the route at its speed; 0 without waypoints."""
        if self.waypoints is None or self.speed <= 0:
            return 0.0
        return float(self._legs[2][-1] / self.speed)

    def state_at(self, t: float) -> tuple:
        """(position, velocity) at time ``t`` (s) of the episode."""
        clock = max(0.0, t + self.phase - self.start_delay)
        moving = t + self.phase >= self.start_delay
        if self.waypoints is None:
            start, velocity = np.asarray(self.start, float), np.asarray(self.velocity, float)
            return start + clock * velocity, velocity if moving else np.zeros(2)
        route = self.route
        legs, lengths, ends = self._legs
        total = ends[-1]
        travelled = clock * self.speed
        if total <= 0:
            return route[0].copy(), np.zeros(2)
        if self.mode == "once" and travelled >= total:
            return route[-1].copy(), np.zeros(2)
        travelled %= total
        i = int(np.searchsorted(ends, travelled, side="right"))
        i = min(i, len(legs) - 1)
        into = travelled - (ends[i] - lengths[i])
        direction = legs[i] / lengths[i] if lengths[i] > 0 else np.zeros(2)
        return route[i] + into * direction, direction * self.speed if moving else np.zeros(2)

    def disc_at(self, t: float) -> Disc:
        position, velocity = self.state_at(t)
        return Disc(position, self.radius, velocity)


@dataclass(frozen=True)
class World:
    """What exists, and what of it the planners know.

    ``grid`` is the map, known to the global and local planners. ``hidden``
    (same cell layout) holds static obstacles missing from the map; ``discs``
    move at constant velocity and ``movers`` along their routes. The planner
    sees hidden obstacles and moving ones only through the lidar, except that
    ``discs_known`` hands it the moving obstacles' true positions and
    velocities. ``terrain`` (same layout) holds slope grades 0-4: each grade
    scales the robot's top speed by ``passing_factors[grade]``, and entering
    grade 4 is a fall.
    """

    grid: Optional[OccupancyGrid] = None
    discs: Sequence[Disc] = ()
    hidden: Optional[OccupancyGrid] = None
    discs_known: bool = True
    movers: Sequence[MovingObstacle] = ()
    terrain: Optional[TerrainGrid] = None
    passing_factors: tuple = (1.0, 0.8, 0.6, 0.4, 0.0)

    def __post_init__(self):
        for name in ("hidden", "terrain"):
            layer = getattr(self, name)
            if layer is None:
                continue
            if self.grid is None:
                raise FgdwaError(f"{name} needs a map grid with the same cell layout")
            origin = getattr(layer, "origin", self.grid.origin)
            if tuple(layer.shape) != tuple(self.grid.shape) or layer.resolution != self.grid.resolution \
                    or tuple(origin) != tuple(self.grid.origin):
                raise FgdwaError(f"{name}: its layout {short_repr(layer)} differs from the map's {short_repr(self.grid)}")
        factors = np.asarray(self.passing_factors, dtype=float)
        if factors.shape != (5,) or not np.all((factors >= 0) & (factors <= 1)):
            raise FgdwaError(f"passing_factors = {short_repr(self.passing_factors)}: expected 5 values in [0, 1]")

    def discs_at(self, t: float) -> list:
        """Every moving obstacle as a Disc at time ``t``, with its velocity then."""
        discs = [Disc(d.center_at(t), d.radius, d.velocity) for d in self.discs]
        return discs + [m.disc_at(t) for m in self.movers]

    @property
    def has_moving(self) -> bool:
        return bool(self.discs) or bool(self.movers)

    def true_grid(self) -> Optional[OccupancyGrid]:
        """The map with the hidden obstacles added: what really stands there."""
        if self.hidden is None:
            return self.grid
        return OccupancyGrid(self.grid.cells | self.hidden.cells, self.grid.resolution, self.grid.origin)

    def grade_at(self, point) -> int:
        """Slope grade under a point (0 without terrain)."""
        return 0 if self.terrain is None else int(self.terrain.grade_at(point))
