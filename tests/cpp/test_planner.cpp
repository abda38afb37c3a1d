#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/collision.hpp"
#include "fgdwa/controller.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/presets.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

using test::expect_error_naming;
using test::kInf;

TEST(PlannerParams, DefaultsAreValid) {
  const PlannerParams params;
  EXPECT_NO_THROW(params.validate());
  EXPECT_EQ(params.n_steps(), 20);  // 3 s / 0.15 s
}

TEST(PlannerParams, RejectsBadValuesByName) {
  const auto rejects = [](auto mutate, const std::string& field) {
    PlannerParams params;
    mutate(params);
    expect_error_naming([&] { params.validate(); }, field);
    // The planner validates its parameters on construction too.
    expect_error_naming([&] { LocalPlanner(RobotLimits{}, Footprint::circle(0.25), params); }, field);
  };
  for (double dt : {0.0, -0.1, std::nan(""), kInf}) rejects([dt](PlannerParams& p) { p.dt = dt; }, "dt");
  rejects([](PlannerParams& p) { p.sim_time = 0.0; }, "sim_time");
  rejects([](PlannerParams& p) { p.sim_time = 0.05; }, "sim_time");  // less than half a step
  rejects([](PlannerParams& p) { p.window.n_v = 0; }, "n_v");
  rejects([](PlannerParams& p) { p.window.n_omega = 0; }, "n_omega");
  rejects([](PlannerParams& p) { p.goal_tolerance = -0.1; }, "goal_tolerance");
  rejects([](PlannerParams& p) { p.critics.clear(); }, "critics");
  rejects([](PlannerParams& p) { p.mover_caution_radius = -1.0; }, "mover_caution_radius");
  for (double w : {-0.1, 1.5, std::nan("")}) rejects([w](PlannerParams& p) { p.mover_speed_weight = w; }, "mover_speed_weight");
  rejects([](PlannerParams& p) { p.critics.push_back({"heading", 1.0, {}}); }, "heading");
}

TEST(PlannerParams, CriticsAreBuiltByNameOnConstruction) {
  PlannerParams params;
  params.critics = {{"heading", 1.0, {}}, {"obstacle", 1.0, {}}};
  expect_error_naming([&] { LocalPlanner(RobotLimits{}, Footprint::circle(0.25), params); }, "obstacle");
  params.critics = {{"clearance", 1.0, {{"capp", 1.0}}}};
  expect_error_naming([&] { LocalPlanner(RobotLimits{}, Footprint::circle(0.25), params); }, "capp");
  RobotLimits limits;
  limits.acc_v = -1.0;
  expect_error_naming([&] { LocalPlanner(limits, Footprint::circle(0.25), PlannerParams{}); }, "acc_v");
}

// A seeded 8 m x 8 m world of clustered obstacles around a free start area.
struct World {
  std::shared_ptr<const DistanceField> field;
  std::unique_ptr<FieldClearance> fast;
  OccupancyGrid grid;
};

World random_world(std::mt19937& rng, Vec2 free_point, double fill = 0.15) {
  OccupancyGrid grid = test::random_rectangles(rng, 80, 80, 0.1, Vec2(-4.0, -4.0), fill, 8, free_point, 0.3);
  World w{std::make_shared<const DistanceField>(grid), nullptr, grid};
  w.fast = std::make_unique<FieldClearance>(w.field);
  return w;
}

RobotState random_state(std::mt19937& rng, const RobotLimits& limits, Vec2 at) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RobotState s;
  s.pose = Pose2{at.x(), at.y(), M_PI * (2.0 * u(rng) - 1.0)};
  s.twist = Twist{limits.v_min + (limits.v_max - limits.v_min) * u(rng), limits.omega_max * (2.0 * u(rng) - 1.0)};
  if (u(rng) < 0.2) s.twist.v = limits.v_max;  // fast: braking matters most
  return s;
}

Vec2 random_goal(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-3.5, 3.5);
  return Vec2(u(rng), u(rng));
}

bool inside_window(const Twist& cmd, const RobotLimits& l, const Twist& c, double dt) {
  const double tol = 1e-9;
  return cmd.v >= l.v_min - tol && cmd.v <= l.v_max + tol && std::abs(cmd.omega) <= l.omega_max + tol &&
         std::abs(cmd.v - c.v) <= l.acc_v * dt + tol && std::abs(cmd.omega - c.omega) <= l.acc_omega * dt + tol;
}

TEST(LocalPlanner, CommandAlwaysLiesInsideTheDynamicWindow) {
  const RobotLimits limits;
  LocalPlanner planner(limits, Footprint::circle(0.25));
  const double dt = planner.params().dt;
  int ok = 0, stuck = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    std::mt19937 rng(seed);
    const Vec2 start(0.0, 0.0);
    const World world = random_world(rng, start);
    for (int trial = 0; trial < 15; ++trial) {
      const RobotState state = random_state(rng, limits, start);
      const PlanResult& r = planner.plan(state, random_goal(rng), *world.fast);
      ASSERT_TRUE(inside_window(r.command, limits, state.twist, dt)) << "seed " << seed << " trial " << trial;
      if (r.status == Status::Ok) {
        ++ok;
        ASSERT_GE(r.best_index, 0);
        ASSERT_EQ(r.reasons[static_cast<std::size_t>(r.best_index)], RejectReason::None);
        ASSERT_EQ(r.command.v, r.samples[static_cast<std::size_t>(r.best_index)].v);
        ASSERT_EQ(r.command.omega, r.samples[static_cast<std::size_t>(r.best_index)].omega);
      } else {
        ASSERT_NE(r.status, Status::Ok);  // NoAdmissibleVelocity or GoalReached: both brake
        ++stuck;
        const Twist b = braking_command(limits, state.twist, dt);
        ASSERT_EQ(r.command.v, b.v);
        ASSERT_EQ(r.command.omega, b.omega);
      }
    }
  }
  EXPECT_GT(ok, 200);
}

// The pose `steps` steps into a constant-command rollout, on its own arc: the
// discrete model's poses all lie on the circle of radius v dt / (2 sin(omega dt / 2))
// through the start, whose tangent there is theta + omega dt / 2.
Pose2 along_rollout_arc(const Pose2& start, const Twist& cmd, double dt, double steps) {
  const double a = start.theta, b = cmd.omega * dt, chord = cmd.v * dt;
  if (b == 0.0) return Pose2{start.x + steps * chord * std::cos(a), start.y + steps * chord * std::sin(a), a};
  const std::complex<double> centre =
      std::complex<double>(start.x, start.y) + std::polar(chord / (2 * std::sin(b / 2)), a + b / 2 + M_PI / 2);
  const std::complex<double> p = centre + std::polar(chord / (2 * std::sin(b / 2)), a + b / 2 - M_PI / 2 + steps * b);
  return Pose2{p.real(), p.imag(), a + steps * b};
}

// From `current`, heads for the command for one period (the wheels ramping
// toward it at the limits), then brakes as the planner's fallback does
// (braking_command each period, the wheels ramping down along the arc) until
// the robot stands, moving with the wheels' mean twist as the motion model
// does: each period turns in place, then drives straight. Checks every `h` metres of the drives and every
// 0.01 rad of the turns; returns the smallest clearance seen and the distance
// travelled.
double braking_clearance(const ClearanceSource& world, const Footprint& fp, const Pose2& start, const Twist& current,
                         const Twist& cmd, const RobotLimits& limits, double dt, double h, double& travelled) {
  travelled = 0.0;
  double worst = world.clearance(fp, start, 0.0);
  Pose2 pose = start;
  Twist wheels = current, command = cmd;
  for (int period = 0; period < 10000 && (wheels.v != 0.0 || wheels.omega != 0.0); ++period) {
    Twist twist;
    if (period == 0) {
      twist.v = ramp_step(wheels.v, command.v, limits.acc_v, limits.braking_v(), dt);
      twist.omega = ramp_step(wheels.omega, command.omega, limits.acc_omega, limits.braking_omega(), dt);
    } else {
      twist = Twist{0.5 * (wheels.v + command.v), 0.5 * (wheels.omega + command.omega)};
      wheels = command;
    }
    const Pose2 next = unicycle_step(pose, twist, dt);
    const double turn = angle_difference(next.theta, pose.theta);
    const int turns = fp.is_circle() ? 0 : static_cast<int>(std::ceil(std::abs(turn) / 0.01));
    for (int k = 1; k <= turns; ++k)
      worst = std::min(worst, world.clearance(fp, Pose2{pose.x, pose.y, pose.theta + turn * k / turns}, 0.0));
    const double length = std::abs(twist.v) * dt;
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / h)));
    for (int k = 1; k <= pieces; ++k) {
      const double f = double(k) / pieces;
      worst = std::min(worst, world.clearance(fp, Pose2{pose.x + f * (next.x - pose.x), pose.y + f * (next.y - pose.y),
                                                        next.theta}, 0.0));
    }
    travelled += length;
    pose = next;
    command = braking_command(limits, wheels, dt);
  }
  return worst;
}

