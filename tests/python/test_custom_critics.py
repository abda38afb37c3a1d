"""Critics written in Python: registered by name, scored in batches, vetoes counted."""

import numpy as np
import pytest

import fgdwa
from fgdwa import FgdwaError


class PreferRight:
    """Cost: how far left each rollout ends; vetoes rollouts ending left of `limit`."""

    sense = "cost"

    def __init__(self, limit=1.0):
        self.limit = limit
        self.prepared = 0

    def prepare(self, context):
        self.prepared += 1
        self.start_y = context["pose"][1]

    def score_batch(self, poses, commands, min_clearance):
        assert poses.ndim == 3 and poses.shape[2] == 3 and commands.shape == (len(poses), 2)
        left = poses[:, -1, 1] - self.start_y
        return np.where(left > self.limit, np.nan, left)


def test_a_python_critic_scores_vetoes_and_steers():
    fgdwa.register_critic("test_prefer_right", PreferRight)
    assert "test_prefer_right" in fgdwa.critic_names()
    with pytest.raises(FgdwaError, match="already registered"):
        fgdwa.register_critic("test_prefer_right", PreferRight)
    with pytest.raises(FgdwaError, match="score_batch"):
        fgdwa.register_critic("test_no_batch", object)
    params = fgdwa.PlannerParams(critics=[("velocity", 1.0), ("test_prefer_right", 0.5, {"limit": 0.2})])
    planner = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.25), params)
    state = fgdwa.RobotState((0.0, 0.0, 0.0), (0.5, 0.0))
    result = planner.plan(state, (5.0, 0.0), fgdwa.FieldClearance())
    rollouts = planner.rollouts()
    ends_left = np.array([r[-1, 1] for r in rollouts]) > 0.2
    reasons = np.array(result.reasons)
    assert ends_left.any() and np.all((reasons == "Critic") == ends_left)
    assert result.reject_counts["Critic"] == ends_left.sum()
    # The cost pulls the choice right of straight ahead.
    assert result.command.omega < 0.0
    with pytest.raises(FgdwaError, match="limt"):
        fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.25),
                           fgdwa.PlannerParams(critics=[("test_prefer_right", 1.0, {"limt": 1.0})]))


class Constant:
    """Scores every rollout `value` (any object numpy takes)."""

    value = 0.0

    def __init__(self):
        pass

    def score_batch(self, poses, commands, min_clearance):
        return np.full(len(poses), self.value)


def _plan_with(name, value, normalization="sum", weight=1.0):
    cls = type(name, (Constant,), {"value": value})
    fgdwa.register_critic(name, cls)
    params = fgdwa.PlannerParams(critics=[("velocity", 1.0), (name, weight)], normalization=normalization)
    planner = fgdwa.LocalPlanner(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.25), params)
    return planner.plan(fgdwa.RobotState((0.0, 0.0, 0.0), (0.5, 0.0)), (5.0, 0.0), fgdwa.FieldClearance())


def test_scores_that_overflow_the_total_or_are_not_real_are_refused():
    with pytest.raises(FgdwaError, match=r"critic 'test_huge'.*overflow"):
        _plan_with("test_huge", 1e308, normalization="none", weight=10.0)  # 1e309: inf
    with pytest.raises(FgdwaError, match=r"critic 'test_complex'.*dtype complex128.*real numbers"):
        _plan_with("test_complex", 1 + 2j)
    assert _plan_with("test_ints", 3).status == fgdwa.Status.Ok  # integers are numbers


def test_a_score_batch_that_is_not_callable_is_refused_at_registration():
    class NotCallable:
        score_batch = 3

    with pytest.raises(FgdwaError, match="callable score_batch"):
        fgdwa.register_critic("test_not_callable", NotCallable)
