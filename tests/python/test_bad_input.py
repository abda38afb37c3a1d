"""Every public entry point rejects bad input with FgdwaError naming what was wrong."""

import math

import numpy as np
import pytest

import fgdwa
from fgdwa.sim import World, run_episode

NAN = float("nan")
INF = float("inf")


def raises(match):
    return pytest.raises(fgdwa.FgdwaError, match=match)


def test_error_is_a_value_error():
    assert issubclass(fgdwa.FgdwaError, ValueError)


@pytest.mark.parametrize("field,value", [("v_max", NAN), ("v_max", INF), ("v_max", -1.0), ("omega_max", 0.0),
                                         ("acc_v", -0.5), ("acc_omega", NAN), ("v_min", -0.1),
                                         ("brake_v", -1.0), ("brake_omega", INF)])
def test_robot_limits(field, value):
    with raises(field):
        fgdwa.RobotLimits(**{field: value})


def test_inverted_speed_limits():
    with raises("v_min"):
        fgdwa.RobotLimits(v_min=1.0, v_max=0.5)


def test_footprints():
    with raises("radius"):
        fgdwa.Footprint.circle(0.0)
    with raises("radius"):
        fgdwa.Footprint.circle(NAN)
    with raises("at least 3"):
        fgdwa.Footprint.polygon([[0, 0], [1, 0]])
    with raises("convex"):
        fgdwa.Footprint.polygon([[1, 1], [-1, 1], [0, 0.2], [-1, -1], [1, -1]])
    with raises("origin"):
        fgdwa.Footprint.polygon([[1, 1], [2, 1], [2, 2], [1, 2]])
    with raises("vertices"):
        fgdwa.Footprint.polygon(np.zeros((4, 3)))
    with raises("not finite"):
        fgdwa.Footprint.polygon([[1, 1], [-1, 1], [-1, NAN]])


def test_grids():
    with raises("empty"):
        fgdwa.OccupancyGrid(np.zeros((0, 5), np.uint8), 0.1)
    with raises("dtype"):
        fgdwa.OccupancyGrid(np.zeros((5, 5), np.float64), 0.1)
    with raises("2-D"):
        fgdwa.OccupancyGrid(np.zeros(5, np.uint8), 0.1)
    with raises("resolution"):
        fgdwa.OccupancyGrid(np.zeros((5, 5), np.uint8), -0.1)
    with raises("resolution"):
        fgdwa.OccupancyGrid(np.zeros((5, 5), np.uint8), NAN)
    with raises("origin"):
        fgdwa.OccupancyGrid(np.zeros((5, 5), np.uint8), 0.1, (0.0, INF))
    with raises("origin"):
        fgdwa.OccupancyGrid(np.zeros((5, 5), np.uint8), 0.1, (0.0, 1.0, 2.0))
    grid = fgdwa.OccupancyGrid(np.zeros((5, 5), np.uint8), 0.1)
    with raises("points"):
        fgdwa.DistanceField(grid).distance(np.zeros((3, 3)))
    with raises("outside the grid"):
        grid.cell_center(5, 0)


def test_discs():
    with raises("radius"):
        fgdwa.Disc((0, 0), -1.0)
    with raises("center"):
        fgdwa.Disc((NAN, 0), 1.0)
    with raises("velocity"):
        fgdwa.Disc((0, 0), 1.0, velocity=(1.0,))
    with raises("growth"):
        fgdwa.Disc((0, 0), 1.0, growth=-0.1)
    with raises("acceleration"):
        fgdwa.Disc((0, 0), 1.0, acceleration=(NAN, 0.0), accel_time=1.0)
    with raises("accel_time"):
        fgdwa.Disc((0, 0), 1.0, acceleration=(1.0, 0.0), accel_time=-1.0)
    with raises("velocity after accel_time"):
        fgdwa.Disc((0, 0), 1.0, acceleration=(9000.0, 0.0), accel_time=1.0)
    with raises("hypothesis_time"):
        fgdwa.TrackerParams(hypothesis_time=-1.0)