// Every admissible sample that meets an obstacle within the horizon can stop
// before it: Eq. 3's v^2 / (2 brake_v) and omega^2 / (2 brake_omega) fit in its
// free distance, and driving it one period and then braking as the fallback
// does touches nothing, between poses included.
void check_admissible_samples_can_stop(const RobotLimits& limits, const Footprint& fp, bool use_fcl, unsigned seeds,
                                       int states, const WindowParams& window, double h) {
  PlannerParams params;
  params.window = window;
  params.wheels = WheelModel::Ramp;
  LocalPlanner planner(limits, fp, params);
  const double dt = params.dt;
  int finite = 0, rejected = 0;
  for (unsigned seed = 1; seed <= seeds; ++seed) {
    std::mt19937 rng(100 + seed);
    const Vec2 start(0.0, 0.0);
    const World world = random_world(rng, start, 0.2);
    const CollisionWorld exact(world.grid);
    const ClearanceSource& source = use_fcl ? static_cast<const ClearanceSource&>(exact) : *world.fast;
    for (int trial = 0; trial < states; ++trial) {
      const RobotState state = random_state(rng, limits, start);
      const PlanResult& r = planner.plan(state, random_goal(rng), source);
      for (std::size_t i = 0; i < r.samples.size(); ++i) {
        const Twist& cmd = r.samples[i];
        const double free = r.free_distance[i];
        SCOPED_TRACE(::testing::Message() << "seed " << seed << " trial " << trial << " sample " << cmd.v << ", "
                                          << cmd.omega << " free " << free);
        if (r.reasons[i] != RejectReason::None) {
          ++rejected;
          ASSERT_TRUE(std::isfinite(free));
          // The default braking model: one period ramping toward the command, then braking.
          ASSERT_FALSE(is_admissible(state.twist, cmd, free, limits, dt));
          continue;
        }
        if (std::isinf(free)) continue;
        ++finite;
        ASSERT_LE(cmd.v * cmd.v / (2 * limits.braking_v()), free + 1e-12);
        ASSERT_LE(cmd.omega * cmd.omega / (2 * limits.braking_omega()), free + 1e-12);
        const Trajectory& poses = planner.rollouts()[i];
        const Trajectory expected = rollout(state.pose, state.twist, cmd, limits, dt, 3);
        for (int k = 1; k <= 3; ++k) {
          ASSERT_LT((expected[k - 1].position() - poses[k - 1].position()).norm(), 1e-9);
          ASSERT_LT(std::abs(angle_difference(expected[k - 1].theta, poses[k - 1].theta)), 1e-9);
        }
        // Once at the command, the poses keep to its arc.
        Twist reached = state.twist;
        ramp_step(reached.v, cmd.v, limits.acc_v, limits.braking_v(), dt);
        ramp_step(reached.omega, cmd.omega, limits.acc_omega, limits.braking_omega(), dt);
        for (int k = 2; k <= 4 && reached.v == cmd.v && reached.omega == cmd.omega; ++k) {
          ASSERT_LT((along_rollout_arc(poses[0], cmd, dt, k - 1).position() - poses[k - 1].position()).norm(), 1e-9);
        }
        double travelled = 0.0;
        const double c = braking_clearance(source, fp, state.pose, state.twist, cmd, limits, dt, h, travelled);
        ASSERT_LE(travelled, free + 1e-9);
        ASSERT_GT(c, 0.0) << "collides while braking after " << travelled << " m";
      }
      ASSERT_TRUE(inside_window(r.command, limits, state.twist, dt));
    }
  }
  EXPECT_GT(finite, 100);
  EXPECT_GT(rejected, 100);
}

TEST(LocalPlanner, AdmissibleSamplesStopBeforeContactFieldCircle) {
  check_admissible_samples_can_stop(RobotLimits{}, Footprint::circle(0.25), false, 25, 8, WindowParams{}, 0.002);
}

TEST(LocalPlanner, AdmissibleSamplesStopBeforeContactFieldPolygon) {
  RobotLimits limits;
  limits.v_max = 0.8;
  limits.acc_v = 0.6;
  limits.brake_v = 0.5;
  limits.acc_omega = 1.5;
  const Footprint fp = Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}});
  check_admissible_samples_can_stop(limits, fp, false, 10, 5, WindowParams{11, 11}, 0.005);
}

TEST(LocalPlanner, AdmissibleSamplesStopBeforeContactFcl) {
  check_admissible_samples_can_stop(RobotLimits{}, Footprint::circle(0.25), true, 4, 3, WindowParams{7, 7}, 0.01);
}

// A sample's free distance is k v dt for the first step k whose motion (the
// turn in place, then the straight drive) brings the footprint within the
// safety margin of an obstacle, checked here by brute force every `h` metres
// of the drives and every `h` radians of the turns. Samples whose closest
// approach lies within `band` of the margin are left out: there the planner's
// millimetre resolution and the sampling may rightly disagree. Long steps
// (0.3 s) among scattered posts make contact between two clear poses common.
struct TouchCounts {
  int touching = 0, clear = 0, between = 0;
};

// One plan from `state`: every sample's free distance against the brute-force sweep.
void expect_free_distances_match_sweeps(LocalPlanner& planner, const ClearanceSource& world, const RobotState& state,
                                        const Vec2& goal, double h, double band, TouchCounts& n) {
  const Footprint& fp = planner.footprint();
  const double margin = planner.params().safety_margin;
  // Clearance beyond the safety margin.
  const auto beyond_margin = [&](const Pose2& pose) { return world.clearance(fp, pose, 0.0) - margin; };
  ASSERT_GT(beyond_margin(state.pose), 1e-3);  // keeps the margin whole
  const PlanResult& r = planner.plan(state, goal, world);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const Trajectory& poses = planner.rollouts()[i];
    int first_touch = -1;
    bool ambiguous = false, ends_clear = false;
    for (std::size_t k = 0; k < poses.size() && first_touch < 0; ++k) {
      const Pose2& from = k == 0 ? state.pose : poses[k - 1];
      const Pose2& to = poses[k];
      double worst = beyond_margin(to);
      ends_clear = worst > 0.0;
      const double turn = angle_difference(to.theta, from.theta);
      const int turn_pieces = fp.is_circle() ? 0 : static_cast<int>(std::ceil(std::abs(turn) / h));
      for (int j = 1; j <= turn_pieces; ++j)
        worst = std::min(worst, beyond_margin(Pose2{from.x, from.y, from.theta + turn * j / turn_pieces}));
      const double length = std::hypot(to.x - from.x, to.y - from.y);
      const int pieces = std::max(1, static_cast<int>(std::ceil(length / h)));
      for (int j = 1; j < pieces; ++j) {
        const double f = double(j) / pieces;
        worst = std::min(worst, beyond_margin(Pose2{from.x + f * (to.x - from.x), from.y + f * (to.y - from.y), to.theta}));
      }
      if (std::abs(worst) < band) ambiguous = true;
      if (worst <= 0.0) first_touch = static_cast<int>(k);
    }
    if (ambiguous) continue;
    const Twist& cmd = r.samples[i];
    SCOPED_TRACE(::testing::Message() << "sample " << cmd.v << ", " << cmd.omega);
    if (first_touch < 0) {
      ++n.clear;
      EXPECT_TRUE(std::isinf(r.free_distance[i])) << r.free_distance[i];
    } else {
      ++n.touching;
      n.between += ends_clear;  // the step's end placement clear: only its sweep shows contact
      // The distance travelled over the first_touch steps before it.
      double travelled = 0.0;
      for (int k = 0; k < first_touch; ++k)
        travelled += (poses[static_cast<std::size_t>(k)].position() -
                      (k == 0 ? state.pose.position() : poses[static_cast<std::size_t>(k - 1)].position())).norm();
      EXPECT_NEAR(r.free_distance[i], travelled, 1e-9);
    }
  }
}

TouchCounts check_free_distance_is_first_touching_step(const Footprint& fp, unsigned seeds, double h, double band) {
  const RobotLimits limits;
  PlannerParams params;
  params.dt = 0.3;
  params.window = WindowParams{11, 11};
  LocalPlanner planner(limits, fp, params);
  TouchCounts n;
  for (unsigned seed = 1; seed <= seeds; ++seed) {
    std::mt19937 rng(700 + seed);
    const Vec2 start(0.0, 0.0);
    // Scattered 2 cm posts: rollouts graze them as often as they run into them.
    const OccupancyGrid grid =
        test::random_rectangles(rng, 400, 400, 0.02, Vec2(-4.0, -4.0), 0.004, 1, start, fp.radius() + 0.05);
    const FieldClearance world(std::make_shared<const DistanceField>(grid));
    for (int trial = 0; trial < 6; ++trial) {
      RobotState state = random_state(rng, limits, start);
      if (trial % 3 == 0) state.twist.v = limits.v_max;  // long drives
      if (trial % 3 == 1) state.twist.v = 0.0;           // turns in place among the samples
      const Vec2 goal = random_goal(rng);
      if (world.clearance(fp, state.pose, 0.0) - params.safety_margin <= 1e-3) continue;  // keeps the margin whole
      SCOPED_TRACE(::testing::Message() << "seed " << seed << " trial " << trial);
      expect_free_distances_match_sweeps(planner, world, state, goal, h, band, n);
    }
  }
  return n;
}

TEST(LocalPlanner, FreeDistanceIsTheFirstTouchingStepCircle) {
  const TouchCounts n = check_free_distance_is_first_touching_step(Footprint::circle(0.25), 6, 0.002, 0.004);
  EXPECT_GT(n.touching, 1000);
  EXPECT_GT(n.clear, 50);
  EXPECT_GT(n.between, 20);  // the sweep between poses is what decides these
}

TEST(LocalPlanner, FreeDistanceIsTheFirstTouchingStepPolygon) {
  // Longer than any drive: every drive between two clear placements is clear.
  const TouchCounts rectangle = check_free_distance_is_first_touching_step(
      Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}}), 2, 0.003, 0.005);
  EXPECT_GT(rectangle.touching, 300);
  // A 0.1 m top edge, shorter than the fast drives: their sweeps decide.
  const TouchCounts trapezoid = check_free_distance_is_first_touching_step(
      Footprint::polygon({{-0.2, -0.15}, {0.2, -0.15}, {0.05, 0.15}, {-0.05, 0.15}}), 2, 0.003, 0.005);
  EXPECT_GT(trapezoid.touching, 300);
  EXPECT_GT(trapezoid.between, 5);
}

// A kite turning in place sweeps its nose along an arc of the circumscribed
// circle. A post on that arc, 70 % of a step's turn ahead of the nose, is
// clear of the start placement by more than half the nose's travel and clear
// of the turned one, and the nose hits it late in the turn.
TEST(LocalPlanner, FreeDistanceCountsContactMidTurn) {
  RobotLimits limits;
  limits.omega_max = 3.0;
  limits.acc_omega = 4.0;
  PlannerParams params;
  params.dt = 0.3;
  params.sim_time = 1.2;
  params.window = WindowParams{5, 11};
  const Footprint fp = Footprint::polygon({{0.4, 0.0}, {0.0, 0.1}, {-0.1, 0.0}, {0.0, -0.1}});
  LocalPlanner planner(limits, fp, params);
  const double turn = 2.0 * params.dt;  // 2 rad/s for one step
  const Vec2 post = (fp.radius() - 0.005) * Vec2(std::cos(0.7 * turn), std::sin(0.7 * turn));
  const double resolution = 0.005;
  const Vec2 origin(-0.5, -0.5);
  std::vector<std::uint8_t> cells(200 * 200, 0);
  cells[static_cast<std::size_t>(std::floor((post.y() - origin.y()) / resolution)) * 200 +
        static_cast<std::size_t>(std::floor((post.x() - origin.x()) / resolution))] = 1;
  const FieldClearance world(
      std::make_shared<const DistanceField>(OccupancyGrid(200, 200, resolution, origin, std::move(cells))));
  const double margin = params.safety_margin;
  ASSERT_GT(world.clearance(fp, Pose2{}, 0.0) - margin, 0.5 * fp.radius() * turn);
  ASSERT_GT(world.clearance(fp, Pose2{0.0, 0.0, turn}, 0.0) - margin, 0.01);
  ASSERT_LE(world.clearance(fp, Pose2{0.0, 0.0, 0.7 * turn}, 0.0) - margin, -0.01);
  TouchCounts n;
  expect_free_distances_match_sweeps(planner, world, RobotState{Pose2{}, Twist{0.5, 2.0}}, Vec2(3.0, 0.0), 0.001,
                                     0.002, n);
  EXPECT_GT(n.between, 5);
}

