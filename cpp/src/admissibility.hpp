#pragma once
// The admissibility test (Eq. 3) without its entry checks: the planner runs it
// for every sample of a cycle whose inputs it checked once.
#include "fgdwa/robot.hpp"
#include "fgdwa/window.hpp"

namespace fgdwa::detail {

double stopping_distance_unchecked(double v, double deceleration, double dt);
double arc_deceleration_unchecked(const Twist& command, const RobotLimits& limits);
bool is_admissible_unchecked(const Twist& command, double free_distance, const RobotLimits& limits, double dt,
                             BrakingModel model);
// The test for a rollout whose first period covers `first_step` (m) and ends at `reached`.
bool is_admissible_unchecked(const Twist& command, const Twist& reached, double first_step, double free_distance,
                             const RobotLimits& limits, double dt, BrakingModel model);
// Wheels ramping down from speed |v| at `deceleration` cover v^2 / (2 deceleration).
double braking_distance(double v, double deceleration);

}  // namespace fgdwa::detail
