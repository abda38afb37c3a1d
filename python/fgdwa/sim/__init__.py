"""The simulator: the world's side of every control cycle. A world (``world``:
the map, what it misses, moving discs, terrain; ``keyframes``: discs moved as
Gazebo animates them), the robot's body between
command and ground (``body``: latency, actuation noise and lag, odometry), the
episode loop that scans, steps the C++ navigator and moves everything
(``episode``), the referee that judges collisions, falls and the metrics
(``referee``), and scenarios with their seeded trials (``scenario``). It never
plans on the robot's behalf: the :class:`fgdwa.Navigator` does.
"""

from fgdwa.sim.body import Body, BodySettings, body_settings, check_seed
from fgdwa.sim.episode import (
    EPISODE_OPTIONS,
    OUTCOMES,
    SCAN_SEED_STRIDE,
    CycleTrace,
    EpisodeOptions,
    EpisodeResult,
    EpisodeSummary,
    Motion,
    NavigationContext,
    PlannerTrace,
    run_episode,
    run_preset,
)
from fgdwa.sim.keyframes import KeyframedMover
from fgdwa.sim.referee import (
    DANGER_MARGIN,
    TURN_RESOLUTION,
    Contact,
    collides_during_step,
    collision_contact,
    danger_point_clearance,
    danger_points,
    falls,
    path_length,
    smoothness,
)
from fgdwa.sim.scenario import (
    PARAM_FIELDS,
    Scenario,
    Variability,
    init_keywords,
    params_with,
    resolve_planner,
    run_scenario,
    scenario_params,
    trial_variation,
)
from fgdwa.sim.world import MOVER_MODES, MovingObstacle, World

__all__ = [
    "Body",
    "BodySettings",
    "Contact",
    "CycleTrace",
    "DANGER_MARGIN",
    "EPISODE_OPTIONS",
    "EpisodeOptions",
    "EpisodeResult",
    "EpisodeSummary",
    "MOVER_MODES",
    "Motion",
    "KeyframedMover",
    "MovingObstacle",
    "NavigationContext",
    "OUTCOMES",
    "PARAM_FIELDS",
    "PlannerTrace",
    "SCAN_SEED_STRIDE",
    "Scenario",
    "TURN_RESOLUTION",
    "Variability",
    "World",
    "body_settings",
    "check_seed",
    "collides_during_step",
    "collision_contact",
    "danger_point_clearance",
    "danger_points",
    "falls",
    "init_keywords",
    "params_with",
    "path_length",
    "resolve_planner",
    "run_episode",
    "run_preset",
    "run_scenario",
    "scenario_params",
    "smoothness",
    "trial_variation",
]
