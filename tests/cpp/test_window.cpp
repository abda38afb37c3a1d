#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fgdwa/window.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

RobotLimits random_limits(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RobotLimits l;
  l.v_min = u(rng) < 0.5 ? 0.0 : 0.3 * u(rng);
  l.v_max = l.v_min + 0.1 + 2.0 * u(rng);
  l.omega_max = 0.1 + 3.0 * u(rng);
  l.acc_v = 0.05 + 3.0 * u(rng);
  l.acc_omega = 0.05 + 5.0 * u(rng);
  l.validate();
  return l;
}

Twist random_twist_within(std::mt19937& rng, const RobotLimits& l) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Twist t{l.v_min + (l.v_max - l.v_min) * u(rng), l.omega_max * (2.0 * u(rng) - 1.0)};
  // The ends of the range are where clipping matters most.
  if (u(rng) < 0.1) t.v = u(rng) < 0.5 ? l.v_min : l.v_max;
  if (u(rng) < 0.1) t.omega = u(rng) < 0.5 ? -l.omega_max : l.omega_max;
  if (u(rng) < 0.1) t.omega = 0.0;
  return t;
}

bool in_vm_and_vd(const Twist& s, const RobotLimits& l, const Twist& c, double dt, double tol = 1e-9) {
  return s.v >= l.v_min - tol && s.v <= l.v_max + tol && std::abs(s.omega) <= l.omega_max + tol &&
         std::abs(s.v - c.v) <= l.acc_v * dt + tol && std::abs(s.omega - c.omega) <= l.acc_omega * dt + tol;
}

TEST(Window, EverySampleLiesInsideVmAndVd) {
  std::vector<Twist> samples;
  std::uniform_int_distribution<int> count(1, 25);
  std::uniform_real_distribution<double> dts(0.02, 0.5);
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    for (int trial = 0; trial < 100; ++trial) {
      const RobotLimits limits = random_limits(rng);
      const Twist current = random_twist_within(rng, limits);
      const double dt = dts(rng);
      WindowParams params;
      params.n_v = count(rng);
      params.n_omega = count(rng);
      const VelocityWindow w = dynamic_window(limits, current, dt);
      sample_window(w, current, params, samples);
      SCOPED_TRACE(::testing::Message() << "seed " << seed << " trial " << trial << " v " << current.v << " omega "
                                        << current.omega << " n " << params.n_v << "x" << params.n_omega);
      ASSERT_EQ(samples.size(), static_cast<std::size_t>(params.n_v * params.n_omega));
      for (const Twist& s : samples) {
        ASSERT_TRUE(in_vm_and_vd(s, limits, current, dt)) << s.v << ", " << s.omega;
        ASSERT_TRUE(w.contains(s));
      }
      // v-major: the first n_omega samples share the first speed.
      for (int i = 0; i < params.n_v; ++i)
        for (int j = 0; j < params.n_omega; ++j)
          ASSERT_EQ(samples[static_cast<std::size_t>(i * params.n_omega + j)].v, samples[i * params.n_omega].v);
      const auto has = [&](auto pred) { return std::any_of(samples.begin(), samples.end(), pred); };
      // The current speed is always inside the window for a state within the limits.
      ASSERT_TRUE(has([&](const Twist& s) { return s.v == current.v; }));
      if (w.omega_lo <= 0.0 && 0.0 <= w.omega_hi) {
        ASSERT_TRUE(has([](const Twist& s) { return s.omega == 0.0; }));
      }
      // Keeping the current command: omega = 0 takes one interior slot, so with
      // three samples (one interior) the current omega fits only as 0 or an end.
      const bool omega_at_end_or_zero =
          current.omega == 0.0 || current.omega == w.omega_lo || current.omega == w.omega_hi;
      if (params.n_omega >= 2 && (params.n_omega != 3 || omega_at_end_or_zero)) {
        ASSERT_TRUE(has([&](const Twist& s) { return s.v == current.v && s.omega == current.omega; }));
      }
      // Both ends of the window are among the samples once there are three or more.
      if (params.n_v >= 3) {
        ASSERT_TRUE(has([&](const Twist& s) { return s.v == w.v_lo; }));
        ASSERT_TRUE(has([&](const Twist& s) { return s.v == w.v_hi; }));
      }
      if (params.n_omega >= 3) {
        ASSERT_TRUE(has([&](const Twist& s) { return s.omega == w.omega_lo; }));
        ASSERT_TRUE(has([&](const Twist& s) { return s.omega == w.omega_hi; }));
      }
    }
  }
}

