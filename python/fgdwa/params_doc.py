"""The parameter reference (docs/parameters.md), written from the schema each
parameter struct declares once in C++ (``cls.schema()``)."""

from __future__ import annotations

import math

from fgdwa._core import (AStarParams, ClearanceParams, DetectWindowParams, DwbGridParams, DwbObstacleParams, LidarParams,
                         NavigatorParams, OmplParams, PlannerParams, RobotLimits, SimilarityParams)

# The sets a robot program, the ROS node and scenario files configure, in the
# order a newcomer meets them.
PARAMETER_SETS = (RobotLimits, PlannerParams, NavigatorParams, DetectWindowParams, LidarParams)
# The global planners' parameters (AStarPlanner, OmplPlanner, plan_global and a
# scenario's global_planner options).
GLOBAL_PARAMETER_SETS = (AStarParams, OmplParams)
# The built-in critics' parameters, given in a critic's `params` in PlannerParams.critics.
CRITIC_PARAMETER_SETS = (ClearanceParams, SimilarityParams, DwbObstacleParams, DwbGridParams)


def _number(value: float) -> str:
    if math.isinf(value):
        return "inf" if value > 0 else "-inf"
    return f"{value:g}"


def bounds_text(entry: dict) -> str:
    """An entry's bounds as an interval: ``[0, 1e+06]``, ``(0, 1]``, ``[0, 1e+06] or inf``."""
    if "min" not in entry:
        return " / ".join(entry["choices"]) if entry["type"] == "choice" else ""
    text = (("(" if entry["min_open"] else "[") + _number(entry["min"]) + ", " + _number(entry["max"])
            + (")" if entry["max_open"] else "]"))
    return text + (" or inf" if entry["infinite_ok"] else "")


def default_text(entry: dict) -> str:
    value = entry.get("default")
    if entry["type"] == "group":
        return ""
    if entry["type"] == "critics":
        return ", ".join(f"{c['name']} {c['weight']:g}" for c in value)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return _number(value)
    return str(value)


def parameter_reference() -> str:
    lines = [
        "# Parameters",
        "",
        "Written by `fgdwa params > docs/parameters.md` from the schema each",
        "parameter struct declares once in C++ (`cpp/include/fgdwa/params.hpp`); a test",
        "checks that this page matches the code.",
        "",
        "One name on every surface: the C++ member, the Python attribute and keyword",
        "(`PlannerParams(window={\"n_v\": 15})`, `params.window.n_v`, `params.set(\"window.n_v\", 15)`),",
        "the ROS node's private parameter (`~planner/window/n_v`), scenario and IR-SIM keys",
        "(`overrides: {window: {n_v: 15}}`), `fgdwa replay --set planner/window/n_v=15` and",
        "the benchmark commands' `--set` (`fgdwa barn`, `fgdwa dynabarn`, `fgdwa dynamic`:",
        "`--set navigator/tracker/hypothesis_time=0.5`, planner and navigator parameters).",
        "Units are SI and radians everywhere; a file key may give an angle (unit rad) in",
        "degrees under its name + `_deg` (`min_turn_deg: 10`). A name that is not known",
        "is refused with the nearest known names.",
        "",
    ]
    for cls in PARAMETER_SETS:
        lines += _section("##", cls, f"{cls.name}/")
    lines += [
        "## Global planners' parameters",
        "",
        "`AStarPlanner(grid, params)` and `OmplPlanner(grid, footprint, params)` take these, or their",
        "fields as keywords; so do `plan_global` and a scenario's `global_planner: {options: ...}`.",
        "",
    ]
    for cls in GLOBAL_PARAMETER_SETS:
        lines += _section("###", cls, f"{cls.name}/")
    lines += [
        "## Critics' parameters",
        "",
        "Given in a critic's `params` in `planner/critics`",
        "(`{name: similarity, weight: 0.2, params: {band: 8}}`); a critic refuses a name it",
        "does not have.",
        "",
    ]
    for cls in CRITIC_PARAMETER_SETS:
        lines += _section("###", cls, "", intro=cls.__doc__.strip().splitlines()[0])
    return "\n".join(lines)


def _section(heading: str, cls, prefix: str, intro: str = "") -> list:
    """A parameter class's heading, its one-line introduction and its table, names prefixed."""
    lines = [f"{heading} `{cls.name}`: `{cls.__name__}`", ""] + ([intro, ""] if intro else [])
    lines += ["| name | unit | bounds | default | meaning |", "|---|---|---|---|---|"]
    for entry in cls.schema():
        name = prefix + entry["name"].replace(".", "/")
        if entry["type"] == "group":
            lines.append(f"| **`{name}/`** | | | | {entry['doc']} |")
            continue
        lines.append(f"| `{name}` | {entry['unit']} | {bounds_text(entry)} | {default_text(entry)} | {entry['doc']} |")
    return lines + [""]
