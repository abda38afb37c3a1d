"""Statistics of experiment trials: summaries, effects and two-sample tests.

Every function takes plain sequences of numbers and returns plain Python
numbers; non-finite values (a metric a run could not measure) are dropped
first. Degenerate inputs give a defined answer and say why in ``note``
instead of a warning or an exception:

- fewer than 2 values on a side: no Welch t-test (p is nan);
- no value on a side: no test at all;
- every value equal on both sides: p = 1.0 (no difference to find);
- both sides constant but different: Welch's p is 0.0 (scipy's limit), and the
  note says the t statistic is degenerate;
- a reference mean of 0: the effect in % is nan unless both means are 0.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import asdict, dataclass
from typing import Optional, Sequence

import numpy as np

SIGNIFICANCE = 0.05  # two-sided p (Holm-corrected over the claims judged together) below which an effect counts
SMALL_SAMPLE = 5  # runs on a side below which a test says too little to judge a claim either way


def holm(p_values: Sequence[float]) -> list:
    """Holm's step-down correction of p-values tested together: the i-th smallest
    of m finite ones times (m - i), never below the one before it, at most 1. A
    NaN stays NaN and does not count in m."""
    p = np.asarray([np.nan if v is None else v for v in p_values], dtype=float).reshape(-1)
    finite_at = np.flatnonzero(np.isfinite(p))
    out = np.full(p.shape, np.nan)
    running = 0.0
    for rank, i in enumerate(finite_at[np.argsort(p[finite_at], kind="stable")]):
        running = max(running, min(1.0, (len(finite_at) - rank) * p[i]))
        out[i] = running
    return out.tolist()


def finishing_rate(successes: int, runs: int) -> float:
    """Successes in % of the runs; NaN without runs."""
    return 100.0 * successes / runs if runs else float("nan")


def finite(values: Sequence[float]) -> np.ndarray:
    """The finite values as a float array."""
    array = np.asarray([v for v in values if v is not None], dtype=float).reshape(-1)
    return array[np.isfinite(array)]


@dataclass(frozen=True)
class Summary:
    n: int
    mean: float
    std: float  # sample standard deviation (ddof 1); nan for n < 2
    median: float
    min: float
    max: float

    def to_dict(self) -> dict:
        return asdict(self)


def describe(values: Sequence[float]) -> Summary:
    """n, mean, sample std, median, min and max of the finite values."""
    x = finite(values)
    if len(x) == 0:
        nan = float("nan")
        return Summary(0, nan, nan, nan, nan, nan)
    return Summary(
        n=int(len(x)),
        mean=float(np.mean(x)),
        std=float(np.std(x, ddof=1)) if len(x) > 1 else float("nan"),
        median=float(np.median(x)),
        min=float(np.min(x)),
        max=float(np.max(x)),
    )


def effect_percent(proposed_mean: float, other_mean: float) -> float:
    """(proposed - other) / |other| in %: negative when the proposed planner's value is lower.

    This is the paper's "effect" with its sign kept: Table 9's 26.2 % shorter
    running time of FGDWA is -26.2 here, Table 12's 50 % larger clearance +50."""
    if not (math.isfinite(proposed_mean) and math.isfinite(other_mean)):
        return float("nan")
    if other_mean == 0:
        return 0.0 if proposed_mean == 0 else float("nan")
    return float((proposed_mean - other_mean) / abs(other_mean) * 100.0)


def welch_p(a: Sequence[float], b: Sequence[float]) -> tuple:
    """(two-sided p of Welch's t-test, note)."""
    from scipy import stats

    x, y = finite(a), finite(b)
    if len(x) < 2 or len(y) < 2:
        return float("nan"), "no t-test: n < 2 on a side"
    sx, sy = np.std(x, ddof=1), np.std(y, ddof=1)
    if sx == 0 and sy == 0:
        if np.mean(x) == np.mean(y):
            return 1.0, "all values equal"
        return 0.0, "both sides constant: t statistic degenerate"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        p = float(stats.ttest_ind(x, y, equal_var=False).pvalue)
    return p, ""


def mwu_p(a: Sequence[float], b: Sequence[float]) -> tuple:
    """(two-sided p of the Mann-Whitney U test, note)."""
    from scipy import stats

    x, y = finite(a), finite(b)
    if len(x) == 0 or len(y) == 0:
        return float("nan"), "no U test: no value on a side"
    if np.all(np.concatenate([x, y]) == x[0]):
        return 1.0, "all values equal"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        p = float(stats.mannwhitneyu(x, y, alternative="two-sided").pvalue)
    return p, ""


def fisher_p(successes_a: int, n_a: int, successes_b: int, n_b: int) -> float:
    """Two-sided p of Fisher's exact test on two success counts (finishing rates)."""
    from scipy import stats

    if n_a == 0 or n_b == 0:
        return float("nan")
    table = [[successes_a, n_a - successes_a], [successes_b, n_b - successes_b]]
    return float(stats.fisher_exact(table).pvalue)


@dataclass(frozen=True)
class Comparison:
    """One metric of the proposed planner against another planner."""

    metric: str
    proposed: str
    other: str
    proposed_summary: Summary
    other_summary: Summary
    effect_pct: float  # effect_percent of the means
    welch_p: float
    mwu_p: float
    note: str = ""

    def to_dict(self) -> dict:
        return {
            "metric": self.metric,
            "proposed": self.proposed,
            "other": self.other,
            "n_proposed": self.proposed_summary.n,
            "n_other": self.other_summary.n,
            "mean_proposed": self.proposed_summary.mean,
            "std_proposed": self.proposed_summary.std,
            "mean_other": self.other_summary.mean,
            "std_other": self.other_summary.std,
            "effect_pct": self.effect_pct,
            "welch_p": self.welch_p,
            "mwu_p": self.mwu_p,
            "note": self.note,
        }


def compare(metric: str, proposed: str, proposed_values: Sequence[float], other: str,
            other_values: Sequence[float]) -> Comparison:
    """Summaries, effect in % and both tests of one metric between two planners."""
    sp, so = describe(proposed_values), describe(other_values)
    p_t, note_t = welch_p(proposed_values, other_values)
    p_u, note_u = mwu_p(proposed_values, other_values)
    notes = []
    for note in (note_t, note_u):
        if note and note not in notes:
            notes.append(note)
    return Comparison(metric, proposed, other, sp, so, effect_percent(sp.mean, so.mean), p_t, p_u, "; ".join(notes))


def percentile(values: Sequence[float], q: float) -> Optional[float]:
    """The q-th percentile of the finite values, nan when there is none."""
    x = finite(values)
    return float(np.percentile(x, q)) if len(x) else float("nan")
