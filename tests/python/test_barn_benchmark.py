"""The BARN benchmark runner: episodes on BARN worlds with the map known or
built from scans, the per-planner summary, the command and its files.

Reads the shared barn.npz (or FGDWA_BARN_DATA) through conftest's fixtures; skips
without it.
"""

import csv
import json

import numpy as np
import pytest

import fgdwa
from fgdwa import FgdwaError, planner_preset
from fgdwa.bench.barn import BarnSetup, barn_tasks, check_planners, format_summary, run_barn, run_barn_task
from fgdwa.bench.runs import Run, run_timing, summarize

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
        resolution = BarnSetup().map_resolution
        for run in runs:
            # The robot's map, in its own cells, holds true obstacles: an occupied
            # cell's centre lies within half its diagonal of a true obstacle, plus
            # the range noise (3 std) and the odometry's drift over the run.
            assert run.scan_map is not None
            rows, cols = run.scan_map.shape
            x0, x1, y0, y1 = run.scan_extent
            assert (x1 - x0, y1 - y0) == pytest.approx((cols * resolution, rows * resolution))
            truth = fgdwa.DistanceField(fgdwa.OccupancyGrid(run.cells.astype(np.uint8), barn.resolution,
                                                            (run.extent[0], run.extent[2])))
            r, c = np.nonzero(run.scan_map)
            assert len(r) > 0
            centres = np.column_stack([x0 + (c + 0.5) * resolution, y0 + (r + 0.5) * resolution])
            far = float(np.max(truth.distance(centres)))
            assert far <= resolution * np.sqrt(0.5) + 3 * 0.03 + 0.1, far
            assert len(run.paths) >= 1


def test_scan_map_knows_less_than_the_world(barn):
    task = barn_tasks(barn, [0], ["gdwa"], "scan")[0]
    run = run_barn_task(task)
    # Obstacles far from the robot's way stay unknown. (With range noise the map
    # also marks free cells just short of obstacles, so count the true ones.)
    r, c = np.nonzero(run.scan_map)
    x0, _, y0, _ = run.scan_extent
    resolution = task.setup.map_resolution
    world_col = np.floor((x0 + (c + 0.5) * resolution - run.extent[0]) / barn.resolution).astype(int)
    world_row = np.floor((y0 + (r + 0.5) * resolution - run.extent[2]) / barn.resolution).astype(int)
    mapped = np.zeros_like(run.cells, dtype=bool)
    mapped[world_row, world_col] = True
    mapped_truth = mapped & (run.cells != 0)
    assert 0 < mapped_truth.sum() < (run.cells != 0).sum()


def test_summary_rates_and_means_on_hand_made_rows():
    def run(planner, outcome, time, score):
        row = {"planner": planner, "outcome": outcome, "success": int(outcome == "success"), "time": time,
               "score": score, "cycle_ms_mean": 1.0}
        return Run(row=row, cells=np.zeros((1, 1)), extent=(0, 1, 0, 1), poses=np.zeros((1, 3)), paths=[])

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
    assert "collision_jumped" not in a and "jumped" not in table  # rows without the column


def test_the_summary_counts_collisions_with_movers_that_jumped():
    def run(outcome, jumped):
        row = {"planner": "a", "outcome": outcome, "success": int(outcome == "success"), "time": 5.0,
               "cycle_ms_mean": 1.0, "jumped": jumped}
        return Run(row=row, cells=np.zeros((1, 1)), extent=(0, 1, 0, 1), poses=np.zeros((1, 3)), paths=[])

    runs = [run("success", 0.0), run("collision", 0.0), run("collision", 6.5), run("timeout", 0.0)]
    summary = summarize(runs)
    assert summary["a"]["collision"] == 0.5 and summary["a"]["collision_jumped"] == 0.25
    header = format_summary(summary, "known").splitlines()
    assert any("of them jumped" in line for line in header)
    # None jumped: the column stays out of the table, the rate in the summary.
    quiet = summarize([run("collision", 0.0)])
    assert quiet["a"]["collision_jumped"] == 0.0
    assert "jumped" not in format_summary(quiet, "known")


