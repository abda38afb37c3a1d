"""The referee of an episode: whether a step touched an obstacle or fell, and the
metrics of the executed run (docs/algorithms.md, "Episodes and metrics").

It judges with what really stands there (the exact FCL ``CollisionWorld`` and
the true distance field), never with what the navigator believes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import CollisionWorld, Disc, DistanceField, FgdwaError, Footprint, OccupancyGrid, wrap_angle
from fgdwa.sim.world import World
from fgdwa.file_limits import short_repr

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


def path_length(points: np.ndarray) -> float:
    """Length of a polyline given as (n, >=2) points."""
    points = np.asarray(points, dtype=float)
    if len(points) < 2:
        return 0.0
    return float(np.sum(np.hypot(*np.diff(points[:, :2], axis=0).T)))


def _along_step(before, after, spacing: float, other_travel: float = 0.0):
    """(f, x, y) along the straight part of a step, f in (0, 1], in pieces short
    enough that the robot and something else moving ``other_travel`` metres in
    the same step close at most ``spacing`` metres between two samples."""
    x0, y0, x1, y1 = before[0], before[1], after[0], after[1]
    pieces = max(1, int(np.ceil((np.hypot(x1 - x0, y1 - y0) + other_travel) / spacing)))
    for i in range(1, pieces + 1):
        f = i / pieces
        yield f, x0 + f * (x1 - x0), y0 + f * (y1 - y0)


def collides_during_step(truth: CollisionWorld, footprint: Footprint, before, after, t: float, dt: float,
                         spacing: float = 0.05, discs_at=None, start_clearance: Optional[float] = None) -> bool:
    """Whether the footprint touches an obstacle anywhere along one step,
    whoever moves into whom.

    A step turns first and then moves straight along the new heading. The turn
    is swept at the start position (a polygon's outline moves; a circle's does
    not): each heading's exact clearance bounds how far the outline may turn
    before it could touch, so a contact deeper than ``TURN_RESOLUTION`` rad
    times the footprint's radius is never missed. The drive is checked at
    instants of the step close enough that neither the robot nor any disc moves
    more than ``spacing`` metres between two of them together: the robot's
    position lies on the segment from ``before`` to ``after``, and the discs are
    where ``discs_at(time)`` puts them (the truth's own discs are restored
    afterwards) or, without it, the truth's discs moved at their velocities.
    ``start_clearance``, when given, is the truth's clearance of the footprint
    at ``before`` at time ``t`` (as ``truth.clearance`` gives it): the turn's
    sweep starts from it instead of measuring it again.
    """
    if start_clearance is not None and (isinstance(start_clearance, bool) or
                                        not isinstance(start_clearance, (int, float, np.floating, np.integer))
                                        or np.isnan(start_clearance)):
        raise FgdwaError(f"start_clearance = {short_repr(start_clearance)}: must be a number (m, +inf when nothing is near) "
                         "or None")
    if discs_at is None:
        discs = truth.discs
        return _step_collides(truth, footprint, before, after, t, dt, spacing, _disc_travel(discs, dt), None,
                              start_clearance)
    # Copies: the truth hands out views of its own discs, which setting new ones overwrites.
    kept = [Disc(d.center, d.radius, d.velocity) for d in truth.discs]
    try:
        travel = max(_disc_travel(discs_at(t), dt), _disc_travel(discs_at(t + dt), dt))
        return _step_collides(truth, footprint, before, after, t, dt, spacing, travel, discs_at, start_clearance)
    finally:
        truth.discs = kept


@dataclass(frozen=True)
class Contact:
    """What a collision touched, where, and who moved into whom (world frame)."""

    point: tuple  # (x, y) m: the obstacle's point deepest inside (or nearest) the robot's true outline
    obstacle: str  # "wall" (on the map), "hidden" (a static obstacle missing from the map) or "mover"
    mover: int = -1  # the mover's index in World.discs_at(t) (World.discs, then World.movers); -1 otherwise
    mover_closing: float = 0.0  # m/s at which the mover closed the gap (0 for a static obstacle)
    robot_closing: float = 0.0  # m/s at which the robot did
    jumped: float = 0.0  # m the mover jumped within the step, beyond what its speed covers by more than its radius; else 0

    @property
    def what(self) -> str:
        """What was hit, as words: "a wall", "an obstacle missing from the map" or "mover 3"."""
        if self.obstacle == "mover":
            return f"mover {self.mover}"
        return "an obstacle missing from the map" if self.obstacle == "hidden" else "a wall"

    @property
    def reason(self) -> str:
        """The collision in a line: what was touched, who moved into whom, where."""
        where = f"at ({self.point[0]:.2f}, {self.point[1]:.2f})"
        if self.obstacle != "mover":
            return f"collision: the robot drove into {self.what} {where}"
        if self.jumped > 0.0:
            # A looping animation that goes back to its start, a person stepping out from behind
            # something: nothing the robot saw a step before was there.
            return (f"collision: {self.what} appeared on the robot {where} (it jumped {self.jumped:.2f} m within the "
                    "step, farther than its speed takes it)")
        if max(self.mover_closing, self.robot_closing) <= 0.0:
            who = f"the robot touched {self.what} as neither closed in (turning, or grazing it)"
        elif self.mover_closing > self.robot_closing:
            who = f"{self.what} drove into the robot"
        else:
            who = f"the robot drove into {self.what}"
        # Rounded before formatting, so that a speed of -0.001 m/s reads 0.00, not -0.00.
        mover, robot = round(self.mover_closing, 2) + 0.0, round(self.robot_closing, 2) + 0.0
        return f"collision: {who} {where} (closing at {mover:.2f} m/s, the robot at {robot:.2f} m/s)"


def collision_contact(truth: CollisionWorld, footprint: Footprint, pose, velocity,
                      grid: Optional[OccupancyGrid] = None, hidden: Optional[OccupancyGrid] = None,
                      before: Optional[Sequence] = None, dt: float = 0.0) -> Contact:
    """What the footprint at ``pose`` touched, where, and who moved into whom.

    The obstacle nearest the footprint is the one touched: the static one (the
    robot drove into it; ``grid`` is the truth's grid, which places the point of
    contact, and a cell set in ``hidden`` was missing from the map) or a moving
    disc, which drove into the robot when its velocity closed the gap faster
    than the robot's own ``velocity`` (vx, vy, m/s) did; when neither closed in,
    the contact came from a turn or a graze. The point of contact is the
    obstacle's point with the smallest signed distance to the footprint: the
    deepest inside it, or the nearest when the two only touch. ``before``, the
    discs (in the same order) ``dt`` seconds earlier, at the step's start, tells
    a mover that jumped: one that moved farther than its speed at either end
    of the step takes it, by more than its radius."""
    discs = [Disc(d.center, d.radius, d.velocity) for d in truth.discs]
    if before is not None:
        if len(before) != len(discs):
            raise FgdwaError(f"before: {len(before)} discs for the truth's {len(discs)}")
        if not (isinstance(dt, (int, float)) and math.isfinite(dt) and dt >= 0):
            raise FgdwaError(f"dt = {short_repr(dt)}: must be a finite number of seconds >= 0")
    pose = tuple(float(v) for v in pose)
    gaps = [footprint.signed_distance(pose, d.center) - d.radius for d in discs]
    truth.discs = []
    try:
        static = truth.clearance(footprint, pose, 0.0)
    finally:
        truth.discs = discs
    if not gaps or static <= min(gaps):
        point, cell = _wall_contact(footprint, pose, grid)
        missing = hidden is not None and cell is not None and bool(np.asarray(hidden.cells)[cell])
        return Contact(point=point, obstacle="hidden" if missing else "wall")
    index = int(np.argmin(gaps))
    mover = discs[index]
    away = np.array(pose[:2]) - np.array(mover.center)
    unit = away / max(float(np.hypot(*away)), 1e-12)
    jumped = 0.0
    if before is not None:
        start = before[index]
        moved = float(np.hypot(*(np.asarray(mover.center) - np.asarray(start.center))))
        speed = max(float(np.hypot(*start.velocity)), float(np.hypot(*mover.velocity)))
        if moved - speed * dt > mover.radius:
            jumped = moved
    return Contact(point=_disc_contact(footprint, pose, mover, unit), obstacle="mover", mover=index,
                   mover_closing=float(np.dot(mover.velocity, unit)), robot_closing=float(np.dot(velocity, -unit)),
                   jumped=jumped)


def collision_reason(truth: CollisionWorld, footprint: Footprint, pose, velocity,
                     grid: Optional[OccupancyGrid] = None, hidden: Optional[OccupancyGrid] = None) -> str:
    """:func:`collision_contact`'s line: what was touched, who moved into whom, where."""
    return collision_contact(truth, footprint, pose, velocity, grid, hidden).reason


