"""The dynamic benchmark: DynaBARN-style fields made from (level, seed), their
scenario files, and the ``fgdwa dynamic`` command and its outputs."""

import csv
import json

import numpy as np
import pytest

import fgdwa
from fgdwa import FgdwaError
from fgdwa.bench.dynamic import (
    PLANNER_VARIANTS,
    DynamicSetup,
    DynamicTask,
    check_variants,
    dynamic_tasks,
    parse_seeds,
    run_dynamic_task,
)
from fgdwa.io.dynamic_fields import LEVELS, closed_route, field_yaml, generate_field, write_field
from fgdwa.sim.scenario import run_scenario
from fgdwa.io.scenario_file import load_scenario


def _distance_to_route(route, point):
    route = np.asarray(route, dtype=float)
    a, b = route[:-1], route[1:]
    ab = b - a
    f = np.clip(np.sum((point - a) * ab, axis=1) / np.sum(ab * ab, axis=1), 0.0, 1.0)
    return np.min(np.hypot(*(a + f[:, None] * ab - point).T))


def test_a_field_is_the_same_for_its_seed_and_differs_across_seeds():
    assert generate_field("medium", 7) == generate_field("medium", 7)
    assert field_yaml(generate_field("medium", 7)) == field_yaml(generate_field("medium", 7))
    fields = [generate_field("medium", seed) for seed in range(5)]
    assert len({field_yaml(f) for f in fields}) == 5
    # The level changes the field too, not only its count of discs.
    assert generate_field("easy", 3)["start"] != generate_field("hard", 3)["start"]


@pytest.mark.parametrize("level", list(LEVELS))
def test_fields_follow_their_level_and_keep_start_and_goal_clear(level):
    spec = LEVELS[level]
    for seed in range(6):
        field = generate_field(level, seed)
        start, goal = np.array(field["start"][:2]), np.array(field["goal"])
        assert 8.0 <= np.hypot(*(goal - start)) <= 10.0
        movers = field["moving_obstacles"]
        assert len(movers) == spec.discs
        for mover in movers:
            assert 0.3 <= mover["radius"] <= 0.5
            assert spec.speed[0] <= mover["speed"] <= spec.speed[1]
            assert mover["known"] is False
            route = closed_route(mover["waypoints"], mover["mode"])
            # Nowhere on its route does a disc touch the robot standing at its start or goal.
            for end in (start, goal):
                assert _distance_to_route(route, end) >= mover["radius"] + 0.25 + 0.5 - 1e-9
            # The route crosses the start-goal line: its points lie on both sides of it.
            way = goal - start
            side = np.sign(way[0] * (route[:, 1] - start[1]) - way[1] * (route[:, 0] - start[0]))
            assert side.min() < 0 < side.max()
        assert len(field["unknown_obstacles"]) >= 2


def test_a_generated_file_loads_and_runs(tmp_path):
    field = generate_field("easy", 4)
    path = write_field(field, tmp_path / "field.yaml", command="fgdwa dynamic generate --level easy --seed 4")
    scenario = load_scenario(str(path))
    assert scenario.name == "dynamic_easy_4"
    assert len(scenario.world.movers) == 2 and not scenario.world.discs_known
    assert scenario.world.hidden is not None and scenario.world.hidden.cells.sum() > 0
    assert scenario.lidar.beams == 541 and scenario.lidar.fov == pytest.approx(np.radians(270.0))
    assert scenario.variability.lidar_noise_std == 0.03 and scenario.variability.lidar_dropout == 0.01
    assert scenario.limits.v_max == 1.2 and scenario.footprint.radius == 0.25
    # Round trip: the file holds exactly the document.
    np.testing.assert_array_equal(scenario.world.movers[0].waypoints, field["moving_obstacles"][0]["waypoints"])
    assert tuple(scenario.goal) == tuple(field["goal"])
    result = run_scenario(scenario, "fgdwa", seed=4, max_steps=30)
    assert result.summary.outcome in ("timeout", "collision", "success")
    assert result.summary.steps >= 1