TEST(Window, WindowIsTheIntersectionOfLimitsAndReachableVelocities) {
  RobotLimits limits;  // v in [0, 1.2], |omega| <= 1, acc 1 and 2
  const VelocityWindow w = dynamic_window(limits, Twist{1.1, -0.9}, 0.15);
  EXPECT_NEAR(w.v_lo, 0.95, 1e-12);
  EXPECT_NEAR(w.v_hi, 1.2, 1e-12);
  EXPECT_NEAR(w.omega_lo, -1.0, 1e-12);
  EXPECT_NEAR(w.omega_hi, -0.6, 1e-12);
  // A speed beyond what any command could produce: the window is the point of
  // the limits nearest to what is reachable, never outside them.
  const VelocityWindow far = dynamic_window(limits, Twist{2.0, 0.0}, 0.15);
  EXPECT_EQ(far.v_lo, limits.v_max);
  EXPECT_EQ(far.v_lo, far.v_hi);
  const VelocityWindow reversing = dynamic_window(limits, Twist{-1.0, 10.0}, 0.15);
  EXPECT_EQ(reversing.v_lo, limits.v_min);
  EXPECT_EQ(reversing.v_hi, limits.v_min);
  EXPECT_EQ(reversing.omega_lo, limits.omega_max);
  EXPECT_EQ(reversing.omega_hi, limits.omega_max);
  const VelocityWindow spinning = dynamic_window(limits, Twist{5.0, -10.0}, 0.15);
  EXPECT_EQ(spinning.v_hi, limits.v_max);
  EXPECT_EQ(spinning.omega_lo, -limits.omega_max);
}

TEST(Window, BrakingCommandSlowsDownAlongTheSameArc) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const RobotLimits limits = random_limits(rng);
    const Twist current = random_twist_within(rng, limits);
    const double dt = 0.02 + 0.4 * u(rng);
    const VelocityWindow w = dynamic_window(limits, current, dt);
    const Twist b = braking_command(limits, current, dt);
    ASSERT_TRUE(w.contains(b, 0.0));
    ASSERT_TRUE(in_vm_and_vd(b, limits, current, dt));
    // b = s (v, omega): the same curvature, and no smaller s stays in the window.
    const double s = current.v > 0.0 ? b.v / current.v : (current.omega != 0.0 ? b.omega / current.omega : 0.0);
    ASSERT_GE(s, 0.0);
    ASSERT_LE(s, 1.0 + 1e-12);
    ASSERT_NEAR(b.v, s * current.v, 1e-12);
    ASSERT_NEAR(b.omega, s * current.omega, 1e-12);
    if (s > 1e-9) {
      const Twist slower{(s - 1e-6) * current.v, (s - 1e-6) * current.omega};
      ASSERT_FALSE(w.contains(slower, 0.0) && slower.v >= limits.v_min);
    }
  }
  RobotLimits limits;
  const Twist b = braking_command(limits, Twist{1.0, 0.5}, 0.15);  // v binds: s = 1 - 0.15 / 1.0
  EXPECT_NEAR(b.v, 0.85, 1e-12);
  EXPECT_NEAR(b.omega, 0.425, 1e-12);
  const Twist turning = braking_command(limits, Twist{0.2, 0.9}, 0.15);  // omega binds: s = 1 - 0.3 / 0.9
  EXPECT_NEAR(turning.v, 0.2 * (2.0 / 3.0), 1e-12);
  EXPECT_NEAR(turning.omega, 0.6, 1e-12);
  const Twist stop = braking_command(limits, Twist{0.1, -0.1}, 0.15);
  EXPECT_EQ(stop.v, 0.0);
  EXPECT_EQ(stop.omega, 0.0);
}