// A robot standing against a wall of its map, facing it, or overlapping it (a
// map built from scans can grow a cell under a robot standing still): turning
// in place and moving away stay admissible, closing in does not. A margin
// clamped at zero counted every motion there as contact, and the robot stood
// still for good.
TEST(LocalPlanner, RobotAtOrInsideAnObstacleMayTurnAndLeaveButNotCloseIn) {
  const OccupancyGrid grid = test::grid_with_boxes(40, 40, 0.05, Vec2(0.0, -1.0), {{0, 20, 40, 4}});  // x in [1.0, 1.2)
  const FieldClearance world(std::make_shared<const DistanceField>(grid));
  const Footprint fp = Footprint::circle(0.25);
  PlannerParams params;
  params.dt = 0.1;
  LocalPlanner planner(RobotLimits{}, fp, params);
  for (const double clearance : {5e-4, 0.0, -0.01}) {
    SCOPED_TRACE(::testing::Message() << "clearance " << clearance);
    const RobotState state{Pose2{1.0 - 0.25 - clearance, 0.0, 0.0}, Twist{}};
    ASSERT_NEAR(world.clearance(fp, state.pose, 0.0), clearance, 1e-9);
    // The goal lies behind the robot: it has to turn away from the wall.
    const PlanResult& r = planner.plan(state, Vec2(-1.0, 0.0), world);
    int turning = 0;
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      if (r.reasons[i] != RejectReason::None) continue;
      EXPECT_GE(r.min_clearance[i], clearance - kContactSlack - 1e-12) << r.samples[i].v << ", " << r.samples[i].omega;
      turning += r.samples[i].v == 0.0 && r.samples[i].omega != 0.0;
    }
    EXPECT_GT(turning, 0);
    EXPECT_EQ(r.status, Status::Ok);
    EXPECT_NE(r.command.omega, 0.0);
    // Straight on into the wall stays inadmissible.
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      if (r.samples[i].v > 0.0 && r.samples[i].omega == 0.0) {
        EXPECT_NE(r.reasons[i], RejectReason::None);
      }
    }
  }
  EXPECT_DOUBLE_EQ(contact_margin(0.5, 0.02), 0.02);
  EXPECT_DOUBLE_EQ(contact_margin(0.011, 0.02), 0.01);
  EXPECT_DOUBLE_EQ(contact_margin(-0.01, 0.02), -0.01 - kContactSlack);
  EXPECT_DOUBLE_EQ(contact_margin(0.0, 0.02), 0.0);
}

// A polygon's clearance stops at zero in contact, so how deep it goes cannot be
// told there: a rectangle touching or overlapping a wall it faces may not drive
// on into it (with a negative margin, zero would have passed for "no deeper").
TEST(LocalPlanner, PolygonInContactMayNotDriveDeeper) {
  const OccupancyGrid grid = test::grid_with_boxes(40, 40, 0.05, Vec2(0.0, -1.0), {{0, 20, 40, 4}});  // x in [1.0, 1.2)
  const FieldClearance world(std::make_shared<const DistanceField>(grid));
  const Footprint fp = Footprint::polygon({{-0.25, -0.15}, {0.25, -0.15}, {0.25, 0.15}, {-0.25, 0.15}});
  PlannerParams params;
  params.dt = 0.1;
  LocalPlanner planner(RobotLimits{}, fp, params);
  for (const double overlap : {0.0, 0.01, 0.04}) {
    SCOPED_TRACE(::testing::Message() << "overlap " << overlap);
    const RobotState state{Pose2{1.0 - 0.25 + overlap, 0.0, 0.0}, Twist{0.3, 0.0}};
    ASSERT_NEAR(world.clearance(fp, state.pose, 0.0), 0.0, 1e-12);
    const PlanResult& r = planner.plan(state, Vec2(3.0, 0.0), world);
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      if (r.samples[i].v > 0.0) {
        EXPECT_NE(r.reasons[i], RejectReason::None) << r.samples[i].v << ", " << r.samples[i].omega;
      }
    }
  }
}

// Fast, straight at a wall 0.25 m beyond the footprint: no command in the
// window can stop in time.
TEST(LocalPlanner, BoxedInReportsNoAdmissibleVelocityAndBrakes) {
  const OccupancyGrid grid = test::grid_with_boxes(40, 40, 0.1, Vec2(-1.0, -2.0), {{0, 15, 40, 5}});  // x in [0.5, 1.0)
  const FieldClearance fast(std::make_shared<const DistanceField>(grid));
  const CollisionWorld exact(grid);
  const RobotLimits limits;
  LocalPlanner planner(limits, Footprint::circle(0.25));
  const RobotState state{Pose2{0.0, 0.0, 0.0}, Twist{1.2, 0.0}};
  for (const ClearanceSource* world : {static_cast<const ClearanceSource*>(&fast), static_cast<const ClearanceSource*>(&exact)}) {
    const PlanResult& r = planner.plan(state, Vec2(3.0, 0.0), *world);
    EXPECT_EQ(r.status, Status::NoAdmissibleVelocity);
    EXPECT_EQ(r.best_index, -1);
    EXPECT_EQ(r.admissible_count(), 0);
    EXPECT_EQ(r.reject_counts[static_cast<std::size_t>(RejectReason::Collision)], static_cast<int>(r.samples.size()));
    const Twist b = braking_command(limits, state.twist, planner.params().dt);
    EXPECT_EQ(r.command.v, b.v);
    EXPECT_EQ(r.command.omega, b.omega);
    EXPECT_NEAR(r.command.v, 1.2 - 0.15, 1e-12);
    EXPECT_EQ(r.command.omega, 0.0);
    for (Eigen::Index i = 0; i < r.total.size(); ++i) EXPECT_EQ(r.total(i), -kInf);
    EXPECT_EQ(r.raw.cwiseAbs().maxCoeff(), 0.0);
  }
  // From rest the same wall is no trouble.
  const PlanResult& calm = planner.plan(RobotState{Pose2{0.0, 0.0, 0.0}, Twist{}}, Vec2(3.0, 0.0), fast);
  EXPECT_EQ(calm.status, Status::Ok);
}

// A wall 2.5 m ahead and the goal behind it: at 0.75 m/s or more a straight
// rollout of 3 s meets the wall, though the braking rule admits it (the robot
// could stop first). Scored on heading and speed alone, preferring clear
// rollouts takes the best that keeps clear to its end; without, the velocity
// critic takes one that meets the wall.
TEST(LocalPlanner, PrefersARolloutClearOfTheWallsToOneOnlyBrakingAdmits) {
  const OccupancyGrid grid = test::grid_with_boxes(60, 80, 0.1, Vec2(-1.0, -3.0), {{0, 35, 60, 5}});  // x in [2.5, 3.0)
  const FieldClearance world(std::make_shared<const DistanceField>(grid));
  const RobotLimits limits;
  const RobotState state{Pose2{0.0, 0.0, 0.0}, Twist{0.8, 0.0}};
  for (const bool prefer : {true, false}) {
    PlannerParams params;
    params.prefer_clear = prefer;
    params.critics = {{"heading", 0.5}, {"velocity", 1.0}};
    LocalPlanner planner(limits, Footprint::circle(0.25), params);
    const PlanResult& r = planner.plan(state, Vec2(5.0, 0.0), world);
    ASSERT_EQ(r.status, Status::Ok);
    const auto best = static_cast<std::size_t>(r.best_index);
    int clear = 0, braking_only = 0;
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      if (r.reasons[i] != RejectReason::None) continue;
      (r.min_clearance[i] > 0.0 ? clear : braking_only) += 1;
    }
    ASSERT_GT(clear, 0);
    ASSERT_GT(braking_only, 0);
    if (prefer) {
      EXPECT_GT(r.min_clearance[best], 0.0);
      // The best of the clear ones by total.
      for (std::size_t i = 0; i < r.samples.size(); ++i) {
        if (r.reasons[i] == RejectReason::None && r.min_clearance[i] > 0.0) {
          EXPECT_LE(r.total(static_cast<Eigen::Index>(i)), r.total(static_cast<Eigen::Index>(best)));
        }
      }
    } else {
      EXPECT_LE(r.min_clearance[best], 0.0);
      EXPECT_GT(r.command.v, 0.75);
    }
  }
}

// A disc overtaking the robot from behind, faster than it can drive, meets
// every sample: the planner evades. Driving on fastest puts the contact off
// longest, but its rollout runs into a wall 2.5 m ahead, which only braking
// keeps the robot off. Preferring clear rollouts takes the best way out that
// keeps clear of the wall to its end; without, the fastest is taken.
TEST(LocalPlanner, AnEvasionTooPrefersAWayOutClearOfTheWalls) {
  const OccupancyGrid grid = test::grid_with_boxes(60, 80, 0.1, Vec2(-1.0, -3.0), {{0, 35, 60, 5}});  // x in [2.5, 3.0)
  const Disc disc{Vec2(-1.4, 0.0), 0.3, Vec2(2.0, 0.0)};
  const FieldClearance world(std::make_shared<const DistanceField>(grid), {disc});
  const Footprint footprint = Footprint::circle(0.25);
  const RobotState state{Pose2{0.0, 0.0, 0.0}, Twist{0.8, 0.0}};
  for (const bool prefer : {true, false}) {
    SCOPED_TRACE(::testing::Message() << "prefer_clear " << prefer);
    PlannerParams params;
    params.prefer_clear = prefer;
    LocalPlanner planner(RobotLimits{}, footprint, params);
    const PlanResult& r = planner.plan(state, Vec2(5.0, 0.0), world);
    ASSERT_EQ(r.status, Status::Evading);
    // Clear of the fixed world over the whole rollout, brute force.
    const auto clear = [&](std::size_t i) {
      for (const Pose2& pose : planner.rollouts()[i])
        if (world.static_part().clearance(footprint, pose, 0.0) <= params.safety_margin) return false;
      return true;
    };
    int clear_ways = 0, braking_only = 0;
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      ASSERT_NE(r.reasons[i], RejectReason::None);
      if (r.reasons[i] == RejectReason::Moving) (clear(i) ? clear_ways : braking_only) += 1;
    }
    ASSERT_GT(clear_ways, 0);
    ASSERT_GT(braking_only, 0);
    EXPECT_EQ(clear(static_cast<std::size_t>(r.best_index)), prefer)
        << "chose (" << r.command.v << ", " << r.command.omega << ")";
  }
}

