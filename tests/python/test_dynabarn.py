"""fgdwa dynabarn: the data file, the arena, the scores and the command."""

import csv
import json
import math
import os
from pathlib import Path

import numpy as np
import pytest

from fgdwa import FgdwaError
from fgdwa.bench.dynabarn import arena_grid, dynabarn_tasks, run_py_score, start_clock
from fgdwa.cli import main
from fgdwa.io.dynabarn_data import load_dynabarn
from fgdwa.sim.keyframes import KeyframedMover

DEV = Path(os.environ.get("FGDWA_DYNABARN_DATA", "/work/shared/benchmarks/dynabarn/dynabarn_dev.json"))


def small_world(world=0, difficulty="easy", **changes):
    """A 6 m arena walled on three sides, open at x = +3 where the robot starts, one cylinder crossing."""
    data = {
        "world": world, "barn_world_idx": 300 + world, "difficulty": difficulty,
        "start": [3.5, 0.0, 3.14], "goal": [-2.0, 0.0], "time_limit": 30.0, "success_radius": 1.0,
        "walls": [{"name": "back", "rect": [-3.25, -3.0, -2.75, 3.0]},
                  {"name": "top", "rect": [-3.0, 2.75, 3.0, 3.25]},
                  {"name": "bottom", "rect": [-3.0, -3.25, 3.0, -2.75]}],
        "movers": [{"model": "m0", "radius": 0.3, "loop": True, "length_s": 8.0,
                    "keyframes": [[0.0, 0.0, -2.5], [4.0, 0.0, 2.5], [8.0, 0.0, -2.5]]}],
    }
    data.update(changes)
    return data


def write_data(path, worlds):
    path.write_text(json.dumps({"about": "test worlds", "worlds": worlds}))
    return path


def test_the_dev_file_loads_with_every_world_and_mover():
    if not DEV.is_file():
        pytest.skip("the shared DynaBARN file is not on this machine")
    data = load_dynabarn(DEV)
    assert len(data) == 20 and data.world_ids[:3] == [0, 3, 6]
    world = data.world(0)
    assert world.start == (11.0, 0.0, 3.14) and world.goal == (-9.0, 0.0)
    assert all(isinstance(m, KeyframedMover) and m.radius == 0.5 for m in world.movers)
    assert {data.world(w).difficulty for w in data.world_ids} == {"easy", "medium", "hard"}


@pytest.mark.parametrize("change, named", [
    ({"start": [1.0, 2.0]}, r"world 0.*start"),
    ({"time_limit": -1}, r"time_limit"),
    ({"walls": [{"rect": [1, 1, 0, 2]}]}, r"walls\[0\]\.rect"),
    ({"movers": [{"radius": 0.3, "keyframes": [[0, 0, 0], [0, 1, 1]]}]}, r"movers\[0\].*keyframes\[1\]"),
    ({"movers": [{"radius": -1, "keyframes": [[0, 0, 0], [1, 1, 1]]}]}, r"movers\[0\]\.radius"),
    ({"movers": [{"radius": 0.3, "keyframes": [[0, 0], [1, 1, 1]]}]}, r"movers\[0\]\.keyframes\[0\]"),
    ({"difficulty": "insane"}, r"difficulty"),
])
def test_a_bad_world_is_refused_naming_the_key(tmp_path, change, named):
    path = write_data(tmp_path / "bad.json", [small_world(**change)])
    with pytest.raises(FgdwaError, match=named):
        load_dynabarn(path)


def test_a_file_that_is_not_a_data_file_is_refused(tmp_path):
    (tmp_path / "a.json").write_text("{not json")
    with pytest.raises(FgdwaError, match="not JSON"):
        load_dynabarn(tmp_path / "a.json")
    (tmp_path / "b.json").write_text('{"worlds": []}')
    with pytest.raises(FgdwaError, match="one world or more"):
        load_dynabarn(tmp_path / "b.json")
    (tmp_path / "c.json").write_bytes(b"\xff\xfe")
    with pytest.raises(FgdwaError, match="UTF-8"):
        load_dynabarn(tmp_path / "c.json")


