import numpy as np
import pytest
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra

import fgdwa
from fgdwa.io.builtin import c_trap_scenario
from fgdwa.global_planning import global_methods, plan_global
from fgdwa.sim import run_episode
from conftest import random_block_grid

RISK = np.array([0.0, 0.5, 1.0, 2.0])


def grid_graph(blocked, grades, resolution, w_risk, unknown=None, unknown_cost=0.0):
    """The 8-connected graph A* searches: no corner cutting, cost = length x (1 + w_risk risk[grade of the cell
    entered]) x (1 + unknown_cost where that cell is unknown)."""
    unknown = np.zeros_like(blocked) if unknown is None else unknown
    rows, cols = blocked.shape
    index = np.arange(rows * cols).reshape(rows, cols)
    src, dst, weight = [], [], []
    for dr, dc in [(1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1)]:
        r0, r1 = max(0, -dr), rows - max(0, dr)
        c0, c1 = max(0, -dc), cols - max(0, dc)
        a = (slice(r0, r1), slice(c0, c1))
        b = (slice(r0 + dr, r1 + dr), slice(c0 + dc, c1 + dc))
        ok = ~blocked[a] & ~blocked[b]
        if dr and dc:
            ok &= ~blocked[(slice(r0, r1), slice(c0 + dc, c1 + dc))] & ~blocked[(slice(r0 + dr, r1 + dr), slice(c0, c1))]
        length = resolution * (np.sqrt(2.0) if dr and dc else 1.0)
        src.append(index[a][ok])
        dst.append(index[b][ok])
        weight.append(length * (1.0 + w_risk * RISK[grades[b][ok]]) * np.where(unknown[b][ok], 1.0 + unknown_cost, 1.0))
    n = rows * cols
    return csr_matrix((np.concatenate(weight), (np.concatenate(src), np.concatenate(dst))), shape=(n, n))


@pytest.mark.parametrize("seed", range(50))
def test_astar_cost_equals_dijkstra(seed):
    rng = np.random.default_rng(seed)
    cells = random_block_grid(rng, rows=40, cols=50, blocks=25, max_size=7)
    use_terrain = seed % 2 == 1
    grades = rng.integers(0, 5, size=cells.shape).astype(np.uint8) if use_terrain else np.zeros_like(cells)
    if use_terrain:
        grades[rng.random(cells.shape) < 0.7] = 0  # mostly flat, some steep patches
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    terrain = fgdwa.TerrainGrid(grades, 0.1) if use_terrain else None
    # Every third seed prices a few unknown patches.
    unknown = np.zeros(cells.shape, dtype=bool)
    if seed % 3 == 2:
        for _ in range(6):
            r, c = rng.integers(0, 35), rng.integers(0, 45)
            unknown[r:r + rng.integers(3, 12), c:c + rng.integers(3, 12)] = True
    unknown_cost = 2.0 if unknown.any() else 0.0
    planner = fgdwa.AStarPlanner(grid, inflation_radius=0.12, terrain=terrain,
                                 terrain_cost={"w_risk": 1.5, "risk": RISK}, unknown_cost=unknown_cost)
    planner.set_unknown(unknown)
    blocked = planner.blocked.astype(bool)
    free = np.argwhere(~blocked)
    start_cell, goal_cell = free[rng.integers(len(free))], free[rng.integers(len(free))]
    start = grid.cell_center(*start_cell)
    goal = grid.cell_center(*goal_cell)
    result = planner.plan(start, goal)
    distances = dijkstra(grid_graph(blocked, grades, 0.1, 1.5, unknown, unknown_cost),
                         indices=start_cell[0] * 50 + start_cell[1])
    expected = distances[goal_cell[0] * 50 + goal_cell[1]]
    if np.isinf(expected):
        assert result.status == fgdwa.GlobalStatus.NoPath
    else:
        assert result.status == fgdwa.GlobalStatus.Found
        assert result.cost == pytest.approx(expected, abs=1e-9)
        assert_path_clear(result.path, blocked, grid)


