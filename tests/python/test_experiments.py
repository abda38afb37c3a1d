"""Experiments E1-E3 (docs/algorithms.md): statistics, tables and reports, executors, the CLI and the GIF."""

import csv
import json
import math

import numpy as np
import pytest
from scipy import stats as sps

from fgdwa import FgdwaError
from fgdwa.bench import stats
from fgdwa.bench.claims import Claim, correct_claims, verdict
from fgdwa.bench.experiments import (
    EXPERIMENTS,
    FINISHING,
    ExperimentResult,
    ExperimentSpec,
    TrialRecord,
    comparable_runs,
    judge_claims,
    run_experiment,
    run_trial,
    trial_tasks,
)
from fgdwa.bench.report import (
    EXCLUSION_NOTE,
    per_trial_table,
    read_json,
    save_experiment,
    terminal_report,
    write_csvs,
    write_json,
    write_markdown,
)
from fgdwa.bench.runner import run_tasks
from fgdwa.cli import main
from fgdwa.io import builtin

A = [89.0, 88.6, 90.2, 81.9, 87.6, 88.6, 93.5]
B = [113.4, 113.6, 115.8, 113.5, 113.2, 112.4, 111.0, 114.1]


# --------------------------------------------------------------------------------------------- statistics

def test_welch_and_mann_whitney_match_scipy():
    p, note = stats.welch_p(A, B)
    assert p == pytest.approx(sps.ttest_ind(A, B, equal_var=False).pvalue, rel=1e-12)
    assert note == ""
    p, note = stats.mwu_p(A, B)
    assert p == pytest.approx(sps.mannwhitneyu(A, B, alternative="two-sided").pvalue, rel=1e-12)
    assert note == ""
    assert stats.fisher_p(15, 15, 12, 15) == pytest.approx(sps.fisher_exact([[15, 0], [12, 3]]).pvalue)


def test_effect_percent_follows_the_papers_tables():
    assert stats.effect_percent(89.58, 121.36) == pytest.approx(-26.19, abs=0.01)  # Table 9
    assert stats.effect_percent(0.48, 0.32) == pytest.approx(50.0)  # Table 12
    assert stats.effect_percent(100.0, 80.0) == pytest.approx(25.0)  # Table 18
    assert stats.effect_percent(1.0, -2.0) == pytest.approx(150.0)  # relative to |other|
    assert stats.effect_percent(0.0, 0.0) == 0.0
    assert math.isnan(stats.effect_percent(1.0, 0.0))
    assert math.isnan(stats.effect_percent(float("nan"), 1.0))


def test_describe_drops_missing_values():
    s = stats.describe([1.0, float("nan"), 3.0, None])
    assert (s.n, s.mean, s.median, s.min, s.max) == (2, 2.0, 2.0, 1.0, 3.0)
    assert s.std == pytest.approx(np.std([1.0, 3.0], ddof=1))
    one = stats.describe([5.0])
    assert one.n == 1 and one.mean == 5.0 and math.isnan(one.std)
    assert stats.describe([]).n == 0 and math.isnan(stats.describe([]).mean)


def test_degenerate_samples_give_defined_p_values():
    assert stats.welch_p([2.0, 2.0, 2.0], [2.0, 2.0]) == (1.0, "all values equal")
    assert stats.mwu_p([2.0, 2.0, 2.0], [2.0, 2.0]) == (1.0, "all values equal")
    p, note = stats.welch_p([1.0, 1.0, 1.0], [2.0, 2.0, 2.0])
    assert p == 0.0 and "constant" in note
    assert stats.mwu_p([1.0, 1.0, 1.0], [2.0, 2.0, 2.0])[0] == pytest.approx(
        sps.mannwhitneyu([1, 1, 1], [2, 2, 2], alternative="two-sided").pvalue)
    p, note = stats.welch_p([1.0], [2.0, 3.0])
    assert math.isnan(p) and "n < 2" in note
    assert stats.mwu_p([1.0], [2.0, 3.0])[0] == pytest.approx(
        sps.mannwhitneyu([1.0], [2.0, 3.0], alternative="two-sided").pvalue)
    p, note = stats.mwu_p([], [1.0])
    assert math.isnan(p) and "no value" in note
    assert math.isnan(stats.fisher_p(0, 0, 1, 2))
    c = stats.compare("steps", "a", [float("nan")] * 3, "b", [1.0, 2.0])
    assert c.proposed_summary.n == 0 and math.isnan(c.welch_p) and math.isnan(c.mwu_p) and c.note


