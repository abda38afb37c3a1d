"""Tables and reports of experiments: terminal text, CSV, JSON and Markdown.

Everything here reads the plain dictionary of ``ExperimentResult.to_dict()``
(or the same read back from its JSON file), so a report can be rebuilt from
the files of an earlier run.
"""

from __future__ import annotations

import csv
import json
import math
import os
from pathlib import Path
from typing import Optional, Sequence

from fgdwa.bench.claims import correct_claims
from fgdwa.bench.stats import SIGNIFICANCE, finishing_rate
from fgdwa.io.table import Table


EXCLUSION_NOTE = ("Runs that did not reach the goal (collision, fall or timeout) count in the finishing rate "
                  "only: their running time, steps, mileage and clearances are left out of the means, the "
                  "tests and the box plots, as the paper leaves out GDWA's unfinished runs (Tables 15-18). "
                  "In the per-trial tables such a run shows its outcome instead of a number.")
TEST_NOTE = ("Effect (%) = (proposed - other) / |other| x 100, so a negative effect means the proposed planner's "
             "value is lower. p-values are two-sided: Welch's t-test and the Mann-Whitney U test (scipy.stats) for "
             "the metrics, Fisher's exact test for the finishing rate. A claim's verdict takes the p-value after Holm's "
             "correction for all the claims judged together (one experiment's in its report, all of them in the "
             "table of the paper's claims), shown beside the raw one; with fewer than 5 runs on a side it says "
             "there are too few runs to judge. Running time is the wall-clock time spent "
             "planning (the sum of the control cycles), so it depends on the machine and its load.")

DIGITS = {"planning_time": 3, "steps": 0, "mileage": 2, "danger_clearance": 3, "sim_time": 2,
          "min_clearance": 3, "mean_deviation": 3, "smoothness": 2}


def fmt(value, digits: int = 3) -> str:
    """A number for a table: '-' for missing or nan, fixed digits otherwise."""
    if value is None:
        return "-"
    if isinstance(value, str):
        return value
    if isinstance(value, float) and not math.isfinite(value):
        return "-" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    return f"{value:.{digits}f}"


def fmt_p(p) -> str:
    if p is None or (isinstance(p, float) and not math.isfinite(p)):
        return "-"
    if p < 1e-4:
        return f"{p:.1e}"
    return f"{p:.4f}"


def fmt_effect(effect) -> str:
    if effect is None or (isinstance(effect, float) and not math.isfinite(effect)):
        return "-"
    return f"{effect:+.1f}" if abs(effect) >= 0.1 or effect == 0 else f"{effect:+.2g}"


def ordinal(i: int) -> str:
    n = i + 1
    suffix = "th" if 10 <= n % 100 <= 20 else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix}"


def _metric(d: dict, key: str) -> dict:
    return next(m for m in d["metrics"] if m["key"] == key)


def _comparison(d: dict, metric: str, other: str) -> Optional[dict]:
    for c in d["comparisons"]:
        if c["metric"] == metric and c["other"] == other:
            return c
    return None


# --------------------------------------------------------------------------------------------- tables

def per_trial_table(d: dict, metric: str) -> Table:
    """The paper's per-trial table of one metric: a row per trial, a column per planner,
    then mean, std, effect and both p-values against the proposed planner."""
    digits = DIGITS.get(metric, 3)
    planners = d["planners"]
    runs = {(r["planner"], r["trial"]): r for r in d["runs"]}
    rows = []
    for i in range(d["trials"]):
        row = [ordinal(i)]
        for p in planners:
            r = runs.get((p, i))
            if r is None:
                row.append("-")
            elif r["outcome"] != "success":
                row.append(r["outcome"])
            else:
                row.append(fmt(r[metric], digits))
        rows.append(row)
    summary = d["summary"]
    rows.append(["Mean"] + [fmt(summary[p][metric]["mean"], max(digits, 1) if metric == "steps" else digits)
                            for p in planners])
    rows.append(["Std"] + [fmt(summary[p][metric]["std"], max(digits, 1) if metric == "steps" else digits)
                           for p in planners])
    rows.append(["n (successful)"] + [str(summary[p][metric]["n"]) for p in planners])
    effect, welch, mwu = ["Effect (%)"], ["Welch p"], ["Mann-Whitney p"]
    for p in planners:
        c = _comparison(d, metric, p)
        effect.append(fmt_effect(c["effect_pct"]) if c else "-")
        welch.append(fmt_p(c["welch_p"]) if c else "-")
        mwu.append(fmt_p(c["mwu_p"]) if c else "-")
    rows += [effect, welch, mwu]
    return Table([_metric(d, metric)["label"]] + [d["labels"][p] for p in planners], rows,
                 title=f"{d['experiment'].upper()}: {_metric(d, metric)['label']} of {d['trials']} trials")