def test_a_benchmark_run_is_the_run_of_its_scenario_file(tmp_path):
    task = DynamicTask("medium", 2, "dwb")
    run = run_dynamic_task(task)
    path = write_field(generate_field("medium", 2), tmp_path / "f.yaml")
    replay = run_scenario(load_scenario(str(path)), "dwb", seed=2)
    np.testing.assert_array_equal(run.poses, replay.motion.poses)
    assert run.row["outcome"] == replay.summary.outcome
    assert run.row["time"] == replay.summary.sim_time
    assert len(run.routes) == 4 and len(run.discs) == 4
    assert set(np.unique(run.cells)) == {0, 1, 2}  # free, on the map, missing from it


def test_a_tiny_benchmark_writes_its_outputs(tmp_path, capsys):
    from fgdwa.cli import main

    out = tmp_path / "dyn"
    assert main(["dynamic", "--level", "easy", "--seeds", "0-1", "--planners", "fgdwa,dwb", "--executor", "serial",
                 "--no-progress", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "level easy" in printed and "fgdwa" in printed and "dwb" in printed and "collision" in printed
    with open(out / "runs.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert [(r["seed"], r["planner"]) for r in rows] == [("0", "fgdwa"), ("0", "dwb"), ("1", "fgdwa"), ("1", "dwb")]
    summary = json.loads((out / "summary.json").read_text())
    assert summary["level"] == "easy" and summary["seeds"] == [0, 1]
    assert summary["setup"] == {"noise_std": 0.03, "dropout": 0.01, "latency": 0, "body": "default", "settings": []}
    for stats in summary["planners"].values():
        assert stats["n"] == 2
        assert stats["success"] + stats["collision"] + stats["timeout"] + stats["failed"] == pytest.approx(1.0)
    assert (out / "failures.png").stat().st_size > 1000
    # Every failed run names a field file that loads, and how to replay it.
    failed = [r for r in rows if r["outcome"] != "success"]
    assert len(summary["failed"]) == len(failed)
    # A run that did not succeed says why in its row; one that did, nothing.
    for row in rows:
        assert (row["reason"] == "") == (row["outcome"] == "success")
        assert row["outcome"] == "success" or row["reason"].startswith(("collision: ", "timeout: ", "the navigator"))
    for entry in summary["failed"]:
        assert load_scenario(entry["file"]).name == f"dynamic_easy_{entry['seed']}"
        assert entry["replay"].startswith(f"fgdwa run {entry['file']} --planner {entry['planner']} "
                                          f"--seed {entry['seed']}")


def test_generate_command_writes_a_field(tmp_path, capsys):
    from fgdwa.cli import main

    path = tmp_path / "field.yaml"
    assert main(["dynamic", "generate", "--level", "hard", "--seed", "7", "--out", str(path)]) == 0
    assert load_scenario(str(path)).name == "dynamic_hard_7"
    assert path.read_text().startswith("# dynamic_hard_7: made by `fgdwa dynamic generate --level hard --seed 7")
    assert main(["dynamic", "generate", "--level", "hard", "--seed", "-1", "--out", str(path)]) == 2
    assert "seed = -1" in capsys.readouterr().err


def test_planner_variants_map_labels_to_presets():
    for label, (preset, overrides) in PLANNER_VARIANTS.items():
        assert preset in fgdwa.preset_names()
        fgdwa.NavigatorParams(**overrides)
    assert check_variants("fgdwa, dwb,fgdwa") == ["fgdwa", "dwb"]


def test_bad_requests_are_named(tmp_path):
    from fgdwa.cli import main

    with pytest.raises(FgdwaError, match="level = 'extreme'"):
        generate_field("extreme", 0)
    with pytest.raises(FgdwaError, match="seed = -3"):
        generate_field("easy", -3)
    with pytest.raises(FgdwaError, match="seed = 1.5"):
        generate_field("easy", 1.5)
    with pytest.raises(FgdwaError, match="dropout"):
        generate_field("easy", 0, dropout=1.0)
    with pytest.raises(FgdwaError, match="seeds '4-2'.*backwards"):
        parse_seeds("4-2")
    with pytest.raises(FgdwaError, match="seeds 'x'"):
        parse_seeds("x")
    assert parse_seeds("0-4:2,7") == [0, 2, 4, 7]
    with pytest.raises(FgdwaError, match="planner 'nope' unknown"):
        dynamic_tasks("easy", [0], ["nope"])
    with pytest.raises(FgdwaError, match="level"):
        dynamic_tasks("extreme", [0], ["fgdwa"])
    with pytest.raises(FgdwaError, match="DynamicSetup.latency"):
        DynamicSetup(latency=-1)
    with pytest.raises(FgdwaError, match="DynamicSetup.noise_std"):
        DynamicSetup(noise_std=float("nan"))
    assert main(["dynamic", "--seeds", "9-1", "--out", str(tmp_path)]) == 2
    assert main(["dynamic", "--executor", "local", "--scheduler", "tcp://localhost:1", "--out", str(tmp_path)]) == 2
    assert main(["dynamic", "--dropout", "1.5", "--seeds", "0", "--out", str(tmp_path)]) == 2


def test_fields_left_by_an_earlier_run_go_unless_they_failed_again(tmp_path):
    from types import SimpleNamespace

    from fgdwa.bench.dynamic import DynamicSetup, write_failed_fields

    fields = tmp_path / "fields"
    fields.mkdir()
    for name in ("dynamic_easy_7.yaml", "dynamic_easy_8.yaml", "dynamic_hard_7.yaml", "my_notes.yaml"):
        (fields / name).write_text("kept?\n")
    runs = [SimpleNamespace(row={"level": "easy", "seed": 8, "planner": "fgdwa", "outcome": "collision",
                                 "reason": "collision: the robot drove into a wall at (1.00, 2.00)"}),
            SimpleNamespace(row={"level": "easy", "seed": 9, "planner": "fgdwa", "outcome": "success", "reason": ""})]
    failed = write_failed_fields(runs, tmp_path, DynamicSetup())
    assert [(entry["seed"], entry["reason"]) for entry in failed] == [(8, runs[0].row["reason"])]
    # easy 7 did not fail this time; another level's file and the user's own stay.
    assert sorted(p.name for p in fields.iterdir()) == ["dynamic_easy_8.yaml", "dynamic_hard_7.yaml", "my_notes.yaml"]
    assert load_scenario(fields / "dynamic_easy_8.yaml").name == "dynamic_easy_8"


def test_failed_runs_can_be_recorded_and_the_recordings_hold_their_runs(tmp_path, capsys):
    from fgdwa.cli import main
    from fgdwa.plot.recording import read_recording

    out, recordings = tmp_path / "dyn", tmp_path / "rrd"
    # Hard field 0 without tracking: the untracked discs run into the robot.
    assert main(["dynamic", "--level", "hard", "--seeds", "0", "--planners", "fgdwa-notrack", "--executor", "serial",
                 "--no-progress", "--no-figures", "--out", str(out), "--record-failures", str(recordings)]) == 0
    printed = capsys.readouterr().out
    row = next(csv.DictReader(open(out / "runs.csv")))
    assert row["outcome"] == "collision"
    path = recordings / "dynamic_hard_0_fgdwa-notrack.rrd"
    assert f"seed 0 planner fgdwa-notrack: {row['reason']} (fgdwa inspect {path})" in printed
    summary = json.loads((out / "summary.json").read_text())
    assert summary["failed"][0]["recording"] == str(path)
    # The recording is that run: as many cycles as the run had steps, up to the collision.
    assert len(read_recording(path, "/world/robot/true")) == int(round(float(row["time"]) / 0.15))