def test_verdicts_come_from_the_numbers():
    down = Claim("steps", "gdwa", -2.5, "paper")
    assert verdict(down, -4.0, 0.01) == ("same direction, significant (-4.0 %, p = 0.01)", True)
    assert verdict(down, -4.0, 0.2)[0].startswith("same direction, not significant")
    assert verdict(down, 3.0, 0.01) == ("opposite direction, significant (+3.0 %, p = 0.01)", False)
    assert verdict(down, float("nan"), float("nan"))[1] is None
    assert verdict(down, 0.0, 1.0)[1] is False
    none = Claim("mileage", "x", 0.1, "paper", kind="no_difference")
    assert verdict(none, 0.05, 0.6)[1] is True
    assert verdict(none, 3.0, 0.001)[1] is False
    # Two runs on a side say nothing, whatever the p-value.
    words, agrees = verdict(down, -4.0, 1e-6, n=[2, 15])
    assert agrees is None and words.startswith("too few runs to say (n = 2, 15")


def test_holm_corrects_the_claims_judged_together():
    assert stats.holm([0.01, 0.04, 0.03, float("nan")]) == pytest.approx([0.03, 0.06, 0.06, float("nan")],
                                                                          nan_ok=True)
    assert stats.holm([0.5, 0.9]) == [1.0, 1.0]
    assert stats.holm([]) == []
    rows = [dict(metric="steps", other="gdwa", paper_effect=-2.0, paper="p", kind="direction", effect_pct=-3.0,
                 p=p, n=[15, 15]) for p in (0.02, 0.02, 0.001)]
    judged = correct_claims(rows)
    assert [r["p_holm"] for r in judged] == pytest.approx([0.04, 0.04, 0.003])
    assert all(r["family"] == 3 and r["agrees"] is True for r in judged)
    assert "significant (-3.0 %, p = 0.04)" in judged[0]["verdict"]
    # Thirteen at once: a raw 0.02 is no longer significant.
    judged = correct_claims(rows[:1] + [dict(rows[0], p=0.5)] * 12)
    assert judged[0]["p_holm"] == pytest.approx(0.26) and "not significant" in judged[0]["verdict"]


# --------------------------------------------------------------------------------------------- tables and files

def _record(planner, trial, outcome="success", steps=100, time=0.1, mileage=10.0, danger=0.5):
    metrics = {"outcome": outcome, "steps": steps, "sim_time": 0.15 * steps, "planning_time": time,
               "mileage": mileage, "min_clearance": 0.2, "mean_clearance": 0.8, "danger_clearance": danger,
               "mean_deviation": 0.1, "max_deviation": 0.3, "smoothness": 1.0}
    n = steps
    return TrialRecord("t", planner, trial, 7 + trial, metrics, wall_time=0.2, poses=np.zeros((n + 1, 3)),
                       cycle_times=np.full(n, time / n), beta=np.full(n, 0.3), delta=np.full(n, 1.0),
                       density=np.zeros(n), deviation=np.zeros(n), dt=0.15)


def _hand_made_result():
    spec = ExperimentSpec("t", "T: hand-made", "demo", ("fgdwa", "gdwa"),
                          claims=(Claim("steps", "gdwa", -10.0, "fewer steps"),
                                  Claim(FINISHING, "gdwa", 25.0, "100 % vs 80 %")))
    records = [_record("fgdwa", i, steps=s, time=t, mileage=m)
               for i, (s, t, m) in enumerate([(100, 0.10, 10.0), (102, 0.11, 10.2), (98, 0.09, 9.9)])]
    records += [_record("gdwa", 0, steps=120, time=0.12, mileage=11.0),
                _record("gdwa", 1, outcome="collision", steps=40, time=0.05, mileage=3.0),
                _record("gdwa", 2, steps=124, time=0.13, mileage=11.4)]
    return ExperimentResult(spec, 3, 7, records, wall_time=1.0, executor="serial")