def finishing_table(d: dict) -> Table:
    planners = d["planners"]
    rates = []
    for p in planners:
        f = d["finishing"][p]
        rates.append(f"{fmt(finishing_rate(f['successes'], f['runs']), 0)} "
                     f"({f['successes']}/{f['runs']})")
    effect, fisher = ["Effect (%)"], ["Fisher p"]
    for p in planners:
        c = next((f for f in d["finishing_comparisons"] if f["other"] == p), None)
        effect.append(fmt_effect(c["effect_pct"]) if c else "-")
        fisher.append(fmt_p(c["fisher_p"]) if c else "-")
    outcomes = []
    for p in planners:
        counts = {}
        for r in d["runs"]:
            if r["planner"] == p:
                counts[r["outcome"]] = counts.get(r["outcome"], 0) + 1
        outcomes.append(", ".join(f"{k} {v}" for k, v in sorted(counts.items())))
    return Table([""] + [d["labels"][p] for p in planners],
                 [["Finishing rate (%)"] + rates, ["Outcomes"] + outcomes, effect, fisher],
                 title=f"{d['experiment'].upper()}: finishing rate")


def comparison_table(d: dict) -> Table:
    rows = []
    for c in d["comparisons"]:
        digits = max(DIGITS.get(c["metric"], 3), 1)
        rows.append([_metric(d, c["metric"])["label"], d["labels"][c["other"]],
                     f"{fmt(c['mean_proposed'], digits)} ± {fmt(c['std_proposed'], digits)}",
                     f"{fmt(c['mean_other'], digits)} ± {fmt(c['std_other'], digits)}",
                     f"{c['n_proposed']}/{c['n_other']}", fmt_effect(c["effect_pct"]),
                     fmt_p(c["welch_p"]), fmt_p(c["mwu_p"]), c["note"]])
    proposed = d["labels"][d["proposed"]]
    return Table(["Metric", "vs", f"{proposed} mean ± std", "other mean ± std", "n", "Effect (%)", "Welch p",
                  "Mann-Whitney p", "note"], rows, title=f"{d['experiment'].upper()}: {proposed} against each planner")


def _significant(p) -> bool:
    return isinstance(p, float) and math.isfinite(p) and p < SIGNIFICANCE


def claim_p(c: dict) -> str:
    """The p-values behind a claim's verdict: Welch's (or Fisher's), raw and Holm-corrected
    over the claims judged with it (the corrected one decides), and Mann-Whitney's."""
    holm = f" (Holm {fmt_p(c.get('p_holm'))} of {c.get('family', 1)})"
    if c["test"] == "Fisher exact":
        return f"Fisher {fmt_p(c['p'])}{holm}"
    return f"t {fmt_p(c['p'])}{holm}, U {fmt_p(c.get('mwu_p'))}"


def claims_table(d: dict) -> Table:
    rows = []
    for c in d["claims"]:
        metric = "Finishing rate (%)" if c["metric"] == "finishing_rate" else _metric(d, c["metric"])["label"]
        rows.append([metric, d["labels"].get(c["other"], c["other"]), c["paper"], c["ours"],
                     fmt_effect(c["effect_pct"]), claim_p(c), c["verdict"]])
    return Table(["Metric", "vs", "Paper", "Ours (mean, successful runs)", "Our effect (%)", "p", "Verdict"], rows,
                 title=f"{d['experiment'].upper()}: the paper's claims against our runs")


