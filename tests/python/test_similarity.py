import numpy as np
import pytest

import fgdwa
from fgdwa.sim import run_episode
from fgdwa.io.builtin import c_trap_scenario


def reference_dtw(a, b, band=None):
    """Plain dynamic programming: sum of Euclidean distances along the best warping path.

    With a band, row i keeps columns within `band` of the diagonal, the band
    widened to the diagonal's slope; the first row starts at column 0 and the
    last row ends at the last column."""
    n, m = len(a), len(b)
    slope = (m - 1) / (n - 1) if n > 1 else 0.0
    cost = np.full((n + 1, m + 1), np.inf)
    cost[0, 0] = 0.0
    d = np.hypot(a[:, None, 0] - b[None, :, 0], a[:, None, 1] - b[None, :, 1])
    for i in range(n):
        lo, hi = 0, m - 1
        if band is not None:
            width = max(band, int(np.ceil(slope)))
            lo = 0 if i == 0 else max(0, int(np.floor(slope * i)) - width)
            hi = m - 1 if i == n - 1 else min(m - 1, int(np.ceil(slope * i)) + width)
        for j in range(lo, hi + 1):
            cost[i + 1, j + 1] = d[i, j] + min(cost[i, j + 1], cost[i + 1, j], cost[i, j])
    return cost[n, m]


def test_dtw_equals_plain_dynamic_programming_on_500_random_pairs():
    rng = np.random.default_rng(2024)
    for _ in range(500):
        a = rng.normal(size=(rng.integers(1, 30), 2)) * rng.uniform(0.1, 5)
        b = rng.normal(size=(rng.integers(1, 30), 2)) * rng.uniform(0.1, 5)
        assert fgdwa.dtw(a, b) == pytest.approx(reference_dtw(a, b), rel=1e-12, abs=1e-12)


def test_dtw_symmetry_identity_and_full_band():
    rng = np.random.default_rng(9)
    for _ in range(100):
        a = rng.uniform(-3, 3, size=(rng.integers(2, 25), 2))
        b = rng.uniform(-3, 3, size=(rng.integers(2, 25), 2))
        assert fgdwa.dtw(a, b) == pytest.approx(fgdwa.dtw(b, a), rel=1e-12)
        assert fgdwa.dtw(a, a) == 0.0
        assert fgdwa.dtw(a, b, band=max(len(a), len(b))) == fgdwa.dtw(a, b)
        assert fgdwa.dtw(a, b, band=2) >= fgdwa.dtw(a, b) - 1e-12


def test_banded_dtw_matches_the_banded_reference():
    rng = np.random.default_rng(4)
    for _ in range(100):
        n = rng.integers(2, 25)
        a, b = rng.uniform(-3, 3, size=(n, 2)), rng.uniform(-3, 3, size=(n, 2))
        for band in (0, 1, 3):
            assert fgdwa.dtw(a, b, band=band) == pytest.approx(reference_dtw(a, b, band), rel=1e-12)


def test_dtw_bad_input():
    with pytest.raises(fgdwa.FgdwaError, match="a:"):
        fgdwa.dtw(np.zeros((0, 2)).reshape(0, 3), np.zeros((3, 2)))
    with pytest.raises(fgdwa.FgdwaError, match="at least one point"):
        fgdwa.dtw(np.zeros((0, 2)), np.zeros((3, 2)))
    with pytest.raises(fgdwa.FgdwaError, match="not finite"):
        fgdwa.dtw(np.array([[0.0, np.nan]]), np.zeros((3, 2)))
    with pytest.raises(fgdwa.FgdwaError, match="band"):
        fgdwa.dtw(np.zeros((2, 2)), np.zeros((3, 2)), band=-2)


def test_reference_samples_on_a_straight_path():
    path = fgdwa.GlobalPath([[0.0, 0.0], [10.0, 0.0]])
    e = fgdwa.reference_samples(path, (2.0, 0.7), v_ref=0.5, dt=0.2, n=20)
    assert e.shape == (20, 2)
    np.testing.assert_allclose(e[:, 0], 2.0 + 0.1 * np.arange(1, 21))
    np.testing.assert_allclose(e[:, 1], 0.0)
    np.testing.assert_allclose(fgdwa.reference_samples(path, (2.0, 0.7), 0.5, 0.2, 20, "segment"), e)


