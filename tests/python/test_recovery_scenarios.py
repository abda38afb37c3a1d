"""The built-in scenarios that only the Navigator's recovery and its terrain-aware planner solve."""

import pytest

from fgdwa.builtin import dead_end_scenario, terrain_temptation_scenario
from fgdwa.scenario import run_scenario


def test_a_dead_end_missing_from_the_map_is_left_by_a_recovery():
    scenario = dead_end_scenario()
    result = run_scenario(scenario, "fgdwa", seed=0)
    assert result.outcome == "success"
    # It stalled at the back wall, backed out, and followed a new path round the pocket.
    assert "BackingUp" in result.modes
    assert len(result.paths) >= 2
    assert result.min_clearance > 0.0


@pytest.mark.parametrize("planner", ["fgdwa", "gdwa", "dwa"])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_dodging_an_unknown_block_never_leads_onto_grade_four(planner, seed):
    result = run_scenario(terrain_temptation_scenario(), planner, seed=seed)
    assert result.outcome != "fall"
    assert result.outcome != "collision"


def test_fgdwa_gets_round_the_block_above_the_slope():
    result = run_scenario(terrain_temptation_scenario(), "fgdwa", seed=0)
    assert result.outcome == "success"
    # Past the block, above it: the slope lies below y = 3.2 m.
    past = result.poses[(result.poses[:, 0] > 6.0) & (result.poses[:, 0] < 6.6)]
    assert len(past) and past[:, 1].min() > 4.8
