"""The BARN benchmark runner: episodes on BARN worlds with the map known or
built from scans, the per-planner summary, the command and its files.

Reads the shared barn.npz (or FGDWA_BARN_DATA) through conftest's fixtures; skips
without it.
"""

import csv
import json

import numpy as np
import pytest
from scipy.ndimage import binary_dilation

import fgdwa
from fgdwa import FgdwaError
from fgdwa.barn_benchmark import (
    BarnRun,
    BarnSetup,
    barn_tasks,
    check_planners,
    format_summary,
    run_barn,
    run_barn_task,
    summarize,
)
from fgdwa.mapping import ScanNavigator

# Worlds of the challenge's local test set, from open to tight fields.
FIVE_WORLDS = [0, 60, 120, 210, 288]


@pytest.mark.parametrize("mapping", ["known", "scan"])
def test_fgdwa_reaches_the_goal_of_five_worlds(barn, mapping):
    runs = run_barn(barn, FIVE_WORLDS, ["fgdwa"], mapping, executor="serial", progress=False)
    assert [r.row["world"] for r in runs] == FIVE_WORLDS
    for run in runs:
        row = run.row
        assert row["outcome"] == "success", row
        assert row["min_clearance"] > 0.0
        # Reaching the goal radius at the 1 m/s cap takes at least the straight 9 m.
        assert 9.0 / 1.0 <= row["time"] < 100.0
        assert row["score"] == pytest.approx(barn.world(row["world"]).score(True, row["time"]))
        # The executed path ends within the goal radius.
        assert np.hypot(*(run.poses[-1, :2] - np.array(barn.goal))) <= barn.goal_radius + 1e-9
    if mapping == "scan":
        for run in runs:
            # The robot's map holds true obstacles; with range noise, a hit may
            # fall in a cell beside one, never farther.
            assert run.scan_map is not None
            near = binary_dilation(run.cells != 0, structure=np.ones((3, 3), bool))
            assert not np.any((run.scan_map != 0) & ~near)
            assert run.scan_map.sum() > 0
            assert len(run.paths) >= 1


def test_scan_map_knows_less_than_the_world(barn):
    task = barn_tasks(barn, [0], ["gdwa"], "scan")[0]
    run = run_barn_task(task)
    # Obstacles far from the robot's way stay unknown.
    assert 0 < run.scan_map.sum() < run.cells.sum()


def test_summary_rates_and_means_on_hand_made_rows():
    def run(planner, outcome, time, score):
        row = {"planner": planner, "outcome": outcome, "success": int(outcome == "success"), "time": time,
               "score": score, "cycle_ms_mean": 1.0}
        return BarnRun(row=row, cells=np.zeros((1, 1)), extent=(0, 1, 0, 1), poses=np.zeros((1, 3)), paths=[])

    runs = [run("a", "success", 10.0, 0.5), run("a", "success", 20.0, 0.25), run("a", "collision", 3.0, 0.0),
            run("a", "timeout", 100.0, 0.0), run("b", "timeout", 100.0, 0.0)]
    summary = summarize(runs)
    assert list(summary) == ["a", "b"]
    a = summary["a"]
    assert a["n"] == 4
    assert (a["success"], a["collision"], a["timeout"]) == (0.5, 0.25, 0.25)
    assert a["mean_time"] == 15.0  # successful runs only
    assert a["mean_score"] == pytest.approx(0.1875)  # every run, failures scoring 0
    assert np.isnan(summary["b"]["mean_time"])
    table = format_summary(summary, "known")
    assert "a" in table and "0.500" in table and "-" in table