TEST(LocalPlanner, GoalReachedWithinTolerance) {
  const RobotLimits limits;
  PlannerParams params;
  params.goal_tolerance = 0.3;
  LocalPlanner planner(limits, Footprint::circle(0.25), params);
  const FieldClearance empty;
  const RobotState state{Pose2{1.0, 1.0, 0.0}, Twist{0.5, 0.4}};
  const PlanResult& r = planner.plan(state, Vec2(1.2, 1.2), empty);  // 0.28 m away
  EXPECT_EQ(r.status, Status::GoalReached);
  const Twist b = braking_command(limits, state.twist, params.dt);
  EXPECT_EQ(r.command.v, b.v);
  EXPECT_EQ(r.command.omega, b.omega);
  EXPECT_EQ(planner.plan(state, Vec2(1.3, 1.2), empty).status, Status::Ok);  // 0.36 m away
  // Reaching the goal after a normal cycle leaves no stale per-sample diagnostics.
  const PlanResult& again = planner.plan(state, Vec2(1.2, 1.2), empty);
  EXPECT_EQ(again.status, Status::GoalReached);
  EXPECT_EQ(again.best_index, -1);
  EXPECT_TRUE(again.samples.empty());
  EXPECT_TRUE(planner.rollouts().empty());
  EXPECT_EQ(again.raw.rows(), 0);
  EXPECT_EQ(again.normalized.rows(), 0);
  EXPECT_EQ(again.total.size(), 0);
  EXPECT_TRUE(again.reasons.empty());
  EXPECT_TRUE(again.min_clearance.empty());
  EXPECT_TRUE(again.free_distance.empty());
  EXPECT_EQ(again.admissible_count(), 0);
}

// Near the goal no faster than the robot can stop on it (sqrt(2 b d)): 0.2 m
// from it at 0.8 m/s with 1 m/s^2 braking, the cap is 0.63 m/s, below what
// the window reaches (0.7-0.9 m/s), so the command is the window's slowest;
// 5 m away the same state keeps its speed.
TEST(LocalPlanner, NearTheGoalNoFasterThanItCanStopOnIt) {
  RobotLimits limits;
  limits.v_max = 1.2;
  PlannerParams params;
  params.goal_tolerance = 0.05;
  LocalPlanner planner(limits, Footprint::circle(0.25), params);
  const FieldClearance empty;
  const RobotState state{Pose2{1.0, 1.0, 0.0}, Twist{0.8, 0.0}};
  const PlanResult& near = planner.plan(state, Vec2(1.2, 1.0), empty);
  ASSERT_EQ(near.status, Status::Ok);
  EXPECT_LE(near.command.v, 0.8 - limits.braking_v() * params.dt + 1e-9);
  for (const Twist& sample : near.samples) EXPECT_LE(sample.v, 0.7 + 1e-9);
  const PlanResult& far = planner.plan(state, Vec2(6.0, 1.0), empty);
  ASSERT_EQ(far.status, Status::Ok);
  EXPECT_GT(far.command.v, 0.8);
}

TEST(LocalPlanner, ClearanceIsScoredUntilTheRolloutReachesTheGoal) {
  // A wall 0.6 m past the goal: rollouts that pass through the goal run into it later.
  const OccupancyGrid grid = test::grid_with_boxes(30, 40, 0.1, Vec2(0.0, 0.0), {{0, 30, 30, 10}});
  const FieldClearance world(std::make_shared<DistanceField>(grid));
  PlannerParams params;
  params.goal_tolerance = 0.2;
  const Footprint footprint = Footprint::circle(0.25);
  LocalPlanner planner(RobotLimits{}, footprint, params);
  const Vec2 goal(2.4, 1.5);
  const PlanResult& r = planner.plan(RobotState{Pose2{1.0, 1.5, 0.0}, Twist{0.6, 0.0}}, goal, world);
  int through_goal = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    if (r.reasons[i] != RejectReason::None) continue;
    const Trajectory& poses = planner.rollouts()[i];
    std::size_t reach = poses.size();
    for (std::size_t k = 0; k < poses.size() && reach == poses.size(); ++k)
      if ((poses[k].position() - goal).norm() <= params.goal_tolerance) reach = k;
    if (reach == poses.size()) continue;
    double until_goal = kInf, whole = kInf;
    for (std::size_t k = 0; k < poses.size(); ++k) {
      const double c = world.clearance(footprint, poses[k], 0.0);
      whole = std::min(whole, c);
      if (k <= reach) until_goal = std::min(until_goal, c);
    }
    ++through_goal;
    EXPECT_NEAR(r.min_clearance[i], until_goal, 1e-9) << "sample " << i;
    if (whole <= 0.0) {
      EXPECT_GT(r.min_clearance[i], 0.1) << "sample " << i;  // the wall beyond is not held against it
    }
  }
  EXPECT_GT(through_goal, 0);
}

TEST(LocalPlanner, DiagnosticsHaveOneRowPerSampleAndOneColumnPerCritic) {
  std::mt19937 rng(3);
  const World world = random_world(rng, Vec2::Zero(), 0.25);
  PlannerParams params;
  params.window = WindowParams{9, 13};
  params.critics = {{"heading", 0.5, {}}, {"clearance", 0.15, {{"cap", 1.5}}}, {"velocity", 1.0, {}}};
  const RobotLimits limits;
  LocalPlanner planner(limits, Footprint::circle(0.25), params);
  int checked = 0;
  for (int trial = 0; trial < 80; ++trial) {
    const RobotState state = random_state(rng, limits, Vec2::Zero());
    const PlanResult& r = planner.plan(state, random_goal(rng), *world.fast);
    if (r.status == Status::GoalReached) continue;
    const Eigen::Index n = 9 * 13, m = 3;
    ASSERT_EQ(static_cast<Eigen::Index>(r.samples.size()), n);
    ASSERT_EQ(r.raw.rows(), n);
    ASSERT_EQ(r.raw.cols(), m);
    ASSERT_EQ(r.normalized.rows(), n);
    ASSERT_EQ(r.normalized.cols(), m);
    ASSERT_EQ(r.total.size(), n);
    ASSERT_EQ(static_cast<Eigen::Index>(r.reasons.size()), n);
    ASSERT_EQ(static_cast<Eigen::Index>(r.min_clearance.size()), n);
    ASSERT_EQ(static_cast<Eigen::Index>(r.free_distance.size()), n);
    ASSERT_EQ(static_cast<Eigen::Index>(planner.rollouts().size()), n);
    for (const Trajectory& t : planner.rollouts()) ASSERT_EQ(t.size(), 20u);
    ASSERT_EQ(r.critic_names, (std::vector<std::string>{"heading", "clearance", "velocity"}));
    ASSERT_EQ(r.weights, (std::vector<double>{0.5, 0.15, 1.0}));
    ASSERT_EQ(r.reject_counts[0] + r.reject_counts[1], n);
    // The first maximum of the total among the samples whose rollouts keep
    // clear (no movers here: min_clearance is the fixed world's), else among all.
    double best = -kInf, best_clear = -kInf;
    for (Eigen::Index i = 0; i < n; ++i) {
      const bool rejected = r.reasons[static_cast<std::size_t>(i)] != RejectReason::None;
      if (rejected) {
        ASSERT_EQ(r.total(i), -kInf);
        ASSERT_EQ(r.raw.row(i).cwiseAbs().maxCoeff(), 0.0);
        ASSERT_EQ(r.normalized.row(i).cwiseAbs().maxCoeff(), 0.0);
        continue;
      }
      ASSERT_NEAR(r.total(i), 0.5 * r.normalized(i, 0) + 0.15 * r.normalized(i, 1) + 1.0 * r.normalized(i, 2), 1e-12);
      ASSERT_LE(r.raw(i, 1), 1.5);  // the cap from the critic's parameters
      ASSERT_EQ(r.raw(i, 2), r.samples[static_cast<std::size_t>(i)].v);
      best = std::max(best, r.total(i));
      if (r.min_clearance[static_cast<std::size_t>(i)] > 0.0) best_clear = std::max(best_clear, r.total(i));
    }
    if (r.status == Status::Ok) {
      const bool any_clear = best_clear > -kInf;
      const double chosen = any_clear ? best_clear : best;
      ASSERT_EQ(r.total(r.best_index), chosen);
      if (any_clear) {
        ASSERT_GT(r.min_clearance[static_cast<std::size_t>(r.best_index)], 0.0);
      }
      // Ties go to the first sample.
      for (Eigen::Index i = 0; i < r.best_index; ++i) {
        if (!any_clear || r.min_clearance[static_cast<std::size_t>(i)] > 0.0) {
          ASSERT_LT(r.total(i), chosen);
        }
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 20);
}

void check_normalization(Normalization mode) {
  std::mt19937 rng(11);
  PlannerParams params;
  params.normalization = mode;
  const RobotLimits limits;
  LocalPlanner planner(limits, Footprint::circle(0.25), params);
  int columns = 0;
  for (unsigned seed = 0; seed < 10; ++seed) {
    const World world = random_world(rng, Vec2::Zero(), 0.25);
    for (int trial = 0; trial < 5; ++trial) {
      const PlanResult& r = planner.plan(random_state(rng, limits, Vec2::Zero()), random_goal(rng), *world.fast);
      if (r.admissible_count() == 0) continue;
      for (Eigen::Index j = 0; j < r.raw.cols(); ++j) {
        double raw_sum = 0.0, sum = 0.0, lo = kInf, hi = -kInf, raw_lo = kInf, raw_hi = -kInf;
        for (Eigen::Index i = 0; i < r.raw.rows(); ++i) {
          if (r.reasons[static_cast<std::size_t>(i)] != RejectReason::None) continue;
          raw_sum += r.raw(i, j);
          sum += r.normalized(i, j);
          lo = std::min(lo, r.normalized(i, j));
          hi = std::max(hi, r.normalized(i, j));
          raw_lo = std::min(raw_lo, r.raw(i, j));
          raw_hi = std::max(raw_hi, r.raw(i, j));
        }
        if (mode == Normalization::Sum) {
          if (raw_sum != 0.0) {
            ASSERT_NEAR(sum, 1.0, 1e-12) << r.critic_names[static_cast<std::size_t>(j)];
            ++columns;
          } else {
            ASSERT_EQ(hi, 0.0);
            ASSERT_EQ(lo, 0.0);
          }
        } else if (mode == Normalization::MinMax) {
          ASSERT_GE(lo, 0.0);
          ASSERT_LE(hi, 1.0);
          if (raw_hi > raw_lo) {
            ASSERT_EQ(lo, 0.0);
            ASSERT_NEAR(hi, 1.0, 1e-12);
            ++columns;
          }
        } else {
          ASSERT_EQ(sum, raw_sum);
          ASSERT_EQ(lo, raw_lo);
          ASSERT_EQ(hi, raw_hi);
          if (raw_hi > raw_lo) ++columns;
        }
      }
      if (mode != Normalization::None) continue;
      // The total is the weighted sum of the raw terms and the choice its first
      // maximum, among the samples that keep clear when some do.
      bool any_clear = false;
      for (Eigen::Index i = 0; i < r.raw.rows(); ++i)
        any_clear = any_clear || (r.reasons[static_cast<std::size_t>(i)] == RejectReason::None &&
                                  r.min_clearance[static_cast<std::size_t>(i)] > 0.0);
      double best = -kInf;
      Eigen::Index best_index = -1;
      for (Eigen::Index i = 0; i < r.raw.rows(); ++i) {
        if (r.reasons[static_cast<std::size_t>(i)] != RejectReason::None) continue;
        ASSERT_EQ(r.normalized.row(i), r.raw.row(i));
        const double total = 0.5 * r.raw(i, 0) + 0.15 * r.raw(i, 1) + 1.0 * r.raw(i, 2);
        ASSERT_NEAR(r.total(i), total, 1e-12);
        if (any_clear && !(r.min_clearance[static_cast<std::size_t>(i)] > 0.0)) continue;
        if (r.total(i) > best) best = r.total(i), best_index = i;
      }
      ASSERT_EQ(r.best_index, best_index);
    }
  }
  EXPECT_GT(columns, 50);
}

TEST(LocalPlanner, SumNormalizationMakesEachColumnSumToOne) { check_normalization(Normalization::Sum); }
TEST(LocalPlanner, MinMaxNormalizationMapsEachColumnOntoZeroOne) { check_normalization(Normalization::MinMax); }
TEST(LocalPlanner, NoNormalizationWeighsTheRawTerms) { check_normalization(Normalization::None); }

TEST(LocalPlanner, SetWeightChangesTheChoice) {
  const RobotLimits limits;
  LocalPlanner planner(limits, Footprint::circle(0.25));
  const FieldClearance empty;
  // Moving along +x with the goal to the left: speed and heading pull apart.
  const RobotState state{Pose2{0.0, 0.0, 0.0}, Twist{0.6, 0.0}};
  const Vec2 goal(0.0, 5.0);
  planner.set_weight("heading", 0.0);
  planner.set_weight("clearance", 0.0);
  planner.set_weight("velocity", 1.0);
  const Twist fast = planner.plan(state, goal, empty).command;
  EXPECT_NEAR(fast.v, 0.75, 1e-12);  // the top of the window
  planner.set_weight("heading", 1.0);
  planner.set_weight("velocity", 0.0);
  EXPECT_EQ(planner.weight("heading"), 1.0);
  const Twist turn = planner.plan(state, goal, empty).command;
  EXPECT_NEAR(turn.omega, 0.3, 1e-12);  // the hardest left turn the window allows
  EXPECT_GT(std::abs(turn.omega - fast.omega) + std::abs(turn.v - fast.v), 0.1);
  expect_error_naming([&] { planner.set_weight("similarity", 1.0); }, "similarity");
  expect_error_naming([&] { planner.set_weight("heading", std::nan("")); }, "heading");
}

TEST(LocalPlanner, RejectsNonFiniteInput) {
  LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25));
  const FieldClearance empty;
  RobotState state;
  state.twist.v = std::nan("");
  expect_error_naming([&] { planner.plan(state, Vec2(1, 1), empty); }, "state v");
  expect_error_naming([&] { planner.plan(RobotState{}, Vec2(kInf, 1), empty); }, "goal x");
}