def test_reference_samples_at_a_corner():
    path = fgdwa.GlobalPath([[0.0, 0.0], [1.0, 0.0], [1.0, 5.0]])
    polyline = fgdwa.reference_samples(path, (0.5, 0.0), 1.0, 0.1, 10, "polyline")
    segment = fgdwa.reference_samples(path, (0.5, 0.0), 1.0, 0.1, 10, "segment")
    # Spacing along the path stays 0.1 m; polyline turns the corner, segment runs on straight.
    arc = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(np.vstack([[0.5, 0.0], polyline]), axis=0).T))])
    np.testing.assert_allclose(arc[-1], 1.0, atol=1e-12)
    np.testing.assert_allclose(polyline[-1], (1.0, 0.5), atol=1e-12)
    np.testing.assert_allclose(segment[-1], (1.5, 0.0), atol=1e-12)
    assert np.all(polyline[5:, 0] == pytest.approx(1.0))
    # At the end of the path the samples stop at the goal.
    end = fgdwa.reference_samples(path, (1.0, 4.9), 1.0, 0.1, 10)
    np.testing.assert_allclose(end[-1], (1.0, 5.0))


def test_similarity_critic_scores_1_over_dtw_plus_1():
    options = {"v_ref_min": 0.1, "reference_speed": "current"}
    params = fgdwa.PlannerParams(critics=[("similarity", 1.0, dict(options, precision="double"))])
    planner = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2), params)
    planner.set_global_path([[0.0, 0.0], [20.0, 0.0]])
    state = fgdwa.RobotState((1.0, 0.5, 0.0), (0.6, 0.0))
    result = planner.plan(state, (20.0, 0.0), fgdwa.FieldClearance())
    rollouts = planner.rollouts()
    e = fgdwa.reference_samples(planner.global_path, (1.0, 0.5), 0.6, 0.15, 20)
    single = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2),
                                fgdwa.PlannerParams(critics=[("similarity", 1.0, options)]))
    single.set_global_path([[0.0, 0.0], [20.0, 0.0]])
    single_result = single.plan(state, (20.0, 0.0), fgdwa.FieldClearance())
    for i in range(0, len(rollouts), 37):
        expected = 1.0 / (fgdwa.dtw(rollouts[i][:, :2], e) + 1.0)
        assert result.raw[i, 0] == expected  # the batched double DTW repeats the single one bit for bit
        # The default single precision: float rounding, relative to the robot.
        assert single_result.raw[i, 0] == pytest.approx(expected, rel=1e-6)
    # The rollout that bends toward the path is the most similar one.
    best = int(np.argmax(result.raw[:, 0]))
    assert result.samples[best][1] < 0.0
    with pytest.raises(fgdwa.FgdwaError, match="needs a global path"):
        fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2), params).plan(state, (20, 0),
                                                                                        fgdwa.FieldClearance())
    # By default E is spaced by the speed limit, not the current speed.
    limit = fgdwa.LocalPlanner(fgdwa.RobotLimits(v_max=1.2), fgdwa.Footprint.circle(0.2),
                               fgdwa.PlannerParams(critics=[("similarity", 1.0)]))
    limit.set_global_path([[0.0, 0.0], [20.0, 0.0]])
    r = limit.plan(state, (20.0, 0.0), fgdwa.FieldClearance())
    e_limit = fgdwa.reference_samples(limit.global_path, (1.0, 0.5), 1.2, 0.15, 20)
    assert r.raw[0, 0] == pytest.approx(1.0 / (fgdwa.dtw(limit.rollouts()[0][:, :2], e_limit) + 1.0), rel=1e-6)
    with pytest.raises(fgdwa.FgdwaError, match="precision"):
        fgdwa.CriticConfig("similarity", 1.0, {"precision": "half"})
    with pytest.raises(fgdwa.FgdwaError, match="reference_speed"):
        fgdwa.CriticConfig("similarity", 1.0, {"reference_speed": "fast"})
    with pytest.raises(fgdwa.FgdwaError, match="sampling"):
        fgdwa.CriticConfig("similarity", 1.0, {"sampling": "spline"})
    with pytest.raises(fgdwa.FgdwaError, match="no option 'mode'"):
        fgdwa.CriticConfig("heading", 1.0, {"mode": "fast"})
    with pytest.raises(fgdwa.FgdwaError, match="v_ref_min"):
        fgdwa.CriticConfig("similarity", 1.0, {"v_ref_min": 0.0})


def test_sgdwa_gets_through_the_trap_too():
    scenario = c_trap_scenario()
    params = fgdwa.PlannerParams(heading_target="key_nodes", critics=[("heading", 0.5), ("clearance", 0.15),
                                                                      ("velocity", 1.0), ("similarity", 0.5)])
    result = run_episode(scenario.world, scenario.start, scenario.goal, params=params, max_steps=400)
    assert result.summary.outcome == "success"
