"""--set NAME=VALUE on the benchmark commands: checked before any run, and reaching the runs."""

import pytest

import fgdwa
from fgdwa.bench import dynamic
from fgdwa.bench.barn import BarnSetup
from fgdwa.settings import benchmark_settings, describe_settings, group_settings


def test_settings_are_read_as_json_and_grouped_by_parameter_set():
    settings = benchmark_settings(["navigator/tracker/hypothesis_time=0.5", "planner/sim_time=1.5",
                                   "planner/window/n_v=9", "navigator/scan_match/enabled=true"])
    assert group_settings(settings, "navigator") == {"tracker.hypothesis_time": 0.5, "scan_match.enabled": True}
    assert group_settings(settings, "planner") == {"sim_time": 1.5, "window.n_v": 9}
    assert describe_settings(settings).startswith(" --set navigator/tracker/hypothesis_time=0.5")
    assert benchmark_settings([]) == ()


@pytest.mark.parametrize("item,match", [
    ("planner/sim_time", "expected NAME=VALUE"),
    ("limits/v_max=1.0", "start with planner/ or navigator/"),
    ("planner=1", "start with planner/ or navigator/"),
    ("navigator/tracker/hypothesis_tim=0.5", "did you mean 'hypothesis_time'"),
    ("planner/sim_time=-1", r"--set planner/sim_time=-1: planner\.sim_time = -1: must be > 0"),
    ("planner/sim_time=fast", "planner/sim_time"),
])
def test_a_wrong_setting_is_refused_by_its_name(item, match):
    with pytest.raises(fgdwa.FgdwaError, match=match):
        benchmark_settings([item])


def test_barn_runs_take_the_settings_after_their_own():
    setup = BarnSetup(settings=(("navigator/tracker/hypothesis_time", 0.5), ("planner/sim_time", 1.5)))
    assert setup.navigator("scan").tracker.hypothesis_time == 0.5
    assert setup.planner_params("fgdwa", 0.5).sim_time == 1.5
    assert BarnSetup().planner_params("fgdwa", 0.5).sim_time == BarnSetup().sim_time
    with pytest.raises(fgdwa.FgdwaError, match="BarnSetup.settings"):
        BarnSetup(settings=(("navigator/tracker/hypothesis_time", -1.0),))


def test_dynamic_runs_take_the_settings(monkeypatch):
    seen = {}

    def fake_run(scenario, preset, seed, navigator=None, **kwargs):
        seen.update(scenario=scenario, navigator=navigator)
        return None

    monkeypatch.setattr(dynamic, "run_scenario", fake_run)
    setup = dynamic.DynamicSetup(settings=(("navigator/tracker/hypothesis_time", 0.5), ("planner/sim_time", 1.7)))
    dynamic._episode(dynamic.DynamicTask("easy", 0, "fgdwa", setup))
    assert seen["navigator"].tracker.hypothesis_time == 0.5
    assert seen["scenario"].overrides["sim_time"] == 1.7
    assert "--set planner/sim_time=1.7" in dynamic.replay_command("f.yaml", "fgdwa", 0, 0, settings=setup.settings)
    with pytest.raises(fgdwa.FgdwaError, match="DynamicSetup.settings"):
        dynamic.DynamicSetup(settings=(("planner/sim_time", 0.0),))