def test_run_py_scores_every_success_an_eighth_here_and_the_time_score_rewards_speed():
    # run.py's reference length goal_x - start_x = -20 m: OT = -10 s, clip(T, -20, -80) = -80.
    assert run_py_score(True, 25.0, -20.0) == pytest.approx(0.125)
    assert run_py_score(True, 90.0, -20.0) == pytest.approx(0.125)
    assert run_py_score(False, 25.0, -20.0) == 0.0
    # With the straight 20 m, OT = 10 s: 0.5 at or under 20 s, 10 / T up to 80 s.
    assert run_py_score(True, 15.0, 20.0) == pytest.approx(0.5)
    assert run_py_score(True, 40.0, 20.0) == pytest.approx(0.25)
    with pytest.raises(FgdwaError, match="time = nan"):
        run_py_score(True, float("nan"), 20.0)
    with pytest.raises(FgdwaError, match="path_length = inf"):
        run_py_score(False, 10.0, float("inf"))
    assert math.isnan(run_py_score(True, 10.0, 0.0))


def test_the_arena_grid_holds_the_walls_and_room_around_everything(tmp_path):
    world = load_dynabarn(write_data(tmp_path / "w.json", [small_world()])).world(0)
    grid = arena_grid(world, resolution=0.25, margin=2.0)
    x0, x1, y0, y1 = grid.extent
    assert x0 <= -3.25 - 2.0 and x1 >= 3.5 + 2.0 and y0 <= -3.25 - 2.0 and y1 >= 3.25 + 2.0
    assert grid.occupied_at(np.array([[-3.0, 0.0], [0.0, 3.0], [0.0, -3.0]])).all()
    assert not grid.occupied_at(np.array([[0.0, 0.0], [3.5, 0.0], [2.9, 2.0]])).any()


def test_the_start_clock_comes_from_the_seed():
    world = load_dynabarn(DEV).world(0) if DEV.is_file() else None
    if world is None:
        pytest.skip("the shared DynaBARN file is not on this machine")
    clocks = [start_clock(world, seed) for seed in range(20)]
    assert clocks == [start_clock(world, seed) for seed in range(20)]
    longest = max(m.period for m in world.movers)
    assert all(0 <= c < longest for c in clocks) and len(set(clocks)) == 20
    with pytest.raises(FgdwaError, match="seed = -1"):
        start_clock(world, -1)


def test_a_missing_data_file_says_how_to_give_one(tmp_path, monkeypatch):
    from fgdwa.io.dynabarn_data import find_dynabarn_file

    with pytest.raises(FgdwaError, match=r"DynaBARN data .*nope\.json \(argument\): no such file"):
        find_dynabarn_file(tmp_path / "nope.json")
    monkeypatch.delenv("FGDWA_DYNABARN_DATA", raising=False)
    with pytest.raises(FgdwaError, match="no DynaBARN data given: pass --data FILE"):
        find_dynabarn_file(None)


def test_tasks_check_their_arguments(tmp_path):
    data = load_dynabarn(write_data(tmp_path / "w.json", [small_world()]))
    with pytest.raises(FgdwaError, match="trials"):
        dynabarn_tasks(data, [0], ["fgdwa"], "scan", trials=0)
    with pytest.raises(FgdwaError, match="seed"):
        dynabarn_tasks(data, [0], ["fgdwa"], "scan", base_seed=-1)
    with pytest.raises(FgdwaError, match="nope"):
        dynabarn_tasks(data, [0], ["nope"], "scan")
    with pytest.raises(FgdwaError, match="DynaBARN world 5"):
        data.world(5)


def test_the_command_runs_scores_and_writes_its_outputs(tmp_path, capsys):
    data = write_data(tmp_path / "w.json", [small_world(0, "easy"), small_world(1, "hard")])
    out = tmp_path / "out"
    assert main(["dynabarn", "--data", str(data), "--planners", "fgdwa", "--out", str(out), "--no-progress",
                 "--executor", "serial", "--no-figures"]) == 0
    text = capsys.readouterr().out
    assert "DynaBARN, map scan, 2 worlds" in text and "time score" in text and "easy: 1 worlds" in text
    with open(out / "runs.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert [int(r["world"]) for r in rows] == [0, 1]
    for r in rows:
        success = r["outcome"] == "success"
        # The reference length goal_x - start_x is negative: a success scores 0.125, whatever its time.
        assert float(r["score"]) == pytest.approx(0.125 if success else 0.0)
        assert (float(r["time_score"]) > 0) == success and float(r["time_score"]) <= 0.5
        assert 0.0 <= float(r["clock"]) < 8.0
        assert success or r["reason"]
    summary = json.loads((out / "summary.json").read_text())
    assert set(summary["planners"]["fgdwa"]) >= {"mean_score", "mean_time_score", "success"}
    assert not math.isnan(summary["planners"]["fgdwa"]["mean_time_score"])
