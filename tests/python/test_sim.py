import re

import numpy as np
import pytest

import fgdwa
from fgdwa.io.builtin import demo_scenario
from fgdwa.cli import main
from fgdwa.sim import World, collides_during_step, path_length, run_episode


def test_path_length_of_a_hand_made_path():
    assert path_length(np.array([[0, 0], [3, 4], [3, 0]])) == pytest.approx(9.0)
    assert path_length(np.zeros((1, 2))) == 0.0


def test_demo_scenario_succeeds_with_classic_dwa():
    scenario = demo_scenario()
    result = run_episode(scenario.world, scenario.start, scenario.goal, max_steps=400)
    assert result.summary.outcome == "success"
    assert np.hypot(*(result.motion.poses[-1, :2] - scenario.goal)) <= 0.3
    assert result.summary.min_clearance > 0.0
    assert result.summary.steps == len(result.motion.commands) == len(result.motion.poses) - 1
    assert result.summary.sim_time == pytest.approx(result.summary.steps * 0.15)
    assert result.summary.mileage == pytest.approx(path_length(result.motion.poses))
    assert result.summary.mileage >= np.hypot(10.0, 0.0) - 0.3
    assert 0 < result.summary.min_clearance <= result.summary.mean_clearance
    assert result.summary.planning_time > 0


def test_episode_is_deterministic():
    scenario = demo_scenario()
    a = run_episode(scenario.world, scenario.start, scenario.goal, max_steps=60)
    b = run_episode(scenario.world, scenario.start, scenario.goal, max_steps=60)
    np.testing.assert_array_equal(a.motion.poses, b.motion.poses)


def test_timeout_when_steps_run_out():
    scenario = demo_scenario()
    result = run_episode(scenario.world, scenario.start, scenario.goal, max_steps=5)
    assert result.summary.outcome == "timeout"
    assert result.summary.steps == 5
    assert result.summary.reason.startswith("timeout: ") and "m from the goal after 0.75 s" in result.summary.reason


def test_a_disc_driving_into_the_robot_is_a_collision():
    disc = fgdwa.Disc((3.0, 0.0), 0.3, velocity=(-2.0, 0.0))
    params = fgdwa.PlannerParams(critics=[("heading", 1.0), ("velocity", 1.0)])
    result = run_episode(World(discs=[disc]), (0.0, 0.0, np.pi), (-20.0, 0.0), body="ideal",
                         limits=fgdwa.RobotLimits(v_max=0.2), params=params, max_steps=50)
    assert result.summary.outcome == "collision"
    assert result.motion.clearances[-1] == pytest.approx(0.0, abs=1e-6)
    assert result.summary.reason.startswith("collision: mover 0 drove into the robot at (")
    # The point of contact is the disc's edge where it meets the robot's, on the line between their centres.
    contact = result.collision
    assert contact.obstacle == "mover" and contact.mover == 0 and contact.what == "mover 0"
    robot = result.motion.poses[-1, :2]
    assert np.hypot(*(np.array(contact.point) - robot)) == pytest.approx(0.25, abs=0.02)
    assert contact.point[1] == pytest.approx(robot[1], abs=0.02) and contact.point[0] > robot[0]
    assert f"at ({contact.point[0]:.2f}, {contact.point[1]:.2f})" in result.summary.reason


def test_contact_between_poses_is_found():
    cells = np.zeros((10, 40), np.uint8)
    cells[:, 20] = 1  # a wall one cell thick at x = 2.0 .. 2.1
    truth = fgdwa.CollisionWorld(fgdwa.OccupancyGrid(cells, 0.1))
    footprint = fgdwa.Footprint.circle(0.05)
    before, after = (1.8, 0.5, 0.0), (2.3, 0.5, 0.0)  # both ends free, the wall in between
    assert not truth.in_collision(footprint, before) and not truth.in_collision(footprint, after)
    assert collides_during_step(truth, footprint, before, after, 0.0, 0.15)


