"""The built-in scenarios that only the Navigator's recovery and its terrain-aware planner solve."""

import numpy as np
import pytest

from fgdwa import NavigatorParams

from fgdwa.io.builtin import dead_end_scenario, terrain_temptation_scenario
from fgdwa.sim.scenario import run_scenario


def test_a_dead_end_missing_from_the_map_is_seen_and_planned_round():
    # The back wall joins the navigator's map as soon as the lidar sees it (from
    # the start, 7 m away): the path goes round the pocket and the robot never
    # enters it, so no recovery is needed.
    result = run_scenario(dead_end_scenario(), "fgdwa", seed=0)
    assert result.summary.outcome == "success"
    assert "BackingUp" not in result.trace.modes and "Rotating" not in result.trace.modes
    x, y = result.motion.poses[:, 0], result.motion.poses[:, 1]
    assert not np.any((x > 4.0) & (x < 9.0) & (y > 3.8) & (y < 6.2))


def test_a_dead_end_missing_from_the_map_is_left_by_a_recovery():
    # A map that never learns (learn_obstacles=False): only a recovery gets out.
    scenario = dead_end_scenario()
    # The ideal body: what is tested is the recovery, not how the live scan holds a drifted map.
    result = run_scenario(scenario, "fgdwa", seed=0, body="ideal", navigator=NavigatorParams(learn_obstacles=False))
    assert result.summary.outcome == "success"
    # It stalled at the back wall, backed out, and followed a new path round the pocket.
    assert "BackingUp" in result.trace.modes
    assert len(result.context.paths) >= 2
    assert result.summary.min_clearance > 0.0


@pytest.mark.parametrize("planner", ["fgdwa", "gdwa", "dwa"])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_dodging_an_unknown_block_never_leads_onto_grade_four(planner, seed):
    result = run_scenario(terrain_temptation_scenario(), planner, seed=seed)
    assert result.summary.outcome != "fall"
    assert result.summary.outcome != "collision"


def test_fgdwa_gets_round_the_block_above_the_slope():
    result = run_scenario(terrain_temptation_scenario(), "fgdwa", seed=0)
    assert result.summary.outcome == "success"
    # Past the block, above it: the slope lies below y = 3.2 m.
    past = result.motion.poses[(result.motion.poses[:, 0] > 6.0) & (result.motion.poses[:, 0] < 6.6)]
    assert len(past) and past[:, 1].min() > 4.8