def test_run_timing_splits_the_wall_time_between_navigator_and_simulator():
    timing = run_timing(1.0, [0.1, 0.2, 0.3])
    assert timing["cycle_ms_mean"] == pytest.approx(200.0)
    assert timing["sim_ms_mean"] == pytest.approx(400.0 / 3)  # the 0.4 s left, over three cycles
    assert timing["cycle_ms_p95"] == pytest.approx(290.0)
    assert all(np.isnan(v) for v in run_timing(0.5, []).values())
    # A clock that read the steps as longer than the run leaves no negative share.
    assert run_timing(0.1, [0.2])["sim_ms_mean"] == 0.0


def test_command_writes_runs_summary_and_failures(barn_file, tmp_path, capsys):
    from fgdwa.cli import main

    out = tmp_path / "barn"
    assert main(["barn", "--data", str(barn_file), "--worlds", "0,6", "--planners", "fgdwa,dwb", "--map", "known",
                 "--executor", "serial", "--no-progress", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "fgdwa" in printed and "dwb" in printed and "mean score" in printed and "sim ms" in printed
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
        assert stats["cycle_ms_mean"] > 0 and stats["sim_ms_mean"] > 0
    assert (out / "failures.png").stat().st_size > 1000
    # The lidar is noisy by default, and the command says so.
    assert summary["setup"]["noise_std"] == 0.03 and summary["setup"]["dropout"] == 0.01
    assert summary["setup"]["latency"] == 0


def test_noise_dropout_and_latency_reach_the_runs(barn, barn_file, tmp_path):
    from fgdwa.cli import main

    assert BarnSetup().lidar().noise_std == 0.03 and BarnSetup().lidar().dropout == 0.01
    # The robot drives at its first scan: no watch for movers before it.
    at_once = (("navigator/start_watch_time", 0.0),)
    setup = BarnSetup(noise_std=0.0, dropout=0.0, latency=2, settings=at_once)
    assert setup.lidar().noise_std == 0.0 and setup.lidar().dropout == 0.0
    run = run_barn_task(barn_tasks(barn, [0], ["fgdwa"], "known", setup=setup)[0])
    prompt = run_barn_task(barn_tasks(barn, [0], ["fgdwa"], "known",
                                      setup=BarnSetup(noise_std=0.0, dropout=0.0, settings=at_once))[0])
    # Two cycles pass before the first command reaches the wheels.
    np.testing.assert_array_equal(run.poses[:3], np.repeat(run.poses[:1], 3, axis=0))
    assert not np.array_equal(prompt.poses[1], prompt.poses[0])
    out = tmp_path / "b"
    assert main(["barn", "--data", str(barn_file), "--worlds", "0", "--planners", "dwa", "--noise", "0.05",
                 "--dropout", "0.02", "--latency", "1", "--executor", "serial", "--no-progress", "--no-figures",
                 "--out", str(out)]) == 0
    written = json.loads((out / "summary.json").read_text())["setup"]
    assert (written["noise_std"], written["dropout"], written["latency"]) == (0.05, 0.02, 1)
    for args in (["--noise", "-0.1"], ["--dropout", "1.0"], ["--latency", "-2"]):
        assert main(["barn", "--data", str(barn_file), "--worlds", "0", "--out", str(out), *args]) == 2


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
    for field, value in (("stall_time", 0.0), ("replan_period", float("nan")), ("max_recoveries", 0),
                         ("max_recoveries", 2.5)):
        with pytest.raises(FgdwaError, match=field):
            BarnSetup(**{field: value})
    assert BarnSetup(stall_time=4.5, max_recoveries=3).navigator().stall_time == 4.5
    for field, value in (("map_resolution", 0.0), ("map_resolution", 2.0), ("wheels", "lagging")):
        with pytest.raises(FgdwaError, match=field):
            BarnSetup(**{field: value})
    # Scans are matched to a map given whole, not to one built from them.
    assert BarnSetup().navigator("known").scan_match.enabled
    assert not BarnSetup().navigator("scan").scan_match.enabled
    with pytest.raises(FgdwaError, match="mapping"):
        BarnSetup().navigator("given")
    assert main(["barn", "--data", str(barn_file), "--worlds", "0", "--executor", "local", "--scheduler",
                 "tcp://localhost:1", "--out", str(tmp_path)]) == 2
    assert main(["barn", "--data", str(tmp_path / "missing.npz"), "--out", str(tmp_path)]) == 2


def _wall_world():
    # A 6 x 3 m room (0.1 m cells) with a wall across x = 3 m, open at the top.
    cells = np.zeros((30, 60), dtype=np.uint8)
    cells[:22, 30] = 1
    return fgdwa.OccupancyGrid(cells, 0.1)


def _navigator(grid, mapping="scan", **params):
    navigator = fgdwa.Navigator(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2), planner_preset("gdwa").params, grid,
                                mapping=mapping, navigator=fgdwa.NavigatorParams(**params))
    navigator.set_goal((5.5, 1.0))
    return navigator


def test_navigator_replans_when_the_scan_shows_the_path_blocked():
    truth = _wall_world()
    scanner = fgdwa.LaserScanner(fgdwa.LidarParams(), fgdwa.DistanceField(truth))
    navigator = _navigator(truth, replan_period=0.15)
    state = fgdwa.RobotState((0.5, 1.0, 0.0), (0.0, 0.0))
    first = navigator.step(state, scanner.scan((0.5, 1.0, 0.0), [], 0.0), 0.0)
    # It stands watching what moves at its first scan, on the route it planned already.
    assert first.path_version == 1 and first.mode == fgdwa.NavigatorMode.Waiting
    assert first.trigger == fgdwa.RecoveryTrigger.Start and not first.planned
    # The first scan already shows the wall: the path goes over its top end.
    assert np.max(first.path_points[:, 1]) > 2.2
    assert first.new_cells > 0 and navigator.map.cells.sum() > 0
    # Nothing new: no replan, however often it may.
    assert navigator.step(state, scanner.scan((0.5, 1.0, 0.0), [], 0.0), 0.15).path_version == 1


def test_navigator_records_the_cycle():
    truth = _wall_world()
    scanner = fgdwa.LaserScanner(fgdwa.LidarParams(), fgdwa.DistanceField(truth))
    navigator = _navigator(truth, record_top_k=3, start_watch_time=0.0)
    record = navigator.step(fgdwa.RobotState((0.5, 1.0, 0.0), (0.0, 0.0)), scanner.scan((0.5, 1.0, 0.0), [], 0.0), 0.0)
    assert record.planned and record.chosen >= 0
    assert len(record.best) == 3 and record.best[0].sample == record.chosen
    assert [b.total for b in record.best] == sorted((b.total for b in record.best), reverse=True)
    np.testing.assert_allclose(record.best[0].poses, record.chosen_rollout)
    assert record.chosen_rollout.shape == (planner_preset("gdwa").params.n_steps, 3)
    assert set(record.times) == {"localise", "tracking", "map", "global", "perception", "plan"} and all(v >= 0 for v in record.times.values())
    assert sum(record.reject_counts.values()) == len(navigator.plan_result.samples)
    # Why each rollout scored as it did: per critic, its raw score and its part of the total.
    plan = navigator.plan_result
    assert record.critic_names == plan.critic_names
    for scored in record.best + [record.choice]:
        np.testing.assert_array_equal(scored.raw, plan.raw[scored.sample])
        assert len(scored.terms) == len(record.critic_names)
        assert sum(scored.terms) == scored.total == plan.total[scored.sample]
    assert record.choice.sample == record.chosen


def test_navigator_and_episode_reject_bad_settings():
    grid = _wall_world()
    for options, name in ((dict(replan_period=0.0), "replan_period"), (dict(stall_time=-1.0), "stall_time"),
                          (dict(max_recoveries=-1), "max_recoveries"), (dict(backup_speed=float("nan")), "backup_speed"),
                          (dict(give_up_length=-0.1), "give_up_length"), (dict(record_top_k=-1), "record_top_k")):
        with pytest.raises(FgdwaError, match=name):
            fgdwa.NavigatorParams(**options)
    with pytest.raises(FgdwaError, match="mapping"):
        fgdwa.Navigator(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2), planner_preset("gdwa").params, grid,
                        mapping="lidar")
    navigator = fgdwa.Navigator(fgdwa.RobotLimits(), fgdwa.Footprint.circle(0.2), planner_preset("gdwa").params, grid)
    state = fgdwa.RobotState((0.5, 1.0, 0.0), (0.0, 0.0))
    with pytest.raises(FgdwaError, match="set_goal"):
        navigator.step(state, None, 0.0)
    with pytest.raises(FgdwaError, match="off the map"):
        navigator.set_goal((50.0, 1.0))
    navigator.set_goal((5.5, 1.0))
    scan = fgdwa.LaserScanner(fgdwa.LidarParams(beams=100), fgdwa.DistanceField(grid)).scan((0.5, 1.0, 0.0), [], 0.0)
    with pytest.raises(FgdwaError, match="beams"):
        navigator.step(state, scan, 0.0)
    with pytest.raises(FgdwaError, match="points"):
        fgdwa.ScanMap(grid).mark(np.zeros((3, 3)))
    from fgdwa.sim import run_episode
    from fgdwa.sim.world import World

    with pytest.raises(FgdwaError, match="mapping"):
        run_episode(World(grid=grid), (0.5, 1.0, 0.0), (5.5, 1.0), mapping="lidar")
    with pytest.raises(FgdwaError, match="needs a grid"):
        run_episode(World(), (0.5, 1.0, 0.0), (5.5, 1.0), mapping="scan")


