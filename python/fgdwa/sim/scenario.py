"""A scenario: a world, a robot, a task and how trials of it vary (docs/algorithms.md, "Experiments E1-E3").

``run_scenario(scenario, planner, seed)`` runs one trial: the seed draws the
start's jitter, the moving obstacles' phases, the lidar's noise and dropped beams (and any actuation noise or
odometry drift asked of ``run_episode``), so the same
seed gives the same episode, bit for bit.
"""

from __future__ import annotations

import copy
import dataclasses
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from fgdwa._core import (
    DetectWindowParams,
    FgdwaError,
    Footprint,
    LidarParams,
    PlannerParams,
    PlannerPreset,
    RobotLimits,
    planner_preset,
)
from fgdwa.sim.body import check_seed
from fgdwa.sim.episode import EpisodeResult, run_episode
from fgdwa.sim.world import World
from fgdwa.file_limits import short_repr

def init_keywords(cls) -> tuple:
    """The top-level fields of a parameter class, in declaration order, from its
    schema (declared once, in C++)."""
    return tuple(entry["name"] for entry in cls.schema() if "." not in entry["name"])


# PlannerParams' fields, each a keyword of its constructor and a readable attribute.
PARAM_FIELDS = init_keywords(PlannerParams)


@dataclass(frozen=True)
class Variability:
    """How trials of a scenario differ; each draw comes from the trial's seed."""

    start_xy_std: float = 0.05  # m, Gaussian jitter of the start position
    start_theta_std: float = 0.05  # rad, Gaussian jitter of the start heading
    mover_phase: bool = True  # start each moving obstacle at a random point of its route
    lidar_noise_std: float = 0.03  # m, Gaussian range noise of every beam's hit
    lidar_dropout: float = 0.01  # probability that a beam returns nothing (reads +inf)

    def __post_init__(self):
        for name in ("start_xy_std", "start_theta_std", "lidar_noise_std", "lidar_dropout"):
            value = getattr(self, name)
            if not (np.isfinite(value) and value >= 0):
                raise FgdwaError(f"variability {name} = {short_repr(value)}: must be a finite number >= 0")
        if self.lidar_dropout >= 1:
            raise FgdwaError(f"variability lidar_dropout = {short_repr(self.lidar_dropout)}: must be < 1 (a probability)")


@dataclass(frozen=True)
class Scenario:
    name: str
    world: World
    start: tuple  # (x, y, theta)
    goal: tuple  # (x, y)
    description: str = ""
    limits: RobotLimits = field(default_factory=RobotLimits)
    footprint: Footprint = field(default_factory=lambda: Footprint.circle(0.25))
    outline: Optional[Footprint] = None  # the body the referee judges; None: the footprint
    planner: str = "fgdwa"  # the preset run when none is named
    overrides: dict = field(default_factory=dict)  # PlannerParams fields replacing the preset's
    global_method: str = "astar"
    global_options: dict = field(default_factory=dict)
    lidar: LidarParams = field(default_factory=LidarParams)
    window: DetectWindowParams = field(default_factory=DetectWindowParams)
    variability: Variability = field(default_factory=Variability)
    max_steps: int = 1500
    goal_tolerance: Optional[float] = None  # m; default the planner's

    def __post_init__(self):
        # Names and each value's bounds: the rules between fields are the
        # preset's with the overrides on top, checked when a planner is built.
        probe = PlannerParams()
        try:
            for name, value in self.overrides.items():
                probe.set(name, value)
        except FgdwaError as error:
            raise FgdwaError(f"scenario {self.name}: planner overrides: {error}") from None


def params_with(params, **overrides):
    """A copy of a parameter set with some fields replaced: names as its attributes,
    nested ones dotted (``"window.n_v"``) or as dicts; checked as a whole."""
    out = copy.copy(params)
    for name, value in overrides.items():
        out.set(name, value)
    out.validate()
    return out


def resolve_planner(scenario: Scenario, planner=None) -> PlannerPreset:
    """The preset to run: ``planner`` (a name or a PlannerPreset) or the scenario's."""
    if isinstance(planner, PlannerPreset):
        return planner
    return planner_preset(planner or scenario.planner)


def scenario_params(scenario: Scenario, planner=None) -> tuple:
    """(preset, planner parameters) of ``planner`` on ``scenario``: the preset's
    parameters with the scenario's overrides."""
    preset = resolve_planner(scenario, planner)
    params = params_with(preset.params, **scenario.overrides) if scenario.overrides else preset.params
    return preset, params


def trial_variation(scenario: Scenario, seed: int) -> tuple:
    """(start pose, world, lidar) of one trial: the seed's draws applied to the scenario."""
    rng = np.random.default_rng(check_seed(seed))
    v = scenario.variability
    start = np.asarray(scenario.start, dtype=float) + np.array(
        [rng.normal(0, v.start_xy_std), rng.normal(0, v.start_xy_std), rng.normal(0, v.start_theta_std)])
    world = scenario.world
    if v.mover_phase and world.movers:
        movers = [dataclasses.replace(m, phase=m.phase + float(rng.uniform(0.0, m.period)))
                  for m in world.movers]
        world = dataclasses.replace(world, movers=tuple(movers))
    lidar = scenario.lidar
    if v.lidar_noise_std > 0 or v.lidar_dropout > 0:
        lidar = params_with(lidar, noise_std=v.lidar_noise_std or lidar.noise_std,
                            dropout=v.lidar_dropout or lidar.dropout)
    return start, world, lidar


def run_scenario(scenario: Scenario, planner=None, seed: int = 0, **kwargs) -> EpisodeResult:
    """One trial of ``scenario`` with a named planner (default the scenario's).

    Every planner senses with the scenario's lidar (obstacles missing from the
    map and moving ones reach it only that way); a fuzzy preset also reads its
    weights from the scan. Keyword arguments go to ``run_episode``.
    """
    preset, params = scenario_params(scenario, planner)
    start, world, lidar = trial_variation(scenario, seed)
    options = dict(global_method=scenario.global_method, global_options=dict(scenario.global_options),
                   max_steps=scenario.max_steps, goal_tolerance=scenario.goal_tolerance, window=scenario.window)
    options.update(kwargs)
    options.setdefault("outline", scenario.outline)
    return run_episode(world, start, scenario.goal, limits=scenario.limits, footprint=scenario.footprint,
                       params=params, lidar=lidar, weight_policy=preset.weight_policy(), seed=seed, **options)
