"""One entry point for the global planners: grid A* and OMPL's planners."""

from __future__ import annotations

from typing import Optional

from fgdwa._core import (AStarParams, AStarPlanner, FgdwaError, Footprint, GlobalPlan, OccupancyGrid, OmplParams,
                         OmplPlanner, TerrainGrid)
from fgdwa.file_limits import short_repr


def global_methods() -> list:
    """The names ``plan_global`` accepts."""
    return ["astar"] + [f"ompl:{name}" for name in OmplPlanner.planner_names()]


def method_params(method: str):
    """The parameter class of a method's planner: AStarParams or OmplParams."""
    if method == "astar":
        return AStarParams
    if isinstance(method, str) and method.startswith("ompl:"):
        return OmplParams
    raise FgdwaError(f"method = {short_repr(method)}: expected one of {global_methods()}")


def plan_global(grid: OccupancyGrid, start, goal, method: str = "astar",
                terrain: Optional[TerrainGrid] = None, footprint: Optional[Footprint] = None,
                **options) -> GlobalPlan:
    """Plans a path on ``grid`` from ``start`` to ``goal`` (x, y in metres).

    ``method`` is ``"astar"`` or ``"ompl:NAME"`` with NAME one of RRTstar,
    InformedRRTstar, PRMstar, BITstar, RRTConnect. ``options`` are the fields of
    the method's parameters (AStarParams or OmplParams, docs/parameters.md):
    ``inflation_radius=0.3``, ``terrain_cost={"w_risk": 2.0}``, OMPL's
    ``time_limit``, ``max_iterations`` and ``seed`` (the same seed repeats a
    path when max_iterations, not the time limit, ends the search), ...
    ``footprint`` (OMPL; a 0.25 m circle without one). No path is a status in
    the result; a start or goal inside an obstacle raises FgdwaError.
    """
    if method_params(method) is AStarParams:
        if footprint is not None:
            raise FgdwaError("plan_global: footprint does not apply to astar (its inflation_radius stands for it)")
        return AStarPlanner(grid, terrain=terrain, **options).plan(start, goal)
    if "planner" in options:
        raise FgdwaError(f"plan_global: the OMPL planner is named by method ({short_repr(method)}), not by a planner option")
    footprint = footprint if footprint is not None else Footprint.circle(0.25)
    return OmplPlanner(grid, footprint, terrain=terrain, planner=method[len("ompl:"):], **options).plan(start, goal)
