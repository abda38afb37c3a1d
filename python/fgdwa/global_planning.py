"""One entry point for the global planners: grid A* and OMPL's planners."""

from __future__ import annotations

from typing import Optional

from fgdwa._core import AStarPlanner, FgdwaError, Footprint, GlobalPlan, OccupancyGrid, OmplPlanner, TerrainGrid

_ASTAR_OPTIONS = {"inflation_radius", "simplify", "terrain", "w_risk", "risk"}
_OMPL_OPTIONS = {"footprint", "time_limit", "range", "max_iterations", "seed", "inflation_radius", "w_length", "w_clearance",
                 "clearance_reference", "terrain", "w_risk", "risk", "simplify", "interpolation", "verbose"}


def global_methods() -> list:
    """The names ``plan_global`` accepts."""
    return ["astar"] + [f"ompl:{name}" for name in OmplPlanner.planner_names()]


def plan_global(grid: OccupancyGrid, start, goal, method: str = "astar",
                terrain: Optional[TerrainGrid] = None, **options) -> GlobalPlan:
    """Plans a path on ``grid`` from ``start`` to ``goal`` (x, y in metres).

    ``method`` is ``"astar"`` or ``"ompl:NAME"`` with NAME one of RRTstar,
    InformedRRTstar, PRMstar, BITstar, RRTConnect. Options go to the planner:
    A*: inflation_radius, simplify, w_risk, risk; OMPL: footprint, time_limit,
    range, max_iterations, seed (the same seed repeats a path when
    max_iterations, not the time limit, ends the search), inflation_radius, w_length, w_clearance, clearance_reference,
    w_risk, risk, simplify, interpolation, verbose. No path is a status in the
    result; a start or goal inside an obstacle raises FgdwaError.
    """
    if method == "astar":
        unknown = set(options) - _ASTAR_OPTIONS
        if unknown:
            raise FgdwaError(f"plan_global: option(s) {sorted(unknown)} do not apply to astar "
                             f"(known: {sorted(_ASTAR_OPTIONS - {'terrain'})})")
        return AStarPlanner(grid, terrain=terrain, **options).plan(start, goal)
    if isinstance(method, str) and method.startswith("ompl:"):
        unknown = set(options) - _OMPL_OPTIONS
        if unknown:
            raise FgdwaError(f"plan_global: option(s) {sorted(unknown)} do not apply to OMPL "
                             f"(known: {sorted(_OMPL_OPTIONS - {'terrain'})})")
        footprint = options.pop("footprint", Footprint.circle(0.25))
        return OmplPlanner(grid, footprint, planner=method[len("ompl:"):], terrain=terrain, **options).plan(start, goal)
    raise FgdwaError(f"method = {method!r}: expected one of {global_methods()}")
