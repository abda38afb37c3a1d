import numpy as np
import pytest

import fgdwa
from fgdwa.io.builtin import unknown_beside_path_scenario
from fgdwa.sim import World, run_preset


def test_presets_follow_the_paper_tables():
    expected = {
        "dwa": ("goal", {"heading": 0.5, "clearance": 0.15, "velocity": 1.0}, False),
        "gdwa": ("key_nodes", {"heading": 0.5, "clearance": 0.15, "velocity": 1.0}, False),
        "sgdwa": ("key_nodes", {"heading": 0.5, "clearance": 0.15, "velocity": 1.0, "similarity": 0.5}, False),
        "fgdwa": ("key_nodes", {"heading": 0.5, "clearance": 0.15, "velocity": 1.0, "similarity": 0.5}, True),
        "gdwa_high_safety": ("key_nodes", {"heading": 0.5, "clearance": 1.0, "velocity": 1.0, "similarity": 0.5}, False),
        "gdwa_high_similarity": ("key_nodes", {"heading": 0.5, "clearance": 0.15, "velocity": 1.0, "similarity": 5.0},
                                 False),
        # Nav2's scales; the map-grid critics' times half the 0.05 m costmap resolution.
        "dwb": ("key_nodes", {"dwb_obstacle": 0.02, "dwb_path_align": 0.8, "dwb_goal_align": 0.6,
                              "dwb_path_dist": 0.8, "dwb_goal_dist": 0.6}, False),
    }
    assert fgdwa.preset_names() == list(expected)
    for name, (target, weights, fuzzy) in expected.items():
        preset = fgdwa.planner_preset(name)
        assert preset.params.heading_target == target
        assert {c["name"]: c["weight"] for c in preset.params.critics} == pytest.approx(weights, rel=1e-12)
        assert preset.params.normalization == ("none" if name == "dwb" else "sum")
        assert (preset.params.dt, preset.params.sim_time) == (0.15, 3.0)
        assert preset.fuzzy == fuzzy
        assert (preset.weight_policy() is not None) == fuzzy
    with pytest.raises(fgdwa.FgdwaError, match="unknown planner preset 'fdwa'"):
        fgdwa.planner_preset("fdwa")


def test_dwb_preset_follows_the_global_path_round_a_wall():
    cells = np.zeros((60, 100), dtype=np.uint8)
    cells[20:40, 48:52] = 1  # a wall across the straight line from start to goal
    world = World(grid=fgdwa.OccupancyGrid(cells, 0.1))
    result = run_preset(world, (1.0, 3.0, 0.0), (9.0, 3.0), "dwb", max_steps=400)
    assert result.summary.outcome == "success"
    assert result.summary.min_clearance > 0.0
    # Its path critics keep it near the A* path around the wall.
    assert result.summary.max_deviation < 0.3
    assert np.all(np.isnan(result.trace.delta))  # no similarity critic to weigh


def test_fuzzy_weights_follow_the_rule_tables():
    policy = fgdwa.FuzzyWeights()
    engine = fgdwa.paper_fuzzy_controller()
    for density, deviation in [(0.1, 0.2), (1.0, 2.5), (1.9, 4.8), (0.5, 3.7)]:
        weights = policy.weights(density, deviation)
        out = engine.evaluate(I=density, D=deviation)
        assert weights == pytest.approx({"clearance": out["beta"], "similarity": out["delta"]})
    # More obstacles ahead: more weight on safety (Table 3, D small); farther off the path:
    # more weight on similarity (Table 4).
    assert policy.weights(1.8, 0.0)["clearance"] > policy.weights(0.1, 0.0)["clearance"] + 0.2
    assert policy.weights(0.1, 4.5)["similarity"] > policy.weights(0.1, 0.0)["similarity"] + 1.5
    assert fgdwa.FixedWeights(0.3, 1.0).weights(2.0, 5.0) == {"clearance": 0.3, "similarity": 1.0}
    assert fgdwa.FixedWeights(weights={"velocity": 0.5}).weights(0.0, 0.0) == {"velocity": 0.5}
    remapped = fgdwa.FuzzyWeights(engine, output_critics={"beta": "dwb_obstacle", "delta": "similarity"})
    assert set(remapped.weights(1.0, 1.0)) == {"dwb_obstacle", "similarity"}
    with pytest.raises(fgdwa.FgdwaError, match="outputs"):
        fgdwa.FuzzyWeights(engine, output_critics={"beta": "clearance"})
    with pytest.raises(fgdwa.FgdwaError, match="beta"):
        fgdwa.FixedWeights(-0.1, 1.0)
    with pytest.raises(fgdwa.FgdwaError, match="density"):
        policy.weights(float("nan"), 0.0)


