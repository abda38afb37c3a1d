"""The robot's own map, grown from its scans, and the global path kept on it.

:class:`ScanNavigator` is what an episode with ``mapping="scan"`` runs each
cycle: the scan's hits go into a :class:`fgdwa.ScanMap`; the local planner gets
the map's new distance field; and the global path is replanned from the robot's
position when the part still ahead of it has become blocked, no more often than
every ``replan_interval`` cycles.

A robot can also stall where the path looks open: a gap that the footprint
passes only at an angle the local planner never tries, or a local minimum of
its cost. With ``stall_cycles`` set, a robot that has moved less than
``stall_distance`` over that many cycles gives up the stretch of path just
ahead: those cells are closed to the global planner (not to the local one, and
not in the map), the robot backs up straight for ``backup_cycles`` cycles
while its map shows the way behind clear (a rectangular robot wedged in a gap
cannot turn there), and the path is replanned from where it stops. With a
known map the navigator starts from it (:meth:`ScanNavigator.with_map`) and
does only this.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import DistanceField, FgdwaError, GlobalPath, GlobalStatus, OccupancyGrid, Scan, ScanMap, path_blocked
from fgdwa.global_planning import plan_global

MAPPING_MODES = ("known", "scan")


def check_mapping(mapping: str) -> str:
    """``mapping`` when it names a mode, else FgdwaError listing the modes."""
    if mapping not in MAPPING_MODES:
        raise FgdwaError(f"mapping = {mapping!r}: expected one of {', '.join(MAPPING_MODES)}")
    return mapping


@dataclass
class ScanUpdate:
    """What one cycle's scan changed."""

    new_cells: int  # cells marked occupied by this scan
    field: Optional[DistanceField]  # the map's distance field after the scan (None while the map is empty)
    path: Optional[GlobalPath]  # the new global path when one was planned this cycle, else None


