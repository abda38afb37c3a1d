#pragma once
// The dynamic window (Eqs. 1-3): the velocities reachable within one control
// period, sampled on a grid, and the admissibility test of a sampled command.
#include <cstdint>
#include <vector>

#include "fgdwa/geometry.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {

struct WindowParams {
  int n_v = 21;
  int n_omega = 21;

  static constexpr const char* kName = "window";
  template <class V>
  static void fields(V& v) {
    const Bounds samples = Bounds::closed(1, limits::kMaxWindowSamplesPerAxis);
    v.integer("n_v", &WindowParams::n_v, "", samples, "samples of the linear velocity, both window ends included");
    v.integer("n_omega", &WindowParams::n_omega, "", samples, "samples of the angular velocity, both window ends included");
  }
  // n_v * n_omega <= limits::kMaxWindowSamples.
  void check_relations(const ParamPath& path) const;
  void validate() const { validate_params(*this); }
};

struct VelocityWindow {
  double v_lo = 0.0, v_hi = 0.0;          // m/s
  double omega_lo = 0.0, omega_hi = 0.0;  // rad/s
  bool contains(const Twist& twist, double tolerance = 1e-9) const;
  // Throws fgdwa::Error unless every end is finite, within limits::kMaxSpeed
  // and lo <= hi.
  void validate() const;
};

// Vm ∩ Vd for the current velocity, always inside the limits. When the
// current velocity lies so far outside them that the two do not meet (a
// state no command of this planner produces: a push, a slope, a bad report),
// the window collapses onto the point of Vm nearest to Vd; the rollouts then
// brake from the state toward it at the limits.
VelocityWindow dynamic_window(const RobotLimits& limits, const Twist& current, double dt);

// n_v x n_omega commands, v-major. The interior sample nearest to the current
// velocity is moved onto it, and in omega the one nearest to 0 onto 0, so that
// keeping the current command and driving straight are always candidates while
// both window ends stay among the samples.
void sample_window(const VelocityWindow& window, const Twist& current, const WindowParams& params,
                   std::vector<Twist>& out);

// How the linear-velocity half of Eq. 3 counts the distance needed to stop.
enum class BrakingModel : std::uint8_t {
  // Eq. 3 as written: v <= sqrt(2 dist brake_v), braking starting at once and
  // continuously.
  Continuous,
  // The robot follows the rollout for one control period (its wheels ramping
  // from the measured twist toward the command), then slows down on the same
  // arc as the window lets it (braking_command): its wheels ramp down at
  // b = min(acc_v, brake_v, acc_omega v / |omega|), covering v^2 / (2 b).
  // The first period's travel plus that must fit in dist. Without the period
  // of latency, Eq. 3 admits commands that cannot stop in time.
  Discrete,
};
const char* to_string(BrakingModel braking);
constexpr std::array<BrakingModel, 2> enum_values(BrakingModel) { return {BrakingModel::Discrete, BrakingModel::Continuous}; }

// Distance covered by the Discrete model from a robot already at speed v:
// v dt + v^2 / (2 b), 0 for v <= 0.
double stopping_distance(double v, double deceleration, double dt);

// Eq. 3: the v condition per the braking model, and |omega| <= sqrt(2 dist brake_omega),
// where `free_distance` is the arc length travelled before first contact (+inf if none),
// for a robot already moving at `command`.
bool is_admissible(const Twist& command, double free_distance, const RobotLimits& limits, double dt,
                   BrakingModel model = BrakingModel::Discrete);
// The same for a robot moving at `current`: its first period ramps toward
// the command (ramp_step), and the braking starts from where that leaves it.
bool is_admissible(const Twist& current, const Twist& command, double free_distance, const RobotLimits& limits,
                   double dt, BrakingModel model = BrakingModel::Discrete);

// Deceleration along the command's arc when v and omega shrink together, as
// braking_command shrinks them: min(acc_v, brake_v, min(acc_omega, brake_omega) v / |omega|).
double arc_deceleration(const Twist& command, const RobotLimits& limits);

// The strongest braking toward (0, 0) that the window allows: (v, omega) scaled
// down together, so the robot keeps to its arc while it slows.
Twist braking_command(const RobotLimits& limits, const Twist& current, double dt);

}  // namespace fgdwa