TEST(Window, SampleCountsMustBePositive) {
  WindowParams params;
  params.n_v = 0;
  test::expect_error_naming([&] { params.validate(); }, "n_v");
  params.n_v = 3;
  params.n_omega = -2;
  test::expect_error_naming([&] { params.validate(); }, "n_omega");
}

// Eq. 3 as written: both the speed and the turn rate must be able to stop within dist.
TEST(Window, ContinuousAdmissibilityIsEquationThree) {
  RobotLimits limits;  // braking 1 m/s^2 and 2 rad/s^2
  const double dt = 0.15;
  const auto ok = [&](Twist t, double d) { return is_admissible(t, d, limits, dt, BrakingModel::Continuous); };
  EXPECT_TRUE(ok(Twist{1.2, 1.0}, test::kInf));
  EXPECT_TRUE(ok(Twist{1.0, 0.0}, 0.5));  // 1.0 <= sqrt(2 * 0.5 * 1)
  EXPECT_FALSE(ok(Twist{1.0 + 1e-9, 0.0}, 0.5));
  EXPECT_TRUE(ok(Twist{0.1, -2.0}, 1.0));  // |omega| 2 <= sqrt(2 * 1 * 2)
  EXPECT_FALSE(ok(Twist{0.1, -2.0 - 1e-9}, 1.0));
  EXPECT_TRUE(ok(Twist{0.0, 0.0}, 0.0));
  EXPECT_FALSE(ok(Twist{0.01, 0.0}, 0.0));
  limits.brake_v = 4.0;  // harder braking admits more speed
  EXPECT_TRUE(ok(Twist{2.0, 0.0}, 0.5));
}

// The discrete model: one period at the command, then wheels ramping down at
// min(acc_v, brake_v), period by period as braking_command asks.
TEST(Window, DiscreteStoppingDistanceRampsDownAfterOnePeriod) {
  EXPECT_EQ(stopping_distance(0.0, 1.0, 0.15), 0.0);
  EXPECT_NEAR(stopping_distance(1.0, 1.0, 0.15), 0.15 + 0.5, 1e-12);
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> speed(0.0, 2.0), decel(0.1, 3.0), dts(0.02, 0.5);
  for (int i = 0; i < 2000; ++i) {
    const double v = speed(rng), b = decel(rng), dt = dts(rng);
    // Wheels that ramp toward a command b dt lower each period, moving with the ramp's mean.
    double ramped = v * dt, wheels = v;
    for (int period = 0; period < 100000 && wheels > 0.0; ++period) {
      const double command = std::max(wheels - b * dt, 0.0);
      ramped += ramp_step(wheels, command, b, b, dt) * dt;
    }
    ASSERT_NEAR(stopping_distance(v, b, dt), ramped, 1e-9);
    // Never shorter than wheels that jump to each command at the period's start.
    double stepped = 0.0;
    for (double u = v; u > 0.0; u -= b * dt) stepped += u * dt;
    ASSERT_GE(stopping_distance(v, b, dt), stepped - 1e-12);
  }
  RobotLimits limits;
  const double d = stopping_distance(1.0, 1.0, 0.15);
  EXPECT_TRUE(is_admissible(Twist{1.0, 0.0}, d, limits, 0.15));  // the default model
  EXPECT_FALSE(is_admissible(Twist{1.0, 0.0}, d - 1e-9, limits, 0.15, BrakingModel::Discrete));
  EXPECT_TRUE(is_admissible(Twist{1.0, 0.0}, 0.5, limits, 0.15, BrakingModel::Continuous));
  EXPECT_FALSE(is_admissible(Twist{1.0, 0.0}, 0.5, limits, 0.15, BrakingModel::Discrete));
  // A weaker acceleration than braking: the window can only slow by acc_v dt per period.
  limits.acc_v = 0.5;
  limits.brake_v = 2.0;
  EXPECT_FALSE(is_admissible(Twist{1.0, 0.0}, d, limits, 0.15));
  EXPECT_TRUE(is_admissible(Twist{1.0, 0.0}, stopping_distance(1.0, 0.5, 0.15), limits, 0.15));
}

