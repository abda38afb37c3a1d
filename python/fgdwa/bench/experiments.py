"""The paper's experiments E1-E3 (docs/algorithms.md): seeded trials of planners on a scenario,
compared metric by metric.

An experiment runs ``trials`` trials of each of its planners; trial ``i`` uses
seed ``base_seed + i`` for every planner, so the planners meet the same start
jitter, moving-obstacle phases and lidar noise. Trials run through
:func:`fgdwa.bench.runner.run_tasks`: in worker processes (``executor="local"``),
on a dask.distributed cluster (``"dask"``) or in this process (``"serial"``); a
trial's result depends only on its task, never on where it ran (the wall-clock
planning time aside).

The first planner of an experiment is the proposed one; every other planner
is compared with it (``fgdwa.bench.stats.compare``). Runs that did not reach the
goal count in the finishing rate only: their time, steps, mileage and
clearances are left out of the comparisons, as the paper leaves out GDWA's
unfinished runs in Tables 15-18.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field
from typing import Iterable, Optional, Sequence, Union

import numpy as np

from fgdwa._core import FgdwaError
from fgdwa.bench import stats
from fgdwa.bench.recordings import record_failures, recorded_navigator
from fgdwa.bench.runner import DEFAULT_WORKERS, run_tasks
from fgdwa.bench.claims import Claim, correct_claims
from fgdwa.bench.stats import finishing_rate
from fgdwa.sim.scenario import Scenario, run_scenario, trial_variation
from fgdwa.file_limits import short_repr


@dataclass(frozen=True)
class Metric:
    key: str  # EpisodeResult.metrics() key
    label: str  # with its unit
    better: str  # "lower" or "higher"
    table: bool = False  # has a per-trial table (the paper's Tables 9-12, 15-17)


METRICS = (
    Metric("planning_time", "Running time (s, wall-clock planning)", "lower", True),
    Metric("steps", "Iteration steps", "lower", True),
    Metric("mileage", "Mileage (m)", "lower", True),
    Metric("danger_clearance", "Danger-point clearance (m)", "higher", True),
    Metric("sim_time", "Simulated time (s)", "lower"),
    Metric("min_clearance", "Minimum clearance (m)", "higher"),
    Metric("mean_deviation", "Mean deviation from the global path (m)", "lower"),
    Metric("smoothness", "Smoothness, sum |d omega| (rad/s)", "lower"),
)
METRIC_BY_KEY = {m.key: m for m in METRICS}
FINISHING = "finishing_rate"

PLANNER_LABELS = {
    "dwa": "DWA",
    "gdwa": "GDWA",
    "sgdwa": "Similarity-GDWA",
    "fgdwa": "FGDWA",
    "gdwa_high_safety": "GDWA, high safety weight",
    "gdwa_high_similarity": "GDWA, high similarity weight",
    "dwb": "DWB (Nav2 critics)",
}


def planner_label(name: str) -> str:
    return PLANNER_LABELS.get(name, name)


@dataclass(frozen=True)
class ExperimentSpec:
    name: str
    title: str
    scenario: object  # a load_scenario source (name, path, YAML) or a zero-argument callable giving a Scenario
    planners: tuple  # the proposed planner first
    claims: tuple = ()
    paper_ref: str = ""
    description: str = ""

    @property
    def proposed(self) -> str:
        return self.planners[0]

    @property
    def others(self) -> tuple:
        return self.planners[1:]


EXPERIMENTS = {
    "e1": ExperimentSpec(
        name="e1",
        title="E1: the similarity cost (GDWA vs Similarity-GDWA)",
        scenario="e1",
        planners=("sgdwa", "gdwa"),
        paper_ref="Tables 5-7",
        description="Fixed weights alpha 0.5, beta 0.15, gamma 1, with and without the similarity cost "
                    "(delta 0.5), on a map whose key nodes lie far apart.",
        claims=(
            Claim("planning_time", "gdwa", -0.7, "execution time 156.5 s vs 157.6 s (-0.7 %)"),
            Claim("steps", "gdwa", -2.5, "iteration steps 352 vs 361 (-2.5 %)"),
            Claim("mileage", "gdwa", -2.1, "mileage 27.6 m vs 28.2 m (-2.1 %)"),
        ),
    ),
    "e2": ExperimentSpec(
        name="e2",
        title="E2: fuzzy weights (FGDWA vs fixed high-safety and high-similarity weights)",
        scenario="e2",
        planners=("fgdwa", "gdwa_high_safety", "gdwa_high_similarity"),
        paper_ref="Tables 8-12",
        description="The E1 map with obstacles missing from it, seen only by the lidar.",
        claims=(
            Claim("planning_time", "gdwa_high_safety", -26.2, "running time 89.58 s vs 121.36 s (-26.2 %)"),
            Claim("planning_time", "gdwa_high_similarity", -10.8, "running time 89.58 s vs 100.37 s (-10.8 %)"),
            Claim("steps", "gdwa_high_safety", -22.8, "iteration steps 171.3 vs 221.9 (-22.8 %)"),
            Claim("steps", "gdwa_high_similarity", -6.8, "iteration steps 171.3 vs 183.9 (-6.8 %)"),
            Claim("mileage", "gdwa_high_safety", -6.4, "mileage 27.36 m vs 29.22 m (-6.4 %)"),
            Claim("mileage", "gdwa_high_similarity", 0.1,
                  "mileage 27.36 m vs 27.32 m (+0.1 %, Table 11's effect -0.1: \"no obvious difference\")",
                  kind="no_difference"),
            Claim("danger_clearance", "gdwa_high_similarity", 50.0,
                  "danger-point clearance 0.48 m vs 0.32 m (+50 %, Table 12)"),
        ),
    ),
    "e3": ExperimentSpec(
        name="e3",
        title="E3: complex terrain (FGDWA vs GDWA)",
        scenario="e3",
        planners=("fgdwa", "gdwa"),
        paper_ref="Tables 13-18",
        description="Slope grades, a C-shaped obstacle group, a dense obstacle area and unknown moving obstacles.",
        claims=(
            Claim(FINISHING, "gdwa", 25.0, "finishing rate 100 % vs 80 % (Table 18)"),
            Claim("planning_time", "gdwa", -21.3, "running time 89.1 s vs 113.2 s over finished runs (Table 15)"),
            Claim("steps", "gdwa", -18.0, "iteration steps 182 vs 222 over finished runs (Table 16)"),
            Claim("mileage", "gdwa", -0.2, "mileage 30.80 m vs 30.87 m over finished runs (Table 17)"),
        ),
    ),
}


def experiment_names() -> list:
    return list(EXPERIMENTS)


# --------------------------------------------------------------------------------------------- scenarios

def resolve_scenario(source) -> Scenario:
    """A Scenario from a Scenario, a zero-argument callable, or a ``load_scenario`` source."""
    if isinstance(source, Scenario):
        return source
    if callable(source):
        scenario = source()
        if not isinstance(scenario, Scenario):
            raise FgdwaError(f"scenario factory {short_repr(source)} returned {type(scenario).__name__}, not a Scenario")
        return scenario
    if not isinstance(source, str):
        raise FgdwaError(f"scenario = {short_repr(source)}: expected a name, a YAML path or text, a callable or a Scenario")
    from fgdwa.io.scenario_file import load_scenario

    return load_scenario(source)


# --------------------------------------------------------------------------------------------- trials

@dataclass(frozen=True)
class TrialTask:
    """One episode to run: picklable, so a worker process or a dask worker can run it."""

    experiment: str
    scenario: object  # see ExperimentSpec.scenario
    planner: str
    trial: int  # 0-based
    seed: int
    options: tuple = ()  # (name, value) pairs of run_scenario keyword arguments, e.g. (("max_steps", 100),)
    record: str = ""  # a path: keep every cycle and write the trial there as a Rerun recording


@dataclass
class TrialRecord:
    """What a trial returns: its metrics and the traces the figures need."""

    experiment: str
    planner: str
    trial: int
    seed: int
    metrics: dict  # EpisodeResult.metrics()
    wall_time: float  # s, the whole episode in its worker
    poses: np.ndarray
    cycle_times: np.ndarray
    beta: np.ndarray
    delta: np.ndarray
    density: np.ndarray
    deviation: np.ndarray
    global_path: Optional[np.ndarray] = None
    key_nodes: Optional[np.ndarray] = None
    dt: float = float("nan")

    @property
    def success(self) -> bool:
        return self.metrics["outcome"] == "success"


def run_trial(task: TrialTask) -> TrialRecord:
    """Run one trial (in whatever process calls it)."""
    scenario = resolve_scenario(task.scenario)
    options = dict(task.options)
    if task.record:
        options.update(record_cycles=True, navigator=recorded_navigator(options.get("mapping", "known")))
    tic = time.perf_counter()
    result = run_scenario(scenario, task.planner, task.seed, **options)
    wall = time.perf_counter() - tic
    if task.record:
        from fgdwa.plot.recording import write_recording

        _, world, _ = trial_variation(scenario, task.seed)
        write_recording(result, world, scenario.goal, scenario.footprint, task.record, title=trial_name(task))
    summary, trace = result.summary, result.trace
    return TrialRecord(
        experiment=task.experiment, planner=task.planner, trial=task.trial, seed=task.seed,
        metrics=result.metrics(), wall_time=wall, poses=result.motion.poses, cycle_times=trace.cycle_times,
        beta=trace.beta, delta=trace.delta, density=trace.density, deviation=trace.deviation,
        global_path=result.context.global_path, key_nodes=result.context.key_nodes,
        dt=summary.sim_time / summary.steps if summary.steps else float("nan"),
    )


def trial_name(task) -> str:
    """A trial's name in file names: experiment, planner, trial (a TrialTask or TrialRecord)."""
    return f"{task.experiment}_{task.planner}_trial{task.trial}"