def test_failed_runs_are_named_and_recorded(barn_file, tmp_path, capsys):
    """A lidar that almost never returns leaves the map built from scans empty:
    the robot drives into a wall. The table's line names why, and its recording
    holds the run up to the collision."""
    pytest.importorskip("rerun")
    from fgdwa.cli import main
    from fgdwa.plot.recording import read_recording

    out, recordings = tmp_path / "barn", tmp_path / "rrd"
    assert main(["barn", "--data", str(barn_file), "--worlds", "0", "--planners", "fgdwa", "--map", "scan",
                 "--dropout", "0.99", "--executor", "serial", "--no-progress", "--no-figures", "--out", str(out),
                 "--record-failures", str(recordings)]) == 0
    printed = capsys.readouterr().out
    with open(out / "runs.csv") as handle:
        (row,) = list(csv.DictReader(handle))
    assert row["outcome"] == "collision" and row["reason"].startswith("collision: the robot drove into")
    path = recordings / "barn_0_fgdwa_scan_trial0.rrd"
    assert f"world 0 planner fgdwa trial 0: {row['reason']} (fgdwa inspect {path})" in printed
    (failed,) = json.loads((out / "summary.json").read_text())["failed"]
    assert failed == {"world": 0, "planner": "fgdwa", "trial": 0, "outcome": "collision", "reason": row["reason"],
                      "recording": str(path)}
    assert len(read_recording(path, "/world/robot/true")) == int(round(float(row["time"]) / 0.1))


def test_a_navigator_step_back_in_time_is_refused_whatever_it_tracks():
    truth = _wall_world()
    scanner = fgdwa.LaserScanner(fgdwa.LidarParams(), fgdwa.DistanceField(truth))
    navigator = _navigator(truth, track_moving=False)
    state = fgdwa.RobotState((0.5, 1.0, 0.0), (0.0, 0.0))
    navigator.step(state, scanner.scan((0.5, 1.0, 0.0), [], 0.0), 10.0)
    navigator.step(state, scanner.scan((0.5, 1.0, 0.0), [], 0.0), 10.0)  # the same time again: a repeat
    with pytest.raises(fgdwa.FgdwaError, match=r"time = -1e\+300: must not be before the last step's 10 s"):
        navigator.step(state, scanner.scan((0.5, 1.0, 0.0), [], 0.0), -1e300)
