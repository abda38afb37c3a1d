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
    # The first cycles stand watching for movers: nothing chosen, nothing logged.
    chose = [len(c.chosen_terms) > 0 for c in cycles]
    assert sum(chose) >= 22 and all(chose[3:])
    for j, critic in enumerate(cycles[-1].critics):
        terms = [value if value is None else value[0] for value in table[f"/critics/{critic}/term:Scalars:scalars"]]
        raw = [value if value is None else value[0] for value in table[f"/critics/{critic}/raw:Scalars:scalars"]]
        assert terms == [c.chosen_terms[j] if k else None for c, k in zip(cycles, chose)]
        assert raw == [c.chosen_raw[j] if k else None for c, k in zip(cycles, chose)]
    # Each cycle's terms add up to the chosen sample's total, the best rollout's.
    for cycle in (c for c, k in zip(cycles, chose) if k):
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


def _values(table, column):
    return [value[0] if value is not None and len(value) else None for value in table[column]]


def test_a_recording_holds_the_critics_spread_vetoes_stage_times_and_mode_of_every_cycle(tmp_path):
    from fgdwa.plot.recording import FAN, write_recording
    from fgdwa.sim import trial_variation

    scenario = resolve_scenario("demo")
    result = run_scenario(scenario, scenario.planner, 1, max_steps=60, record_cycles=True, mapping="scan",
                          navigator=fgdwa.NavigatorParams(record_top_k=12))
    _, world, _ = trial_variation(scenario, 1)
    rrd = write_recording(result, world, scenario.goal, scenario.footprint, tmp_path / "scan.rrd")
    cycles = result.trace.cycles
    critics = read_recording(rrd, "/critics/**")
    for j, critic in enumerate(cycles[0].critics):
        for column, name in enumerate(("min", "mean", "max")):
            assert _values(critics, f"/critics/{critic}/{name}:Scalars:scalars") == \
                [c.critic_stats[j, column] for c in cycles]
        assert _values(critics, f"/critics/{critic}/vetoes:Scalars:scalars") == [c.critic_vetoes[j] for c in cycles]
        # The chosen rollout is one of the admissible samples the spread covers.
        for c in cycles:
            if len(c.chosen):
                assert c.critic_stats[j, 0] <= c.chosen_terms[j] <= c.critic_stats[j, 2]
    # T, the time to the nearest predicted contact, beside I and D, in the cycles that had one.
    weights = read_recording(rrd, "/weights/**")
    contact = [t for t in result.trace.contact_time if t != float("inf")]
    logged = [v for v in _values(weights, "/weights/contact_time:Scalars:scalars") if v is not None]
    assert contact and logged == contact
    times = read_recording(rrd, "/times/**")
    assert _values(times, "/times/plan_ms:Scalars:scalars") == [1e3 * c.times["plan"] for c in cycles]
    navigator = read_recording(rrd, "/navigator/**")
    assert _values(navigator, "/navigator/mode:Scalars:scalars") == \
        [float(int(fgdwa.NavigatorMode.__members__[c.mode])) for c in cycles]
    # The fan by total and by each critic; the colourings differ where the critics disagree.
    fan = read_recording(rrd, f"/{FAN}/**")
    columns = {f"/{FAN}/total:LineStrips2D:colors"} | {f"/{FAN}/by_critic/{c}:LineStrips2D:colors"
                                                        for c in cycles[0].critics}
    assert columns <= set(fan.columns)
    k = max(range(len(cycles)), key=lambda i: len(cycles[i].rollouts))
    colourings = {tuple(fan[column][k]) for column in columns}
    assert len(colourings) > 1
    # The robot's own map, logged when a scan changed it: the first cycle at least.
    own = read_recording(rrd, "/world/map/robot")
    logged = [i for i, c in enumerate(cycles) if c.scan_map is not None]
    assert logged and logged[0] == 0
    assert own["/world/map/robot:Image:buffer"].notna().sum() == len(logged)


def test_without_rerun_everything_else_runs_and_inspect_says_what_to_install(tmp_path):
    """rerun-sdk is optional: with it unimportable, fgdwa runs and draws, and
    fgdwa inspect / --record name the extra to install."""
    import subprocess
    import sys

    rrd = tmp_path / "x.rrd"
    rrd.write_bytes(b"")
    code = f"""
import sys
sys.modules["rerun"] = None  # import rerun raises ImportError
from fgdwa.cli import main
assert main(["run", "demo", "--max-steps", "5", "--out", {str(tmp_path)!r}]) in (0, 1)
assert main(["inspect", {str(rrd)!r}]) != 0
assert main(["run", "demo", "--max-steps", "5", "--out", {str(tmp_path / "r")!r}, "--record", {str(rrd)!r}]) != 0
assert main(["dynamic", "--level", "easy", "--seeds", "0", "--out", {str(tmp_path / "d")!r},
             "--record-failures", {str(tmp_path / "rrd")!r}]) != 0
"""
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert done.stderr.count('pip install "fgdwa[inspect]"') == 3
    assert (tmp_path / "demo_fgdwa.png").is_file()
    # Refused before running: nothing was run or written.
    assert not (tmp_path / "r").exists() and not (tmp_path / "d").exists()


def test_the_viewer_command_refuses_a_port_out_of_range(tmp_path):
    pytest.importorskip("rerun")
    from fgdwa.plot.recording import viewer_command

    rrd = tmp_path / "x.rrd"
    rrd.write_bytes(b"")
    assert "--web-viewer-port" in viewer_command(rrd, web=True, web_port=9090)
    for name, ports in (("web_port", {"web_port": 0}), ("grpc_port", {"grpc_port": 70000})):
        with pytest.raises(fgdwa.FgdwaError, match=name):
            viewer_command(rrd, web=True, **ports)