def record_failed_trials(results: Sequence["ExperimentResult"], directory, **executor) -> dict:
    """Run each failed trial of ``results`` again, writing it as a Rerun recording
    into ``directory`` (see fgdwa.bench.recordings); returns {trial_name: path}."""
    tasks, outcomes = [], []
    for result in results:
        options = tuple(sorted(result.options.items()))
        for r in result.records:
            tasks.append(TrialTask(result.spec.name, result.spec.scenario, r.planner, r.trial, r.seed, options))
            outcomes.append(r.metrics["outcome"])
    paths = record_failures(tasks, outcomes, run_trial, directory, trial_name,
                            outcome_of=lambda record: record.metrics["outcome"], check_task=check_portable,
                            **executor)
    return {trial_name(task): path for task, path in zip(tasks, paths) if path is not None}


def trial_failures(result: "ExperimentResult", recordings: Optional[dict] = None) -> list:
    """One entry per failed trial: planner, trial, seed, outcome, reason and its recording when there is one."""
    entries = []
    for r in result.records:
        if r.success:
            continue
        entry = {"planner": r.planner, "trial": r.trial, "seed": r.seed, "outcome": r.metrics["outcome"],
                 "reason": r.metrics["reason"]}
        if recordings and trial_name(r) in recordings:
            entry["recording"] = str(recordings[trial_name(r)])
        entries.append(entry)
    return entries