def test_the_point_of_contact_is_where_the_outline_meets_what_it_hit():
    from fgdwa.sim import collision_contact

    cells = np.zeros((20, 40), np.uint8)
    cells[:, 20] = 1  # a wall one cell thick at x = 2.0 .. 2.1
    hidden = np.zeros_like(cells)
    hidden[15:, 20] = 1  # its top quarter (y >= 1.5) is missing from the map
    grid, missing = fgdwa.OccupancyGrid(cells, 0.1), fgdwa.OccupancyGrid(hidden, 0.1)
    truth = fgdwa.CollisionWorld(grid)
    circle = fgdwa.Footprint.circle(0.25)
    # A circle 1 cm into the wall touches it on the line through its centre.
    contact = collision_contact(truth, circle, (1.76, 1.0, 0.0), (0.5, 0.0), grid=grid, hidden=missing)
    assert contact.obstacle == "wall" and contact.what == "a wall" and contact.mover == -1
    np.testing.assert_allclose(contact.point, (2.0, 1.0), atol=1e-9)
    assert contact.reason == "collision: the robot drove into a wall at (2.00, 1.00)"
    contact = collision_contact(truth, circle, (1.76, 1.7, 0.0), (0.5, 0.0), grid=grid, hidden=missing)
    assert contact.obstacle == "hidden" and contact.reason.startswith(
        "collision: the robot drove into an obstacle missing from the map at (2.00, 1.70)")
    # A turned rectangle's front right corner pokes in: the wall's point deepest inside it is at
    # x = 2.0, y = 0.93 (depth 4 cm), placed within half a cell.
    jackal = fgdwa.robot_preset("jackal").footprint
    contact = collision_contact(truth, jackal, (1.8, 1.0, 0.3), (0.5, 0.0), grid=grid)
    assert contact.point[0] == pytest.approx(2.0) and contact.point[1] == pytest.approx(0.93, abs=0.05)
    assert jackal.signed_distance((1.8, 1.0, 0.3), contact.point) < -0.03
    # The second of two discs hits the robot: its index names it, its edge is the point.
    truth.discs = [fgdwa.Disc((1.0, 0.2), 0.1), fgdwa.Disc((1.6, 1.0), 0.2, velocity=(-1.0, 0.0))]
    contact = collision_contact(truth, circle, (1.2, 1.0, 0.0), (0.0, 0.0), grid=grid)
    assert contact.obstacle == "mover" and contact.mover == 1 and contact.what == "mover 1"
    np.testing.assert_allclose(contact.point, (1.4, 1.0), atol=1e-9)
    assert contact.mover_closing == pytest.approx(1.0) and contact.robot_closing == pytest.approx(0.0)
    assert contact.reason.startswith("collision: mover 1 drove into the robot at (1.40, 1.00)")
    assert collision_contact(truth, circle, (1.2, 1.0, 0.0), (0.0, 0.0)).point == contact.point  # no grid needed


def test_a_mover_that_jumped_within_the_step_appeared_on_the_robot():
    from fgdwa.sim import collision_contact

    circle = fgdwa.Footprint.circle(0.25)
    truth = fgdwa.CollisionWorld(fgdwa.OccupancyGrid(np.zeros((20, 40), np.uint8), 0.1))
    truth.discs = [fgdwa.Disc((3.0, 0.5), 0.1), fgdwa.Disc((1.6, 1.0), 0.2, velocity=(-1.0, 0.0))]
    # Moving at 1 m/s it covers 0.1 m in 0.1 s: from 1.7 m it drove in; from 1.95 m (0.35 m, more
    # than its speed covers by over its radius) and from 7 m it jumped.
    came = [fgdwa.Disc((3.0, 0.5), 0.1), fgdwa.Disc((1.7, 1.0), 0.2, velocity=(-1.0, 0.0))]
    contact = collision_contact(truth, circle, (1.2, 1.0, 0.0), (0.0, 0.0), before=came, dt=0.1)
    assert contact.jumped == 0.0 and contact.reason.startswith("collision: mover 1 drove into the robot")
    for start, distance in ((1.95, "0.35"), (8.6, "7.00")):
        came = [fgdwa.Disc((3.0, 0.5), 0.1), fgdwa.Disc((start, 1.0), 0.2, velocity=(-1.0, 0.0))]
        contact = collision_contact(truth, circle, (1.2, 1.0, 0.0), (0.0, 0.0), before=came, dt=0.1)
        assert contact.jumped == pytest.approx(start - 1.6)
        assert contact.reason == (f"collision: mover 1 appeared on the robot at (1.40, 1.00) (it jumped {distance} m "
                                  "within the step, farther than its speed takes it)")
    # Just within its speed and radius: 0.1 m of travel plus 0.2 m of radius.
    came = [fgdwa.Disc((3.0, 0.5), 0.1), fgdwa.Disc((1.899, 1.0), 0.2, velocity=(-1.0, 0.0))]
    assert collision_contact(truth, circle, (1.2, 1.0, 0.0), (0.0, 0.0), before=came, dt=0.1).jumped == 0.0
    with pytest.raises(fgdwa.FgdwaError, match="before: 1 discs for the truth's 2"):
        collision_contact(truth, circle, (1.2, 1.0, 0.0), (0.0, 0.0), before=came[:1], dt=0.1)
    with pytest.raises(fgdwa.FgdwaError, match="dt = -0.1"):
        collision_contact(truth, circle, (1.2, 1.0, 0.0), (0.0, 0.0), before=came, dt=-0.1)