@pytest.mark.parametrize("make,match", [
    (lambda: fgdwa.NavigatorParams(unknown_cost=-1.0), "unknown_cost"),
    (lambda: fgdwa.NavigatorParams(mover_margin=NAN), "mover_margin"),
    (lambda: fgdwa.NavigatorParams(mover_route_horizon=-0.5), "mover_route_horizon"),
    (lambda: fgdwa.NavigatorParams(mover_route_lookahead=INF), "mover_route_lookahead"),
    (lambda: fgdwa.NavigatorParams(occupancy=fgdwa.OccupancyParams(hit_share=0.0)), "hit_share"),
    (lambda: fgdwa.TrackerParams(max_uncertainty=-0.1), "max_uncertainty"),
    (lambda: fgdwa.OccupancyParams(clear_range=NAN), "clear_range"),
])
def test_noisy_world_settings(make, match):
    with raises(match):
        make()


@pytest.mark.parametrize("kwargs,match", [({"dt": 0.0}, "dt"), ({"dt": NAN}, "dt"), ({"sim_time": -1.0}, "sim_time"),
                                          ({"sim_time": 0.01}, "sim_time"),
                                          ({"window": {"n_v": 0}}, r"planner\.window\.n_v = 0: must be >= 1"),
                                          ({"window.n_omega": -3}, r"planner\.window\.n_omega = -3: must be >= 1"),
                                          ({"window": {"n_v": 2000, "n_omega": 2000}},
                                           r"window\.n_v \* n_omega"),
                                          ({"n_v": 5}, r"unknown parameter 'n_v'; did you mean 'window\.n_v'"),
                                          ({"normalization": "l2"}, "normalization"),
                                          ({"braking": "soft"}, "braking"), ({"goal_tolerance": -1.0}, "goal_tolerance"),
                                          ({"moving_horizon": -1.0}, "moving_horizon"),
                                          ({"mover_caution_radius": NAN}, "mover_caution_radius"),
                                          ({"mover_speed_weight": 1.5}, "mover_speed_weight"),
                                          ({"critics": []}, "at least one"),
                                          ({"critics": [("heading", 1.0), ("heading", 2.0)]}, "twice"),
                                          ({"critics": [("nonsense", 1.0)]}, "unknown critic"),
                                          ({"critics": [("clearance", 1.0, {"radius": 1.0})]}, "no parameter 'radius'"),
                                          ({"critics": [("clearance", 1.0, {"cap": -1.0})]}, "cap"),
                                          ({"critics": [("heading", NAN)]}, "weight"),
                                          ({"critics": [{"name": "heading", "wieght": 1.0}]}, "unknown key 'wieght'"),
                                          ({"critics": [42]}, r"critics\[0\]: each critic is")])
def test_planner_params(kwargs, match):
    with raises(match):
        fgdwa.PlannerParams(**kwargs)


def test_plan_arguments(open_world):
    planner = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.25))
    world = fgdwa.FieldClearance(fgdwa.DistanceField(open_world))
    with raises("goal"):
        planner.plan(fgdwa.RobotState((0, 0, 0)), (1.0, NAN), world)
    with raises("goal"):
        planner.plan(fgdwa.RobotState((0, 0, 0)), (1.0, 2.0, 3.0), world)
    with raises("pose"):
        fgdwa.RobotState((NAN, 0, 0))
    state = fgdwa.RobotState()
    state.pose = fgdwa.Pose2(NAN, 0.0, 0.0)
    with raises("state x"):
        planner.plan(state, (1.0, 2.0), world)
    with raises("pose"):
        fgdwa.RobotState((0, 0), (0, 0))
    with raises("dtype"):
        fgdwa.RobotState(("a", "b", "c"))
    with raises("no critic 'similarity'"):
        planner.set_weight("similarity", 1.0)
    with raises("weight"):
        planner.set_weight("heading", INF)
    with raises("dt"):
        fgdwa.unicycle_step((0, 0, 0), (1, 0), -0.1)
    with raises("n_steps"):
        fgdwa.rollout((0, 0, 0), (1, 0), 0.1, 0)


def test_episode_arguments(open_world):
    cells = np.zeros((30, 30), np.uint8)
    cells[10:20, 10:20] = 1
    world = World(grid=fgdwa.OccupancyGrid(cells, 0.1))
    with raises("start"):
        run_episode(world, (1.5, 1.5, 0.0), (2.8, 2.8))
    with raises("start"):
        run_episode(world, (0.5, 0.5), (2.8, 2.8))
    with raises("goal"):
        run_episode(world, (0.5, 0.5, 0.0), (math.nan, 2.8))
    with raises("max_steps"):
        run_episode(world, (0.5, 0.5, 0.0), (2.8, 2.8), max_steps=0)