// From a robot moving otherwise, the first period ramps toward the command:
// speeding up it covers less than the command's v dt, slowing down more.
TEST(Window, AdmissibilityCountsTheFirstPeriodsRamp) {
  const RobotLimits limits;  // acc_v 1
  const double dt = 0.15;
  const Twist command{1.0, 0.0};
  const double steady = stopping_distance(1.0, 1.0, dt);
  const double from_slower = (0.85 + 1.0) / 2 * dt + 0.5;  // ramp 0.85 -> 1.0, then braking from 1.0
  EXPECT_TRUE(is_admissible(Twist{0.85, 0.0}, command, from_slower, limits, dt));
  EXPECT_FALSE(is_admissible(Twist{0.85, 0.0}, command, from_slower - 1e-9, limits, dt));
  EXPECT_LT(from_slower, steady);
  EXPECT_TRUE(is_admissible(command, command, steady, limits, dt));
  // A state beyond the limits: the first period brakes from it and ends above the command.
  const double from_faster = (2.0 + 1.85) / 2 * dt + 1.85 * 1.85 / 2;
  EXPECT_TRUE(is_admissible(Twist{2.0, 0.0}, command, from_faster, limits, dt));
  EXPECT_FALSE(is_admissible(Twist{2.0, 0.0}, command, from_faster - 1e-9, limits, dt));
}

TEST(Window, RampStepMovesAtTheLimitsThenHolds) {
  double v = 0.0;
  EXPECT_DOUBLE_EQ(ramp_step(v, 1.0, 2.0, 4.0, 0.25), 0.25);  // 0 -> 0.5 at 2 m/s^2
  EXPECT_DOUBLE_EQ(v, 0.5);
  EXPECT_NEAR(ramp_step(v, 0.6, 2.0, 4.0, 0.25), 0.59, 1e-12);  // reaches 0.6 after 0.05 s
  EXPECT_DOUBLE_EQ(v, 0.6);
  EXPECT_DOUBLE_EQ(ramp_step(v, 0.6, 2.0, 4.0, 0.25), 0.6);  // holds
  v = 1.0;
  ramp_step(v, -1.0, 2.0, 4.0, 0.25);  // through zero: down at 4 for 0.25 s, then up at 2
  EXPECT_DOUBLE_EQ(v, 0.0);
  ramp_step(v, -1.0, 2.0, 4.0, 0.25);
  EXPECT_DOUBLE_EQ(v, -0.5);
}

// A first-order lag on top of the ramp: with room to accelerate the velocity
// follows the lag exactly (its end and its mean over the step); where the lag
// asks for more than the acceleration allows, the ramp holds it back.
TEST(Window, ResponseStepFollowsTheLagWithinTheLimits) {
  const double dt = 0.1, tau = 0.1, keep = std::exp(-1.0), mean_keep = 1.0 - std::exp(-1.0);
  double v = 0.2, ramped = 0.2;
  EXPECT_DOUBLE_EQ(response_step(v, 1.0, 100.0, 100.0, 0.0, dt), ramp_step(ramped, 1.0, 100.0, 100.0, dt));
  EXPECT_DOUBLE_EQ(v, ramped);
  v = 0.2;
  EXPECT_NEAR(response_step(v, 1.0, 100.0, 100.0, tau, dt), 1.0 - 0.8 * mean_keep, 1e-12);
  EXPECT_NEAR(v, 1.0 - 0.8 * keep, 1e-12);
  // Held back by a 2 m/s^2 acceleration: 0.2 m/s more at most.
  v = 0.2;
  EXPECT_NEAR(response_step(v, 1.0, 2.0, 4.0, tau, dt), 0.3, 1e-12);
  EXPECT_NEAR(v, 0.4, 1e-12);
  // Braking lags too: from 1 m/s toward 0 the wheels still turn after a step.
  v = 1.0;
  response_step(v, 0.0, 100.0, 100.0, tau, dt);
  EXPECT_NEAR(v, keep, 1e-12);
}

}  // namespace
}  // namespace fgdwa
