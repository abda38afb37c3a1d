"""Built-in scenarios, made in code so they need no file."""

from __future__ import annotations

import numpy as np

from fgdwa._core import OccupancyGrid, TerrainGrid
from fgdwa.sim.scenario import Scenario
from fgdwa.sim.world import World


def _fill(cells: np.ndarray, resolution: float, x0: float, y0: float, x1: float, y1: float) -> None:
    """Marks the cells of the rectangle [x0, x1] x [y0, y1] (metres) occupied."""
    c0, c1 = int(round(x0 / resolution)), int(round(x1 / resolution))
    r0, r1 = int(round(y0 / resolution)), int(round(y1 / resolution))
    cells[r0:r1, c0:c1] = 1


def _walled_room(rows: int, cols: int) -> np.ndarray:
    """Cells of a room whose border cells are walls."""
    cells = np.zeros((rows, cols), dtype=np.uint8)
    cells[0, :] = cells[-1, :] = 1
    cells[:, 0] = cells[:, -1] = 1
    return cells


def demo_scenario() -> Scenario:
    """A 12 m x 8 m room: blocks beside the straight line and a wall with a gap stand between start and goal."""
    resolution = 0.1
    cells = _walled_room(80, 120)
    _fill(cells, resolution, 3.0, 4.4, 3.6, 6.6)  # block just above the straight line
    _fill(cells, resolution, 5.6, 0.0, 6.0, 2.9)  # broken wall, lower part
    _fill(cells, resolution, 5.6, 5.1, 6.0, 8.0)  # broken wall, upper part: the gap is at y 2.9-5.1
    _fill(cells, resolution, 8.0, 2.2, 8.6, 3.7)  # block just below the straight line
    _fill(cells, resolution, 7.6, 5.6, 8.2, 6.6)
    _fill(cells, resolution, 2.0, 1.2, 2.6, 2.0)
    _fill(cells, resolution, 9.6, 4.9, 10.0, 5.9)
    grid = OccupancyGrid(cells, resolution, (0.0, 0.0))
    return Scenario(
        name="demo",
        world=World(grid=grid),
        start=(1.0, 4.0, 0.0),
        goal=(11.0, 4.0),
        description="Blocks beside the straight line and a wall with a 2.2 m gap between start and goal.",
    )


def c_trap_scenario() -> Scenario:
    """A C-shaped obstacle group open toward the start, right between start and goal.

    Heading straight for the goal leads into the C's pocket, where every way
    forward is blocked: plain DWA is trapped. The global path runs around the C."""
    resolution = 0.1
    cells = _walled_room(100, 140)
    _fill(cells, resolution, 8.0, 2.5, 8.5, 7.5)  # back of the C, facing the start
    _fill(cells, resolution, 5.0, 2.5, 8.5, 3.0)  # lower arm
    _fill(cells, resolution, 5.0, 7.0, 8.5, 7.5)  # upper arm
    grid = OccupancyGrid(cells, resolution, (0.0, 0.0))
    return Scenario(
        name="c_trap",
        world=World(grid=grid),
        start=(1.5, 5.0, 0.0),
        goal=(12.5, 5.0),
        description="A C-shaped obstacle group open toward the start, between start and goal.",
    )


def hidden_obstacles_scenario() -> Scenario:
    """An open room whose map misses two blocks lying on the straight path.

    The global path runs straight through where the blocks stand; only the lidar
    shows them, so a planner that does not sense collides, and one that does
    must leave the path to get round them."""
    resolution = 0.1
    cells = _walled_room(60, 140)
    hidden = np.zeros_like(cells)
    _fill(hidden, resolution, 5.0, 2.4, 5.6, 3.6)
    _fill(hidden, resolution, 9.0, 2.7, 9.4, 4.2)
    grid = OccupancyGrid(cells, resolution, (0.0, 0.0))
    return Scenario(
        name="hidden_obstacles",
        world=World(grid=grid, hidden=OccupancyGrid(hidden, resolution, (0.0, 0.0))),
        start=(1.0, 3.0, 0.0),
        goal=(13.0, 3.0),
        description="Two blocks on the straight path that the map does not show.",
    )