def test_failed_runs_count_in_the_finishing_rate_only():
    result = _hand_made_result()
    assert result.values("gdwa", "steps")[1] != result.values("gdwa", "steps")[1]  # nan
    assert result.finishing("gdwa") == (2, 3)
    d = result.to_dict()
    assert d["summary"]["gdwa"]["steps"]["n"] == 2
    assert d["summary"]["gdwa"]["steps"]["mean"] == pytest.approx(122.0)
    steps = next(c for c in d["comparisons"] if c["metric"] == "steps")
    assert steps["welch_p"] == pytest.approx(sps.ttest_ind([100, 102, 98], [120, 124], equal_var=False).pvalue)
    assert steps["effect_pct"] == pytest.approx((100.0 - 122.0) / 122.0 * 100)
    finishing = d["finishing_comparisons"][0]
    assert (finishing["rate_proposed"], finishing["rate_other"]) == (100.0, pytest.approx(200 / 3))
    assert finishing["fisher_p"] == pytest.approx(sps.fisher_exact([[3, 0], [2, 1]]).pvalue)
    claims = {c["metric"]: c for c in d["claims"]}
    # Three runs against two: the same direction as the paper, but too few runs to judge.
    assert claims["steps"]["agrees"] is None
    assert claims["steps"]["verdict"].startswith("too few runs to say (n = 3, 2; -18.0 %")
    assert claims[FINISHING]["agrees"] is None and claims[FINISHING]["verdict"].startswith("too few runs to say (n = 3, 3")
    assert d["seeds"] == [7, 8, 9]
    assert d["cycle_time_ms"]["all"]["cycles"] == 100 + 102 + 98 + 120 + 40 + 124


def test_tables_csv_json_and_markdown(tmp_path):
    d = _hand_made_result().to_dict()
    table = per_trial_table(d, "steps")
    text = table.text()
    assert "collision" in text and "Welch p" in text and "Mann-Whitney p" in text
    assert table.rows[0][1:] == ["100", "120"]
    text = terminal_report(d)
    for words in ("finishing rate", "Iteration steps", "Mileage", "Danger-point clearance", "claims", "p95"):
        assert words in text

    paths = write_csvs(d, tmp_path)
    with open(paths[0]) as f:
        runs = list(csv.DictReader(f))
    assert len(runs) == 6 and runs[4]["outcome"] == "collision" and runs[4]["steps"] == "40"
    with open(paths[2]) as f:
        comparisons = list(csv.DictReader(f))
    assert {r["metric"] for r in comparisons} >= {"steps", "planning_time", "mileage", FINISHING}

    d["comparisons"][0]["note"] = "x"
    d["comparisons"][0]["mwu_p"] = float("nan")
    path = write_json(d, tmp_path / "t.json")
    raw = json.loads(path.read_text())  # strict JSON: nan written as null
    assert raw["comparisons"][0]["mwu_p"] is None
    back = read_json(path)
    assert math.isnan(back["comparisons"][0]["mwu_p"])
    assert per_trial_table(back, "mileage").text() == per_trial_table(d, "mileage").text()

    md = write_markdown(d, tmp_path / "sub" / "report.md", {"a figure": tmp_path / "fig.png"}).read_text()
    assert EXCLUSION_NOTE in md and "| Iteration steps |" in md and "![a figure](../fig.png)" in md


# --------------------------------------------------------------------------------------------- running

SMALL = ExperimentSpec("small", "small", builtin.unknown_beside_path_scenario, ("fgdwa", "gdwa"))


def test_trials_share_seeds_across_planners():
    tasks = trial_tasks(SMALL, 3, base_seed=10, options={"max_steps": 5})
    assert [(t.planner, t.seed) for t in tasks] == [("fgdwa", 10), ("gdwa", 10), ("fgdwa", 11), ("gdwa", 11),
                                                     ("fgdwa", 12), ("gdwa", 12)]
    assert all(dict(t.options) == {"max_steps": 5} for t in tasks)
    with pytest.raises(FgdwaError, match="trials"):
        trial_tasks(SMALL, 0)


def test_bad_executor_arguments():
    with pytest.raises(FgdwaError, match="executor"):
        run_tasks([], run_trial, executor="threads")
    with pytest.raises(FgdwaError, match="scheduler"):
        run_tasks([], run_trial, executor="local", scheduler="tcp://x:1")
    scenario_object = ExperimentSpec("o", "o", builtin.demo_scenario(), ("gdwa",))
    with pytest.raises(FgdwaError, match="cannot be sent"):
        run_experiment(scenario_object, trials=1, executor="local", progress=False)


def test_a_scheduler_that_does_not_answer_is_named(monkeypatch):
    import socket

    from fgdwa.bench import runner

    monkeypatch.setattr(runner, "SCHEDULER_TIMEOUT", 1.0)
    with socket.socket() as s:  # a port nothing listens on
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    for address in (f"tcp://127.0.0.1:{port}", "not an address"):
        with pytest.raises(FgdwaError, match="no dask scheduler answered within 1 s"):
            run_tasks([1], abs, executor="dask", scheduler=address, progress=False)


