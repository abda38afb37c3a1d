"""A Rerun recording of an episode holds what the records hold, read back with Rerun's own API."""

import pytest

import fgdwa
from fgdwa.bench.experiments import resolve_scenario
from fgdwa.cli import main
from fgdwa.plot.recording import read_recording
from fgdwa.sim import run_scenario


def test_a_recording_holds_each_critics_part_of_the_chosen_total_cycle_by_cycle(tmp_path):
    rrd = tmp_path / "demo.rrd"
    assert main(["run", "demo", "--seed", "2", "--max-steps", "25", "--out", str(tmp_path), "--record", str(rrd)]) in (0, 1)
    # The same episode, run again: the records the recording was written from.
    scenario = resolve_scenario("demo")
    result = run_scenario(scenario, scenario.planner, 2, max_steps=25, record_cycles=True,
                          navigator=fgdwa.NavigatorParams(record_top_k=40))
    cycles = result.trace.cycles
    assert len(cycles) == 25 and cycles[0].critics
    table = read_recording(rrd, "/critics/**")
    assert list(table["cycle"]) == list(range(25))
    for j, critic in enumerate(cycles[0].critics):
        terms = [value[0] for value in table[f"/critics/{critic}/term:Scalars:scalars"]]
        raw = [value[0] for value in table[f"/critics/{critic}/raw:Scalars:scalars"]]
        assert terms == [c.chosen_terms[j] for c in cycles]
        assert raw == [c.chosen_raw[j] for c in cycles]
    # Each cycle's terms add up to the chosen sample's total, the best rollout's.
    for cycle in cycles:
        assert sum(cycle.chosen_terms) == cycle.totals[0]
    world = read_recording(rrd, "/world/**")
    assert {"/world/robot/true:LineStrips2D:strips", "/world/scan:Points2D:positions",
            "/world/chosen:LineStrips2D:strips"} <= set(world.columns)


def test_writing_a_recording_needs_recorded_cycles(tmp_path):
    from fgdwa.plot.recording import write_recording

    scenario = resolve_scenario("demo")
    result = run_scenario(scenario, scenario.planner, 0, max_steps=3)
    with pytest.raises(fgdwa.FgdwaError, match="record_cycles"):
        write_recording(result, scenario.world, scenario.goal, scenario.footprint, tmp_path / "x.rrd")


def test_inspect_names_a_missing_recording(tmp_path, capsys):
    assert main(["inspect", str(tmp_path / "none.rrd")]) != 0
    assert "no such recording" in capsys.readouterr().err
    with pytest.raises(fgdwa.FgdwaError, match="no such recording"):
        read_recording(tmp_path / "none.rrd")