def _best_point(footprint: Footprint, pose, candidates: np.ndarray) -> int:
    """The index of the candidate point with the smallest signed distance to the footprint at ``pose``."""
    return int(np.argmin([footprint.signed_distance(pose, tuple(p)) for p in candidates]))


def _disc_contact(footprint: Footprint, pose, disc, toward: np.ndarray) -> tuple:
    """The point of the disc's edge deepest in the footprint (its edge sampled every 2 degrees and
    toward the robot's centre)."""
    angles = np.radians(np.arange(0.0, 360.0, 2.0))
    directions = np.vstack([toward, np.column_stack([np.cos(angles), np.sin(angles)])])
    edge = np.asarray(disc.center, dtype=float) + disc.radius * directions
    x, y = edge[_best_point(footprint, pose, edge)]
    return float(x), float(y)


def _wall_contact(footprint: Footprint, pose, grid: Optional[OccupancyGrid]):
    """((x, y), (row, col)): the point of the occupied cells near ``pose`` deepest in
    the footprint, and its cell; the robot's centre and None without a grid or a
    cell near. A cell's candidates are its corners, the middles of its sides, its
    centre and its points nearest the robot's centre and each polygon vertex,
    which places the contact within half a cell."""
    centre = np.array(pose[:2])
    if grid is None:
        return (float(centre[0]), float(centre[1])), None
    cells = np.asarray(grid.cells)
    resolution, origin = grid.resolution, np.asarray(grid.origin, dtype=float)
    reach = footprint.radius + 3 * resolution
    low = np.floor((centre - reach - origin) / resolution).astype(int)
    high = np.ceil((centre + reach - origin) / resolution).astype(int)
    rows = slice(max(low[1], 0), max(min(high[1], cells.shape[0]), 0))
    cols = slice(max(low[0], 0), max(min(high[0], cells.shape[1]), 0))
    occupied = np.argwhere(cells[rows, cols] != 0) + (rows.start, cols.start)
    if not len(occupied):
        return (float(centre[0]), float(centre[1])), None
    corners_low = origin + occupied[:, ::-1] * resolution  # (x, y) of each cell's lower-left corner
    anchors = [centre] if footprint.is_circle else [centre, *placed_outline(footprint.vertices, pose)]
    candidates, owners = [], []
    for offset in np.array(np.meshgrid([0.0, 0.5, 1.0], [0.0, 0.5, 1.0])).reshape(2, -1).T * resolution:
        candidates.append(corners_low + offset)
        owners.append(np.arange(len(occupied)))
    for anchor in anchors:
        candidates.append(np.clip(anchor, corners_low, corners_low + resolution))
        owners.append(np.arange(len(occupied)))
    candidates, owners = np.vstack(candidates), np.concatenate(owners)
    best = _best_point(footprint, pose, candidates)
    row, col = occupied[owners[best]]
    return (float(candidates[best, 0]), float(candidates[best, 1])), (int(row), int(col))