def test_results_do_not_depend_on_the_executor():
    options = {"max_steps": 60}
    serial = run_experiment(SMALL, trials=2, base_seed=3, executor="serial", progress=False, options=options)
    local = run_experiment(SMALL, trials=2, base_seed=3, executor="local", progress=False, options=options)
    dask = run_experiment(SMALL, trials=2, base_seed=3, executor="dask", progress=False, options=options)
    expected = comparable_runs(serial)
    assert [r[:3] for r in expected] == [("fgdwa", 0, 3), ("fgdwa", 1, 4), ("gdwa", 0, 3), ("gdwa", 1, 4)]
    assert comparable_runs(local) == expected
    assert comparable_runs(dask) == expected
    for other in (local, dask):
        for a, b in zip(serial.records, other.records):
            np.testing.assert_array_equal(a.poses, b.poses)
            np.testing.assert_array_equal(a.beta, b.beta)


def test_judge_claims_without_runs():
    rows = judge_claims([Claim("steps", "gdwa", -1.0, "p")], [], [])
    assert rows[0]["agrees"] is None and "not measurable" in rows[0]["verdict"]


def test_the_three_experiments_end_to_end(tmp_path, capsys):
    out = tmp_path / "results"
    results_md = tmp_path / "docs" / "RESULTS.md"
    code = main(["experiment", "all", "--trials", "3", "--seed", "0", "--out", str(out), "--results-md",
                 str(results_md), "--no-progress"])
    assert code == 0
    printed = capsys.readouterr().out
    assert "wall time:" in printed and "per-cycle planning time median" in printed and "p95" in printed
    for name, spec in EXPERIMENTS.items():
        folder = out / name
        for f in (f"{name}.json", f"{name}_runs.csv", f"{name}_summary.csv", f"{name}_comparisons.csv",
                  "report.md", f"{name}_paths.png", f"{name}_boxplots.png"):
            assert (folder / f).stat().st_size > 0, f
        d = read_json(folder / f"{name}.json")
        assert d["planners"] == list(spec.planners) and d["trials"] == 3 and d["seeds"] == [0, 1, 2]
        assert len(d["runs"]) == 3 * len(spec.planners)
        assert len(d["claims"]) == len(spec.claims)
        assert all(c["verdict"] for c in d["claims"])
        assert (folder / f"{name}_weights.png").exists() == ("fgdwa" in spec.planners)
        assert spec.title in printed
    assert (out / "control_surfaces.png").stat().st_size > 0
    page = results_md.read_text()
    assert "## The paper's claims" in page and "../results/e2/e2_paths.png" in page
    # The per-trial tables stay in each experiment's report.md, which the page links.
    assert "Per-trial tables: [../results/e1/report.md](../results/e1/report.md)." in page
    assert "**E1: Iteration steps of 3 trials**" not in page
    assert "**E1: Iteration steps of 3 trials**" in (out / "e1" / "report.md").read_text()
    assert page.count("| E2 |") == len(EXPERIMENTS["e2"].claims)
    assert (out / "report.md").exists()


def test_results_page_counts_claims_read_back_from_json(tmp_path):
    from fgdwa.bench.report import write_results

    mileages = ([10.0, 10.2, 9.9, 10.1, 10.0, 10.3], [11.0, 11.4, 10.9, 11.2, 11.1, 11.3])
    records = [_record(planner, i, steps=steps + i, mileage=m)
               for planner, steps, ms in (("fgdwa", 100, mileages[0]), ("gdwa", 120, mileages[1]))
               for i, m in enumerate(ms)]
    spec = ExperimentSpec("t", "T", "demo", ("fgdwa", "gdwa"),
                          claims=(Claim("steps", "gdwa", -10.0, "fewer"),
                                  Claim("steps", "nobody", -10.0, "not run here"),
                                  Claim("mileage", "gdwa", 0.1, "same", kind="no_difference")))
    save_experiment(ExperimentResult(spec, 6, 0, records, wall_time=1.0, executor="serial"), tmp_path)
    d = read_json(tmp_path / "t" / "t.json")
    mileage_p = sps.ttest_ind(*mileages, equal_var=False).pvalue
    steps_p = sps.ttest_ind([100 + i for i in range(6)], [120 + i for i in range(6)], equal_var=False).pvalue
    # Holm over the two finite p-values (the claim against "nobody" has none): the larger is kept as it is.
    mileage_holm = max(2 * steps_p, mileage_p)
    assert d["claims"][2]["p_holm"] == pytest.approx(mileage_holm) and d["claims"][0]["p_holm"] == pytest.approx(
        2 * steps_p)
    assert [c["agrees"] for c in d["claims"]] == [True, None, bool(mileage_holm >= 0.05)]
    page = write_results(tmp_path, ["t"], "fgdwa experiment t", tmp_path / "R.md").read_text()
    assert "Of the paper's 2 directional claims, 1 could be measured here; 1 show the same direction" in page
    assert f"1 claim(s) of no difference, 1 could be measured and {int(mileage_holm >= 0.05)} hold" in page
    # Sections below the keep marker (the BARN results) survive a rewrite; the rest is regenerated.
    from fgdwa.bench.report import KEEP_MARKER

    (tmp_path / "R.md").write_text(page.replace("## The paper's claims", "## stale") + "\n" + KEEP_MARKER
                                   + "\n\n## BARN\n\nkept\n")
    again = write_results(tmp_path, ["t"], "fgdwa experiment t", tmp_path / "R.md").read_text()
    assert "## stale" not in again and "## The paper's claims" in again
    assert again.endswith(KEEP_MARKER + "\n\n## BARN\n\nkept\n") and again.count(KEEP_MARKER) == 1


