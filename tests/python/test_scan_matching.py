"""Scan matching keeps a drifting robot's map true: the same drifting episode
builds a map whose obstacles lie nearer the real ones with matching than
without, and the correction is reported in every record."""

import numpy as np
import pytest

from fgdwa import DistanceField, FgdwaError, LidarParams, NavigatorParams, OccupancyGrid
from fgdwa.sim.body import body_profile
from fgdwa.sim.episode import GOAL_MARGIN_SHARE, default_goal_margin, run_episode
from fgdwa.sim.world import World


def _room():
    # 8 m x 6 m at 5 cm: a wall round it and posts to drive between.
    rng = np.random.default_rng(4)
    cells = np.zeros((120, 160), dtype=np.uint8)
    cells[0, :] = cells[-1, :] = cells[:, 0] = cells[:, -1] = 1
    for _ in range(25):
        r, c = rng.integers(10, 110), rng.integers(30, 130)
        h, w = rng.integers(2, 8, size=2)
        cells[r:r + h, c:c + w] = 1
    cells[50:70, 5:25] = 0
    cells[50:70, 135:155] = 0
    return OccupancyGrid(cells, 0.05, (0.0, 0.0))


def _map_error(grid, true_grid):
    """Mean distance (m) from the map's occupied cells to the real obstacles."""
    field = DistanceField(true_grid)
    rows, cols = np.nonzero(np.asarray(grid))
    centres = np.column_stack([(cols + 0.5) * 0.05, (rows + 0.5) * 0.05])
    return float(np.mean(field.distance(centres)))


def test_a_drifting_robot_maps_truer_with_scan_matching():
    grid = _room()
    world = World(grid=grid)
    errors = {}
    for matching in (False, True):
        navigator = NavigatorParams()
        navigator.scan_match.enabled = matching
        result = run_episode(world, (0.6, 3.0, 0.0), (7.4, 3.0), mapping="scan", navigator=navigator,
                             lidar=LidarParams(noise_std=0.02), odometry_drift=(0.05, 0.02), seed=2,
                             max_steps=300)
        errors[matching] = _map_error(result.context.scan_map, grid)
    assert errors[True] < errors[False], errors


def test_the_record_reports_the_correction_and_the_odometry():
    grid = _room()
    from fgdwa import Footprint, Navigator, PlannerParams, RobotLimits, RobotState, LaserScanner, Pose2
    navigator = NavigatorParams()
    navigator.scan_match.enabled = True
    nav = Navigator(RobotLimits(), Footprint.circle(0.25), PlannerParams(), grid, mapping="known",
                    lidar=LidarParams(noise_std=0.0), navigator=navigator)
    nav.set_goal((7.4, 3.0))
    scanner = LaserScanner(LidarParams(noise_std=0.0), DistanceField(grid))
    scan = scanner.scan(Pose2(2.0, 3.0, 0.0), [], 0.0, seed=1)
    scan.pose = (2.08, 2.95, 0.02)
    record = nav.step(RobotState((2.08, 2.95, 0.02), (0.0, 0.0)), scan, 0.0)
    assert record.match.accepted, record.match
    assert tuple(record.odometry) == (2.08, 2.95, 0.02)
    assert abs(record.state.pose.x - 2.0) < 0.05 and abs(record.state.pose.y - 3.0) < 0.05
    assert abs(record.map_to_odom.x) > 0.03
    assert "localise" in record.times


def test_the_robot_maps_in_cells_of_its_own_whatever_the_worlds():
    # The world in 15 cm cells, the robot's map in 5 cm: its occupied cells lie
    # on the real walls, within half a cell's diagonal and the range noise.
    room = _room()
    coarse = OccupancyGrid(np.asarray(room.cells)[::3, ::3].copy(), 0.15, (0.0, 0.0))
    result = run_episode(World(grid=coarse), (0.6, 3.0, 0.0), (7.4, 3.0), mapping="scan", map_resolution=0.05,
                         lidar=LidarParams(noise_std=0.01), max_steps=20, body="ideal")
    assert result.context.scan_map.shape == (40 * 3, 54 * 3)
    assert result.context.scan_extent == pytest.approx((0.0, 8.1, 0.0, 6.0))
    rows, cols = np.nonzero(result.context.scan_map)
    assert len(rows) > 100
    centres = np.column_stack([(cols + 0.5) * 0.05, (rows + 0.5) * 0.05])
    assert float(np.max(DistanceField(coarse).distance(centres))) <= 0.05 * np.sqrt(0.5) + 0.03 + 1e-9


@pytest.mark.parametrize("value", [0.0, -0.1, 2.0, float("nan"), True, "0.1"])
def test_a_map_resolution_out_of_bounds_is_refused_by_name(value):
    with pytest.raises(FgdwaError, match="map_resolution"):
        run_episode(World(grid=_room()), (0.6, 3.0, 0.0), (7.4, 3.0), mapping="scan", map_resolution=value,
                    max_steps=1)


def test_a_map_resolution_with_the_map_known_is_refused():
    with pytest.raises(FgdwaError, match="map_resolution: only the map the robot builds"):
        run_episode(World(grid=_room()), (0.6, 3.0, 0.0), (7.4, 3.0), mapping="known", map_resolution=0.05,
                    max_steps=1)


def test_a_matched_pose_is_an_estimate_and_the_goal_is_aimed_inside_the_tolerance():
    # Even on an ideal body a matched pose is an estimate, off by a little: the
    # navigator aims inside the referee's tolerance, as with drifting
    # odometry, not at its edge (where a millimetre decides).
    matching = NavigatorParams()
    matching.scan_match.enabled = True
    assert default_goal_margin(body_profile("ideal"), NavigatorParams(), 1.0) == 0.0
    assert default_goal_margin(body_profile("ideal"), matching, 1.0) == GOAL_MARGIN_SHARE
    assert default_goal_margin(body_profile("default"), NavigatorParams(), 0.4) == 0.4 * GOAL_MARGIN_SHARE