def unknown_beside_path_scenario() -> Scenario:
    """Obstacles missing from the map stand just beside the straight global path.

    The robot passes close by each; a planner that weighs safety more where the
    detect window fills keeps a wider berth there and drives freely elsewhere."""
    resolution = 0.1
    cells = _walled_room(60, 160)
    hidden = np.zeros_like(cells)
    _fill(hidden, resolution, 4.0, 3.5, 4.8, 4.5)  # above the path, 0.5 m from it
    _fill(hidden, resolution, 7.5, 1.6, 8.3, 2.5)  # below the path, 0.5 m from it
    _fill(hidden, resolution, 11.0, 3.5, 11.6, 4.3)
    grid = OccupancyGrid(cells, resolution, (0.0, 0.0))
    return Scenario(
        name="unknown_beside_path",
        world=World(grid=grid, hidden=OccupancyGrid(hidden, resolution, (0.0, 0.0))),
        start=(1.0, 3.0, 0.0),
        goal=(15.0, 3.0),
        description="Obstacles missing from the map, 0.5 m beside the straight global path.",
    )


def dead_end_scenario() -> Scenario:
    """A pocket open toward the start whose back wall the map lacks.

    The global path runs straight through the pocket to the goal beyond it;
    the lidar shows the back wall as the robot approaches. A navigator that
    learns obstacles (NavigatorParams.learn_obstacles, the default) adds it to
    its map and replans round the pocket; one whose map never learns needs a
    recovery: it stalls at the wall, gives up the stretch of path ahead, backs
    out, and the replanned path goes round the pocket."""
    resolution = 0.1
    cells = _walled_room(100, 140)
    _fill(cells, resolution, 4.0, 3.8, 9.0, 4.0)  # lower side of the pocket
    _fill(cells, resolution, 4.0, 6.0, 9.0, 6.2)  # upper side
    hidden = np.zeros_like(cells)
    _fill(hidden, resolution, 8.8, 4.0, 9.0, 6.0)  # its back wall, missing from the map
    grid = OccupancyGrid(cells, resolution, (0.0, 0.0))
    return Scenario(
        name="dead_end",
        world=World(grid=grid, hidden=OccupancyGrid(hidden, resolution, (0.0, 0.0))),
        start=(1.5, 5.0, 0.0),
        goal=(12.5, 5.0),
        description="A pocket the global path enters because the map lacks its back wall: learnt from the scans, or "
                    "left by a recovery.",
    )


def terrain_temptation_scenario() -> Scenario:
    """A block missing from the map stands on the path beside a grade-4 slope.

    Dodging it below is the short way round, onto ground the robot cannot
    enter; above, the way is clear but longer. A planner blind to terrain
    dodges onto the slope and falls."""
    resolution = 0.1
    cells = _walled_room(80, 140)
    hidden = np.zeros_like(cells)
    _fill(hidden, resolution, 6.0, 3.5, 6.6, 4.8)  # on the path, reaching further up than down
    grades = np.zeros_like(cells)
    _fill(grades, resolution, 4.0, 0.1, 9.0, 3.2)  # the slope below the path
    grades[grades == 1] = 4
    _fill(grades, resolution, 4.0, 3.2, 9.0, 3.4)  # its edge, steep but passable
    grades[grades == 1] = 3
    grid = OccupancyGrid(cells, resolution, (0.0, 0.0))
    return Scenario(
        name="terrain_temptation",
        world=World(grid=grid, hidden=OccupancyGrid(hidden, resolution, (0.0, 0.0)),
                    terrain=TerrainGrid(grades, resolution, (0.0, 0.0))),
        start=(1.5, 4.0, 0.0),
        goal=(12.5, 4.0),
        description="A block missing from the map on the path; dodging it below leads onto a grade-4 slope.",
    )