class ScanNavigator:
    """The map a robot builds from its scans and the global path it keeps on it.

    ``layout`` gives the map's cells (size, resolution, origin; its contents are
    ignored). The path is planned by A* with obstacles inflated by each of
    ``inflation_radii`` in turn, the first that finds a way winning; a plan
    that finds none keeps the old path. Unknown space counts as free, so the
    first path is the straight way to the goal.
    """

    def __init__(self, layout: OccupancyGrid, goal, inflation_radii: Sequence[float], blocked_clearance: float,
                 replan_interval: int = 5, follow_path: bool = True, stall_cycles: Optional[int] = None,
                 stall_distance: float = 0.1, give_up_length: float = 0.6, keep_clear: float = 0.3,
                 backup_cycles: int = 10, backup_speed: float = 0.2):
        if not isinstance(replan_interval, (int, np.integer)) or replan_interval < 1:
            raise FgdwaError(f"replan_interval = {replan_interval!r}: must be an integer >= 1 (cycles)")
        if stall_cycles is not None and (not isinstance(stall_cycles, (int, np.integer)) or stall_cycles < 1):
            raise FgdwaError(f"stall_cycles = {stall_cycles!r}: must be None or an integer >= 1 (cycles)")
        if not isinstance(backup_cycles, (int, np.integer)) or backup_cycles < 0:
            raise FgdwaError(f"backup_cycles = {backup_cycles!r}: must be an integer >= 0 (cycles)")
        for name, value in (("backup_speed", backup_speed), ("stall_distance", stall_distance), ("give_up_length", give_up_length),
                            ("keep_clear", keep_clear)):
            if not (np.isfinite(value) and value >= 0):
                raise FgdwaError(f"{name} = {value!r}: must be a finite distance >= 0 (m)")
        radii = [float(r) for r in inflation_radii]
        if not radii or not all(np.isfinite(r) and r >= 0 for r in radii):
            raise FgdwaError(f"inflation_radii = {inflation_radii!r}: expected one or more finite radii >= 0 (m)")
        if not (np.isfinite(blocked_clearance) and blocked_clearance >= 0):
            raise FgdwaError(f"blocked_clearance = {blocked_clearance!r}: must be a finite distance >= 0 (m)")
        self.map = ScanMap(layout)
        self.goal = np.asarray(goal, dtype=float)
        self.inflation_radii = radii
        self.blocked_clearance = float(blocked_clearance)
        self.replan_interval = int(replan_interval)
        self.follow_path = follow_path
        self.stall_cycles = None if stall_cycles is None else int(stall_cycles)
        self.stall_distance = float(stall_distance)
        self.give_up_length = float(give_up_length)
        self.keep_clear = float(keep_clear)
        self.backup_cycles = int(backup_cycles)
        self.backup_speed = float(backup_speed)  # m/s
        self.backing_up = 0  # cycles of backing up left
        self.scanning = True
        self.path: Optional[GlobalPath] = None
        self.paths: list = []  # every path followed, in order: (cycle, (n, 2) points)
        self.stalls = 0
        self._closed = np.zeros((layout.rows, layout.cols), dtype=np.uint8)  # given-up cells
        # Positions of the last stall_cycles + 1 cycles: the oldest is stall_cycles ago.
        self._recent = deque(maxlen=None if stall_cycles is None else int(stall_cycles) + 1)
        self._last_plan_cycle: Optional[int] = None
        self._replan_now = False

    @classmethod
    def with_map(cls, grid: OccupancyGrid, goal, inflation_radii: Sequence[float], blocked_clearance: float,
                 **options) -> "ScanNavigator":
        """A navigator that knows ``grid`` from the start and ignores scans."""
        navigator = cls(grid, goal, inflation_radii, blocked_clearance, **options)
        occupied = np.argwhere(grid.cells != 0)
        if len(occupied):
            centres = np.asarray(grid.origin) + (occupied[:, ::-1] + 0.5) * grid.resolution
            navigator.map.mark(centres)
        navigator.scanning = False
        return navigator

    def follow(self, path: Optional[GlobalPath], cycle: int = 0) -> None:
        """Take ``path`` (planned elsewhere, e.g. on the known map) as the one to keep."""
        self.path = path
        if path is not None:
            self.paths.append((cycle, path.points))

    def update(self, scan: Optional[Scan], position, cycle: int) -> ScanUpdate:
        """Integrate this cycle's scan taken at ``position`` and replan if needed."""
        position = np.asarray(position, dtype=float)
        new_cells = self.map.integrate(scan) if self.scanning and scan is not None else 0
        field = self.map.field() if self.map.occupied_count else None
        new_path = None
        if self.follow_path:
            if self._stalled(position):
                self._give_up_ahead(position)
                self.backing_up = self.backup_cycles
                self._replan_now = True
            if self.backing_up == 0 and (self._replan_now or (self._due(cycle) and self._blocked(position, field))):
                new_path = self._plan(position, cycle)
        return ScanUpdate(new_cells, field, new_path)

    def _blocked(self, position: np.ndarray, field: Optional[DistanceField]) -> bool:
        if self.path is None:
            return True
        return field is not None and path_blocked(self.path, position, field, self.blocked_clearance)

    def backed_up(self, done: bool) -> None:
        """The loop's report after a cycle of backing up; ``done`` ends it early
        (the way behind is not clear). The path is replanned next cycle."""
        self.backing_up = 0 if done else max(0, self.backing_up - 1)
        self._replan_now = True

    def _stalled(self, position: np.ndarray) -> bool:
        if self.stall_cycles is None or self.path is None:
            return False
        self._recent.append(position)
        if len(self._recent) < self._recent.maxlen or np.hypot(*(position - self._recent[0])) >= self.stall_distance:
            return False
        self._recent.clear()
        self.stalls += 1
        return True

    def _give_up_ahead(self, position: np.ndarray) -> None:
        """Close the cells of the path's next ``give_up_length`` metres, except
        within ``keep_clear`` of the robot (the planner must start somewhere free)."""
        grid = self.map.grid
        res = grid.resolution
        s0 = self.path.project(position).arc_length
        for s in np.arange(s0, min(s0 + self.give_up_length, self.path.length) + 1e-9, 0.5 * res):
            point = np.asarray(self.path.point_at(float(s)))
            if np.hypot(*(point - position)) < self.keep_clear or np.hypot(*(point - self.goal)) < self.keep_clear:
                continue
            col, row = np.floor((point - np.asarray(grid.origin)) / res).astype(int)
            if 0 <= row < grid.rows and 0 <= col < grid.cols:
                self._closed[row, col] = 1

    def _due(self, cycle: int) -> bool:
        return self._last_plan_cycle is None or cycle - self._last_plan_cycle >= self.replan_interval

    def _plan(self, position, cycle: int) -> Optional[GlobalPath]:
        self._last_plan_cycle = cycle
        self._replan_now = False
        grid = self.map.grid
        if self._closed.any():
            grid = OccupancyGrid(np.maximum(grid.cells, self._closed), grid.resolution, grid.origin)
        for radius in self.inflation_radii:
            try:
                plan = plan_global(grid, position, self.goal, method="astar", inflation_radius=radius)
            except FgdwaError:  # start or goal cell marked occupied: no way from here on this map
                continue
            if plan.status == GlobalStatus.Found:
                self.follow(GlobalPath(np.asarray(plan.path, dtype=float)), cycle)
                return self.path
        return None