// Space-time clearance: pose k of a rollout meets each moving disc where the
// disc will be then, and the motion between poses is checked against the
// discs moving too. The first contact the planner reports is the one found by
// walking every rollout on a 1 ms time axis, never later.
// Moving discs held in the sweep as a world that cannot split them off does it.
class Unsplit : public ClearanceSource {
 public:
  explicit Unsplit(const FieldClearance& inner) : inner_(inner) {}
  double clearance(const Footprint& fp, const Pose2& pose, double t) const override {
    return inner_.clearance(fp, pose, t);
  }
  double obstacle_speed() const override { return inner_.obstacle_speed(); }

 protected:
  void lower_bounds(const Footprint& fp, const Trajectory& poses, double dt, double* out) const override {
    inner_.clearance_lower_bounds(fp, poses, dt, out);
  }

 private:
  const FieldClearance& inner_;
};

// Beside a mover (within mover_caution_radius) the velocity critic weighs
// mover_speed_weight of its weight; farther away, or beside a still obstacle,
// all of it.
TEST(LocalPlanner, AMoverNearbyMakesSpeedWorthLess) {
  PlannerParams params;
  params.normalization = Normalization::None;
  params.mover_caution_radius = 2.0;
  params.mover_speed_weight = 0.5;
  const Footprint footprint = Footprint::circle(0.25);
  LocalPlanner planner(RobotLimits{}, footprint, params);
  const RobotState state{Pose2{0.0, 0.0, 0.0}, Twist{0.6, 0.0}};
  const auto velocity_weight_used = [&](const std::vector<Disc>& discs) {
    const FieldClearance world(nullptr, discs);
    const PlanResult& r = planner.plan(state, Vec2(5.0, 0.0), world);
    // total = 0.5 heading + 0.15 clearance + w velocity: solve for w on two samples.
    for (Eigen::Index i = 0; i < r.raw.rows(); ++i) {
      if (r.reasons[static_cast<std::size_t>(i)] != RejectReason::None || r.raw(i, 2) <= 0.0) continue;
      return (r.total(i) - 0.5 * r.raw(i, 0) - 0.15 * r.raw(i, 1)) / r.raw(i, 2);
    }
    return std::nan("");
  };
  // A disc 1.5 m to the left moving away at 0.4 m/s; the same disc 3 m away; the same disc standing.
  EXPECT_NEAR(velocity_weight_used({Disc{Vec2(0.0, 1.5 + 0.6), 0.3, Vec2(0.0, 0.4)}}), 0.5, 1e-9);
  EXPECT_NEAR(velocity_weight_used({Disc{Vec2(0.0, 3.0 + 0.6), 0.3, Vec2(0.0, 0.4)}}), 1.0, 1e-9);
  EXPECT_NEAR(velocity_weight_used({Disc{Vec2(0.0, 1.5 + 0.6), 0.3, Vec2::Zero()}}), 1.0, 1e-9);
  EXPECT_NEAR(velocity_weight_used({}), 1.0, 1e-9);
}

TEST(LocalPlanner, SpaceTimeContactMatchesBruteForceOverTime) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0), angle(-M_PI, M_PI);
  PlannerParams params;
  params.safety_margin = 0.0;
  params.moving_horizon = 0.0;
  const Footprint footprint = Footprint::circle(0.25);
  LocalPlanner planner(RobotLimits{}, footprint, params);
  int checked = 0, exact_matches = 0;
  for (int trial = 0; trial < 40; ++trial) {
    std::vector<Disc> discs;
    for (int i = 0; i < 3; ++i) {
      const double bearing = angle(rng), distance = 0.9 + 1.5 * unit(rng), heading = angle(rng);
      const double speed = 0.3 + 0.9 * unit(rng);
      Disc d{Vec2(distance * std::cos(bearing), distance * std::sin(bearing)), 0.2 + 0.3 * unit(rng),
             speed * Vec2(std::cos(heading), std::sin(heading)), trial % 2 ? 0.1 * unit(rng) : 0.0};
      discs.push_back(d);
    }
    const FieldClearance discs_world(nullptr, discs);
    const Unsplit world(discs_world);
    if (world.clearance(footprint, Pose2{}, 0.0) <= 0.0) continue;
    const PlanResult& result = planner.plan(RobotState{Pose2{0.0, 0.0, angle(rng)}, Twist{0.6, 0.3}}, Vec2(3, 0), world);
    const auto& rollouts = planner.rollouts();
    for (std::size_t i = 0; i < result.samples.size(); ++i) {
      const Twist& cmd = result.samples[i];
      if (cmd.v <= 0.0) continue;
      // Brute force: step k drives from pose k - 1 (time k dt) to pose k ((k + 1) dt).
      int first_contact = params.n_steps();
      for (int k = 0; k < params.n_steps() && first_contact == params.n_steps(); ++k) {
        const Vec2 from = k == 0 ? Vec2::Zero() : rollouts[i][static_cast<std::size_t>(k - 1)].position();
        const Vec2 to = rollouts[i][static_cast<std::size_t>(k)].position();
        for (int m = 0; m <= 100; ++m) {
          const double f = m / 100.0;
          const Vec2 p = from + f * (to - from);
          if (world.clearance(footprint, Pose2{p.x(), p.y(), 0.0}, (k + f) * params.dt) <= 0.0) {
            first_contact = k;
            break;
          }
        }
      }
      const double step = cmd.v * params.dt;
      const int planner_contact = std::isinf(result.free_distance[i])
                                      ? params.n_steps()
                                      : static_cast<int>(std::lround(result.free_distance[i] / step));
      ASSERT_LE(planner_contact, first_contact) << "trial " << trial << ", sample " << i;
      ++checked;
      exact_matches += planner_contact == first_contact;
    }
  }
  ASSERT_GT(checked, 5000);
  // Finer than the brute force's 1 ms only where a contact lasts less than that.
  EXPECT_GE(exact_matches, checked * 99 / 100);
}