def trial_tasks(spec: ExperimentSpec, trials: int, base_seed: int = 0, options: Optional[dict] = None) -> list:
    """Every (planner, trial) task of an experiment; trial i has seed base_seed + i for every planner."""
    if isinstance(trials, bool) or not isinstance(trials, (int, np.integer)) or trials < 1:
        raise FgdwaError(f"trials = {short_repr(trials)}: must be an integer >= 1")
    items = tuple(sorted((options or {}).items()))
    return [TrialTask(spec.name, spec.scenario, planner, i, int(base_seed) + i, items)
            for i in range(int(trials)) for planner in spec.planners]


def check_portable(task: TrialTask) -> None:
    """FgdwaError when a trial cannot be sent to a worker process: its scenario is a Scenario object."""
    if isinstance(task.scenario, Scenario):
        raise FgdwaError("a Scenario object cannot be sent to worker processes: give the experiment a "
                         "scenario name, file or a module-level factory function, or use executor='serial'")


# --------------------------------------------------------------------------------------------- results

@dataclass
class ExperimentResult:
    spec: ExperimentSpec
    trials: int
    base_seed: int
    records: list  # TrialRecord, by planner (spec order) then trial
    wall_time: float = float("nan")  # s, the run these trials were part of
    executor: str = "local"
    options: dict = field(default_factory=dict)

    def planner_records(self, planner: str) -> list:
        return [r for r in self.records if r.planner == planner]

    def record(self, planner: str, trial: int) -> TrialRecord:
        for r in self.records:
            if r.planner == planner and r.trial == trial:
                return r
        raise KeyError((planner, trial))

    def values(self, planner: str, metric: str, successful_only: bool = True) -> list:
        """The metric of each trial of ``planner`` (nan where the run failed, unless ``successful_only`` is False)."""
        out = []
        for r in self.planner_records(planner):
            value = r.metrics[metric]
            out.append(float(value) if (r.success or not successful_only) else float("nan"))
        return out

    def finishing(self, planner: str) -> tuple:
        """(successful runs, runs) of ``planner``."""
        records = self.planner_records(planner)
        return sum(r.success for r in records), len(records)

    def comparisons(self) -> list:
        """Every metric of the proposed planner against each other planner (successful runs only)."""
        out = []
        for other in self.spec.others:
            for metric in METRICS:
                out.append(stats.compare(metric.key, self.spec.proposed, self.values(self.spec.proposed, metric.key),
                                         other, self.values(other, metric.key)))
        return out

    def finishing_comparisons(self) -> list:
        out = []
        sp, n_p = self.finishing(self.spec.proposed)
        for other in self.spec.others:
            so, n_o = self.finishing(other)
            rate_p, rate_o = finishing_rate(sp, n_p), finishing_rate(so, n_o)
            out.append({"metric": FINISHING, "proposed": self.spec.proposed, "other": other,
                        "rate_proposed": rate_p, "rate_other": rate_o,
                        "runs_proposed": n_p, "runs_other": n_o,
                        "effect_pct": stats.effect_percent(rate_p, rate_o),
                        "fisher_p": stats.fisher_p(sp, n_p, so, n_o)})
        return out

    def cycle_time_stats(self) -> dict:
        """Per planner and overall: median and 95th percentile of the per-cycle planning time (ms)."""
        out = {}
        everything = []
        for planner in self.spec.planners:
            times = np.concatenate([r.cycle_times for r in self.planner_records(planner)] or [np.zeros(0)])
            everything.append(times)
            out[planner] = _cycle_stats(times)
        out["all"] = _cycle_stats(np.concatenate(everything) if everything else np.zeros(0))
        return out

    def to_dict(self) -> dict:
        """Everything the reports need, as JSON-able plain data."""
        comparisons = [c.to_dict() for c in self.comparisons()]
        finishing = self.finishing_comparisons()
        return {
            "experiment": self.spec.name,
            "title": self.spec.title,
            "description": self.spec.description,
            "paper_ref": self.spec.paper_ref,
            "scenario": self.spec.scenario if isinstance(self.spec.scenario, str) else repr(self.spec.scenario),
            "planners": list(self.spec.planners),
            "labels": {p: planner_label(p) for p in self.spec.planners},
            "proposed": self.spec.proposed,
            "trials": self.trials,
            "base_seed": self.base_seed,
            "seeds": [self.base_seed + i for i in range(self.trials)],
            "executor": self.executor,
            "options": dict(self.options),
            "wall_time": self.wall_time,
            "episode_wall_time": float(sum(r.wall_time for r in self.records)),
            "metrics": [dataclasses.asdict(m) for m in METRICS],
            "runs": [dict(planner=r.planner, trial=r.trial, seed=r.seed, wall_time=r.wall_time, **r.metrics)
                     for r in self.records],
            "summary": {p: {m.key: stats.describe(self.values(p, m.key)).to_dict() for m in METRICS}
                        for p in self.spec.planners},
            "finishing": {p: dict(zip(("successes", "runs"), self.finishing(p))) for p in self.spec.planners},
            "comparisons": comparisons,
            "finishing_comparisons": finishing,
            "claims": judge_claims(self.spec.claims, comparisons, finishing),
            "cycle_time_ms": self.cycle_time_stats(),
        }


