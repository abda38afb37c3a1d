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

}  // namespace fgdwa::detail