def cycle_table(d: dict) -> Table:
    rows = []
    for p in d["planners"] + ["all"]:
        s = d["cycle_time_ms"][p]
        rows.append([d["labels"].get(p, p), str(s["cycles"]), fmt(s["median"], 3), fmt(s["p95"], 3),
                     fmt(s["max"], 3)])
    return Table(["Planner", "cycles", "median (ms)", "p95 (ms)", "max (ms)"], rows,
                 title=f"{d['experiment'].upper()}: planning time per control cycle")


def table_metrics(d: dict) -> list:
    return [m["key"] for m in d["metrics"] if m["table"]]


def terminal_report(d: dict) -> str:
    parts = [f"== {d['title']} ==", f"scenario {d['scenario']}, {d['trials']} trials per planner, seeds "
                                     f"{d['base_seed']}..{d['base_seed'] + d['trials'] - 1}"]
    parts.append(finishing_table(d).text())
    parts += [per_trial_table(d, m).text() for m in table_metrics(d)]
    parts.append(comparison_table(d).text())
    if d["claims"]:
        parts.append(claims_table(d).text())
    parts.append(cycle_table(d).text())
    return "\n\n".join(parts)


# --------------------------------------------------------------------------------------------- files

def json_safe(value):
    """NaN and infinities become None, numpy scalars plain numbers: strict JSON."""
    if isinstance(value, dict):
        return {str(k): json_safe(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_safe(v) for v in value]
    if hasattr(value, "item") and not isinstance(value, (str, bytes)):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


NOT_NUMBERS = ("agrees",)  # keys whose None means "unknown", not a missing number


def json_restore(value, key: str = ""):
    """The inverse of json_safe for the numbers the tables read: None back to nan."""
    if isinstance(value, dict):
        return {k: json_restore(v, k) for k, v in value.items()}
    if isinstance(value, list):
        return [json_restore(v, key) for v in value]
    return float("nan") if value is None and key not in NOT_NUMBERS else value


def write_json(d: dict, path: Path) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(json_safe(d), indent=1, allow_nan=False) + "\n")
    return path


def read_json(path: Path) -> dict:
    return json_restore(json.loads(Path(path).read_text()))


def _write_csv(path: Path, fields: Sequence[str], rows: Sequence[dict]) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(fields), extrasaction="ignore")
        writer.writeheader()
        for row in rows:
            writer.writerow({k: ("" if v is None or (isinstance(v, float) and math.isnan(v)) else v)
                             for k, v in row.items()})
    return path


def write_csvs(d: dict, directory: Path) -> list:
    """runs.csv (one row per planner and trial), summary.csv, comparisons.csv."""
    directory = Path(directory)
    name = d["experiment"]
    metric_keys = [m["key"] for m in d["metrics"]]
    runs = _write_csv(directory / f"{name}_runs.csv",
                      ["experiment", "planner", "trial", "seed", "outcome", "reason"] + metric_keys + ["wall_time"],
                      [dict(experiment=name, **r) for r in d["runs"]])
    summary_rows = []
    for p in d["planners"]:
        f = d["finishing"][p]
        summary_rows.append(dict(planner=p, metric="finishing_rate", n=f["runs"],
                                 mean=finishing_rate(f["successes"], f["runs"])))
        for key in metric_keys:
            summary_rows.append(dict(planner=p, metric=key, **d["summary"][p][key]))
    summary = _write_csv(directory / f"{name}_summary.csv",
                         ["planner", "metric", "n", "mean", "std", "median", "min", "max"], summary_rows)
    comparison_rows = list(d["comparisons"]) + [
        dict(metric=f["metric"], proposed=f["proposed"], other=f["other"], mean_proposed=f["rate_proposed"],
             mean_other=f["rate_other"], effect_pct=f["effect_pct"], fisher_p=f["fisher_p"])
        for f in d["finishing_comparisons"]]
    comparisons = _write_csv(directory / f"{name}_comparisons.csv",
                             ["metric", "proposed", "other", "n_proposed", "n_other", "mean_proposed",
                              "std_proposed", "mean_other", "std_other", "effect_pct", "welch_p", "mwu_p",
                              "fisher_p", "note"], comparison_rows)
    return [runs, summary, comparisons]


