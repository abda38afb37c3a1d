import numpy as np
import pytest

import fgdwa
from fgdwa.sim import World, run_episode
from conftest import random_block_grid


def make_planner(**kwargs):
    return fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.25), fgdwa.PlannerParams(**kwargs))


def test_commands_always_inside_the_window(rng):
    cells = random_block_grid(rng, rows=80, cols=80, blocks=30)
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    world = fgdwa.FieldClearance(fgdwa.DistanceField(grid))
    truth = fgdwa.CollisionWorld(grid)
    planner = make_planner()
    footprint = fgdwa.Footprint.circle(0.25)
    limits = fgdwa.RobotLimits()
    checked = 0
    while checked < 100:
        pose = (rng.uniform(0, 8), rng.uniform(0, 8), rng.uniform(-np.pi, np.pi))
        if truth.in_collision(footprint, pose):
            continue
        twist = (rng.uniform(0, 1.2), rng.uniform(-1, 1))
        result = planner.plan(fgdwa.RobotState(pose, twist), (rng.uniform(0, 8), rng.uniform(0, 8)), world)
        window = fgdwa.dynamic_window(limits, twist, 0.15)
        assert window.contains(result.command)
        checked += 1


def test_diagnostics_and_sum_normalisation(rng):
    cells = random_block_grid(rng)
    world = fgdwa.FieldClearance(fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1)))
    planner = make_planner()
    result = planner.plan(fgdwa.RobotState((0.3, 0.3, 0.5), (0.5, 0.0)), (7.0, 5.0), world)
    n = len(result.samples)
    assert result.raw.shape == (n, 3) and result.normalized.shape == (n, 3)
    assert result.critic_names == ["heading", "clearance", "velocity"]
    ok = result.admissible
    assert ok.sum() == result.reject_counts["None"]
    assert np.all(np.isneginf(result.total[~ok]))
    sums = result.normalized[ok].sum(axis=0)
    for j in range(3):
        if result.raw[ok, j].sum() > 0:
            assert sums[j] == pytest.approx(1.0)
    expected_total = result.normalized[ok] @ np.array(result.weights)
    np.testing.assert_allclose(result.total[ok], expected_total)
    assert result.best_index == int(np.argmax(result.total))
    assert tuple(result.command) == tuple(result.samples[result.best_index])


def test_minmax_normalisation_maps_to_unit_interval(rng):
    world = fgdwa.FieldClearance(fgdwa.DistanceField(fgdwa.OccupancyGrid(random_block_grid(rng), 0.1)))
    result = make_planner(normalization="minmax").plan(fgdwa.RobotState((0.3, 0.3, 0.5), (0.5, 0.0)), (7, 5), world)
    ok = result.admissible
    assert result.normalized[ok].min() == pytest.approx(0.0)
    assert result.normalized[ok].max() == pytest.approx(1.0)


def test_no_normalisation_weighs_the_raw_terms(rng):
    world = fgdwa.FieldClearance(fgdwa.DistanceField(fgdwa.OccupancyGrid(random_block_grid(rng), 0.1)))
    planner = make_planner(normalization="none")
    assert planner.params.normalization == "none"
    result = planner.plan(fgdwa.RobotState((0.3, 0.3, 0.5), (0.5, 0.0)), (7, 5), world)
    ok = result.admissible
    np.testing.assert_array_equal(result.normalized[ok], result.raw[ok])
    np.testing.assert_allclose(result.total[ok], result.raw[ok] @ np.array(result.weights))
    assert result.best_index == int(np.argmax(result.total))
    with pytest.raises(fgdwa.FgdwaError, match="'none'"):
        make_planner(normalization="raw")


def test_boxed_in_robot_brakes_with_status():
    cells = np.zeros((40, 40), dtype=np.uint8)
    cells[:, 22:24] = 1  # a wall 0.2 m past the robot's nose
    world = fgdwa.FieldClearance(fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1)))
    planner = make_planner()
    result = planner.plan(fgdwa.RobotState((1.85, 2.0, 0.0), (1.2, 0.0)), (4.0, 2.0), world)
    assert result.status == fgdwa.Status.NoAdmissibleVelocity
    assert result.command.v == pytest.approx(1.2 - 0.15)
    assert result.command.omega == 0.0
    assert result.reject_counts["Collision"] == len(result.samples)


def test_goal_reached_status(open_world):
    world = fgdwa.FieldClearance(fgdwa.DistanceField(open_world))
    result = make_planner(goal_tolerance=0.3).plan(fgdwa.RobotState((1.0, 1.0, 0.0)), (1.2, 1.1), world)
    assert result.status == fgdwa.Status.GoalReached