def test_safety_margin():
    assert fgdwa.PlannerParams().safety_margin == 0.02
    with raises("safety_margin"):
        fgdwa.PlannerParams(safety_margin=-0.01)


# The library checks at its own entries, whatever the Python object carries:
# a NaN inside a Pose2 used to index the grid with static_cast<int>(NaN).
def _field():
    cells = np.zeros((20, 20), np.uint8)
    cells[5, 5] = 1
    return fgdwa.DistanceField(fgdwa.OccupancyGrid(cells, 0.1))


@pytest.mark.parametrize("pose,field", [(fgdwa.Pose2(NAN, 0.5, 0.0), "pose x"), (fgdwa.Pose2(0.5, INF, 0.0), "pose y"),
                                        (fgdwa.Pose2(0.5, 0.5, NAN), "pose theta"),
                                        (fgdwa.Pose2(1e300, 0.5, 0.0), "pose x")])
def test_non_finite_inside_pose_objects(pose, field):
    world = fgdwa.FieldClearance(_field())
    for footprint in (fgdwa.Footprint.circle(0.2), fgdwa.Footprint.polygon([[0.2, 0.1], [-0.2, 0.1], [-0.2, -0.1], [0.2, -0.1]])):
        with raises(field):
            world.clearance(footprint, pose)
        with raises(field):
            fgdwa.CollisionWorld(_field().grid).clearance(footprint, pose)
    with raises(field):
        fgdwa.unicycle_step(pose, fgdwa.Twist(0.1, 0.0), 0.1)


@pytest.mark.parametrize("resolution", [5e-324, 1e-9, 1e200, 1e308])
def test_resolutions_outside_the_limits(resolution):
    with raises(r"resolution = .*must lie in \[1e-04, 1000\]"):
        fgdwa.OccupancyGrid(np.zeros((4, 4), np.uint8), resolution)


def test_grid_beyond_the_coordinate_limit():
    with raises("origin"):
        fgdwa.OccupancyGrid(np.zeros((4, 4), np.uint8), 0.1, (2e7, 0.0))


def test_star_footprint_is_refused():
    star = [[np.cos(a) * 0.3, np.sin(a) * 0.3] for a in np.arange(5) * 4 * np.pi / 5]
    with raises("intersects itself"):
        fgdwa.Footprint.polygon(star)


def test_huge_footprint_is_refused():
    with raises("vertex 0 x"):
        fgdwa.Footprint.polygon([[1e6, 1.0], [-1.0, 1.0], [-1.0, -1.0]])


def test_path_too_long_to_walk():
    with raises("global path length"):
        fgdwa.GlobalPath([[-9e5, -9e5], [9e5, 9e5]] * 400)


def test_path_blocked_walks_a_long_path_in_strides():
    field = _field()
    path = fgdwa.GlobalPath([[50.0, 0.0], [5e5, 0.0]])
    assert not fgdwa.path_blocked(path, (50.0, 0.0), field, 0.3)
    blocked = fgdwa.GlobalPath([[5e5, 0.55], [-5e5, 0.55]])
    assert fgdwa.path_blocked(blocked, (5e5, 0.55), field, 0.3)


@pytest.mark.parametrize("critics,field", [([(None, 1.0)], r"critics\[0\]\.name"),
                                           ([("heading", "x")], "weight of 'heading'"),
                                           ([{"name": "heading", "params": 3}], "params of 'heading'"),
                                           ([("clearance", 1.0, {"cap": 10 ** 400})], "clearance.cap")])
def test_critic_entries_of_the_wrong_type_are_named(critics, field):
    with raises(field):
        fgdwa.PlannerParams(critics=critics)