def test_an_episode_names_a_mover_that_jumped_onto_the_robot():
    # A looping route whose start lies on the robot's standing place: at the wrap the disc jumps
    # back onto it from 3 m away.
    from fgdwa.sim import run_episode
    from fgdwa.sim.keyframes import KeyframedMover
    from fgdwa.sim.world import World

    grid = fgdwa.OccupancyGrid(np.zeros((40, 60), np.uint8), 0.1)
    mover = KeyframedMover(radius=0.3, keyframes=[[0.0, 1.0, 2.0], [1.0, 2.5, 2.0], [2.0, 4.0, 2.0]], phase=1.5)
    world = World(grid=grid, movers=[mover], discs_known=True)
    result = run_episode(world, (1.0, 2.0, 0.0), (1.0, 3.5), seed=0, max_steps=40, body="ideal")
    assert result.summary.outcome == "collision"
    assert 2.5 < result.collision.jumped < 3.0  # the route's 3 m less what it drives in a step
    assert "mover 0 appeared on the robot" in result.summary.reason


def test_a_rectangle_turning_in_place_beside_a_post_is_a_collision():
    # The Jackal's 0.42 m x 0.33 m rectangle turns a quarter turn in place; a 2 cm post lies
    # clear of both end placements but inside the footprint between 42 and 50 degrees.
    cells = np.zeros((100, 100), np.uint8)
    cells[62, 51] = 1  # the post: x 1.02 .. 1.04, y 1.24 .. 1.26
    truth = fgdwa.CollisionWorld(fgdwa.OccupancyGrid(cells, 0.02))
    rectangle = fgdwa.robot_preset("jackal").footprint
    before, after = (1.0, 1.0, 0.0), (1.0, 1.0, np.pi / 2)
    assert truth.clearance(rectangle, before) > 0.02 and truth.clearance(rectangle, after) > 0.02
    assert collides_during_step(truth, rectangle, before, after, 0.0, 0.1)
    # A smaller turn stops short of it; a circle turns anywhere.
    assert not collides_during_step(truth, rectangle, before, (1.0, 1.0, np.radians(30)), 0.0, 0.1)
    assert not collides_during_step(truth, fgdwa.Footprint.circle(0.2), before, after, 0.0, 0.1)
    # The clearance at the start, when the caller has it, gives the same verdicts, and is what the sweep starts from.
    start = truth.clearance(rectangle, before, 0.0)
    for heading in (np.pi / 2, np.radians(30), -np.pi / 2):
        assert collides_during_step(truth, rectangle, before, (1.0, 1.0, heading), 0.0, 0.1,
                                    start_clearance=start) == \
            collides_during_step(truth, rectangle, before, (1.0, 1.0, heading), 0.0, 0.1)
    assert collides_during_step(truth, rectangle, before, (1.0, 1.0, np.radians(30)), 0.0, 0.1, start_clearance=0.0)
    for bad in (float("nan"), "0.1", True):
        with pytest.raises(fgdwa.FgdwaError, match="start_clearance"):
            collides_during_step(truth, rectangle, before, after, 0.0, 0.1, start_clearance=bad)
    # The planner agrees: from that pose it never commands the turn that sweeps the post.
    params = fgdwa.PlannerParams(dt=0.1, window={"n_v": 5, "n_omega": 41})
    planner = fgdwa.LocalPlanner(fgdwa.RobotLimits(omega_max=16.0, acc_omega=200.0), rectangle, params)
    result = planner.plan(fgdwa.RobotState(before, (0.0, 0.0)), (1.0, 3.0), fgdwa.FieldClearance(
        fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.02))))
    sweeping = [reason for sample, reason in zip(result.samples, result.reasons)
                if sample[0] == 0.0 and sample[1] * 0.1 >= np.pi / 2]
    assert sweeping and all(reason == "Collision" for reason in sweeping)