def placed_outline(vertices: np.ndarray, pose) -> np.ndarray:
    """A polygon footprint's (n, 2) vertices (robot frame) placed at pose (x, y, theta)."""
    x, y, theta = pose
    c, s = np.cos(theta), np.sin(theta)
    return np.asarray(vertices, dtype=float) @ np.array([[c, s], [-s, c]]) + (x, y)


def _disc_travel(discs, dt: float) -> float:
    """The farthest any of the discs moves in ``dt`` at its velocity, m."""
    return max((float(np.hypot(*d.velocity)) * dt for d in discs), default=0.0)


def _step_collides(truth, footprint, before, after, t, dt, spacing, disc_travel, discs_at, start_clearance) -> bool:
    def clock(time: float) -> float:
        """The time to query the truth at for the discs to be where they are at ``time``."""
        if discs_at is None:
            return time
        truth.discs = discs_at(time)
        return 0.0

    if not footprint.is_circle and _turn_collides(truth, footprint, before, after[2], clock(t), start_clearance):
        return True
    return any(truth.in_collision(footprint, (x, y, after[2]), clock(t + f * dt))
               for f, x, y in _along_step(before, after, spacing, disc_travel))


TURN_RESOLUTION = 1e-3  # rad, the smallest heading step of the referee's turn sweep


def _turn_collides(truth: CollisionWorld, footprint: Footprint, before, heading: float, t: float,
                   start_clearance: Optional[float] = None) -> bool:
    turn = wrap_angle(heading - before[2])
    turned = 0.0
    while True:
        if turned == 0.0 and start_clearance is not None:
            clearance = start_clearance
        else:
            clearance = truth.clearance(footprint, (before[0], before[1], before[2] + np.copysign(turned, turn)), t)
        if clearance <= 0.0:
            return True
        if turned >= abs(turn):
            return False
        # No point of the outline moves farther than radius x angle.
        turned = min(abs(turn), turned + max(clearance / footprint.radius, TURN_RESOLUTION))


def falls(world: World, before, after, spacing: float = 0.05) -> bool:
    """Whether the robot's centre enters grade-4 terrain during a step."""
    return any(world.grade_at((x, y)) >= 4 for _, x, y in _along_step(before, after, spacing))