def _cycle_stats(times: np.ndarray) -> dict:
    ms = 1e3 * np.asarray(times, dtype=float)
    return {"cycles": int(len(ms)), "median": stats.percentile(ms, 50), "p95": stats.percentile(ms, 95),
            "max": float(np.max(ms)) if len(ms) else float("nan")}


def judge_claims(claims: Iterable[Claim], comparisons: Sequence[dict], finishing: Sequence[dict]) -> list:
    """For each claim of the paper: our effect, its p-values (raw and Holm-corrected
    over these claims) and a verdict computed from them."""
    out = []
    for claim in claims:
        row = {"metric": claim.metric, "other": claim.other, "paper_effect": claim.paper_effect,
               "paper": claim.paper, "kind": claim.kind}
        if claim.metric == FINISHING:
            found = [f for f in finishing if f["other"] == claim.other]
            ours = found[0] if found else {}
            row.update(effect_pct=ours.get("effect_pct", float("nan")), p=ours.get("fisher_p", float("nan")),
                       n=[ours.get("runs_proposed", 0), ours.get("runs_other", 0)],
                       test="Fisher exact", ours=f"{_fmt(ours.get('rate_proposed'), 0)} % vs "
                                                  f"{_fmt(ours.get('rate_other'), 0)} %")
        else:
            digits = 1 if claim.metric == "steps" else 3
            found = [c for c in comparisons if c["metric"] == claim.metric and c["other"] == claim.other]
            ours = found[0] if found else {}
            row.update(effect_pct=ours.get("effect_pct", float("nan")), p=ours.get("welch_p", float("nan")),
                       mwu_p=ours.get("mwu_p", float("nan")), test="Welch t",
                       n=[ours.get("n_proposed", 0), ours.get("n_other", 0)],
                       ours=f"{_fmt(ours.get('mean_proposed'), digits)} vs {_fmt(ours.get('mean_other'), digits)} "
                            f"(n = {ours.get('n_proposed', 0)}, {ours.get('n_other', 0)})")
        out.append(row)
    return correct_claims(out)


