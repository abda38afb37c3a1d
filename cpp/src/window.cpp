#include "fgdwa/window.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "admissibility.hpp"
#include "validation.hpp"

namespace fgdwa {

void WindowParams::check_relations(const ParamPath& path) const {
  const long total = static_cast<long>(n_v) * n_omega;
  if (total > limits::kMaxWindowSamples)
    fail_param(path.field("n_v * n_omega"), std::to_string(total), "must be <= " + std::to_string(limits::kMaxWindowSamples));
}

void VelocityWindow::validate() const {
  using limits::kMaxSpeed;
  detail::require_magnitude("window v_lo", v_lo, kMaxSpeed);
  detail::require_magnitude("window v_hi", v_hi, kMaxSpeed);
  detail::require_magnitude("window omega_lo", omega_lo, kMaxSpeed);
  detail::require_magnitude("window omega_hi", omega_hi, kMaxSpeed);
  if (v_lo > v_hi)
    throw Error(detail::describe("window v_lo", v_lo, "must be <= v_hi = " + detail::format_number(v_hi)));
  if (omega_lo > omega_hi)
    throw Error(
        detail::describe("window omega_lo", omega_lo, "must be <= omega_hi = " + detail::format_number(omega_hi)));
}

bool VelocityWindow::contains(const Twist& t, double tol) const {
  return t.v >= v_lo - tol && t.v <= v_hi + tol && t.omega >= omega_lo - tol && t.omega <= omega_hi + tol;
}

namespace {
// [lo, hi] ∩ [a, b], or the end of [lo, hi] nearest to [a, b] when they miss:
// a command is never outside the limits, whatever the robot does now.
void intersect(double lo, double hi, double a, double b, double& out_lo, double& out_hi) {
  out_lo = std::max(lo, a);
  out_hi = std::min(hi, b);
  if (out_lo > out_hi) out_lo = out_hi = (a > hi) ? hi : lo;
}

void linspace(double lo, double hi, int n, std::vector<double>& out) {
  out.resize(static_cast<std::size_t>(n));
  if (n == 1) {
    out[0] = 0.5 * (lo + hi);
    return;
  }
  for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = lo + (hi - lo) * i / (n - 1);
  out.back() = hi;
}

// The interior sample nearest to x (any sample when there are two or fewer), so
// that both window ends stay among the samples.
std::size_t nearest(const std::vector<double>& values, double x, std::size_t skip) {
  std::size_t best = values.size();
  const std::size_t first = values.size() > 2 ? 1 : 0;
  const std::size_t last = values.size() > 2 ? values.size() - 1 : values.size();
  for (std::size_t i = first; i < last; ++i)
    if (i != skip && (best == values.size() || std::abs(values[i] - x) < std::abs(values[best] - x))) best = i;
  return best;
}

void snap(std::vector<double>& values, double x, double lo, double hi, std::size_t skip, std::size_t& snapped) {
  snapped = values.size();
  if (x < lo || x > hi) return;
  if (values.front() == x && skip != 0) {
    snapped = 0;
    return;
  }
  if (values.back() == x && skip != values.size() - 1) {
    snapped = values.size() - 1;
    return;
  }
  snapped = nearest(values, x, skip);
  if (snapped < values.size()) values[snapped] = x;
}
}  // namespace

VelocityWindow dynamic_window(const RobotLimits& limits, const Twist& current, double dt) {
  limits.validate();
  detail::require_twist("current", current);
  detail::require_step_length("dt", dt);
  VelocityWindow w;
  intersect(limits.v_min, limits.v_max, current.v - limits.acc_v * dt, current.v + limits.acc_v * dt, w.v_lo, w.v_hi);
  intersect(-limits.omega_max, limits.omega_max, current.omega - limits.acc_omega * dt,
            current.omega + limits.acc_omega * dt, w.omega_lo, w.omega_hi);
  return w;
}

void sample_window(const VelocityWindow& w, const Twist& current, const WindowParams& params,
                   std::vector<Twist>& out) {
  w.validate();
  detail::require_twist("current", current);
  params.validate();
  thread_local std::vector<double> vs, ws;
  linspace(w.v_lo, w.v_hi, params.n_v, vs);
  linspace(w.omega_lo, w.omega_hi, params.n_omega, ws);
  std::size_t v_index = 0, omega_index = 0, zero_index = 0;
  snap(vs, current.v, w.v_lo, w.v_hi, vs.size(), v_index);
  snap(ws, 0.0, w.omega_lo, w.omega_hi, ws.size(), zero_index);
  if (zero_index == ws.size() || current.omega != 0.0)
    snap(ws, current.omega, w.omega_lo, w.omega_hi, zero_index, omega_index);
  out.resize(vs.size() * ws.size());
  std::size_t k = 0;
  for (double v : vs)
    for (double omega : ws) out[k++] = Twist{v, omega};
}

double stopping_distance(double v, double deceleration, double dt) {
  detail::require_magnitude("v", v, limits::kMaxSpeed);
  detail::require_in_range("deceleration", deceleration, limits::kMinAcceleration, limits::kMaxAcceleration);
  detail::require_time_step("dt", dt);
  return detail::stopping_distance_unchecked(v, deceleration, dt);
}

double detail::stopping_distance_unchecked(double v, double deceleration, double dt) {
  if (v <= 0.0) return 0.0;
  return v * dt + braking_distance(v, deceleration);
}

double detail::braking_distance(double v, double deceleration) { return v * v / (2.0 * deceleration); }

double arc_deceleration(const Twist& command, const RobotLimits& limits) {
  detail::require_twist("command", command);
  limits.validate();
  return detail::arc_deceleration_unchecked(command, limits);
}

double detail::arc_deceleration_unchecked(const Twist& command, const RobotLimits& limits) {
  double b = std::min(limits.acc_v, limits.braking_v());
  const double speed = std::abs(command.v);
  if (command.omega != 0.0 && speed > 0.0)
    b = std::min(b, std::min(limits.acc_omega, limits.braking_omega()) * speed / std::abs(command.omega));
  return b;
}

bool is_admissible(const Twist& command, double free_distance, const RobotLimits& limits, double dt,
                   BrakingModel model) {
  detail::require_twist("command", command);
  if (std::isnan(free_distance) || free_distance < 0.0)
    throw Error(detail::describe("free_distance", free_distance, "must be >= 0 (+inf: no contact)"));
  limits.validate();
  detail::require_time_step("dt", dt);
  return detail::is_admissible_unchecked(command, free_distance, limits, dt, model);
}

bool detail::is_admissible_unchecked(const Twist& command, double free_distance, const RobotLimits& limits, double dt,
                                     BrakingModel model) {
  return is_admissible_unchecked(command, command, std::max(command.v, 0.0) * dt, free_distance, limits, dt, model);
}

bool detail::is_admissible_unchecked(const Twist& command, const Twist& reached, double first_step,
                                     double free_distance, const RobotLimits& limits, double dt, BrakingModel model) {
  (void)dt;
  if (std::isinf(free_distance)) return true;
  const bool v_ok =
      model == BrakingModel::Continuous
          ? command.v <= std::sqrt(2.0 * free_distance * limits.braking_v())
          : first_step + braking_distance(reached.v, arc_deceleration_unchecked(reached, limits)) <= free_distance;
  return v_ok && std::abs(command.omega) <= std::sqrt(2.0 * free_distance * limits.braking_omega());
}

bool is_admissible(const Twist& current, const Twist& command, double free_distance, const RobotLimits& limits,
                   double dt, BrakingModel model) {
  detail::require_twist("current", current);
  detail::require_twist("command", command);
  if (std::isnan(free_distance) || free_distance < 0.0)
    throw Error(detail::describe("free_distance", free_distance, "must be >= 0 (+inf: no contact)"));
  limits.validate();
  detail::require_time_step("dt", dt);
  Twist reached = current;
  const double first = std::abs(ramp_step(reached.v, command.v, limits.acc_v, limits.braking_v(), dt)) * dt;
  ramp_step(reached.omega, command.omega, limits.acc_omega, limits.braking_omega(), dt);
  return detail::is_admissible_unchecked(command, reached, first, free_distance, limits, dt, model);
}

Twist braking_command(const RobotLimits& limits, const Twist& current, double dt) {
  const VelocityWindow w = dynamic_window(limits, current, dt);  // checks the arguments
  // Scale (v, omega) toward (0, 0) as far as the window allows: the robot slows
  // down on the arc it was on, the one its last command was checked along.
  double s = 0.0;
  if (current.v > 0.0) s = std::max({s, 1.0 - limits.acc_v * dt / current.v, limits.v_min / current.v});
  if (current.omega != 0.0) s = std::max(s, 1.0 - limits.acc_omega * dt / std::abs(current.omega));
  s = std::min(s, 1.0);
  return Twist{std::clamp(s * current.v, w.v_lo, w.v_hi), std::clamp(s * current.omega, w.omega_lo, w.omega_hi)};
}

}  // namespace fgdwa