def test_fgdwa_passes_unknown_obstacles_and_raises_beta_near_them():
    scenario = unknown_beside_path_scenario()
    result = run_preset(scenario.world, scenario.start, scenario.goal, "fgdwa", max_steps=500)
    assert result.summary.outcome == "success"
    assert result.summary.min_clearance > 0.0
    assert len(result.trace.beta) == result.summary.steps
    # The cycles the planner drove (the first stand watching for movers: no weights).
    planned = ~np.isnan(result.trace.beta)
    assert 0 < np.count_nonzero(~planned) <= 3 and not np.any(~planned[3:])
    beta, density = result.trace.beta[planned], result.trace.density[planned]
    crowded = density > 0.6  # an unknown block fills part of the detect window
    assert crowded.any() and (~crowded).any()
    assert beta[crowded].mean() > beta[~crowded].mean() + 0.1
    assert np.corrcoef(beta, density)[0, 1] > 0.8
    assert np.all((result.trace.delta[planned] >= 0.0) & (result.trace.delta[planned] <= 5.0))


def test_fixed_presets_keep_their_weights():
    scenario = unknown_beside_path_scenario()
    result = run_preset(scenario.world, scenario.start, scenario.goal, "gdwa_high_safety", max_steps=30)
    assert np.all(result.trace.beta == 1.0) and np.all(result.trace.delta == 0.5)
    assert np.all(np.isnan(result.trace.density))  # a fixed preset needs no lidar unless asked


def test_controller_runs_the_cycle_a_robot_would():
    scenario = unknown_beside_path_scenario()
    grid = scenario.world.grid
    truth = fgdwa.DistanceField(scenario.world.true_grid())
    preset = fgdwa.planner_preset("fgdwa")
    controller = fgdwa.Controller(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.25), preset.params,
                                  fgdwa.DistanceField(grid), preset.weight_policy())
    controller.set_global_path([[1.0, 3.0], [15.0, 3.0]])
    state = fgdwa.RobotState((3.2, 3.2, 0.0), (0.5, 0.0))  # the first unknown block is 0.8 m ahead-left
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(), truth).scan(state.pose)
    plan = controller.step(state, (15.0, 3.0), scan)
    report = controller.report
    assert plan.status == fgdwa.Status.Ok
    assert report.sensed_points > 10  # the block is not on the map
    assert report.density == pytest.approx(fgdwa.obstacle_density(scan).density)
    assert report.deviation == pytest.approx(0.2)
    weights = preset.weight_policy().weights(report.density, 0.2)
    assert (report.beta, report.delta) == pytest.approx((weights["clearance"], weights["similarity"]))
    assert plan.weights[plan.critic_names.index("clearance")] == report.beta
    with pytest.raises(fgdwa.FgdwaError, match="needs a scan"):
        controller.step(state, (15.0, 3.0), None)


def test_robot_presets():
    jackal = fgdwa.robot_preset("jackal")
    assert (jackal.limits.v_max, jackal.limits.omega_max, jackal.limits.acc_v, jackal.limits.acc_omega) == \
        (2.0, 4.0, 20.0, 25.0)
    assert not jackal.footprint.is_circle
    np.testing.assert_allclose(np.ptp(jackal.footprint.vertices, axis=0), (0.42, 0.33))
    assert fgdwa.robot_preset("default").footprint.radius == 0.25
    assert fgdwa.robot_names() == ["default", "jackal"]
    with pytest.raises(fgdwa.FgdwaError, match="unknown robot preset 'husky'"):
        fgdwa.robot_preset("husky")