def test_results_page_keeps_a_hand_written_head(tmp_path):
    from fgdwa.bench.report import HEAD_MARKER, KEEP_MARKER, write_results

    save_experiment(_hand_made_result(), tmp_path)
    head = "# Results\n\nContents and a summary.\n\n" + HEAD_MARKER
    (tmp_path / "R.md").write_text(head + "\n\n## stale\n\n" + KEEP_MARKER + "\n\n## BARN\n\nkept\n")
    page = write_results(tmp_path, ["t"], "fgdwa experiment t", tmp_path / "R.md").read_text()
    assert page.startswith(head + "\n\n## The paper's experiments E1-E3, rerun\n")
    assert "## stale" not in page and "## The paper's claims" in page and page.count("\n# ") == 0
    assert page.endswith(KEEP_MARKER + "\n\n## BARN\n\nkept\n") and page.count(HEAD_MARKER) == 1


def test_a_single_experiment_updates_the_results_page_from_saved_runs(tmp_path):
    out = tmp_path / "r"
    save_experiment(_hand_made_result(), out)
    assert main(["experiment", "e1", "--trials", "2", "--out", str(out), "--results-md", str(tmp_path / "R.md"),
                 "--no-figures", "--no-progress", "--executor", "serial", "--max-steps", "30"]) == 0
    page = (tmp_path / "R.md").read_text()
    assert "E1" in page and (out / "e1" / "e1.json").exists()


def test_failed_trials_are_named_in_the_runs_table_and_recorded(tmp_path, capsys):
    """30 cycles are too few to reach E1's goal: every trial times out, says how far it was, and is recorded."""
    pytest.importorskip("rerun")
    from fgdwa.plot.recording import read_recording

    out, recordings = tmp_path / "r", tmp_path / "rrd"
    assert main(["experiment", "e1", "--trials", "1", "--out", str(out), "--no-figures", "--no-progress",
                 "--executor", "serial", "--max-steps", "30", "--record-failures", str(recordings)]) == 0
    printed = capsys.readouterr().out
    with open(out / "e1" / "e1_runs.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert rows and all(r["outcome"] == "timeout" and r["reason"].startswith("timeout: ") for r in rows)
    for row in rows:
        path = recordings / f"e1_{row['planner']}_trial0.rrd"
        assert f"planner {row['planner']} trial 0: {row['reason']} (fgdwa inspect {path})" in printed
        assert len(read_recording(path, "/world/robot/true")) == 30


def test_run_writes_png_and_a_readable_gif(tmp_path, capsys):
    from PIL import Image

    gif = tmp_path / "demo.gif"
    code = main(["run", "demo", "--planner", "fgdwa", "--seed", "1", "--out", str(tmp_path), "--gif", str(gif),
                 "--frames", "12"])
    printed = capsys.readouterr().out
    assert code == 0, printed
    assert "outcome          success" in printed and "cycle time" in printed
    assert (tmp_path / "demo_fgdwa.png").stat().st_size > 0
    with Image.open(gif) as image:
        assert image.format == "GIF"
        assert image.n_frames == 12
        image.seek(image.n_frames - 1)
        assert image.size[0] > 100
    import matplotlib.image

    assert matplotlib.image.imread(tmp_path / "demo_fgdwa.png").ndim == 3


def test_cli_rejects_bad_arguments(capsys):
    with pytest.raises(SystemExit):
        main(["experiment", "e1", "--scheduler", "tcp://127.0.0.1:1"])
    with pytest.raises(SystemExit):
        main(["experiment", "e9"])
    with pytest.raises(SystemExit):
        main(["experiment", "e1", "--trials", "0"])
    assert main(["run", "no_such_scenario_xyz"]) == 2
    assert "no_such_scenario_xyz" in capsys.readouterr().err
