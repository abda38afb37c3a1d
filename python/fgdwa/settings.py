"""Parameters changed by name on the command line (``--set planner/sim_time=1.5``,
``--set navigator/tracker/hypothesis_time=0.5``): the schema's names, as
docs/parameters.md lists them and the ROS node takes them, values read as JSON."""

from __future__ import annotations

import json
from typing import Dict, Sequence, Tuple

from fgdwa._core import FgdwaError, NavigatorParams, PlannerParams
from fgdwa.file_limits import short_repr

# The parameter sets a benchmark run may have changed, by the name their settings start with.
BENCHMARK_GROUPS = {"planner": PlannerParams, "navigator": NavigatorParams}

Settings = Tuple[Tuple[str, object], ...]


def parse_overrides(items: Sequence[str]) -> Dict[str, object]:
    """``NAME=VALUE`` pairs, values read as JSON (numbers, true/false, strings in quotes)."""
    out = {}
    for item in items:
        if not isinstance(item, str) or "=" not in item:
            raise FgdwaError(f"--set {short_repr(item)}: expected NAME=VALUE, e.g. planner/sim_time=1.5")
        name, text = item.split("=", 1)
        try:
            out[name.strip()] = json.loads(text)
        except json.JSONDecodeError:
            out[name.strip()] = text
    return out


def benchmark_settings(items: Sequence[str]) -> Settings:
    """The ``--set`` items of a benchmark command, each checked on its parameter
    set's defaults so that a wrong name or value stops the command before its runs."""
    settings = tuple(parse_overrides(items or []).items())
    for name, value in settings:
        group, _, rest = name.partition("/")
        if group not in BENCHMARK_GROUPS or not rest:
            raise FgdwaError(f"--set {name}: a benchmark run's settings start with "
                             f"{' or '.join(g + '/' for g in BENCHMARK_GROUPS)} (docs/parameters.md lists them)")
        try:
            params = BENCHMARK_GROUPS[group]()
            params.set(rest.replace("/", "."), value)
            params.validate()
        except FgdwaError as error:
            raise FgdwaError(f"--set {name}={short_repr(value)}: {error}") from None
    return settings


def group_settings(settings: Settings, group: str) -> Dict[str, object]:
    """The settings of one parameter set, by their dotted names within it ({"tracker.hypothesis_time": 0.5})."""
    prefix = group + "/"
    return {name[len(prefix):].replace("/", "."): value for name, value in settings if name.startswith(prefix)}


def describe_settings(settings: Settings) -> str:
    """The settings as the command line gives them ('' for none)."""
    return "".join(f" --set {name}={json.dumps(value)}" for name, value in settings)