// When every sample meets a mover soon, the planner drives the one after which
// the robot can get away best: checked against a brute force that drives each
// sample for one period, then heads for 5 x 5 commands over the whole
// velocity range at the acceleration limits, and finds the first contact with
// the discs on a 10 ms time axis. The chosen sample gets away as late as the
// best (within the planner's coarser contact test), and never earlier than
// the sample whose own arc meets a mover latest.
TEST(LocalPlanner, AnEvasionTakesTheSampleAfterWhichTheRobotGetsAwayBest) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0), angle(-M_PI, M_PI);
  PlannerParams params;
  params.sim_time = 1.5;
  const RobotLimits limits;
  const Footprint footprint = Footprint::circle(0.25);
  LocalPlanner planner(limits, footprint, params);
  const double dt = params.dt, horizon = params.n_steps() * dt;
  // Brute-force first contact (s, horizon if none) of sample `cmd` then the best continuation.
  // Contact as the planner counts it: within the safety margin plus half a
  // step's relative motion (the robot's drive and turn, the fastest disc's travel).
  const auto gets_away_until = [&](const std::vector<Disc>& discs, const RobotState& state, const Twist& cmd) {
    double disc_speed = 0.0;
    for (const Disc& d : discs) disc_speed = std::max(disc_speed, d.velocity.norm());
    const auto touches = [&](const Vec2& p, double t, const Twist& twist) {
      const double allowance = params.safety_margin + 0.5 * dt * (std::abs(twist.v) + footprint.radius() *
                                                                  std::abs(twist.omega) + disc_speed);
      for (const Disc& d : discs)
        if ((p - d.center_at(t)).norm() - footprint.radius() - d.radius_at(t) <= allowance) return true;
      return false;
    };
    const auto toward = [](double from, double to, double rate, double dt_) {
      return to > from ? std::min(to, from + rate * dt_) : std::max(to, from - rate * dt_);
    };
    double best = 0.0;
    for (int a = 0; a < 5; ++a) {
      for (int b = 0; b < 5; ++b) {
        const double v_to = limits.v_min + (limits.v_max - limits.v_min) * a / 4.0;
        const double omega_to = limits.omega_max * (b / 2.0 - 1.0);
        Pose2 pose = state.pose;
        Twist twist = cmd;
        double contact = horizon;
        for (int k = 0; k * dt < horizon - 1e-9 && contact == horizon; ++k) {
          if (k > 0) {
            twist.v = toward(twist.v, v_to, limits.acc_v, dt);
            twist.omega = toward(twist.omega, omega_to, limits.acc_omega, dt);
          }
          const Pose2 next = unicycle_step(pose, twist, dt);
          for (int m = 1; m <= 15; ++m) {
            const double f = m / 15.0;
            if (touches(pose.position() + f * (next.position() - pose.position()), (k + f) * dt, twist)) {
              contact = (k + f) * dt;
              break;
            }
          }
          pose = next;
        }
        best = std::max(best, contact);
      }
    }
    return best;
  };
  int evasions = 0, better_than_latest_arc = 0;
  for (int trial = 0; trial < 300 && evasions < 40; ++trial) {
    std::vector<Disc> discs;
    for (int i = 0; i < 3; ++i) {
      const double bearing = angle(rng), distance = 0.8 + 1.2 * unit(rng);
      const Vec2 center(distance * std::cos(bearing), distance * std::sin(bearing));
      // Heading roughly at the robot, at 0.3-0.8 m/s.
      const double heading = std::atan2(-center.y(), -center.x()) + 0.6 * (unit(rng) - 0.5);
      discs.push_back(Disc{center, 0.3 + 0.2 * unit(rng), (0.3 + 0.5 * unit(rng)) * Vec2(std::cos(heading), std::sin(heading))});
    }
    const FieldClearance world(nullptr, discs);
    if (world.clearance(footprint, Pose2{}, 0.0) <= 0.1) continue;
    const RobotState state{Pose2{0.0, 0.0, angle(rng)}, Twist{1.2 * unit(rng), 0.0}};
    const PlanResult& r = planner.plan(state, Vec2(5.0, 0.0), world);
    if (r.status != Status::Evading) continue;
    ++evasions;
    double best = 0.0;
    int latest_arc = -1;
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      if (r.reasons[i] != RejectReason::Moving) continue;
      best = std::max(best, gets_away_until(discs, state, r.samples[i]));
      if (latest_arc < 0 || r.moving_contact[i] > r.moving_contact[static_cast<std::size_t>(latest_arc)])
        latest_arc = static_cast<int>(i);
    }
    const double chosen = gets_away_until(discs, state, r.command);
    const double arc_choice = gets_away_until(discs, state, r.samples[static_cast<std::size_t>(latest_arc)]);
    // The planner looks at the poses a period apart: a step coarser.
    EXPECT_GE(chosen, best - dt) << "trial " << trial;
    EXPECT_GE(chosen, arc_choice - dt) << "trial " << trial;
    better_than_latest_arc += chosen > arc_choice + 1e-9;
  }
  std::cout << evasions << " evasions; the chosen sample gets away later than the latest-meeting arc in "
            << better_than_latest_arc << "\n";
  ASSERT_GE(evasions, 20);
  EXPECT_GT(better_than_latest_arc, 0);
}

// A slow disc walks at the standing robot, its prediction growing fast (an
// uncertain track, as a tracker gives a disc it has seen for a few scans):
// within the horizon every way meets the grown disc, standing still last,
// since the growth closes in whatever the robot does. Where the disc most
// likely goes, driving off gets away. Each cycle the prediction starts again
// from where the disc is; the robot, at rest, must get out of its way. The
// disc comes from anywhere but within 60 degrees of straight ahead: with no
// reverse (v_min 0) the robot cannot turn away from one ahead before it
// arrives.
TEST(LocalPlanner, WhenNoWayEscapesTheGrownDiscsTheLikelyOnesDecide) {
  PlannerParams params;
  params.sim_time = 1.5;
  const RobotLimits limits;
  const Footprint footprint = Footprint::circle(0.25);
  LocalPlanner planner(limits, footprint, params);
  for (int degrees = 60; degrees <= 300; degrees += 10) {
    const double bearing = degrees * M_PI / 180;
    SCOPED_TRACE(::testing::Message() << "disc from bearing " << bearing);
    const Vec2 toward(-std::cos(bearing), -std::sin(bearing));
    const Disc truth{-1.05 * toward, 0.35, 0.35 * toward};
    RobotState state{Pose2{}, Twist{}};
    double closest = std::numeric_limits<double>::infinity();
    int evasions = 0;
    for (int k = 0; k < 25; ++k) {
      const double t = k * params.dt;
      Disc predicted = truth;
      predicted.center = truth.center_at(t);
      predicted.growth = 0.45;
      const FieldClearance world(nullptr, {predicted});
      // The goal behind the disc: the robot has no business going anywhere but out of its way.
      const PlanResult& r = planner.plan(state, -3.0 * toward, world);
      evasions += r.status == Status::Evading;
      state = RobotState{unicycle_step(state.pose, r.command, params.dt), r.command};
      closest = std::min(closest, (state.pose.position() - truth.center_at(t + params.dt)).norm() - 0.25 - 0.35);
    }
    EXPECT_GT(evasions, 0);
    EXPECT_GT(closest, 0.0);
  }
}

// A disc already at the robot and coming on: every sample meets it in the
// first period, so no continuation helps. The planner drives the sample that
// goes least deep into it over the horizon, not the one that would come out
// farthest beyond it: driving at it, through it, ends farthest away.
TEST(LocalPlanner, WhenEveryWayMeetsAMoverAtOnceTheShallowestWins) {
  PlannerParams params;
  const Footprint footprint = Footprint::circle(0.2);
  LocalPlanner planner(RobotLimits{}, footprint, params);
  for (const double lateral : {-0.1, 0.0, 0.1}) {
    SCOPED_TRACE(::testing::Message() << "disc " << lateral << " m to the side");
    const Disc disc{Vec2(0.45, lateral), 0.24, Vec2(-0.2, 0.0)};
    const FieldClearance world(nullptr, {disc});
    const RobotState state{Pose2{}, Twist{0.3, 0.0}};
    const PlanResult& r = planner.plan(state, Vec2(5.0, 0.0), world);
    ASSERT_EQ(r.status, Status::Evading);
    ASSERT_GE(r.best_index, 0);
    // The least clearance to the disc from the start through the horizon, brute force.
    const auto deepest = [&](std::size_t i) {
      double low = world.moving_clearance(footprint, state.pose, 0.0);
      for (int k = 0; (k + 1) * params.dt - params.dt < params.moving_horizon - 1e-9; ++k)
        low = std::min(low, world.moving_clearance(footprint, planner.rollouts()[i][static_cast<std::size_t>(k)],
                                                   (k + 1) * params.dt));
      return low;
    };
    double shallowest = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      ASSERT_EQ(r.reasons[i], RejectReason::Moving);
      ASSERT_LE(r.moving_contact[i], params.dt);
      shallowest = std::max(shallowest, deepest(i));
    }
    const auto chosen = static_cast<std::size_t>(r.best_index);
    EXPECT_NEAR(deepest(chosen), shallowest, 1e-9);
    // Straight through it at the fastest speed sampled goes deeper.
    std::size_t through = 0;
    for (std::size_t i = 1; i < r.samples.size(); ++i)
      if (std::make_pair(r.samples[i].v, -std::abs(r.samples[i].omega)) >
          std::make_pair(r.samples[through].v, -std::abs(r.samples[through].omega)))
        through = i;
    EXPECT_GT(deepest(chosen), deepest(through) + 0.03)
        << "chose (" << r.samples[chosen].v << ", " << r.samples[chosen].omega << ")";
  }
}

// A disc coming straight at the standing robot meets it 0.85 s ahead. At
// 1 m/s the rejection's horizon is moving_horizon (1 s): standing still is
// rejected. At 3 m/s it is what the disc takes to travel moving_reach (2 m,
// 0.67 s): standing still is admissible and left to the clearance critic;
// with moving_reach 0 it is rejected again.
TEST(LocalPlanner, AmongFastMoversTheRejectionLooksLessFarAhead) {
  const Footprint footprint = Footprint::circle(0.25);
  const RobotState state{Pose2{}, Twist{}};
  const auto standing_reason = [&](double speed, double reach) {
    PlannerParams params;
    params.moving_reach = reach;
    LocalPlanner planner(RobotLimits{}, footprint, params);
    const double meet = 0.85, radius = 0.3;
    // Contact as the planner counts it: within the margin plus half a step's travel.
    const double gap = footprint.radius() + radius + params.safety_margin + 0.5 * params.dt * speed;
    const Disc disc{Vec2(0.0, gap + speed * meet), radius, Vec2(0.0, -speed)};
    const FieldClearance world(nullptr, {disc});
    const PlanResult& r = planner.plan(state, Vec2(5.0, 0.0), world);
    for (std::size_t i = 0; i < r.samples.size(); ++i)
      if (r.samples[i].v == 0.0 && r.samples[i].omega == 0.0) {
        return r.reasons[i];
      }
    ADD_FAILURE() << "no standing sample";
    return RejectReason::None;
  };
  EXPECT_EQ(standing_reason(1.0, 2.0), RejectReason::Moving);
  EXPECT_NE(standing_reason(3.0, 2.0), RejectReason::Moving);
  EXPECT_EQ(standing_reason(3.0, 0.0), RejectReason::Moving);
}

