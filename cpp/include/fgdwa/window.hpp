#pragma once
// The dynamic window (Eqs. 1-3): the velocities reachable within one control
// period, sampled on a grid, and the admissibility test of a sampled command.
#include <vector>

#include "fgdwa/geometry.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {

struct WindowParams {
  int n_v = 21;      // samples of the linear velocity, both window ends included
  int n_omega = 21;  // samples of the angular velocity, both window ends included
  void validate() const;
};

struct VelocityWindow {
  double v_lo = 0.0, v_hi = 0.0;          // m/s
  double omega_lo = 0.0, omega_hi = 0.0;  // rad/s
  bool contains(const Twist& twist, double tolerance = 1e-9) const;
};

// Vm ∩ Vd for the current velocity. When the current velocity lies so far
// outside the limits that the two do not meet (a state no command of this
// planner produces), the window collapses onto the point of Vd nearest to Vm.
VelocityWindow dynamic_window(const RobotLimits& limits, const Twist& current, double dt);

// n_v x n_omega commands, v-major. The sample nearest to the current velocity
// is moved onto it, and in omega the one nearest to 0 onto 0, so that keeping
// the current command and driving straight are always candidates.
void sample_window(const VelocityWindow& window, const Twist& current, const WindowParams& params,
                   std::vector<Twist>& out);

// Eq. 3: v <= sqrt(2 dist brake_v) and |omega| <= sqrt(2 dist brake_omega), where
// `free_distance` is the arc length travelled before first contact (+inf if none).
bool is_admissible(const Twist& command, double free_distance, const RobotLimits& limits);

// The strongest braking toward (0, 0) that the window allows.
Twist braking_command(const RobotLimits& limits, const Twist& current, double dt);

}  // namespace fgdwa