def experiment_markdown(d: dict, figures: Optional[dict] = None, relative_to: Optional[Path] = None,
                        heading: str = "#", notes: bool = True, trials_link: Optional[str] = None) -> str:
    """The Markdown report of one experiment; ``figures`` maps a caption to a PNG path,
    linked relative to ``relative_to`` (the report's folder). With ``trials_link`` (the
    experiment's own report.md) the per-trial tables are linked instead of shown."""
    lines = [f"{heading} {d['title']}", ""]
    if d.get("description"):
        lines += [d["description"], ""]
    seeds = f"{d['base_seed']}..{d['base_seed'] + d['trials'] - 1}"
    lines += [f"Paper: {d['paper_ref']}. Scenario `{d['scenario']}`; {d['trials']} trials per planner, trial i "
              f"with seed {d['base_seed']} + i (seeds {seeds}) for every planner; executor `{d['executor']}`"
              + (f"; run options {d['options']}" if d.get("options") else "") + ".", ""]
    if notes:
        lines += [EXCLUSION_NOTE, "", TEST_NOTE, ""]
    if isinstance(d.get("wall_time"), float) and math.isfinite(d["wall_time"]):
        lines += [f"{len(d['runs'])} episodes, {d['episode_wall_time']:.1f} s of episode wall time in the workers; "
                  f"the trials of this invocation took {d['wall_time']:.1f} s wall.", ""]
    if d["claims"]:
        lines += [claims_table(d).markdown(), ""]
    lines += [finishing_table(d).markdown(), ""]
    if trials_link is not None:
        lines += [f"Per-trial tables: [{trials_link}]({trials_link}).", ""]
    else:
        for m in table_metrics(d):
            lines += [per_trial_table(d, m).markdown(), ""]
    lines += [comparison_table(d).markdown(), ""]
    lines += [cycle_table(d).markdown(), ""]
    for caption, path in (figures or {}).items():
        target = Path(path)
        if relative_to is not None:
            target = Path(os.path.relpath(Path(path).resolve(), Path(relative_to).resolve()))
        lines += [f"![{caption}]({target.as_posix()})", "", f"*{caption}*", ""]
    return "\n".join(lines)


def write_markdown(d: dict, path: Path, figures: Optional[dict] = None) -> Path:
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(experiment_markdown(d, figures, relative_to=path.parent) + "\n")
    return path


def results_markdown(experiments: Sequence[tuple], command: str, relative_to: Path,
                     directory: Optional[Path] = None) -> str:
    """docs/RESULTS.md: the claims of every experiment first, then each experiment's report.

    ``experiments``: (dict, figures) pairs. An experiment whose report.md is in ``directory``
    links its per-trial tables there instead of showing them."""
    lines = ["# The paper's experiments E1-E3, rerun", "",
             f"Written by `{command}` from the numbers of the runs; the command rewrites this part, so do not edit "
             "it by hand. Our maps are our own (the paper's are only pictured), so what can be compared is the "
             "direction of each effect and its significance, not the numbers (docs/algorithms.md, \"Experiments "
             "E1-E3\").", "", EXCLUSION_NOTE, "", TEST_NOTE, "",
             "## The paper's claims", ""]
    # The paper's claims of every experiment are judged together: one Holm correction over all of them.
    judged = iter(correct_claims([c for d, _ in experiments for c in d["claims"]]))
    experiments = [(dict(d, claims=[next(judged) for _ in d["claims"]]), figures) for d, figures in experiments]
    rows = []
    for d, _ in experiments:
        for c in d["claims"]:
            metric = "finishing rate" if c["metric"] == "finishing_rate" else _metric(d, c["metric"])["label"]
            rows.append([d["experiment"].upper(), metric, d["labels"][d["proposed"]],
                         d["labels"].get(c["other"], c["other"]), c["paper"],
                         c["ours"], fmt_effect(c["effect_pct"]), claim_p(c), c["verdict"]])
    lines.append(Table(["Exp.", "Metric", "Proposed", "vs", "Paper", "Ours", "Our effect (%)", "p", "Verdict"],
                       rows).markdown())
    claims = [c for d, _ in experiments for c in d["claims"]]
    direction = [c for c in claims if c["kind"] == "direction"]
    same = [c for c in direction if c["agrees"] is True]
    significant = [c for c in same if _significant(c["p_holm"])]
    measurable = [c for c in direction if c["agrees"] in (True, False)]
    none_claims = [c for c in claims if c["kind"] == "no_difference"]
    summary = (f"Of the paper's {len(direction)} directional claims, {len(measurable)} could be measured here; "
               f"{len(same)} show the same direction in our runs, {len(significant)} of them significant "
               f"(p < 0.05 after Holm's correction over the {len(claims)} claims).")
    if none_claims:
        summary += (f" Of its {len(none_claims)} claim(s) of no difference, "
                    f"{sum(1 for c in none_claims if c['agrees'] in (True, False))} could be measured and "
                    f"{sum(1 for c in none_claims if c['agrees'] is True)} hold (no significant difference here).")
    lines += ["", summary, ""]
    for d, figures in experiments:
        report = Path(directory) / d["experiment"] / "report.md" if directory is not None else None
        link = (Path(os.path.relpath(report.resolve(), Path(relative_to).resolve())).as_posix()
                if report is not None and report.exists() else None)
        lines += [experiment_markdown(d, figures, relative_to=relative_to, heading="##", notes=False,
                                      trials_link=link), ""]
    return "\n".join(lines)