// In open space nothing is rejected and every rollout is free for good.
TEST(LocalPlanner, OpenSpaceAdmitsEverySample) {
  LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25));
  const PlanResult& r = planner.plan(RobotState{Pose2{}, Twist{0.5, 0.2}}, Vec2(4.0, 1.0), FieldClearance());
  EXPECT_EQ(r.status, Status::Ok);
  EXPECT_EQ(r.admissible_count(), 21 * 21);
  for (double d : r.free_distance) EXPECT_TRUE(std::isinf(d));
  for (double c : r.min_clearance) EXPECT_TRUE(std::isinf(c));
}
}  // namespace
}  // namespace fgdwa

namespace fgdwa {
namespace {

// The same world without lower bounds: every pose is evaluated exactly.
class WithoutBounds : public ClearanceSource {
 public:
  explicit WithoutBounds(const ClearanceSource& inner) : inner_(inner) {
    if (&inner.static_part() != &inner) fixed_ = std::make_unique<WithoutBounds>(inner.static_part());
  }
  const ClearanceSource& static_part() const override { return fixed_ ? *fixed_ : *this; }
  double clearance(const Footprint& fp, const Pose2& pose, double t) const override {
    return inner_.clearance(fp, pose, t);
  }
  double obstacle_speed() const override { return inner_.obstacle_speed(); }
  double moving_clearance(const Footprint& fp, const Pose2& pose, double t) const override {
    return inner_.moving_clearance(fp, pose, t);
  }

 private:
  const ClearanceSource& inner_;
  std::unique_ptr<WithoutBounds> fixed_;
};

void expect_bounds_change_nothing(const Footprint& footprint) {
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> where(0.5, 9.5), heading(-M_PI, M_PI), speed(0.0, 1.2), turn(-1.0, 1.0);
  const OccupancyGrid grid = test::random_rectangles(rng, 100, 100, 0.1, Vec2::Zero(), 0.15);
  FieldClearance world(std::make_shared<DistanceField>(grid),
                       {Disc{Vec2(5.0, 5.0), 0.3, Vec2(0.2, -0.1)}});
  const WithoutBounds exact(world);
  LocalPlanner bounded(RobotLimits{}, footprint), plain(RobotLimits{}, footprint);
  // Starts anywhere in the map, then near its edge (within 0.6 m, some just
  // outside), where rollouts leave the grid and the bounds come from its edge.
  std::uniform_real_distribution<double> near_edge(-0.2, 0.6);
  std::bernoulli_distribution coin(0.5);
  int cycles = 0;
  while (cycles < 100) {
    Vec2 start(where(rng), where(rng));
    if (cycles >= 60) start[coin(rng) ? 0 : 1] = coin(rng) ? near_edge(rng) : 10.0 - near_edge(rng);
    const RobotState state{Pose2{start.x(), start.y(), heading(rng)}, Twist{speed(rng), turn(rng)}};
    if (world.clearance(footprint, state.pose, 0.0) < 0.05) continue;
    const Vec2 goal(where(rng), where(rng));
    const PlanResult& a = bounded.plan(state, goal, world);
    const PlanResult& b = plain.plan(state, goal, exact);
    ASSERT_EQ(a.best_index, b.best_index);
    ASSERT_EQ(a.command.v, b.command.v);
    ASSERT_EQ(a.command.omega, b.command.omega);
    ASSERT_EQ(a.reasons, b.reasons);
    ASSERT_EQ(a.free_distance, b.free_distance);
    ASSERT_EQ(a.min_clearance, b.min_clearance);
    ++cycles;
  }
}

TEST(LocalPlanner, ClearanceBoundsChangeNoResultCircle) { expect_bounds_change_nothing(Footprint::circle(0.25)); }

TEST(LocalPlanner, ClearanceBoundsChangeNoResultPolygon) {
  expect_bounds_change_nothing(Footprint::polygon({{0.21, 0.165}, {-0.21, 0.165}, {-0.21, -0.165}, {0.21, -0.165}}));
}

TEST(DistanceField, LowerBoundNeverExceedsTheDistance) {
  std::mt19937 rng(8);
  const OccupancyGrid grid = test::random_rectangles(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.2);
  const DistanceField field(grid);
  std::uniform_real_distribution<double> x(-2.0, 8.0), y(-0.5, 7.5);
  EXPECT_EQ(field.bound_subdivisions(), 4);  // 2.5 cm pieces of 0.1 m cells
  const double piece_diagonal = std::sqrt(2.0) * 0.1 / 4;
  const double step = 0.1 / 4 / 64;  // the table holds bounds in 64ths of a piece
  for (int i = 0; i < 20000; ++i) {
    const Vec2 p(x(rng), y(rng));
    const double bound = field.lower_bound(p), d = field.distance(p);
    ASSERT_LE(bound, d + 1e-12);
    const bool inside = p.x() > -1.0 && p.x() < 7.0 && p.y() > 0.5 && p.y() < 6.5;
    const bool tight = bound >= d - piece_diagonal - step - 1e-9;  // no looser than its piece and one step
    if (inside) {
      ASSERT_TRUE(tight);
    } else {
      // Outside: as tight as inside where the field keeps its free margin,
      // and beyond it at least as far as the grid's edge.
      const double edge = std::hypot(std::max({-1.0 - p.x(), 0.0, p.x() - 7.0}), std::max({0.5 - p.y(), 0.0, p.y() - 6.5}));
      ASSERT_TRUE(tight || bound >= edge * (1.0 - 1e-9)) << p.transpose() << " bound " << bound << " d " << d;
    }
  }
}

// The upper bound comes from the same piece: never below the distance, at
// most the piece's diagonal and two steps above the lower bound, and +inf
// (no claim) off the table, where the field keeps no pieces.
TEST(DistanceField, UpperBoundNeverFallsBelowTheDistance) {
  std::mt19937 rng(9);
  const OccupancyGrid grid = test::random_rectangles(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.2);
  const DistanceField field(grid, 1.0);
  std::uniform_real_distribution<double> x(-3.0, 9.0), y(-2.5, 9.5);
  const double piece_diagonal = std::sqrt(2.0) * 0.1 / 4, step = 0.1 / 4 / 64;
  int on_table = 0, near_obstacles = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec2 p(x(rng), y(rng));
    const double upper = field.upper_bound(p), d = field.distance(p);
    ASSERT_GE(upper, d) << p.transpose();
    const bool table = p.x() > -1.9 && p.x() < 7.9 && p.y() > -0.4 && p.y() < 7.4;  // the grid and its 1 m margin
    const bool off_table = p.x() < -2.1 || p.x() > 8.1 || p.y() < -0.6 || p.y() > 7.6;
    if (table) {
      ASSERT_LE(upper, field.lower_bound(p) + piece_diagonal + 2.0 * step + 1e-9) << p.transpose();
      ++on_table;
      near_obstacles += d < 0.15;
    }
    if (off_table) {
      ASSERT_EQ(upper, std::numeric_limits<double>::infinity()) << p.transpose();
    }
  }
  EXPECT_GT(on_table, 10000);
  EXPECT_GT(near_obstacles, 1000);
  EXPECT_THROW(field.upper_bound(Vec2(std::nan(""), 0.0)), Error);
  EXPECT_EQ(DistanceField(OccupancyGrid(3, 3, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(9, 0))).upper_bound(Vec2(0.1, 0.1)),
            std::numeric_limits<double>::infinity());
}

// Farther than the table's 16 bits reach (1024 pieces, 25.6 m here) a bound
// stays at the largest it holds: still below the distance, and not wrapped
// round to a small one.
TEST(DistanceField, LowerBoundFarFromEveryObstacleStaysAtTheTablesLargest) {
  std::vector<std::uint8_t> cells(3000, 0);
  cells[0] = 1;
  const OccupancyGrid grid(1, 3000, 0.1, Vec2(0.0, 0.0), cells);  // one obstacle at x = 0, 300 m of row
  const DistanceField field(grid);
  ASSERT_EQ(field.bound_subdivisions(), 4);
  const double piece_diagonal = std::sqrt(2.0) * 0.1 / 4, step = 0.1 / 4 / 64, largest = 65535 * step;
  for (double x = 0.05; x < 300.0; x += 0.37) {
    const Vec2 p(x, 0.05);
    const double bound = field.lower_bound(p), d = field.distance(p);
    ASSERT_LE(bound, d + 1e-12) << x;
    ASSERT_GE(bound, std::min(d - piece_diagonal - step, largest) - 1e-9) << x;
    ASSERT_LE(bound, largest) << x;
  }
  EXPECT_EQ(field.lower_bound(Vec2(250.0, 0.05)), largest);
}

// A segment's distance is exact, inside the grid, outside it and across its
// edges and corners: no sample along it is nearer, and the nearest of fine
// samples is within half their spacing of it.
TEST(DistanceField, SegmentDistanceIsTheNearestPointOfTheSegment) {
  std::mt19937 rng(9);
  const OccupancyGrid grid = test::random_rectangles(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.2);
  const DistanceField field(grid);
  // The grid spans x in [-1, 7] and y in [0.5, 6.5].
  std::uniform_real_distribution<double> x(-0.8, 6.8), y(0.7, 6.3), step(-0.1, 0.1);
  std::uniform_real_distribution<double> out_x(-1.6, 7.6), out_y(-0.1, 7.1), long_step(-0.4, 0.4);
  int touching = 0, across = 0;
  for (int i = 0; i < 6000; ++i) {
    const bool inside = i % 2 == 0;
    const Vec2 a = inside ? Vec2(x(rng), y(rng)) : Vec2(out_x(rng), out_y(rng));
    const Vec2 b = a + (inside ? Vec2(step(rng), step(rng)) : Vec2(long_step(rng), long_step(rng)));
    const auto in_grid = [](const Vec2& p) { return p.x() >= -1.0 && p.x() <= 7.0 && p.y() >= 0.5 && p.y() <= 6.5; };
    across += in_grid(a) != in_grid(b);
    const double d = field.segment_distance(a, b);
    double sampled = kInf;
    const int n = 200;
    for (int k = 0; k <= n; ++k) sampled = std::min(sampled, field.distance(a + (b - a) * (double(k) / n)));
    SCOPED_TRACE(::testing::Message() << "a " << a.transpose() << " b " << b.transpose());
    ASSERT_LE(d, sampled + 1e-12);
    ASSERT_GE(d, sampled - 0.5 * (b - a).norm() / n - 1e-12);
    touching += d == 0.0;
  }
  EXPECT_GT(touching, 100);
  EXPECT_GT(across, 150);
  // A segment of one point is that point's distance; one lying along the
  // grid's edge is no farther than any of its points.
  EXPECT_DOUBLE_EQ(field.segment_distance(Vec2(-1.05, 1.0), Vec2(-1.05, 1.0)), field.distance(Vec2(-1.05, 1.0)));
  EXPECT_LE(field.segment_distance(Vec2(-1.0, 0.5), Vec2(7.0, 0.5)), field.distance(Vec2(3.0, 0.5)));
  // No obstacles: infinitely far.
  const DistanceField empty(OccupancyGrid(10, 10, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(100, 0)));
  EXPECT_TRUE(std::isinf(empty.segment_distance(Vec2(0.2, 0.2), Vec2(0.3, 0.3))));
}

// The single-precision DTW must not change what the planner drives: over
// 10 000 random cycles the chosen sample is the double-precision one's, except
// where the reference's two best totals lie within 1e-6 (a tie either may win).
TEST(LocalPlanner, SinglePrecisionDtwChoosesAsDoubleDoes) {
  const RobotLimits limits;
  const Footprint fp = Footprint::circle(0.25);
  const auto planner_with = [&](const std::string& precision, double similarity_weight) {
    PlannerParams params = planner_preset("fgdwa").params;
    for (CriticConfig& c : params.critics)
      if (c.name == "similarity") {
        c.options["precision"] = precision;
        c.weight = similarity_weight;
      }
    return LocalPlanner(limits, fp, params);
  };
  int cycles = 0, chosen = 0, ties = 0;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (unsigned seed = 1; seed <= 100; ++seed) {
    std::mt19937 rng(900 + seed);
    // Far from the origin, where a float's digits would not hold millimetres.
    const Vec2 origin(200.0 * u(rng) - 100.0, 200.0 * u(rng) - 100.0);
    const Vec2 start = origin + Vec2(4.0, 4.0);
    const OccupancyGrid grid = test::random_rectangles(rng, 80, 80, 0.1, origin, 0.05, 6, start, 0.6);
    const FieldClearance world(std::make_shared<const DistanceField>(grid));
    const double weight = 0.05 + 2.0 * u(rng);
    LocalPlanner single = planner_with("single", weight), reference = planner_with("double", weight);
    for (int trial = 0; trial < 100; ++trial) {
      std::vector<Vec2> points{start};
      for (int k = 0; k < 1 + trial % 4; ++k) points.push_back(points.back() + Vec2(3.0 * u(rng) - 1.5, 3.0 * u(rng) - 1.5));
      const GlobalPath path(points);
      single.set_global_path(path);
      reference.set_global_path(path);
      const RobotState state = random_state(rng, limits, start);
      const Vec2 goal = points.back();
      const int a = single.plan(state, goal, world).best_index;
      const PlanResult& r = reference.plan(state, goal, world);
      ++cycles;
      if (r.best_index < 0) {
        EXPECT_EQ(a, -1);
        continue;
      }
      ++chosen;
      if (a == r.best_index) continue;
      ASSERT_GE(a, 0);
      // Which samples tie for first in the reference?
      std::vector<double> totals(r.total.data(), r.total.data() + r.total.size());
      std::nth_element(totals.begin(), totals.begin() + 1, totals.end(), std::greater<double>());
      const bool tie = totals[0] - totals[1] <= 1e-6;
      EXPECT_TRUE(tie) << "seed " << seed << " trial " << trial << ": single chose " << a << ", double "
                       << r.best_index << " (totals " << r.total[a] << " and " << r.total[r.best_index] << ")";
      if (tie) {
        ++ties;
        EXPECT_LE(r.total[r.best_index] - r.total[a], 1e-6);  // the other sample of the tie
      }
    }
  }
  std::printf("single vs double DTW: %d cycles, %d with a choice, %d differ within a 1e-6 tie\n", cycles, chosen, ties);
  EXPECT_EQ(cycles, 10000);
  EXPECT_GT(chosen, 9000);
}

}  // namespace
}  // namespace fgdwa

