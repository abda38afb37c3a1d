"""The paper's claims and how our runs judge them: a claim's verdict comes from
our effect and its p-value after Holm's correction over the claims judged
together, and says "too few runs to say" below SMALL_SAMPLE runs a side.

Plain data in, plain data out: the experiments judge their claims with it, and
the reports judge all experiments' claims together when they read them back.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Sequence

from fgdwa.bench import stats
from fgdwa.bench.stats import SIGNIFICANCE, SMALL_SAMPLE


@dataclass(frozen=True)
class Claim:
    """What the paper reports for one metric of the proposed planner against another.

    ``paper_effect`` is in % as ``fgdwa.bench.stats.effect_percent`` defines it (the
    sign gives the direction). ``kind`` "direction": our effect should have the
    same sign; "no_difference": the paper found none, so ours should not be
    significant."""

    metric: str  # a Metric key or FINISHING
    other: str  # the planner compared against
    paper_effect: float
    paper: str  # the paper's numbers, in words
    kind: str = "direction"


def correct_claims(rows: Sequence[dict]) -> list:
    """The claims judged together: each gets its Holm-corrected p (``p_holm``, over
    all of them) and its verdict from that; the raw ``p`` stays beside it."""
    rows = [dict(r) for r in rows]
    for row, p_holm in zip(rows, stats.holm([r["p"] for r in rows])):
        row["p_holm"], row["family"] = p_holm, len(rows)
        row["verdict"], row["agrees"] = verdict(Claim(row["metric"], row["other"], row["paper_effect"], row["paper"],
                                                      row["kind"]), row["effect_pct"], p_holm, row.get("n"))
    return rows


def verdict(claim: Claim, effect: float, p: float, n: Optional[Sequence[int]] = None) -> tuple:
    """(words, agrees) for a claim given our effect in % and its (corrected) p-value;
    agrees is None when not measurable: no effect, or fewer than SMALL_SAMPLE runs
    on a side (``n``: the runs each side's numbers come from)."""
    if effect is None or not math.isfinite(effect):
        return "not measurable (no successful run on a side, or a zero reference)", None
    p_text = f"p = {p:.3g}" if p is not None and math.isfinite(p) else "no p-value"
    if n is not None and min(n) < SMALL_SAMPLE:
        return (f"too few runs to say (n = {', '.join(str(k) for k in n)}; {_pct(effect)} %, {p_text})", None)
    significant = p is not None and math.isfinite(p) and p < SIGNIFICANCE
    if claim.kind == "no_difference":
        if significant:
            return f"differs: significant {_pct(effect)} % ({p_text})", False
        return f"same: no significant difference, {_pct(effect)} % ({p_text})", True
    if effect == 0:
        return f"no difference in our runs ({p_text})", False
    same = math.copysign(1.0, effect) == math.copysign(1.0, claim.paper_effect)
    direction = "same direction" if same else "opposite direction"
    strength = "significant" if significant else "not significant"
    return f"{direction}, {strength} ({_pct(effect)} %, {p_text})", same


def _pct(effect: float) -> str:
    return f"{effect:+.1f}" if abs(effect) >= 0.1 else f"{effect:+.2g}"