# --------------------------------------------------------------------------------------------- saving

SURFACES_CAPTION = "The paper's fuzzy controller: control surfaces beta(I, D) and delta(I, D)"
SURFACES_FILE = "control_surfaces.png"


def save_experiment(result, directory: Path, figures: Optional[dict] = None) -> dict:
    """Write an ExperimentResult into ``directory/<name>/``: <name>.json, the CSVs and
    report.md, which shows ``figures`` ({caption: path}, made there beforehand by
    ``fgdwa.plot.experiments.experiment_figures``). Returns its dictionary, with the figures'
    file names."""
    directory = Path(directory) / result.spec.name
    directory.mkdir(parents=True, exist_ok=True)
    d = result.to_dict()
    paths = dict(figures or {})
    d["figures"] = {caption: Path(p).name for caption, p in paths.items()}
    write_json(d, directory / f"{result.spec.name}.json")
    write_csvs(d, directory)
    write_markdown(d, directory / "report.md", paths)
    return d


def saved_experiments(directory: Path, names: Sequence[str]) -> list:
    """(dict, {caption: path}) of each experiment whose JSON is in ``directory``, in ``names`` order."""
    out = []
    for name in names:
        path = Path(directory) / name / f"{name}.json"
        if path.exists():
            d = read_json(path)
            out.append((d, {caption: path.parent / f for caption, f in d.get("figures", {}).items()}))
    return out


KEEP_MARKER = "<!-- Sections below are not written by `fgdwa experiment`, which keeps them. -->"
HEAD_MARKER = "<!-- Sections above are not written by `fgdwa experiment`, which keeps them. -->"


def write_results(directory: Path, names: Sequence[str], command: str, path: Path,
                  surfaces: Optional[Path] = None) -> Path:
    """A results page (e.g. docs/RESULTS.md) from the experiments saved in ``directory``."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    text = results_markdown(saved_experiments(directory, names), command, path.parent, directory)
    if surfaces is not None and Path(surfaces).exists():
        target = Path(os.path.relpath(Path(surfaces).resolve(), path.parent.resolve())).as_posix()
        text += f"\n## The fuzzy controller\n\n![{SURFACES_CAPTION}]({target})\n\n*{SURFACES_CAPTION}*\n"
    # A hand-written head (title, contents, summary) above HEAD_MARKER stays, the generated title then one level
    # down; sections written by other commands (fgdwa barn) sit below KEEP_MARKER and stay.
    if path.exists():
        old = path.read_text()
        if HEAD_MARKER in old:
            text = old[:old.index(HEAD_MARKER) + len(HEAD_MARKER)] + "\n\n#" + text
        if KEEP_MARKER in old:
            text = text.rstrip("\n") + "\n\n" + old[old.index(KEEP_MARKER):]
    path.write_text(text)
    return path