def test_command_writes_runs_summary_and_failures(barn_file, tmp_path, capsys):
    from fgdwa.cli import main

    out = tmp_path / "barn"
    assert main(["barn", "--data", str(barn_file), "--worlds", "0,6", "--planners", "fgdwa,dwb", "--map", "known",
                 "--executor", "serial", "--no-progress", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "fgdwa" in printed and "dwb" in printed and "mean score" in printed
    with open(out / "runs.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert [(r["world"], r["planner"]) for r in rows] == [("0", "fgdwa"), ("0", "dwb"), ("6", "fgdwa"), ("6", "dwb")]
    assert all(r["mapping"] == "known" for r in rows)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["mapping"] == "known" and summary["worlds"] == [0, 6]
    assert set(summary["planners"]) == {"fgdwa", "dwb"}
    for stats in summary["planners"].values():
        assert stats["n"] == 2
        assert stats["success"] + stats["collision"] + stats["timeout"] == pytest.approx(1.0)
        assert set(stats) >= {"n", "success", "collision", "timeout", "mean_time", "mean_score"}
    assert (out / "failures.png").stat().st_size > 1000


def test_bad_requests_are_named(barn, barn_file, tmp_path):
    from fgdwa.cli import main

    with pytest.raises(FgdwaError, match="planner 'nope' unknown"):
        check_planners("fgdwa,nope")
    with pytest.raises(FgdwaError, match="mapping"):
        barn_tasks(barn, [0], ["fgdwa"], "lidar")
    with pytest.raises(FgdwaError, match="trials"):
        barn_tasks(barn, [0], ["fgdwa"], "known", trials=0)
    with pytest.raises(FgdwaError, match="world 3 is not in this data set"):
        barn.select_ids([3])
    with pytest.raises(FgdwaError, match="v_max"):
        BarnSetup(v_max=-1.0)
    with pytest.raises(FgdwaError, match="v_max"):
        BarnSetup(v_max=3.0).limits()
    assert main(["barn", "--data", str(barn_file), "--worlds", "0", "--executor", "local", "--scheduler",
                 "tcp://localhost:1", "--out", str(tmp_path)]) == 2
    assert main(["barn", "--data", str(tmp_path / "missing.npz"), "--out", str(tmp_path)]) == 2


def _wall_world():
    # A 6 x 3 m room (0.1 m cells) with a wall across x = 3 m, open at the top.
    cells = np.zeros((30, 60), dtype=np.uint8)
    cells[:22, 30] = 1
    return fgdwa.OccupancyGrid(cells, 0.1)


def test_navigator_replans_when_the_scan_shows_the_path_blocked():
    truth = _wall_world()
    scanner = fgdwa.LaserScanner(fgdwa.LidarParams(), fgdwa.DistanceField(truth))
    navigator = ScanNavigator(truth, (5.5, 1.0), [0.3, 0.2], 0.2, replan_interval=1)
    first = navigator.update(scanner.scan((0.5, 1.0, 0.0), [], 0.0), (0.5, 1.0), 0).path
    assert first is not None and len(navigator.paths) == 1
    # The first scan already shows the wall: the path goes over its top end.
    assert np.max(first.points[:, 1]) > 2.2
    assert navigator.map.occupied_count > 0
    # Nothing new: no replan, however often it may.
    assert navigator.update(scanner.scan((0.5, 1.0, 0.0), [], 0.0), (0.5, 1.0), 1).path is None


def test_navigator_starting_blind_replans_once_the_wall_is_seen():
    truth = _wall_world()
    navigator = ScanNavigator(truth, (5.5, 1.0), [0.3], 0.2, replan_interval=3)
    empty_scan = fgdwa.LaserScanner(fgdwa.LidarParams(max_range=0.5), fgdwa.DistanceField(truth)).scan(
        (0.5, 1.0, 0.0), [], 0.0)
    straight = navigator.update(empty_scan, (0.5, 1.0), 0).path
    assert straight is not None and np.allclose(straight.points[:, 1], 1.0)  # unknown space is free
    seeing = fgdwa.LaserScanner(fgdwa.LidarParams(), fgdwa.DistanceField(truth)).scan((2.0, 1.0, 0.0), [], 0.0)
    assert navigator.update(seeing, (2.0, 1.0), 1).path is None  # blocked, but not due before cycle 3
    replanned = navigator.update(seeing, (2.0, 1.0), 3).path
    assert replanned is not None and np.max(replanned.points[:, 1]) > 2.2


def test_stalled_robot_gives_up_the_path_ahead_and_backs_up():
    grid = fgdwa.OccupancyGrid(np.zeros((30, 60), dtype=np.uint8), 0.1)
    navigator = ScanNavigator.with_map(grid, (5.5, 1.5), [0.2], 0.2, stall_cycles=5, backup_cycles=3)
    navigator.path = fgdwa.GlobalPath(np.array([[0.5, 1.5], [5.5, 1.5]]))
    for cycle in range(5):
        update = navigator.update(None, (2.0, 1.5), cycle)
        assert update.path is None and navigator.backing_up == 0
    navigator.update(None, (2.0, 1.5), 5)  # six positions within 0.1 m: stalled
    assert navigator.stalls == 1 and navigator.backing_up == 3
    for _ in range(3):
        navigator.backed_up(done=False)
    replanned = navigator.update(None, (1.7, 1.5), 9).path
    assert replanned is not None
    # The new path leaves the straight line where the robot gave up.
    points = replanned.points
    assert np.max(np.abs(points[:, 1] - 1.5)) > 0.1


def test_navigator_and_episode_reject_bad_settings():
    grid = _wall_world()
    for options, name in ((dict(replan_interval=0), "replan_interval"), (dict(stall_cycles=0), "stall_cycles"),
                          (dict(backup_cycles=-1), "backup_cycles"), (dict(backup_speed=float("nan")), "backup_speed"),
                          (dict(give_up_length=-0.1), "give_up_length")):
        with pytest.raises(FgdwaError, match=name):
            ScanNavigator(grid, (5.5, 1.0), [0.3], 0.2, **options)
    with pytest.raises(FgdwaError, match="inflation_radii"):
        ScanNavigator(grid, (5.5, 1.0), [], 0.2)
    with pytest.raises(FgdwaError, match="blocked_clearance"):
        ScanNavigator(grid, (5.5, 1.0), [0.3], -1.0)
    with pytest.raises(FgdwaError, match="points"):
        fgdwa.ScanMap(grid).mark(np.zeros((3, 3)))
    from fgdwa.sim import run_episode
    from fgdwa.world import World

    with pytest.raises(FgdwaError, match="mapping"):
        run_episode(World(grid=grid), (0.5, 1.0, 0.0), (5.5, 1.0), mapping="lidar")
    with pytest.raises(FgdwaError, match="needs a grid"):
        run_episode(World(), (0.5, 1.0, 0.0), (5.5, 1.0), mapping="scan")
