"""Metrics on hand-made trajectories."""

import numpy as np
import pytest

import fgdwa
from fgdwa.sim.referee import danger_point_clearance, danger_points, smoothness
from fgdwa.sim import path_length


def wall_field():
    cells = np.zeros((40, 100), np.uint8)
    cells[20:22, 30:60] = 1  # a wall from x 3 to 6, y 2.0 to 2.2
    return fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1))


def test_danger_points_lie_where_the_path_passes_close_and_are_thinned():
    field = wall_field()
    path = np.array([[0.0, 1.5], [10.0, 1.5]])  # 0.5 m below the wall from x 3 to 6
    points = danger_points(path, field, danger_clearance=0.55, spacing=1.0)
    # Closer than 0.55 m from x = 3 - sqrt(0.55^2 - 0.5^2) = 2.77 to 6.23, walked every
    # 5 cm: the first point at 2.8, then one per metre.
    np.testing.assert_allclose(points, [[2.8, 1.5], [3.8, 1.5], [4.8, 1.5], [5.8, 1.5]], atol=1e-9)
    assert len(danger_points(path, field, danger_clearance=0.45)) == 0
    assert len(danger_points(np.array([[0.0, 1.0]]), field, 1.0)) == 0


def test_danger_point_clearance_measures_the_executed_path_nearest_each_point():
    field = wall_field()
    points = np.array([[4.0, 1.5], [5.0, 1.5]])
    executed = np.column_stack([np.linspace(0, 10, 101), np.full(101, 1.2)])  # 0.8 m below the wall
    assert danger_point_clearance(executed, points, field) == pytest.approx(0.8)
    assert np.isnan(danger_point_clearance(executed, np.zeros((0, 2)), field))


def test_mileage_and_smoothness():
    assert path_length(np.array([[0, 0, 0], [3, 4, 0], [3, 0, 0]])) == pytest.approx(9.0)
    commands = np.array([[1.0, 0.0], [1.0, 0.3], [1.0, -0.2], [1.0, -0.2]])
    assert smoothness(commands) == pytest.approx(0.8)
    assert smoothness(commands[:1]) == 0.0


def test_deviation_is_recorded_against_the_global_path():
    from fgdwa.io.builtin import c_trap_scenario
    from fgdwa.sim import run_episode

    scenario = c_trap_scenario()
    result = run_episode(scenario.world, scenario.start, scenario.goal,
                         params=fgdwa.PlannerParams(heading_target="key_nodes"), max_steps=400)
    path = fgdwa.GlobalPath(result.context.global_path)
    # D is the navigator's: measured from where its odometry says it is.
    expected = [path.deviation(p[:2]) for p in result.motion.believed_poses[:-1]]
    np.testing.assert_allclose(result.trace.deviation, expected)
    assert result.summary.mean_deviation == pytest.approx(np.mean(expected))
    assert result.summary.max_deviation == pytest.approx(np.max(expected))