namespace fgdwa {
namespace {

// States no command produces: a push, a slope or a bad report.
const std::vector<Twist> kWildTwists = {{5.0, 0.0}, {-1.0, 0.0}, {0.3, 10.0}, {0.3, -10.0}, {5.0, 10.0}, {-1.0, -10.0}};

void expect_inside_limits(const Twist& command, const RobotLimits& limits) {
  EXPECT_GE(command.v, limits.v_min);
  EXPECT_LE(command.v, limits.v_max);
  EXPECT_LE(std::abs(command.omega), limits.omega_max);
}

TEST(LocalPlanner, CommandsStayInsideTheLimitsWhateverTheState) {
  RobotLimits limits;
  limits.v_max = 0.8;
  PlannerParams params;
  params.wheels = WheelModel::Ramp;
  LocalPlanner planner(limits, Footprint::circle(0.25), params);
  const FieldClearance open;
  const std::vector<std::uint8_t> cells = [] {
    std::vector<std::uint8_t> c(40 * 40, 0);
    for (int row = 15; row < 25; ++row) c[static_cast<std::size_t>(row) * 40 + 30] = 1;  // a wall 1 m ahead
    return c;
  }();
  const FieldClearance wall(std::make_shared<DistanceField>(OccupancyGrid(40, 40, 0.1, Vec2(-2.0, -2.0), cells)));
  for (const Twist& wild : kWildTwists)
    for (const FieldClearance* world : {&open, &wall}) {
      SCOPED_TRACE(::testing::Message() << "state twist " << wild.v << ", " << wild.omega);
      const RobotState state{Pose2{}, wild};
      const PlanResult& r = planner.plan(state, Vec2(3.0, 0.0), *world);
      expect_inside_limits(r.command, limits);
      for (const Twist& sample : r.samples) expect_inside_limits(sample, limits);
      // The rollouts start where the robot is: the first step brakes from the state's twist.
      if (!r.samples.empty()) {
        const Trajectory expected = rollout(state.pose, wild, r.samples[0], limits, params.dt, 2);
        EXPECT_LT((planner.rollouts()[0][1].position() - expected[1].position()).norm(), 1e-9);
      }
    }
  // With a wall 1 m ahead, 5 m/s cannot stop in time: every sample is rejected, the command brakes.
  const PlanResult& r = planner.plan(RobotState{Pose2{}, Twist{5.0, 0.0}}, Vec2(3.0, 0.0), wall);
  EXPECT_EQ(r.status, Status::NoAdmissibleVelocity);
  EXPECT_EQ(r.command.v, limits.v_max);  // the closest to braking the wheels may be asked for
}

// Wheels that lag behind a command: the rollouts follow the lag (the first
// step from rest covers the lag's mean, not the command's v dt), so a robot
// told its response does not count on a turn or a stop it cannot make.
TEST(LocalPlanner, RolloutsFollowTheWheelsResponse) {
  RobotLimits limits;
  limits.v_max = 1.0;  // speed samples every 0.05 m/s
  limits.acc_v = limits.brake_v = 100.0;
  limits.acc_omega = limits.brake_omega = 100.0;
  PlannerParams params;
  params.wheels = WheelModel::Ramp;
  params.dt = 0.1;
  params.sim_time = 1.0;
  const FieldClearance open;
  const RobotState rest{Pose2{}, Twist{}};
  LocalPlanner prompt(limits, Footprint::circle(0.25), params);
  params.response_time = 0.1;
  LocalPlanner lagging(limits, Footprint::circle(0.25), params);
  prompt.plan(rest, Vec2(3.0, 0.0), open);
  const PlanResult& r = lagging.plan(rest, Vec2(3.0, 0.0), open);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const Twist& s = r.samples[i];
    if (s.omega != 0.0 || s.v <= 0.0) continue;
    const double first = lagging.rollouts()[i][0].x;
    EXPECT_NEAR(first, s.v * (1.0 - (1.0 - std::exp(-1.0))) * params.dt, 1e-9) << "v " << s.v;
    EXPECT_LT(first, prompt.rollouts()[i][0].x);
  }
  // Lagging wheels brake late: 1 m/s toward a wall 0.25 m off the footprint is
  // admissible to prompt wheels only.
  const std::vector<std::uint8_t> cells = [] {
    std::vector<std::uint8_t> c(40 * 40, 0);
    for (int row = 0; row < 40; ++row) c[static_cast<std::size_t>(row) * 40 + 25] = 1;  // x = 0.5 m
    return c;
  }();
  const FieldClearance wall(std::make_shared<DistanceField>(OccupancyGrid(40, 40, 0.1, Vec2(-2.0, -2.0), cells)));
  // 0.12 m from the wall's margin at 0.5 m/s: straight on, contact after 0.1 m;
  // prompt wheels need 0.05 m and 1 mm of braking, lagging ones 0.05 m more.
  const RobotState moving{Pose2{0.11, 0.0, 0.0}, Twist{0.5, 0.0}};
  const auto admits_straight = [&](LocalPlanner& planner) {
    const PlanResult& plan = planner.plan(moving, Vec2(3.0, 0.0), wall);
    for (std::size_t i = 0; i < plan.samples.size(); ++i)
      if (plan.samples[i].omega == 0.0 && std::abs(plan.samples[i].v - 0.5) < 1e-9)
        return plan.reasons[i] == RejectReason::None;
    ADD_FAILURE() << "no straight sample at 0.5 m/s";
    return false;
  };
  EXPECT_TRUE(admits_straight(prompt));
  EXPECT_FALSE(admits_straight(lagging));
}

TEST(Controller, CommandsStayInsideTheLimitsWhateverTheState) {
  RobotLimits limits;
  limits.v_max = 0.8;
  Controller controller(limits, Footprint::circle(0.25), PlannerParams{});
  for (const Twist& wild : kWildTwists) {
    SCOPED_TRACE(::testing::Message() << "state twist " << wild.v << ", " << wild.omega);
    const CycleReport& r = controller.step(RobotState{Pose2{}, wild}, Vec2(3.0, 0.0), nullptr);
    expect_inside_limits(r.command, limits);
    // At the goal the command brakes, inside the limits too.
    const CycleReport& at_goal = controller.step(RobotState{Pose2{3.0, 0.0, 0.0}, wild}, Vec2(3.0, 0.0), nullptr);
    EXPECT_EQ(at_goal.status, Status::GoalReached);
    expect_inside_limits(at_goal.command, limits);
  }
}

}  // namespace
}  // namespace fgdwa