# Angles are radians in the Python API: the error names the field by its path, the bound broken and the unit.
@pytest.mark.parametrize("make,field", [
    (lambda: fgdwa.LidarParams(fov=7.0), r"^lidar\.fov = 7: must be <= 6\.2831853\d* \(rad\)$"),
    (lambda: fgdwa.LidarParams(fov=0.0), r"^lidar\.fov = 0: must be > 0 \(rad\)$"),
    (lambda: fgdwa.PlannerParams(key_nodes=dict(min_turn=math.pi)),
     r"^planner\.key_nodes\.min_turn = 3\.14159\d*: must be < 3\.14159\d* \(rad\)$"),
    (lambda: fgdwa.PlannerParams(**{"key_nodes.min_turn": -0.1}),
     r"^planner\.key_nodes\.min_turn = -0\.1: must be >= 0 \(rad\)$"),
    (lambda: fgdwa.DetectWindowParams(half_angle=-5.0), r"^detect_window\.half_angle = -5: must be > 0 \(rad\)$"),
    (lambda: fgdwa.DetectWindowParams(half_angle=4.0),
     r"^detect_window\.half_angle = 4: must be <= 3\.14159\d* \(rad\)$"),
    (lambda: fgdwa.NavigatorParams(rotate_limit=NAN), r"^navigator\.rotate_limit = nan: must be finite \(rad\)$"),
    (lambda: fgdwa.NavigatorParams(rotate_limit=2e7), r"^navigator\.rotate_limit = 2e\+07: must be <= 1e\+07 \(rad\)$"),
])
def test_angle_arguments_name_the_field_and_its_bound(make, field):
    with raises(field):
        make()


# Degrees are only for file keys ending in _deg (scenario YAML); the constructors take no such keyword.
# Where the name is close enough the message suggests the radian field; fov_deg and key_node_angle_deg are
# too far from fov and key_nodes.min_turn for the library's did-you-mean, so only the refusal is checked there.
@pytest.mark.parametrize("cls,key,suggestion", [(fgdwa.LidarParams, "fov_deg", None),
                                                (fgdwa.PlannerParams, "key_node_angle_deg", None),
                                                (fgdwa.DetectWindowParams, "half_angle_deg", "half_angle"),
                                                (fgdwa.NavigatorParams, "rotate_limit_deg", "rotate_limit")])
def test_degree_keywords_are_not_taken(cls, key, suggestion):
    with raises(rf"^{cls.name}: unknown parameter '{key}'") as caught:
        cls(**{key: 10.0})
    if suggestion is not None:
        assert f"did you mean '{suggestion}'" in str(caught.value)
    with raises(f"unknown parameter '{key}'"):
        cls().set(key, 10.0)


def test_tiny_control_period_names_the_bound():
    with raises(r"^planner\.dt = 1e-09: must be >= 1e-04 \(s\)$"):
        fgdwa.PlannerParams(dt=1e-9)


def test_numbers_in_python_containers():
    """A critic's weight or parameter given in a list or dict: a numpy scalar is a number, a bool is not."""
    params = fgdwa.PlannerParams(critics=[("heading", np.float32(0.5)), ("clearance", 0.15, {"cap": np.float32(1.5)}),
                                          ("velocity", 1.0)])
    assert params.critics[0]["weight"] == 0.5 and params.critics[1]["params"]["cap"] == 1.5
    with pytest.raises(fgdwa.FgdwaError, match="weight of 'heading'.*bool"):
        fgdwa.PlannerParams(critics=[("heading", True)])
    with pytest.raises(fgdwa.FgdwaError, match="critic clearance.cap.*bool"):
        fgdwa.PlannerParams(critics=[("clearance", 1.0, {"cap": False})])
    with pytest.raises(fgdwa.FgdwaError, match="too large for a float"):
        fgdwa.PlannerParams(critics=[("heading", 10**400)])


def test_a_cycle_of_more_rollout_poses_than_the_cap_is_refused_before_any_allocation():
    # 1000 x 1000 samples x 100 000 steps would end in bad_alloc inside plan().
    with raises(r"planner\.sim_time = 10: with dt = 1e-04 s and 1000 x 1000 samples, a cycle rolls out 1e\+11 "
                r"poses, more than 10000000"):
        fgdwa.PlannerParams(window={"n_v": 1000, "n_omega": 1000}, dt=1e-4, sim_time=10)
    fgdwa.PlannerParams(window={"n_v": 100, "n_omega": 100}, dt=0.01, sim_time=10)  # 1e7 poses: at the cap


def test_an_episode_with_no_global_method_names_the_methods():
    from fgdwa.io.builtin import demo_scenario
    from fgdwa.sim.episode import run_preset

    scenario = demo_scenario()
    with raises(r"method = None: expected one of \['astar', 'ompl:"):
        run_preset(scenario.world, scenario.start, scenario.goal, global_method=None, max_steps=3)


def test_max_steps_true_is_not_one_step():
    from fgdwa.io.builtin import demo_scenario
    from fgdwa.sim.episode import run_episode

    scenario = demo_scenario()
    with raises(r"max_steps = True: must be an integer >= 1"):
        run_episode(scenario.world, scenario.start, scenario.goal, max_steps=True)
