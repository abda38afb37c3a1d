"""Episodes: a robot driven by a local planner through a world until it
reaches the goal, collides, or runs out of steps (SPEC 9).

The planner sees the world through a fast ``FieldClearance``; the simulator
judges collisions with the exact FCL ``CollisionWorld``.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from fgdwa._core import (
    CollisionWorld,
    Disc,
    DistanceField,
    FgdwaError,
    FieldClearance,
    Footprint,
    GlobalPath,
    GlobalStatus,
    LocalPlanner,
    OccupancyGrid,
    PlannerParams,
    PlanResult,
    RobotLimits,
    RobotState,
    Status,
    step,
)
from fgdwa.global_planning import plan_global

OUTCOMES = ("success", "collision", "timeout")
GLOBAL_PATH_MARGIN = 0.3  # m kept beyond the footprint's radius by the global path where the map allows


@dataclass(frozen=True)
class World:
    """What exists: a static occupancy grid (optional) and moving discs."""

    grid: Optional[OccupancyGrid] = None
    discs: Sequence[Disc] = ()

    def discs_at(self, t: float) -> list:
        """The discs moved ``t`` seconds ahead, velocities kept."""
        return [Disc(d.center_at(t), d.radius, d.velocity) for d in self.discs]


@dataclass
class EpisodeResult:
    """The executed run and its SPEC 9 metrics."""

    outcome: str
    steps: int
    sim_time: float  # s, simulated
    planning_time: float  # s, wall clock spent choosing commands
    mileage: float  # m, length of the executed path
    min_clearance: float  # m, exact (FCL) clearance along the executed path
    mean_clearance: float  # m
    poses: np.ndarray  # (steps + 1, 3) x, y, theta, start included
    commands: np.ndarray  # (steps, 2) v, omega
    clearances: np.ndarray  # (steps + 1,) m
    statuses: list = field(default_factory=list)
    cycle_times: np.ndarray = field(default_factory=lambda: np.zeros(0))  # s, per cycle
    last_plan: Optional[PlanResult] = None
    last_rollouts: Optional[np.ndarray] = None  # (samples, n_steps, 3)
    global_path: Optional[np.ndarray] = None  # (n, 2), when the planner followed one
    key_nodes: Optional[np.ndarray] = None  # (k, 2) key-node positions
    targets: Optional[np.ndarray] = None  # (steps, 2) the heading's target each cycle

    def metrics(self) -> dict:
        """The scalar metrics, as plain Python numbers."""
        return {
            "outcome": self.outcome,
            "steps": self.steps,
            "sim_time": self.sim_time,
            "planning_time": self.planning_time,
            "mileage": self.mileage,
            "min_clearance": self.min_clearance,
            "mean_clearance": self.mean_clearance,
        }


def _as_pose(value, name: str) -> np.ndarray:
    pose = np.asarray(value, dtype=float)
    if pose.shape != (3,) or not np.all(np.isfinite(pose)):
        raise FgdwaError(f"{name}: expected a finite (x, y, theta), got {value!r}")
    return pose


def _as_point(value, name: str) -> np.ndarray:
    point = np.asarray(value, dtype=float)
    if point.shape != (2,) or not np.all(np.isfinite(point)):
        raise FgdwaError(f"{name}: expected a finite (x, y), got {value!r}")
    return point


def path_length(points: np.ndarray) -> float:
    """Length of a polyline given as (n, >=2) points."""
    points = np.asarray(points, dtype=float)
    if len(points) < 2:
        return 0.0
    return float(np.sum(np.hypot(*np.diff(points[:, :2], axis=0).T)))


def collides_during_step(truth: CollisionWorld, footprint: Footprint, before, after, t: float, dt: float,
                         spacing: float = 0.05) -> bool:
    """Whether the footprint touches an obstacle anywhere along one step.

    A step turns first and then moves straight along the new heading, so the
    positions in between lie on the segment from ``before`` to ``after``; they
    are checked every ``spacing`` metres, the discs moving with them.
    """
    x0, y0 = before[0], before[1]
    x1, y1, theta = after[0], after[1], after[2]
    pieces = max(1, int(np.ceil(np.hypot(x1 - x0, y1 - y0) / spacing)))
    for i in range(1, pieces + 1):
        f = i / pieces
        if truth.in_collision(footprint, (x0 + f * (x1 - x0), y0 + f * (y1 - y0), theta), t + f * dt):
            return True
    return False


def run_episode(
    world: World,
    start,
    goal,
    limits: Optional[RobotLimits] = None,
    footprint: Optional[Footprint] = None,
    params: Optional[PlannerParams] = None,
    max_steps: int = 1000,
    goal_tolerance: Optional[float] = None,
    global_path=None,
    global_method: str = "astar",
    global_options: Optional[dict] = None,
) -> EpisodeResult:
    """Drive from ``start`` (x, y, theta, at rest) to ``goal`` (x, y).

    Every cycle the planner picks a command from the current state, the robot
    moves one ``dt`` with it, and the discs move too. The episode ends on
    success (within ``goal_tolerance`` of the goal, default the planner's),
    collision (exact footprint contact anywhere along a step), or ``max_steps``
    cycles (timeout).

    With ``params.heading_target == "key_nodes"`` the planner follows a global
    path: ``global_path`` ((n, 2) points) when given, else one planned once on
    the map by ``plan_global(method=global_method, **global_options)``, with
    obstacles inflated by the footprint's radius plus GLOBAL_PATH_MARGIN (or the
    radius alone where the margin closes every way) unless the options say otherwise.
    """
    limits = limits if limits is not None else RobotLimits()
    footprint = footprint if footprint is not None else Footprint.circle(0.25)
    params = params if params is not None else PlannerParams()
    start_pose = _as_pose(start, "start")
    goal_point = _as_point(goal, "goal")
    if not isinstance(max_steps, (int, np.integer)) or max_steps < 1:
        raise FgdwaError(f"max_steps = {max_steps!r}: must be an integer >= 1")
    tolerance = params.goal_tolerance if goal_tolerance is None else float(goal_tolerance)
    if not np.isfinite(tolerance) or tolerance < 0:
        raise FgdwaError(f"goal_tolerance = {goal_tolerance!r}: must be >= 0")

    truth = CollisionWorld(world.grid, list(world.discs))
    if truth.in_collision(footprint, start_pose, 0.0):
        raise FgdwaError(f"start = {tuple(start_pose)}: the robot's footprint there overlaps an obstacle")
    field_ = DistanceField(world.grid) if world.grid is not None else None
    seen = FieldClearance(field_, list(world.discs))
    planner = LocalPlanner(limits, footprint, params)
    path = _global_path(world, start_pose, goal_point, footprint, params, global_path, global_method, global_options)
    if path is not None:
        planner.set_global_path(path)

    dt = params.dt
    state = RobotState(start_pose, (0.0, 0.0))
    poses = [start_pose.copy()]
    commands = []
    clearances = [truth.clearance(footprint, start_pose, 0.0)]
    statuses = []
    cycle_times = []
    targets = []
    outcome = "timeout"
    last_plan = None
    last_rollouts = None
    for k in range(max_steps):
        position = np.array([state.pose.x, state.pose.y])
        if np.hypot(*(position - goal_point)) <= tolerance:
            outcome = "success"
            break
        t = k * dt
        seen.discs = world.discs_at(t)
        tic = time.perf_counter()
        plan = planner.plan(state, goal_point, seen)
        cycle_times.append(time.perf_counter() - tic)
        last_plan = plan
        last_rollouts = planner.rollouts()
        statuses.append(plan.status.name)
        targets.append(plan.target)
        command = plan.command
        pose = step(state.pose, command, dt)
        state = RobotState(pose, command)
        commands.append((command.v, command.omega))
        poses.append(np.array([pose.x, pose.y, pose.theta]))
        clearances.append(truth.clearance(footprint, pose, t + dt))
        if collides_during_step(truth, footprint, poses[-2], poses[-1], t, dt):
            outcome = "collision"
            break
    else:
        position = np.array([state.pose.x, state.pose.y])
        if np.hypot(*(position - goal_point)) <= tolerance:
            outcome = "success"

    poses_arr = np.array(poses)
    clear_arr = np.array(clearances, dtype=float)
    finite = clear_arr[np.isfinite(clear_arr)]
    steps = len(commands)
    return EpisodeResult(
        outcome=outcome,
        steps=steps,
        sim_time=steps * dt,
        planning_time=float(np.sum(cycle_times)),
        mileage=path_length(poses_arr),
        min_clearance=float(np.min(clear_arr)) if len(clear_arr) else float("inf"),
        mean_clearance=float(np.mean(finite)) if len(finite) else float("inf"),
        poses=poses_arr,
        commands=np.array(commands, dtype=float).reshape(-1, 2),
        clearances=clear_arr,
        statuses=statuses,
        cycle_times=np.array(cycle_times),
        last_plan=last_plan,
        last_rollouts=last_rollouts,
        global_path=None if path is None else path.points,
        key_nodes=None if path is None else path.points[planner.key_nodes],
        targets=np.array(targets, dtype=float).reshape(-1, 2),
    )


def _global_path(world: World, start, goal, footprint: Footprint, params: PlannerParams, given, method: str,
                 options: Optional[dict]) -> Optional[GlobalPath]:
    if given is not None:
        return given if isinstance(given, GlobalPath) else GlobalPath(np.asarray(given, dtype=float))
    if params.heading_target != "key_nodes":
        return None
    if world.grid is None:
        raise FgdwaError("heading_target = key_nodes needs a global path: give global_path or a world with a grid")
    options = dict(options or {})
    if method.startswith("ompl:"):
        options.setdefault("footprint", footprint)
    # A path that keeps a margin beyond the footprint gives the local planner
    # room at the corners where key nodes sit; where the margin closes every
    # passage, the footprint's radius alone decides.
    radii = [options.pop("inflation_radius")] if "inflation_radius" in options else \
        [footprint.radius + GLOBAL_PATH_MARGIN, footprint.radius]
    for radius in radii:
        plan = plan_global(world.grid, start[:2], goal, method=method, inflation_radius=radius, **options)
        if plan.status == GlobalStatus.Found:
            break
    if plan.status != GlobalStatus.Found:
        raise FgdwaError(f"global planner {method}: no path from start to goal ({plan.status.name})")
    return GlobalPath(plan.path)