def test_weights_change_the_choice(open_world):
    world = fgdwa.FieldClearance(fgdwa.DistanceField(open_world))
    planner = make_planner()
    state = fgdwa.RobotState((1.0, 1.0, 0.0), (0.5, 0.0))
    fast = planner.plan(state, (1.0, 4.0), world).command
    planner.set_weight("velocity", 0.0)
    assert planner.weight("velocity") == 0.0
    turning = planner.plan(state, (1.0, 4.0), world).command
    assert turning.v < fast.v
    assert turning.omega > 0.0


def test_admissible_samples_stop_before_contact():
    """Braking from an admissible command, as the window allows, never reaches an obstacle."""
    rng = np.random.default_rng(3)
    cells = random_block_grid(rng, rows=80, cols=80, blocks=40)
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    world = fgdwa.FieldClearance(fgdwa.DistanceField(grid))
    truth = fgdwa.CollisionWorld(grid)
    footprint = fgdwa.Footprint.circle(0.25)
    limits = fgdwa.RobotLimits()
    planner = make_planner()
    dt = 0.15
    finite = 0
    for _ in range(40):
        pose = (rng.uniform(0, 8), rng.uniform(0, 8), rng.uniform(-np.pi, np.pi))
        if truth.in_collision(footprint, pose):
            continue
        state = fgdwa.RobotState(pose, (rng.uniform(0, 1.2), rng.uniform(-1, 1)))
        result = planner.plan(state, (4.0, 4.0), world)
        for i in np.flatnonzero(result.admissible):
            if np.isinf(result.free_distance[i]):
                continue
            finite += 1
            v, omega = result.samples[i]
            # Drive the command one period, then brake with the window's deceleration
            # keeping the arc's curvature, checking every 2 cm of the way.
            p, speed, travelled = fgdwa.Pose2(*pose), v, 0.0
            curvature = omega / v if v > 0 else 0.0
            while speed > 0:
                for _ in range(10):
                    p = fgdwa.unicycle_step(p, (speed, speed * curvature), dt / 10)
                    travelled += speed * dt / 10
                    assert world.clearance(footprint, p) > 0.0
                speed = max(speed - limits.acc_v * dt, 0.0)
            assert travelled <= result.free_distance[i] + 1e-9
    assert finite > 100


def test_peer_case_python_robotics_dwa():
    """PythonRobotics' DWA example (MIT): 15 point obstacles, robot radius 1 m, goal (10, 10).

    Weights: heading 0.15, clearance 1.0, velocity 1.0 (the example's own), min-max
    normalisation, 21 x 21 samples; goal reached within 1.0 m."""
    points = [(-1, -1), (0, 2), (4, 2), (5, 4), (5, 5), (5, 6), (5, 9), (8, 9), (7, 9), (8, 10), (9, 11),
              (12, 13), (12, 12), (15, 15), (13, 13)]
    world = World(discs=[fgdwa.Disc(p, 0.0) for p in points])
    limits = fgdwa.RobotLimits(v_min=0.0, v_max=1.0, omega_max=np.radians(40), acc_v=0.2, acc_omega=np.radians(40))
    params = fgdwa.PlannerParams(dt=0.1, sim_time=3.0, normalization="minmax", goal_tolerance=1.0,
                                 critics=[("heading", 0.15), ("clearance", 1.0), ("velocity", 1.0)])
    result = run_episode(world, (0.0, 0.0, np.pi / 8), (10.0, 10.0), limits=limits,
                         footprint=fgdwa.Footprint.circle(1.0), params=params, max_steps=1500)
    assert result.summary.outcome == "success"
    assert result.summary.min_clearance > 0.0


@pytest.mark.parametrize("twist", [(5.0, 0.0), (-1.0, 0.0), (0.3, 10.0), (0.3, -10.0)])
def test_a_state_beyond_the_limits_never_yields_a_command_beyond_them(twist):
    # A push, a slope or a bad report: the wheels are still asked for nothing the limits forbid.
    limits = fgdwa.RobotLimits(v_max=0.8)
    footprint = fgdwa.Footprint.circle(0.25)
    cells = np.zeros((30, 60), dtype=np.uint8)
    cells[:22, 30] = 1
    grid = fgdwa.OccupancyGrid(cells, 0.1)
    world = fgdwa.FieldClearance(fgdwa.DistanceField(grid))
    state = fgdwa.RobotState((0.5, 1.0, 0.0), twist)
    planner = fgdwa.LocalPlanner(limits, footprint, fgdwa.PlannerParams())
    controller = fgdwa.Controller(limits, footprint, fgdwa.PlannerParams())
    navigator = fgdwa.Navigator(limits, footprint, fgdwa.PlannerParams(), grid, mapping="known")
    navigator.set_goal((5.5, 1.0))
    commands = [planner.plan(state, (5.5, 1.0), world).command, controller.step(state, (5.5, 1.0), None).command,
                navigator.step(state, None, 0.0).command]
    for command in commands:
        assert limits.v_min <= command.v <= limits.v_max
        assert abs(command.omega) <= limits.omega_max
