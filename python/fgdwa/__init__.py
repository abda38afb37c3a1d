"""fgdwa: a dynamic window local planner guided by a global path, with a
trajectory-similarity cost and fuzzy-controlled weights.

The C++ core (``fgdwa._core``) runs every control cycle; this package adds
episodes, scenarios, experiments and figures on top of it.
"""

from fgdwa._core import (
    ClearanceSource,
    CollisionWorld,
    CriticConfig,
    Disc,
    DistanceField,
    FgdwaError,
    FieldClearance,
    Footprint,
    LocalPlanner,
    OccupancyGrid,
    PlannerParams,
    PlanResult,
    Pose2,
    RejectReason,
    RobotLimits,
    RobotState,
    Status,
    Twist,
    VelocityWindow,
    angle_difference,
    critic_names,
    dynamic_window,
    rollout,
    sample_window,
    step,
    wrap_angle,
)

__version__ = "0.1.0"

__all__ = [
    "ClearanceSource",
    "CollisionWorld",
    "CriticConfig",
    "Disc",
    "DistanceField",
    "FgdwaError",
    "FieldClearance",
    "Footprint",
    "LocalPlanner",
    "OccupancyGrid",
    "PlannerParams",
    "PlanResult",
    "Pose2",
    "RejectReason",
    "RobotLimits",
    "RobotState",
    "Status",
    "Twist",
    "VelocityWindow",
    "angle_difference",
    "critic_names",
    "dynamic_window",
    "rollout",
    "sample_window",
    "step",
    "wrap_angle",
]
