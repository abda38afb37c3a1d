import numpy as np
import pytest

import fgdwa


def test_step_turns_first_then_moves_along_the_new_heading():
    pose = fgdwa.unicycle_step((1.0, 2.0, 0.0), (1.0, np.pi / 2), 1.0)
    assert (pose.x, pose.y, pose.theta) == pytest.approx((1.0, 3.0, np.pi / 2), abs=1e-12)


@pytest.mark.parametrize("v,omega", [(0.8, 0.6), (1.2, -1.0), (0.3, 0.05)])
def test_constant_command_rollout_matches_the_closed_form_arc(v, omega):
    dt, n, theta0 = 0.1, 30, 0.4
    poses = fgdwa.rollout((0.5, -0.2, theta0), (v, omega), dt, n)
    k = np.arange(1, n + 1)
    b = omega * dt
    # Discrete model, closed form of sum_{j=1..k} cos/sin(theta0 + j b).
    scale = np.sin(k * b / 2) / np.sin(b / 2)
    x = 0.5 + v * dt * scale * np.cos(theta0 + (k + 1) * b / 2)
    y = -0.2 + v * dt * scale * np.sin(theta0 + (k + 1) * b / 2)
    np.testing.assert_allclose(poses[:, 0], x, atol=1e-10)
    np.testing.assert_allclose(poses[:, 1], y, atol=1e-10)
    # Every pose lies on one circle whose radius tends to v / omega as dt -> 0.
    centre_radius = v * dt / (2 * abs(np.sin(b / 2)))
    assert abs(centre_radius - v / abs(omega)) * abs(omega) / v < 1e-2


def test_rollout_equals_repeated_steps():
    pose = fgdwa.Pose2(0.0, 0.0, 3.0)
    poses = fgdwa.rollout(pose, (1.0, 0.7), 0.15, 40)
    for expected in poses:
        pose = fgdwa.unicycle_step(pose, (1.0, 0.7), 0.15)
        assert (pose.x, pose.y) == pytest.approx(tuple(expected[:2]), abs=1e-12)
        assert fgdwa.angle_difference(pose.theta, expected[2]) == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("seed", range(5))
def test_samples_lie_in_the_window_and_include_current_and_straight(seed):
    rng = np.random.default_rng(seed)
    limits = fgdwa.RobotLimits()
    for _ in range(200):
        current = (rng.uniform(0, limits.v_max), rng.uniform(-limits.omega_max, limits.omega_max))
        window = fgdwa.dynamic_window(limits, current, 0.15)
        samples = fgdwa.sample_window(window, current, 21, 21)
        assert samples.shape == (441, 2)
        assert np.all(samples[:, 0] >= max(limits.v_min, current[0] - 0.15) - 1e-12)
        assert np.all(samples[:, 0] <= min(limits.v_max, current[0] + 0.15) + 1e-12)
        assert np.all(np.abs(samples[:, 1]) <= limits.omega_max + 1e-12)
        assert np.all(np.abs(samples[:, 1] - current[1]) <= 0.3 + 1e-12)
        assert np.any(samples[:, 0] == current[0])
        assert np.any(samples[:, 1] == current[1])
        if window.omega_lo <= 0.0 <= window.omega_hi:
            assert np.any(samples[:, 1] == 0.0)