def _fmt(value, digits: int = 3) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "-"
    return f"{value:.{digits}f}" if digits else f"{value:.0f}"


# --------------------------------------------------------------------------------------------- running

def run_experiments(specs: Sequence[Union[ExperimentSpec, str]], trials: int = 15, base_seed: int = 0,
                    executor: str = "local", scheduler: Optional[str] = None, workers: int = DEFAULT_WORKERS,
                    progress: bool = True, options: Optional[dict] = None) -> list:
    """Run the trials of several experiments in one pool (so the workers stay busy) and
    return one ExperimentResult each. ``options`` go to ``run_scenario`` (e.g. max_steps)."""
    specs = [EXPERIMENTS[s] if isinstance(s, str) and s in EXPERIMENTS else s for s in specs]
    for spec in specs:
        if not isinstance(spec, ExperimentSpec):
            raise FgdwaError(f"experiment {short_repr(spec)}: expected one of {', '.join(EXPERIMENTS)} or an ExperimentSpec")
    tasks = [task for spec in specs for task in trial_tasks(spec, trials, base_seed, options)]
    tic = time.perf_counter()
    records = run_tasks(tasks, run_trial, executor=executor, scheduler=scheduler, workers=workers, progress=progress,
                        check_task=check_portable)
    wall = time.perf_counter() - tic
    out = []
    for spec in specs:
        mine = [r for r in records if r.experiment == spec.name]
        mine.sort(key=lambda r: (spec.planners.index(r.planner), r.trial))
        out.append(ExperimentResult(spec, int(trials), int(base_seed), mine, wall, executor, dict(options or {})))
    return out


def run_experiment(spec: Union[ExperimentSpec, str], trials: int = 15, base_seed: int = 0, **kwargs) -> ExperimentResult:
    """One experiment; see run_experiments."""
    return run_experiments([spec], trials, base_seed, **kwargs)[0]


def comparable_runs(result: ExperimentResult, exclude: Sequence[str] = ("planning_time",)) -> list:
    """The per-trial metrics without wall-clock fields: what must not depend on the executor."""
    return [(r.planner, r.trial, r.seed, {k: v for k, v in r.metrics.items() if k not in exclude})
            for r in result.records]