@pytest.mark.parametrize("side", [3, 10, 30])
def test_astar_goal_walled_in_is_no_path_unless_the_start_is_inside(side):
    """A goal in a walled room: no path from outside (whether the room is a few cells or more than the
    search walks from the goal before leaving it to the search), and a path from inside it."""
    cells = np.zeros((50, 50), dtype=np.uint8)
    lo, hi = 5, 5 + side + 1
    cells[lo, lo:hi + 1] = cells[hi, lo:hi + 1] = cells[lo:hi + 1, lo] = cells[lo:hi + 1, hi] = 1
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    planner = fgdwa.AStarPlanner(grid, inflation_radius=0.0)
    goal = grid.cell_center(lo + 1, lo + 1)
    assert planner.plan(grid.cell_center(45, 45), goal).status == fgdwa.GlobalStatus.NoPath
    inside = planner.plan(grid.cell_center(hi - 1, hi - 1), goal)
    assert inside.status == fgdwa.GlobalStatus.Found
    assert inside.cost == pytest.approx(0.1 * np.sqrt(2.0) * (side - 1), abs=1e-9)
    # A gap in the wall lets the search in.
    cells[hi, lo + 2] = 0
    opened = fgdwa.AStarPlanner(fgdwa.OccupancyGrid(cells, 0.1), inflation_radius=0.0)
    assert opened.plan(grid.cell_center(45, 45), goal).status == fgdwa.GlobalStatus.Found


