"""Whether a scenario can be run: the start and goal free for the footprint and
on the map, the start farther from the goal than the goal tolerance, and a path
between them."""

from __future__ import annotations

import math
from typing import Any


from fgdwa._core import CollisionWorld, FgdwaError, Footprint
from fgdwa.file_limits import clip, short_repr
from fgdwa.io.scenario_maps import Layout
from fgdwa.io.scenario_values import ValueReader
from fgdwa.sim.world import World


class FeasibilityChecks(ValueReader):
    """Checks of a scenario's start, goal and reachability."""

    def inside(self, point, layout: Layout) -> bool:
        x0, x1, y0, y1 = layout.extent
        return x0 <= point[0] < x1 and y0 <= point[1] < y1

    def check_start(self, start: tuple, value: Any, world: World, footprint: Footprint, layout: Layout) -> None:
        if not self.inside(start, layout):
            x0, x1, y0, y1 = layout.extent
            self.fail("start", value, f"off the map (x {x0:g} to {x1:g}, y {y0:g} to {y1:g})")
        if CollisionWorld(world.grid).in_collision(footprint, start):
            self.fail("start", value, f"the robot's footprint ({short_repr(footprint, 120)}) there overlaps an "
                                      f"obstacle of the map")
        if CollisionWorld(world.true_grid()).in_collision(footprint, start):
            self.fail("start", value, f"the robot's footprint ({short_repr(footprint, 120)}) there overlaps an "
                                      f"unknown obstacle")
        if world.grade_at(start[:2]) >= 4:
            self.fail("start", value, "on impassable terrain (grade 4)")

    def check_goal(self, goal: tuple, value: Any, world: World, footprint: Footprint, layout: Layout) -> None:
        if not self.inside(goal, layout):
            x0, x1, y0, y1 = layout.extent
            self.fail("goal", value, f"off the map (x {x0:g} to {x1:g}, y {y0:g} to {y1:g})")
        # The robot may arrive at any heading: the circle it always fills must fit.
        probe = Footprint.circle(footprint.inscribed_radius)
        if CollisionWorld(world.true_grid()).in_collision(probe, (goal[0], goal[1], 0.0)):
            self.fail("goal", value, f"inside an obstacle (a circle of the footprint's inscribed radius "
                                     f"{footprint.inscribed_radius:g} m there overlaps one)")
        if world.grade_at(goal) >= 4:
            self.fail("goal", value, "on impassable terrain (grade 4)")

    def check_not_at_goal(self, start: tuple, goal: tuple, tolerance: float, key: str, value: Any) -> None:
        """A start within the goal tolerance would report every run a success before it moves."""
        distance = math.hypot(goal[0] - start[0], goal[1] - start[1])
        if distance <= tolerance:
            self.fail(key, value, f"the start is {distance:g} m from the goal, within the goal tolerance "
                                  f"{tolerance:g} m: every run would succeed before the robot moves")

    def check_reachable(self, start: tuple, goal: tuple, value: Any, world: World, footprint: Footprint,
                        options: dict) -> None:
        """A* on the map, obstacles inflated as the episode's last resort does (the footprint's radius)."""
        from fgdwa._core import AStarParams
        from fgdwa.global_planning import plan_global

        radius = options.get("inflation_radius", footprint.radius)
        # An OMPL scenario's options that A* shares (its terrain cost).
        shared = {entry["name"] for entry in AStarParams.schema()} - {"inflation_radius"}
        extra = {k: v for k, v in options.items() if k in shared}
        try:
            plan = plan_global(world.grid, start[:2], goal, method="astar", terrain=world.terrain,
                               inflation_radius=radius, **extra)
            found = plan.status.name == "Found"
        except FgdwaError as error:
            self.fail("goal", value, f"the global planner cannot start ({clip(error)})")
        if not found:
            self.fail("goal", value, f"no global path from the start {tuple(round(v, 3) for v in start[:2])} on "
                                     f"the map (A*, obstacles and grade 4 inflated by {radius:g} m): the start or "
                                     f"the goal is walled off or nearer than that to an obstacle")