def test_cli_demo_is_fgdwa_run_demo(tmp_path, capsys):
    assert main(["demo", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert main(["run", "demo", "--planner", "fgdwa", "--out", str(tmp_path / "run")]) == 0
    run = capsys.readouterr().out.replace(str(tmp_path / "run"), str(tmp_path))

    def untimed(text):
        return [line for line in text.splitlines() if not any(w in line for w in ("cycle time", "wall", "planning_time"))]

    assert untimed(run) == untimed(out)
    assert "planner fgdwa, seed 0" in out
    assert "outcome          success" in out
    # Each metric with its unit; a run that succeeded gives no reason.
    assert re.search(r"^  mileage +[0-9.]+ m$", out, flags=re.M) and re.search(r"^  smoothness +[0-9.]+ rad/s$", out,
                                                                                flags=re.M)
    assert "reason" not in out
    png = tmp_path / "demo_fgdwa.png"
    assert png.stat().st_size > 10_000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_obstacles_missing_from_the_map_are_seen_by_the_lidar():
    from fgdwa.io.builtin import hidden_obstacles_scenario

    scenario = hidden_obstacles_scenario()
    params = fgdwa.PlannerParams(heading_target="key_nodes")
    blind = run_episode(scenario.world, scenario.start, scenario.goal, params=params, max_steps=300)
    assert blind.summary.outcome == "collision"
    assert blind.summary.reason.startswith("collision: the robot drove into an obstacle missing from the map at (")
    assert blind.collision.obstacle == "hidden" and blind.collision.mover == -1
    # The point of contact lies on a hidden cell's square, within the footprint's reach of the robot.
    hidden = scenario.world.hidden
    squares = np.argwhere(hidden.cells != 0)[:, ::-1] * hidden.resolution + hidden.origin
    point = np.array(blind.collision.point)
    assert np.any(np.all((squares - 1e-9 <= point) & (point <= squares + hidden.resolution + 1e-9), axis=1))
    assert np.hypot(*(point - blind.motion.poses[-1, :2])) <= 0.25 + 1e-6
    sensing = run_episode(scenario.world, scenario.start, scenario.goal, params=params, lidar=fgdwa.LidarParams(),
                          max_steps=300, body="ideal")
    assert sensing.summary.outcome == "success"
    assert sensing.summary.min_clearance > 0.0
    # The density of the detect window rises when the hidden blocks come into it.
    first = np.flatnonzero(~np.isnan(sensing.trace.density))[0]  # after the start's watch
    assert sensing.trace.density[first] == pytest.approx(0.5 ** (4 * np.sin(np.pi / 3)))
    assert np.nanmax(sensing.trace.density) > 0.5
    deviation = sensing.trace.deviation[first:]
    assert np.all(np.isfinite(deviation)) and deviation.max() > 0.3


def test_a_robot_whose_odometry_drifted_says_so_when_it_stops_short():
    """With drifting odometry the navigator can stop where it believes the goal
    is; the reason says so, and by how much its odometry was off."""
    world = World()
    result = run_episode(world, (0.0, 0.0, 0.0), (6.0, 0.0), max_steps=150, goal_tolerance=0.05,
                         params=fgdwa.PlannerParams(goal_tolerance=0.05), odometry_drift=(0.2, 0.0), seed=4)
    assert result.summary.outcome == "timeout" and result.trace.modes[-1] == "GoalReached"
    off = np.hypot(*(result.motion.believed_poses[-1, :2] - result.motion.poses[-1, :2]))
    assert result.summary.reason.endswith(f"(it believed it had arrived: its odometry was {off:.2f} m off)")


def test_hidden_layout_must_match_the_map():
    grid = fgdwa.OccupancyGrid(np.zeros((10, 10), np.uint8), 0.1)
    with pytest.raises(fgdwa.FgdwaError, match="hidden"):
        World(grid=grid, hidden=fgdwa.OccupancyGrid(np.zeros((10, 12), np.uint8), 0.1))


def test_weight_policy_needs_a_lidar():
    scenario = demo_scenario()

    class Constant(fgdwa.WeightPolicy):
        def weights(self, density, deviation):
            return {"clearance": 0.2}

    class Pair(fgdwa.WeightPolicy):
        def weights(self, density, deviation):
            return 0.2, 0.0

    with pytest.raises(fgdwa.FgdwaError, match="lidar"):
        run_episode(scenario.world, scenario.start, scenario.goal, weight_policy=Constant())
    result = run_episode(scenario.world, scenario.start, scenario.goal, weight_policy=Constant(),
                         lidar=fgdwa.LidarParams(), max_steps=20)
    # Every cycle the planner drove; the start's watch (beta NaN) does not plan.
    planned = ~np.isnan(result.trace.beta)
    assert planned.sum() >= 17 and np.all(result.trace.beta[planned] == 0.2)
    with pytest.raises(fgdwa.FgdwaError, match="dict"):
        run_episode(scenario.world, scenario.start, scenario.goal, weight_policy=Pair(), lidar=fgdwa.LidarParams(),
                    max_steps=5)


def test_recorded_cycles_are_what_the_planner_scored_and_the_gif_replays_them(tmp_path):
    from fgdwa.plot.animation import write_gif

    scenario = demo_scenario()
    plain = run_episode(scenario.world, scenario.start, scenario.goal, max_steps=30, lidar=fgdwa.LidarParams())
    assert plain.trace.cycles == []
    with pytest.raises(fgdwa.FgdwaError, match="record_cycles"):
        write_gif(plain, scenario, tmp_path / "x.gif", planner="dwa")
    result = run_episode(scenario.world, scenario.start, scenario.goal, max_steps=30, lidar=fgdwa.LidarParams(), body="ideal",
                         record_cycles=True, navigator=fgdwa.NavigatorParams(record_top_k=7, start_watch_time=0.0))
    assert len(result.trace.cycles) == result.summary.steps == 30
    n_steps = fgdwa.PlannerParams().n_steps
    for k, cycle in enumerate(result.trace.cycles):
        assert cycle.rollouts.shape == (7, n_steps, 3)
        assert np.all(np.diff(cycle.totals) <= 0)  # best first
        np.testing.assert_allclose(cycle.chosen, cycle.rollouts[0])
        # The chosen rollout starts with the command the robot then executed.
        after = fgdwa.unicycle_step(tuple(result.motion.poses[k]), tuple(result.motion.commands[k]), 0.15)
        np.testing.assert_allclose(cycle.chosen[0], (after.x, after.y, after.theta), atol=1e-9)
        assert cycle.hits.ndim == 2 and cycle.hits.shape[1] == 2 and len(cycle.hits) > 0
    gif = write_gif(result, scenario, tmp_path / "demo.gif", planner="dwa", max_frames=5)
    assert gif.stat().st_size > 0


def test_the_footprint_is_drawn_as_it_is(tmp_path):
    from fgdwa.plot.episode import footprint_patch, placed_outline, plot_episode

    jackal = fgdwa.robot_preset("jackal").footprint
    corners = placed_outline(jackal.vertices, (1.0, 2.0, np.pi / 2))
    np.testing.assert_allclose(sorted(corners[:, 0]), [0.835, 0.835, 1.165, 1.165], atol=1e-9)
    np.testing.assert_allclose(sorted(corners[:, 1]), [1.79, 1.79, 2.21, 2.21], atol=1e-9)
    assert footprint_patch(jackal, (1.0, 2.0, 0.0)).get_xy().shape[1] == 2
    scenario = demo_scenario()
    result = run_episode(scenario.world, scenario.start, scenario.goal, footprint=jackal, max_steps=10)
    plot_episode(result, scenario.world, scenario.goal, tmp_path / "jackal.png", footprint=jackal)
    assert (tmp_path / "jackal.png").stat().st_size > 0


def test_episode_options_and_keyword_settings_agree():
    from fgdwa.sim import EpisodeOptions

    scenario = demo_scenario()
    options = EpisodeOptions(max_steps=15, lidar=fgdwa.LidarParams(), seed=3)
    by_object = run_episode(scenario.world, scenario.start, scenario.goal, options)
    by_keywords = run_episode(scenario.world, scenario.start, scenario.goal, max_steps=15, lidar=fgdwa.LidarParams(),
                              seed=3)
    np.testing.assert_array_equal(by_object.motion.poses, by_keywords.motion.poses)
    # Keywords go on top of the object.
    assert run_episode(scenario.world, scenario.start, scenario.goal, options, max_steps=5).summary.steps == 5
    with pytest.raises(fgdwa.FgdwaError, match="max_step"):
        run_episode(scenario.world, scenario.start, scenario.goal, max_step=5)


# ----------------------------------------------------------------------------- the robot's body


def open_run(**settings):
    """The classic DWA driving 8 m across an empty world, on the ideal body with the given settings."""
    return run_episode(World(), (0.0, 0.0, 0.0), (8.0, 0.0), **{"body": "ideal", **settings})


def test_latency_delays_every_command_by_its_cycles():
    prompt = open_run(max_steps=12)
    late = open_run(max_steps=12, latency=1)
    # Nothing reaches the wheels in the first cycle: the robot stays at rest.
    np.testing.assert_array_equal(late.motion.commands[0], (0.0, 0.0))
    np.testing.assert_array_equal(late.motion.poses[1], late.motion.poses[0])
    # Still at rest in the second cycle, the navigator computes what it computed in the first,
    # and that now reaches the wheels.
    np.testing.assert_array_equal(late.motion.commands[1], prompt.motion.commands[0])
    later = open_run(max_steps=12, latency=3)
    np.testing.assert_array_equal(later.motion.commands[:3], np.zeros((3, 2)))
    assert later.motion.commands[3, 0] > 0
    assert later.summary.mileage < late.summary.mileage < prompt.summary.mileage


def test_actuation_lag_follows_the_command_as_a_first_order_lag():
    tau, dt = 0.5, 0.15
    lagging = open_run(max_steps=20, actuation_lag=tau)
    # From rest toward the first command: the mean of v over the cycle is
    # v_c (1 - tau / dt (1 - exp(-dt / tau))).
    v_c = lagging.motion.commands[0, 0]
    assert v_c > 0
    assert lagging.motion.twists[0, 0] == pytest.approx(v_c * (1 - tau / dt * (1 - np.exp(-dt / tau))), rel=1e-12)
    assert np.all(lagging.motion.twists[:5, 0] < lagging.motion.commands[:5, 0])
    assert lagging.summary.mileage < open_run(max_steps=20).summary.mileage
    # Without lag the robot moves exactly as commanded.
    prompt = open_run(max_steps=20)
    np.testing.assert_array_equal(prompt.motion.twists, prompt.motion.commands)


def test_actuation_noise_has_the_asked_spread():
    from fgdwa.sim.body import Body, BodySettings

    body = Body(BodySettings(actuation_noise=(0.05, 0.1)), 0.15, seed=2)
    v, omega = np.array([tuple(body.wheels(fgdwa.Twist(0.5, 0.2))) for _ in range(400)]).T
    # 400 draws: the sample std lies within 15 % of the true one with odds far beyond 1e-5.
    assert 0.85 * 0.05 < np.std(v) < 1.15 * 0.05
    assert 0.85 * 0.1 < np.std(omega) < 1.15 * 0.1
    assert abs(np.mean(v) - 0.5) < 0.05 * 5 / np.sqrt(400)
    # A standing command stays standing.
    assert all(tuple(body.wheels(fgdwa.Twist(0.0, 0.0))) == (0.0, 0.0) for _ in range(50))


def test_odometry_drift_misleads_the_navigator_but_not_the_referee():
    world = demo_scenario().world
    start, goal = (1.2, 4.0, 0.0), (10.8, 4.0)
    result = run_episode(world, start, goal, max_steps=40, lidar=fgdwa.LidarParams(beams=181),
                         odometry_drift=(0.05, 0.05), seed=1)
    assert result.summary.outcome == "timeout"
    np.testing.assert_array_equal(result.motion.believed_poses[0], result.motion.poses[0])
    gap = np.hypot(*(result.motion.believed_poses[:, :2] - result.motion.poses[:, :2]).T)
    assert gap[-1] > 1e-3
    # The scans were placed where the robot believed it was when it took them ...
    last_scan = result.context.last_scan
    np.testing.assert_allclose((last_scan.pose.x, last_scan.pose.y, last_scan.pose.theta),
                               result.motion.believed_poses[-2])
    # ... while the referee's poses follow the driven twists exactly, from the true start.
    for k in range(result.summary.steps):
        pose = fgdwa.unicycle_step(result.motion.poses[k], result.motion.twists[k], 0.15)
        np.testing.assert_array_equal(result.motion.poses[k + 1], (pose.x, pose.y, pose.theta))
    truth = fgdwa.CollisionWorld(world.true_grid())
    final = result.motion.poses[-1]
    assert result.motion.clearances[-1] == pytest.approx(truth.clearance(fgdwa.Footprint.circle(0.25), final))
    # Without drift the believed pose is the true one.
    plain = run_episode(world, start, goal, max_steps=10, lidar=fgdwa.LidarParams(beams=181), seed=1, body="ideal")
    np.testing.assert_array_equal(plain.motion.believed_poses, plain.motion.poses)


def test_a_simulated_robot_given_its_map_matches_its_scans_to_it():
    """Given the map whole, a simulated robot localises against it (simulated_navigator): with odometry drifting
    5 cm per sqrt(m) it reaches the goal every time, where on odometry alone it stops short, believing it has
    arrived. On a map built from scans the odometry stands."""
    from fgdwa.sim.episode import simulated_navigator

    assert simulated_navigator("known").scan_match.enabled
    assert not simulated_navigator("scan").scan_match.enabled
    with pytest.raises(fgdwa.FgdwaError, match="mapping = 'nowhere'"):
        simulated_navigator("nowhere")
    from fgdwa.bench.recordings import RECORDED_ROLLOUTS, recorded_navigator

    recorded = recorded_navigator("known")
    assert recorded.scan_match.enabled and recorded.record_top_k == RECORDED_ROLLOUTS
    with pytest.raises(fgdwa.FgdwaError, match="mapping = 'nowhere'"):
        recorded_navigator("nowhere")
    world = demo_scenario().world
    start, goal = (1.2, 4.0, 0.0), (10.8, 4.0)
    outcomes = {}
    for label, navigator in (("matched", None), ("odometry", fgdwa.NavigatorParams())):
        outcomes[label] = [run_episode(world, start, goal, max_steps=200, lidar=fgdwa.LidarParams(beams=181),
                                       odometry_drift=(0.05, 0.02), seed=seed, navigator=navigator).summary
                           for seed in range(4)]
    assert [s.outcome for s in outcomes["matched"]] == ["success"] * 4
    short = [s for s in outcomes["odometry"] if s.outcome != "success"]
    assert short and all("GoalReached" in s.reason for s in short)


def test_the_same_seed_repeats_a_noisy_episode_bit_for_bit():
    scenario = demo_scenario()
    noisy = dict(max_steps=60, lidar=fgdwa.LidarParams(beams=181, noise_std=0.03, dropout=0.02), latency=1,
                 actuation_noise=(0.03, 0.05), actuation_lag=0.2, odometry_drift=(0.02, 0.02))
    a = run_episode(scenario.world, scenario.start, scenario.goal, seed=11, **noisy)
    b = run_episode(scenario.world, scenario.start, scenario.goal, seed=11, **noisy)
    c = run_episode(scenario.world, scenario.start, scenario.goal, seed=12, **noisy)
    for name in ("poses", "believed_poses", "commands", "twists", "clearances"):
        np.testing.assert_array_equal(getattr(a.motion, name), getattr(b.motion, name))
    np.testing.assert_array_equal(a.context.last_scan.ranges, b.context.last_scan.ranges)
    assert a.summary.outcome == b.summary.outcome and a.summary.steps == b.summary.steps
    assert not np.array_equal(a.motion.poses[:20], c.motion.poses[:20])


def test_a_disc_driven_into_a_standing_robot_is_a_collision():
    disc = fgdwa.Disc((3.0, 0.0), 0.3, velocity=(-1.0, 0.0))
    # The robot is told to stand still throughout: no command reaches its wheels in time.
    result = run_episode(World(discs=[disc]), (0.0, 0.0, 0.0), (-20.0, 0.0), max_steps=60, latency=60)
    assert result.summary.outcome == "collision"
    assert np.all(result.motion.poses == result.motion.poses[0])
    assert "mover 0 drove into the robot" in result.summary.reason and "the robot at 0.00 m/s" in result.summary.reason
    # The disc's edge reaches the robot's after 2.45 s: in cycle 17 of 0.15 s.
    assert result.summary.steps == 17


def test_a_fast_disc_passing_a_standing_robot_within_one_step_is_a_collision():
    robot = fgdwa.Footprint.circle(0.25)
    standing = (0.0, 0.0, 0.0)
    fast = fgdwa.Disc((-1.0, 0.0), 0.1, velocity=(20.0, 0.0))  # from x = -1 to x = +1 in 0.1 s
    truth = fgdwa.CollisionWorld(None, [fast])
    assert not truth.in_collision(robot, standing, 0.0) and not truth.in_collision(robot, standing, 0.1)
    assert collides_during_step(truth, robot, standing, standing, 0.0, 0.1)
    # The same disc 0.5 m aside passes clear.
    aside = fgdwa.CollisionWorld(None, [fgdwa.Disc((-1.0, 0.5), 0.1, velocity=(20.0, 0.0))])
    assert not collides_during_step(aside, robot, standing, standing, 0.0, 0.1)
    # Discs given by where they are at each time: a mover along its route, restored afterwards.
    mover = fgdwa.sim.MovingObstacle(radius=0.1, waypoints=np.array([[-1.0, 0.0], [1.0, 0.0]]), speed=20.0,
                                     mode="once")
    world = World(movers=[mover])
    truth = fgdwa.CollisionWorld(None, world.discs_at(0.0))
    assert collides_during_step(truth, robot, standing, standing, 0.0, 0.1, discs_at=world.discs_at)
    assert truth.discs[0].center[0] == pytest.approx(-1.0)


@pytest.mark.parametrize("setting, value", [
    ("latency", -1), ("latency", 1.5), ("latency", True),
    ("actuation_noise", (-0.1, 0.0)), ("actuation_noise", (0.1,)), ("actuation_noise", "ab"),
    ("actuation_lag", -0.1), ("actuation_lag", float("nan")),
    ("odometry_drift", (float("nan"), 0.0)), ("odometry_drift", "x"), ("motor_rate", -1.0), ("motor_rate", 1e5),
    ("actuation_lag", 10 ** 400), ("body", "wobbly"),
    ("seed", -1), ("seed", 0.5),
])
def test_bad_body_settings_are_named(setting, value):
    with pytest.raises(fgdwa.FgdwaError, match=setting) as error:
        open_run(max_steps=2, **{setting: value})
    assert len(str(error.value)) < 200  # a huge number is named by its size, not its 400 digits


def test_the_wheels_ramp_at_the_acceleration_limits_of_a_100_hz_motor_controller():
    from fgdwa.sim.body import Body, BodySettings

    limits = fgdwa.RobotLimits(acc_v=1.0, acc_omega=2.0, brake_v=3.0)
    body = Body(BodySettings(motor_rate=100.0), 0.15, seed=0, limits=limits)
    mean = body.drive(fgdwa.Twist(1.0, 1.0))
    # 15 periods of 0.01 s: v gains 0.01 m/s each, omega 0.02 rad/s; the mean is over the trapezoids.
    assert body.twist.v == pytest.approx(0.15) and body.twist.omega == pytest.approx(0.30)
    assert mean.v == pytest.approx(0.075) and mean.omega == pytest.approx(0.15)
    for _ in range(10):
        body.drive(fgdwa.Twist(1.0, 1.0))
    assert body.twist.v == pytest.approx(1.0) and body.twist.omega == pytest.approx(1.0)
    # Slowing down is limited by the braking deceleration: 3 m/s^2 over 0.15 s.
    body.drive(fgdwa.Twist(0.0, 1.0))
    assert body.twist.v == pytest.approx(0.55)
    with pytest.raises(fgdwa.FgdwaError, match="limits"):
        Body(BodySettings(motor_rate=100.0), 0.15, seed=0)


def test_the_default_body_is_a_real_robots_and_ideal_is_the_old_one():
    from fgdwa.sim.body import BODY_PROFILES, BodySettings

    default = BODY_PROFILES["default"]
    assert default.motor_rate == 100.0 and min(default.actuation_noise) > 0 and min(default.odometry_drift) > 0
    assert BODY_PROFILES["ideal"] == BodySettings()
    drifting = open_run(max_steps=40, body="default", seed=5)
    assert np.any(drifting.motion.believed_poses != drifting.motion.poses)
    assert np.all(drifting.motion.twists[:3, 0] < drifting.motion.commands[:3, 0])
    # A field given replaces the profile's.
    exact = open_run(max_steps=40, body="default", odometry_drift=(0.0, 0.0), seed=5)
    np.testing.assert_array_equal(exact.motion.believed_poses, exact.motion.poses)