def assert_path_clear(path, blocked, grid, spacing_cells=0.25):
    """Every point every quarter cell along the path lies on an unblocked cell (ends excepted)."""
    res = grid.resolution
    x0, _, y0, _ = grid.extent
    for a, b in zip(path[:-1], path[1:]):
        n = max(2, int(np.ceil(np.hypot(*(b - a)) / (spacing_cells * res))) + 1)
        for p in np.linspace(a, b, n):
            row, col = int((p[1] - y0) // res), int((p[0] - x0) // res)
            assert not blocked[row, col], f"path crosses blocked cell ({row}, {col}) at {p}"


def test_astar_detours_around_unknown_cells_when_they_cost():
    grid = fgdwa.OccupancyGrid(np.zeros((20, 40), dtype=np.uint8), 0.1)
    unknown = np.zeros((20, 40), dtype=bool)
    unknown[2:18, 18:22] = True  # a band across the straight line, open above and below
    straight = fgdwa.AStarPlanner(grid, inflation_radius=0.1)
    straight.set_unknown(unknown)
    through = straight.plan((0.5, 1.0), (3.5, 1.0))
    priced = fgdwa.AStarPlanner(grid, inflation_radius=0.1, unknown_cost=3.0)
    priced.set_unknown(unknown)
    around = priced.plan((0.5, 1.0), (3.5, 1.0))
    assert len(through.path) == 2 and through.cost == pytest.approx(3.0, abs=0.11)
    x, y = around.path[:, 0], around.path[:, 1]
    band = (x > 1.8) & (x < 2.2)
    assert np.all(np.interp(np.linspace(1.8, 2.2, 20), x, y) < 0.2) or np.all(
        np.interp(np.linspace(1.8, 2.2, 20), x, y) > 1.8), around.path
    assert not band.any() or np.all((y[band] < 0.2) | (y[band] > 1.8))
    with pytest.raises(fgdwa.FgdwaError, match="unknown"):
        priced.set_unknown(np.zeros((3, 3)))
    with pytest.raises(fgdwa.FgdwaError, match="unknown_cost"):
        fgdwa.AStarPlanner(grid, unknown_cost=-1.0)


def test_astar_simplified_path_never_crosses_the_inflated_grid(rng):
    for _ in range(20):
        cells = random_block_grid(rng, rows=60, cols=60, blocks=30)
        cells[:4, :4] = 0
        cells[-4:, -4:] = 0
        grid = fgdwa.OccupancyGrid(cells, 0.1)
        planner = fgdwa.AStarPlanner(grid, inflation_radius=0.1)
        result = planner.plan((0.15, 0.15), (5.85, 5.85))
        if result.found:
            assert len(result.path) >= 2
            assert_path_clear(result.path, planner.blocked.astype(bool), grid)


def test_astar_start_in_the_band_leaves_it_without_touching_obstacles():
    # The start sits 0.1 m below a wall, deep in the 0.3 m band: every
    # neighbour of its cell is banded too. Before, A* found no path.
    cells = np.zeros((30, 40), dtype=np.uint8)
    cells[10, :] = 1
    cells[6, 14:17] = 1  # an obstacle between start and goal
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    planner = fgdwa.AStarPlanner(grid, inflation_radius=0.3, simplify=False)
    start, goal = (1.05, 0.95), (3.5, 0.35)
    assert all(planner.blocked[9 + dr, 10 + dc] for dr in (-1, 0) for dc in (-1, 0, 1))
    result = planner.plan(start, goal)
    assert result.status == fgdwa.GlobalStatus.Found
    path = np.asarray(result.path)
    rows, cols = (path[:, 1] // 0.1).astype(int), (path[:, 0] // 0.1).astype(int)
    assert not cells[rows, cols].any()
    banded = planner.blocked.astype(bool)[rows, cols]
    from_start = np.hypot(path[:, 0] - start[0], path[:, 1] - start[1])
    assert np.all(from_start[banded] <= 0.3), "the band is open near the start only"
    assert not banded[-1]


def test_astar_is_deterministic(rng):
    cells = random_block_grid(rng, rows=60, cols=60, blocks=20)
    cells[:3, :3] = 0
    cells[-3:, -3:] = 0
    planner = fgdwa.AStarPlanner(fgdwa.OccupancyGrid(cells, 0.1), inflation_radius=0.0)
    a, b = planner.plan((0.1, 0.1), (5.9, 5.9)), planner.plan((0.1, 0.1), (5.9, 5.9))
    np.testing.assert_array_equal(a.path, b.path)


def test_grade_four_is_impassable_and_risk_detours():
    cells = np.zeros((30, 60), np.uint8)
    grades = np.zeros((30, 60), np.uint8)
    grades[:, 28:32] = 3  # a steep band across the map, with a flat gap at the top
    grades[25:, 28:32] = 0
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    terrain = fgdwa.TerrainGrid(grades, 0.1)
    cautious = fgdwa.AStarPlanner(grid, inflation_radius=0.0, terrain=terrain, terrain_cost={"w_risk": 10.0}).plan((0.5, 0.5), (5.5, 0.5))
    assert cautious.path[:, 1].max() > 2.5  # goes round through the flat gap
    bold = fgdwa.AStarPlanner(grid, inflation_radius=0.0, terrain=terrain, terrain_cost={"w_risk": 0.0}).plan((0.5, 0.5), (5.5, 0.5))
    assert bold.path[:, 1].max() < 0.6
    grades[25:, 28:32] = 4
    grades[:25, 28:32] = 4
    wall = fgdwa.AStarPlanner(grid, inflation_radius=0.0, terrain=fgdwa.TerrainGrid(grades, 0.1))
    assert wall.plan((0.5, 0.5), (5.5, 0.5)).status == fgdwa.GlobalStatus.NoPath


@pytest.mark.parametrize("method", ["ompl:RRTstar", "ompl:InformedRRTstar", "ompl:PRMstar", "ompl:BITstar"])
def test_ompl_paths_are_valid_and_no_shorter_than_the_straight_line(method):
    rng = np.random.default_rng(11)
    cells = random_block_grid(rng, rows=60, cols=80, blocks=18, max_size=10)
    cells[25:35, :8] = 0
    cells[25:35, -8:] = 0
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    start, goal = np.array([0.4, 3.0]), np.array([7.6, 3.0])
    result = plan_global(grid, start, goal, method=method, time_limit=10.0, max_iterations=3000, seed=3,
                         footprint=fgdwa.Footprint.circle(0.15))
    assert result.status == fgdwa.GlobalStatus.Found
    np.testing.assert_allclose(result.path[0], start)
    np.testing.assert_allclose(result.path[-1], goal)
    assert_path_clear(result.path, fgdwa.inflate(grid, 0.15).astype(bool), grid)
    length = np.sum(np.hypot(*np.diff(result.path, axis=0).T))
    assert length >= np.hypot(*(goal - start)) - 1e-9


def test_ompl_same_seed_same_path():
    rng = np.random.default_rng(5)
    cells = random_block_grid(rng, rows=50, cols=50, blocks=12)
    cells[:6, :6] = 0
    cells[-6:, -6:] = 0
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    runs = [plan_global(grid, (0.3, 0.3), (4.7, 4.7), method="ompl:RRTstar", time_limit=30.0, max_iterations=1500,
                        seed=seed,
                        footprint=fgdwa.Footprint.circle(0.1)) for seed in (7, 7)]
    assert runs[0].found
    np.testing.assert_array_equal(runs[0].path, runs[1].path)


def test_ompl_polygon_footprint_plans_in_se2():
    cells = np.zeros((40, 60), np.uint8)
    cells[:, 30] = 1
    cells[18:22, 30] = 0  # a gap 0.4 m wide: a 0.42 x 0.33 m robot passes only lengthwise
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    jackal = fgdwa.Footprint.polygon([[0.21, 0.165], [-0.21, 0.165], [-0.21, -0.165], [0.21, -0.165]])
    result = plan_global(grid, (1.0, 2.0), (5.0, 2.0), method="ompl:RRTConnect", time_limit=2.0, seed=1,
                         footprint=jackal)
    assert result.found
    # The returned path keeps positions only; whatever the heading, the footprint's
    # inscribed circle is free at every point, and the path goes through the gap.
    truth = fgdwa.CollisionWorld(grid)
    inscribed = fgdwa.Footprint.circle(jackal.inscribed_radius)
    poses = np.column_stack([result.path, np.zeros(len(result.path))])
    assert np.all(truth.clearance(inscribed, poses) > 0.0)
    assert np.all(np.abs(result.path[:, 1][np.abs(result.path[:, 0] - 3.05) < 0.1] - 2.0) < 0.2)


def test_plan_global_errors():
    grid = fgdwa.OccupancyGrid(np.pad(np.ones((2, 2), np.uint8), 4), 0.5)
    with pytest.raises(fgdwa.FgdwaError, match="method"):
        plan_global(grid, (0.2, 0.2), (4.5, 4.5), method="dijkstra")
    with pytest.raises(fgdwa.FgdwaError, match="time_limit"):
        plan_global(grid, (0.2, 0.2), (4.5, 4.5), method="astar", time_limit=1.0)
    with pytest.raises(fgdwa.FgdwaError, match="start .* inside an obstacle"):
        plan_global(grid, (2.2, 2.2), (4.5, 4.5))
    with pytest.raises(fgdwa.FgdwaError, match="goal .* inside an obstacle"):
        plan_global(grid, (0.2, 0.2), (2.2, 2.4), method="ompl:RRTstar")
    with pytest.raises(fgdwa.FgdwaError, match="goal .* outside the map"):
        plan_global(grid, (0.2, 0.2), (9.0, 0.0))
    with pytest.raises(fgdwa.FgdwaError, match="unknown OMPL planner"):
        plan_global(grid, (0.2, 0.2), (4.5, 4.5), method="ompl:Dijkstra")
    with pytest.raises(fgdwa.FgdwaError, match="grade"):
        fgdwa.TerrainGrid(np.full((3, 3), 5, np.uint8), 0.1)
    with pytest.raises(fgdwa.FgdwaError, match="terrain"):
        fgdwa.AStarPlanner(grid, terrain=fgdwa.TerrainGrid(np.zeros((3, 3), np.uint8), 0.1))
    with pytest.raises(fgdwa.FgdwaError, match="risk"):
        fgdwa.AStarPlanner(grid, terrain_cost={"risk": (0.0, -1.0, 0.0, 0.0)})
    with pytest.raises(fgdwa.FgdwaError, match="footprint does not apply to astar"):
        plan_global(grid, (0.2, 0.2), (4.5, 4.5), footprint=fgdwa.Footprint.circle(0.2))
    with pytest.raises(fgdwa.FgdwaError, match="named by method"):
        plan_global(grid, (0.2, 0.2), (4.5, 4.5), method="ompl:RRTstar", planner="PRMstar")
    with pytest.raises(fgdwa.FgdwaError, match="did you mean 'terrain_cost.w_risk'"):
        fgdwa.AStarPlanner(grid, w_risk=2.0)
    assert "astar" in global_methods() and "ompl:BITstar" in global_methods()


def test_c_shaped_trap_dwa_is_stuck_gdwa_gets_through():
    scenario = c_trap_scenario()
    # The default body: the known map sits where drifting odometry puts it, and the live scan keeps
    # DWA off the trap's walls until it gives up.
    dwa = run_episode(scenario.world, scenario.start, scenario.goal, lidar=fgdwa.LidarParams(),
                      params=fgdwa.PlannerParams(heading_target="goal"), max_steps=400)
    gdwa = run_episode(scenario.world, scenario.start, scenario.goal, lidar=fgdwa.LidarParams(),
                       params=fgdwa.PlannerParams(heading_target="key_nodes"), max_steps=400)
    # Heading straight for the goal, DWA stalls in the trap; its recoveries cannot get it out,
    # and the navigator gives up after max_recoveries of them.
    assert dwa.summary.outcome == "failed"
    assert dwa.summary.reason.startswith("the navigator gave up: RecoveriesExhausted (")
    assert {"BackingUp", "Rotating"} & set(dwa.trace.modes)
    assert np.hypot(*(dwa.motion.poses[-1, :2] - scenario.goal)) > 4.0
    assert gdwa.summary.outcome == "success"
    assert gdwa.summary.min_clearance > 0.0
    assert gdwa.context.global_path is not None and len(gdwa.context.key_nodes) >= 2
    np.testing.assert_allclose(gdwa.context.key_nodes[-1], scenario.goal)
    # The target walks through the key nodes in order (from the end of the start's watch, which aims at none).
    seen = [tuple(t) for t, mode in zip(gdwa.trace.targets, gdwa.trace.modes) if mode != "Waiting"]
    order = [seen.index(tuple(k)) for k in gdwa.context.key_nodes if tuple(k) in seen]
    assert order == sorted(order) and len(order) >= 2
