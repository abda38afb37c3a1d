// The Navigator's modes and every transition between them, its replanning,
// terrain in the local planner, and its checks of bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

#include "fgdwa/navigator.hpp"
#include "fgdwa/presets.hpp"
#include "test_support.hpp"

using namespace fgdwa;
using fgdwa::test::expect_error_naming;
using fgdwa::test::kInf;

namespace {

OccupancyGrid room(int rows, int cols, const std::vector<std::array<int, 4>>& boxes = {}) {
  return fgdwa::test::grid_with_boxes(rows, cols, 0.1, Vec2(0.0, 0.0), boxes);
}

PlannerParams gdwa() { return planner_preset("gdwa").params; }

RobotState at(double x, double y, double theta = 0.0) {
  RobotState s;
  s.pose = Pose2{x, y, theta};
  return s;
}

// Steps the navigator without moving the robot: a robot held in place stalls.
const CycleRecord& hold(Navigator& nav, const RobotState& state, int cycles, double& t, double dt) {
  const CycleRecord* r = nullptr;
  for (int i = 0; i < cycles; ++i, t += dt) r = &nav.step(state, nullptr, t);
  return *r;
}

struct Drive {
  RobotState state;
  double t = 0.0;
};

// One cycle in a world of `truth`: scan, step, move.
const CycleRecord& drive(Navigator& nav, Drive& d, const LaserScanner* scanner, std::mt19937_64& rng, Scan& scan,
                         double dt) {
  if (scanner) scanner->scan(d.state.pose, {}, 0.0, rng, scan);
  const CycleRecord& r = nav.step(d.state, scanner ? &scan : nullptr, d.t);
  d.state.pose = unicycle_step(d.state.pose, r.command, dt);
  d.state.twist = r.command;
  d.t += dt;
  return r;
}

}  // namespace

TEST(Navigator, FollowsToTheGoalAndReportsGoalReached) {
  const OccupancyGrid map = room(40, 60, {{5, 25, 8, 4}, {28, 35, 8, 4}});
  Navigator nav(RobotLimits{}, Footprint::circle(0.25), gdwa(), map, MapMode::Known, LidarParams{});
  nav.set_goal(Vec2(5.0, 2.0));
  Drive d{at(0.8, 2.0)};
  std::mt19937_64 rng(0);
  Scan scan;
  const FieldClearance truth(std::make_shared<DistanceField>(map));
  NavigatorMode last = NavigatorMode::Following;
  for (int i = 0; i < 300 && last != NavigatorMode::GoalReached; ++i) {
    const CycleRecord& r = drive(nav, d, nullptr, rng, scan, 0.15);
    ASSERT_GT(truth.clearance(Footprint::circle(0.25), d.state.pose, 0.0), 0.0);
    if (i == 0) {
      EXPECT_EQ(r.mode, NavigatorMode::Replanning);  // the first path
      EXPECT_EQ(r.path_version, 1);
      ASSERT_TRUE(r.path);
    }
    
    last = r.mode;
    if (r.planned) {
      EXPECT_LE(r.control.best.size(), 5u);
      for (std::size_t k = 1; k < r.control.best.size(); ++k) EXPECT_GE(r.control.best[k - 1].total, r.control.best[k].total);
      if (r.control.choice.sample >= 0) {
        ASSERT_FALSE(r.control.best.empty());
        EXPECT_EQ(r.control.best[0].sample, r.control.choice.sample);
        EXPECT_EQ(r.control.choice.poses.size(), static_cast<std::size_t>(gdwa().n_steps()));
        EXPECT_EQ(r.control.choice.total, r.control.best[0].total);
      }
      // Each critic's part of a total, in the planner's order, adds up to it exactly.
      for (const ScoredRollout& b : r.control.best) {
        ASSERT_EQ(b.terms.size(), r.control.critic_names.size());
        ASSERT_EQ(b.raw.size(), r.control.critic_names.size());
        double sum = 0.0;
        for (const double term : b.terms) sum += term;
        EXPECT_EQ(sum, b.total);
      }
      // Every admissible rollout's term lies within its critic's statistics.
      ASSERT_EQ(r.control.critic_stats.size(), r.control.critic_names.size());
      for (const ScoredRollout& b : r.control.best)
        for (std::size_t j = 0; j < b.terms.size(); ++j) {
          const CriticStats& stats = r.control.critic_stats[j];
          EXPECT_LE(stats.min, b.terms[j]);
          EXPECT_GE(stats.max, b.terms[j]);
          EXPECT_LE(stats.min, stats.mean);
          EXPECT_LE(stats.mean, stats.max + 1e-12);
        }
    }
  }
  EXPECT_EQ(last, NavigatorMode::GoalReached);
  EXPECT_EQ(nav.path_version(), 1);  // the known map never blocks its own path
  const CycleRecord& after = nav.step(d.state, nullptr, d.t);
  EXPECT_EQ(after.mode, NavigatorMode::GoalReached);
  EXPECT_LE(std::abs(after.command.v), std::abs(d.state.twist.v));
}

TEST(Navigator, ReplansWhenTheScanShowsThePathBlocked) {
  // A wall across the room, open at the top, that the map built from scans lacks at first.
  const OccupancyGrid truth = room(30, 60, {{0, 30, 22, 1}});
  LidarParams lidar;
  NavigatorParams params;
  params.start_watch_time = 0.0;  // plans at the first scan
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), truth, MapMode::Scan, lidar, nullptr, params);
  nav.set_goal(Vec2(5.5, 1.0));
  // A short-sighted first scan sees nothing: the first path is straight (unknown is free).
  const LaserScanner blind(LidarParams{lidar.fov, lidar.beams, 0.5, 0.0}, std::make_shared<DistanceField>(truth));
  std::mt19937_64 rng(0);
  Scan scan;
  blind.scan(Pose2{0.5, 1.0, 0.0}, {}, 0.0, rng, scan);
  const CycleRecord& first = nav.step(at(0.5, 1.0), &scan, 0.0);
  EXPECT_EQ(first.mode, NavigatorMode::Replanning);
  ASSERT_TRUE(first.path);
  for (const Vec2& p : first.path->points()) EXPECT_NEAR(p.y(), 1.0, 1e-9);
  // The full scan shows the wall; the replan waits for replan_period (0.5 s: 3 cycles of 0.15 s).
  const LaserScanner seeing(lidar, std::make_shared<DistanceField>(truth));
  double t = 0.15;
  int replanned_at = -1;
  for (int i = 1; i <= 6 && replanned_at < 0; ++i, t += 0.15) {
    seeing.scan(Pose2{0.5, 1.0, 0.0}, {}, 0.0, rng, scan);
    const CycleRecord& r = nav.step(at(0.5, 1.0), &scan, t);
    if (i == 1) {
      EXPECT_GT(r.new_cells, 0u);
    }
    if (r.path_version == 2) {
      replanned_at = i;
      EXPECT_EQ(r.mode, NavigatorMode::Replanning);
      double top = 0.0;
      for (const Vec2& p : r.path->points()) top = std::max(top, p.y());
      EXPECT_GT(top, 2.2);  // over the wall's open end
    }
  }
  EXPECT_EQ(replanned_at, 3);
}

TEST(Navigator, StandsWatchingFromItsFirstScanThenDrives) {
  const OccupancyGrid truth = room(30, 60);
  const LidarParams lidar;
  const LaserScanner scanner(lidar, std::make_shared<DistanceField>(truth));
  std::mt19937_64 rng(0);
  Scan scan;
  RobotState moving = at(1.0, 1.5);
  moving.twist = Twist{0.4, 0.0};  // braked to a stop, within the limits
  for (const bool track : {true, false}) {
    NavigatorParams params;
    params.track_moving = track;
    params.start_watch_time = 0.45;  // 3 cycles of 0.15 s
    Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), truth, MapMode::Scan, lidar, nullptr, params);
    nav.set_goal(Vec2(5.5, 1.5));
    // Steps without a scan do not start the watch.
    EXPECT_TRUE(nav.step(moving, nullptr, 0.0).planned);
    int watched = 0;
    double t = 0.15;
    for (int i = 0; i < 6; ++i, t += 0.15) {
      scanner.scan(moving.pose, {}, 0.0, rng, scan);
      const CycleRecord& r = nav.step(moving, &scan, t);
      if (r.mode != NavigatorMode::Waiting) break;
      ++watched;
      EXPECT_EQ(r.trigger, RecoveryTrigger::Start);
      EXPECT_FALSE(r.planned);
      EXPECT_LT(r.command.v, moving.twist.v);
      EXPECT_GE(r.command.v, 0.0);
    }
    EXPECT_EQ(watched, track ? 3 : 0) << "track_moving " << track;
    EXPECT_TRUE(nav.record().planned);
    EXPECT_EQ(nav.record().trigger, RecoveryTrigger::None);
    EXPECT_GT(nav.record().command.v, 0.0);
  }
}

TEST(Recovery, AWatchOfNoTimeOrOfABadOneIsRefusedOrNone) {
  Recovery recovery(RobotLimits{}, Footprint::circle(0.2), NavigatorParams{}, 0.1, 0.02, 0.1);
  for (const double bad : {-0.1, std::nan(""), std::numeric_limits<double>::infinity(), 1e300})
    EXPECT_THROW(recovery.watch(bad), Error) << bad;
  recovery.watch(0.04);  // under half a cycle: no watch
  EXPECT_EQ(recovery.mode(), NavigatorMode::Following);
  recovery.watch(0.3);
  EXPECT_EQ(recovery.mode(), NavigatorMode::Waiting);
  EXPECT_EQ(recovery.trigger(), RecoveryTrigger::Start);
}

TEST(Navigator, SomethingTheScansFindOnTheGoalIsDrivenUpToNotRefused) {
  // A box standing on the goal (another robot, a person) that only the scans show.
  const OccupancyGrid truth = room(30, 60, {{12, 47, 6, 6}});
  LidarParams lidar;
  const LaserScanner scanner(lidar, std::make_shared<DistanceField>(truth));
  std::mt19937_64 rng(0);
  Scan scan;
  const Vec2 goal(4.8, 1.5);  // 0.1 m from the box's near side, inside every inflation of it
  for (const MapMode mode : {MapMode::Scan, MapMode::Known}) {
    // Scan: the map is built from the scans; Known: the given map lacks the box and learns it.
    Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), mode == MapMode::Scan ? truth : room(30, 60), mode,
                  lidar);
    nav.set_goal(goal);
    double t = 0.0;
    const CycleRecord* r = nullptr;
    for (int i = 0; i < 4; ++i, t += 0.15) {
      scanner.scan(Pose2{1.0, 1.5, 0.0}, {}, 0.0, rng, scan);
      r = &nav.step(at(1.0, 1.5), &scan, t);
      EXPECT_NE(r->mode, NavigatorMode::Failed) << to_string(mode) << " cycle " << i;
    }
    EXPECT_TRUE(nav.map().occupied_at(Vec2(4.75, 1.5))) << to_string(mode);  // the box's near side is on the map...
    ASSERT_TRUE(r->path);
    EXPECT_LT((r->path->points().back() - goal).norm(), 1e-9);  // ... and the path still leads to the goal
  }
  // A goal inside the given map's obstacles stays refused.
  Navigator walled(RobotLimits{}, Footprint::circle(0.2), gdwa(), truth, MapMode::Known, lidar);
  walled.set_goal(goal);
  EXPECT_EQ(walled.step(at(1.0, 1.5), nullptr, 0.0).failure, FailureReason::NoGlobalPath);
}

// Moving to and fro without getting anywhere is a stall too: a robot going
// round a circle of 0.2 m (never 3 s without 0.1 m of displacement) stays
// within 0.5 m of one point, and after wander_time a recovery begins.
TEST(Navigator, WanderingInPlaceIsAStall) {
  const OccupancyGrid map = room(30, 60);
  for (const double wander_time : {10.0, 0.0}) {
    NavigatorParams params;
    params.wander_time = wander_time;
    Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
    nav.set_goal(Vec2(5.5, 1.5));
    int stalled_at = -1;
    for (int i = 0; i < 100 && stalled_at < 0; ++i) {
      const double a = 2.0 * 3.141592653589793 * (0.15 * i) / 4.0;  // once round every 4 s
      const CycleRecord& r = nav.step(at(2.0 + 0.2 * std::cos(a), 1.5 + 0.2 * std::sin(a)), nullptr, 0.15 * i);
      if (r.trigger != RecoveryTrigger::None) {
        EXPECT_EQ(r.trigger, RecoveryTrigger::Wandering);
        stalled_at = i;
      }
    }
    // 10 s of 0.15 s cycles, counted from the first.
    EXPECT_EQ(stalled_at, wander_time > 0.0 ? 67 : -1) << "wander_time " << wander_time;
  }
}

TEST(Navigator, StallBacksUpWithinTheLimitsThenReplansAroundTheGivenUpPath) {
  const OccupancyGrid map = room(30, 60);
  NavigatorParams params;
  params.stall_time = 0.75;  // 5 cycles of 0.15 s
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  nav.set_goal(Vec2(5.5, 1.5));
  double t = 0.0;
  const RobotState held = at(2.0, 1.5);
  const CycleRecord& before = hold(nav, held, 5, t, 0.15);
  EXPECT_EQ(before.mode, NavigatorMode::Following);
  EXPECT_EQ(before.recoveries, 0);
  const CycleRecord& stalled = nav.step(held, nullptr, t);  // six positions within 0.1 m
  t += 0.15;
  ASSERT_EQ(stalled.mode, NavigatorMode::BackingUp);
  EXPECT_EQ(stalled.recoveries, 1);
  EXPECT_FALSE(stalled.planned);
  // Reverse within the acceleration limit, up to backup_speed, then stop after backup_distance.
  RobotState s = held;
  const RobotLimits limits;
  double driven = 0.0;
  Twist command = stalled.command;
  int cycles = 0;
  while (true) {
    EXPECT_LE(command.v, 0.0);
    EXPECT_GE(command.v, -params.backup_speed - 1e-12);
    EXPECT_LE(std::abs(command.v - s.twist.v), limits.acc_v * 0.15 + 1e-12);
    driven += -command.v * 0.15;
    s.pose = unicycle_step(s.pose, command, 0.15);
    s.twist = command;
    const CycleRecord& r = nav.step(s, nullptr, t);
    t += 0.15;
    ++cycles;
    ASSERT_LT(cycles, 40);
    if (r.mode != NavigatorMode::BackingUp) {
      // Backed up: the planner takes over on a new path around the given-up stretch.
      EXPECT_TRUE(r.planned);
      EXPECT_EQ(r.mode, NavigatorMode::Replanning);
      EXPECT_EQ(r.path_version, 2);
      double off = 0.0;
      for (const Vec2& p : r.path->points()) off = std::max(off, std::abs(p.y() - 1.5));
      EXPECT_GT(off, 0.1);
      break;
    }
    command = r.command;
  }
  EXPECT_NEAR(driven, params.backup_distance, 0.06);
  EXPECT_EQ(nav.mode_counts()[static_cast<std::size_t>(NavigatorMode::BackingUp)], cycles);
}

TEST(Navigator, StallWithTheRearBlockedRotatesTowardOpenSpace) {
  // A corridor along x: the robot stands across it, facing its upper wall, its back
  // 1.5 cm from the lower one. Backing up is blocked; turning toward +-x opens the way.
  const OccupancyGrid map = room(40, 40, {{17, 0, 1, 40}, {25, 0, 1, 40}});
  NavigatorParams params;
  params.stall_time = 0.3;  // 2 cycles
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  nav.set_goal(Vec2(3.5, 2.1));
  double t = 0.0;
  const RobotState held = at(2.0, 2.015, M_PI / 2);
  hold(nav, held, 2, t, 0.15);
  const CycleRecord& r = nav.step(held, nullptr, t);
  ASSERT_EQ(r.mode, NavigatorMode::Rotating);
  EXPECT_EQ(r.command.v, 0.0);
  EXPECT_NE(r.command.omega, 0.0);
  EXPECT_LE(std::abs(r.command.omega), RobotLimits{}.acc_omega * 0.15 + 1e-12);
  // Turning ends the recovery: the goal heading reached, the limit turned, or the turn blocked.
  RobotState s = held;
  Twist command = r.command;
  t += 0.15;
  double turned = 0.0;
  for (int i = 0; i < 200; ++i, t += 0.15) {
    s.pose = unicycle_step(s.pose, command, 0.15);
    s.twist = command;
    turned += std::abs(command.omega) * 0.15;
    const CycleRecord& next = nav.step(s, nullptr, t);
    if (next.mode != NavigatorMode::Rotating) {
      EXPECT_TRUE(next.planned);
      EXPECT_NEAR(std::abs(wrap_angle(s.pose.theta - M_PI / 2)), M_PI / 2, 0.06);  // along the corridor
      EXPECT_LE(turned, params.rotate_limit + 1e-9);
      return;
    }
    command = next.command;
  }
  FAIL() << "the rotation never ended";
}

TEST(Navigator, StallBesideAMovingObstacleWaitsThenFollows) {
  const OccupancyGrid map = room(30, 60);
  NavigatorParams params;
  params.stall_time = 0.3;
  params.wait_time = 0.6;  // 4 cycles
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  nav.set_goal(Vec2(5.5, 1.5));
  const std::vector<Disc> passing = {Disc{Vec2(2.8, 1.5), 0.3, Vec2(0.0, 0.5)}};
  double t = 0.0;
  const RobotState held = at(2.0, 1.5);
  for (int i = 0; i < 2; ++i, t += 0.15) nav.step(held, nullptr, t, passing);
  int waited = 0;
  for (int i = 0; i < 10; ++i, t += 0.15) {
    const CycleRecord& r = nav.step(held, nullptr, t, passing);
    if (r.mode == NavigatorMode::Waiting) {
      ++waited;
      EXPECT_EQ(r.command.v, 0.0);
    } else if (waited) {
      EXPECT_TRUE(r.planned);  // the wait over, the planner drives again
      break;
    }
  }
  EXPECT_EQ(waited, 4);
}

TEST(Navigator, AMoverComingAtAStalledRobotEndsTheWaitAtOnce) {
  // The same stall as above, but the mover heads for the robot: standing
  // still there is no way to let it pass, so the planner keeps driving.
  const OccupancyGrid map = room(30, 60);
  NavigatorParams params;
  params.stall_time = 0.3;
  params.wait_time = 0.6;
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  nav.set_goal(Vec2(5.5, 1.5));
  const std::vector<Disc> coming = {Disc{Vec2(2.0, 2.2), 0.3, Vec2(0.0, -0.4)}};  // in contact after 0.5 s
  double t = 0.0;
  const RobotState held = at(2.0, 1.5);
  for (int i = 0; i < 12; ++i, t += 0.15) {
    const CycleRecord& r = nav.step(held, nullptr, t, coming);
    EXPECT_NE(r.mode, NavigatorMode::Waiting) << "cycle " << i;
    EXPECT_TRUE(r.planned) << "cycle " << i;
  }
}

// A robot stalls with no mover near and backs up. Two cycles on, a disc 1 m
// ahead comes at it: it would arrive within the 1.5 s the backing up has
// left, so the recovery ends at once, uncounted, and the planner drives. A
// disc going away leaves the backing up be.
TEST(Navigator, AMoverComingAtARobotBackingUpEndsTheRecovery) {
  const OccupancyGrid map = room(30, 60);
  NavigatorParams params;
  params.stall_time = 0.75;
  const auto third_cycle = [&](const Vec2& disc_velocity) {
    Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
    nav.set_goal(Vec2(5.5, 1.5));
    double t = 0.0;
    RobotState s = at(2.0, 1.5);
    hold(nav, s, 5, t, 0.15);
    for (int i = 0; i < 2; ++i, t += 0.15) {
      const CycleRecord& r = nav.step(s, nullptr, t);
      EXPECT_EQ(r.mode, NavigatorMode::BackingUp);
      s.pose = unicycle_step(s.pose, r.command, 0.15);
      s.twist = r.command;
    }
    const std::vector<Disc> disc = {Disc{s.pose.position() + Vec2(1.0, 0.0), 0.3, disc_velocity}};
    return nav.step(s, nullptr, t, disc);  // a copy: the navigator goes with the lambda
  };
  const CycleRecord coming = third_cycle(Vec2(-1.0, 0.0));
  EXPECT_NE(coming.mode, NavigatorMode::BackingUp);
  EXPECT_TRUE(coming.planned);
  EXPECT_EQ(coming.recoveries, 0);
  const CycleRecord leaving = third_cycle(Vec2(1.0, 0.0));
  EXPECT_EQ(leaving.mode, NavigatorMode::BackingUp);
  EXPECT_FALSE(leaving.planned);
  EXPECT_EQ(leaving.recoveries, 1);
}

namespace {

// Distance from p to the disc `d` swept over `horizon` seconds (a capsule).
double distance_to_sweep(const Disc& d, double horizon, const Vec2& p) {
  const Vec2 a = d.center, b = d.center_at(horizon);
  const Vec2 ab = b - a;
  const double f = ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + f * ab)).norm() - d.radius;
}

// Nearest approach (m) of a path, sampled every 5 mm, to the sweep of `d`.
double path_distance_to_sweep(const GlobalPath& path, const Disc& d, double horizon) {
  double nearest = kInf;
  for (double s = 0.0; s <= path.length(); s += 0.005)
    nearest = std::min(nearest, distance_to_sweep(d, horizon, path.point_at(s)));
  return nearest;
}

}  // namespace

TEST(Navigator, GlobalPathGoesRoundAMoverCrossingIt) {
  const OccupancyGrid map = room(30, 60);
  const Disc crossing{Vec2(3.0, 2.2), 0.3, Vec2(0.0, -0.5)};  // its next second covers the straight path
  for (const bool route : {true, false}) {
    NavigatorParams params;
    params.route_around_movers = route;
    params.stall_time = 0.0;
    Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
    nav.set_goal(Vec2(5.5, 1.5));
    const RobotState held = at(0.8, 1.5);
    const CycleRecord& first = nav.step(held, nullptr, 0.0);
    ASSERT_TRUE(first.path);
    for (const Vec2& p : first.path->points()) EXPECT_NEAR(p.y(), 1.5, 1e-9);  // straight: nothing in the way yet
    double t = 0.15;
    int replanned_at = -1;
    for (int i = 1; i <= 6; ++i, t += 0.15) {
      const CycleRecord& r = nav.step(held, nullptr, t, {crossing});
      if (r.path_version == 2 && replanned_at < 0) {
        replanned_at = i;
        ASSERT_TRUE(r.path);
        // Round the sweep by at least the footprint's inscribed radius, and still to the goal.
        EXPECT_GE(path_distance_to_sweep(*r.path, crossing, params.mover_route_horizon), 0.2);
        EXPECT_LT((r.path->points().back() - Vec2(5.5, 1.5)).norm(), 1e-9);
      }
    }
    if (route) {
      EXPECT_EQ(replanned_at, 3);  // at the first replan_period (0.5 s: 3 cycles of 0.15 s)
    } else {
      EXPECT_EQ(replanned_at, -1);  // the ablation: movers reach only the local planner
      EXPECT_EQ(nav.path_version(), 1);
    }
  }
}

TEST(Navigator, MoversAtTheGoalOrOffTheMapLeaveTheWayOpen) {
  const OccupancyGrid map = room(30, 60);
  NavigatorParams params;
  params.stall_time = 0.0;
  params.replan_period = 0.15;
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  nav.set_goal(Vec2(5.5, 1.5));
  // One sweeps over the goal, one over the robot, one lies far off the map, one crosses its edge.
  const std::vector<Disc> movers = {Disc{Vec2(5.5, 2.0), 0.4, Vec2(0.0, -0.5)},
                                    Disc{Vec2(0.8, 1.0), 0.3, Vec2(0.0, 0.5)},
                                    Disc{Vec2(-40.0, 1e3), 0.5, Vec2(3.0, 0.0)},
                                    Disc{Vec2(3.0, -0.2), 0.5, Vec2(0.0, 1.2)}};
  double t = 0.0;
  for (int i = 0; i < 4; ++i, t += 0.15) {
    const CycleRecord& r = nav.step(at(0.8, 1.5), nullptr, t, movers);
    EXPECT_NE(r.mode, NavigatorMode::Failed) << "cycle " << i;
    ASSERT_TRUE(r.path);
    EXPECT_LT((r.path->points().back() - Vec2(5.5, 1.5)).norm(), 1e-9);
    // Round the mover crossing the map's edge, which the path would otherwise cross.
    EXPECT_GE(path_distance_to_sweep(*r.path, movers[3], params.mover_route_horizon), 0.2) << "cycle " << i;
  }
}

// Refuses every sample: the planner can choose nothing, wherever the robot is.
class RefuseAll : public Critic {
 public:
  std::string name() const override { return "test_refuse_all"; }
  double score(const Rollout&) const override { return veto(); }
};

TEST(Navigator, EverySampleRejectedForStallTimeIsAStallWhereverTheRobotDrifts) {
  register_critic("test_refuse_all", [](auto&, auto&) { return std::make_unique<RefuseAll>(); });
  PlannerParams planner = gdwa();
  planner.critics.push_back(CriticConfig("test_refuse_all", 1.0));
  NavigatorParams params;
  params.stall_time = 0.45;  // 3 cycles
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), planner, room(30, 60), MapMode::Known, LidarParams{}, nullptr,
                params);
  nav.set_goal(Vec2(5.5, 1.5));
  // Pushed 0.3 m along each cycle: never too little progress, yet nothing the planner could drive.
  int first_stall = -1;
  for (int i = 0; i < 8 && first_stall < 0; ++i) {
    const CycleRecord& r = nav.step(at(0.8 + 0.3 * i, 1.5), nullptr, 0.15 * i);
    if (r.trigger != RecoveryTrigger::None) {
      EXPECT_EQ(r.trigger, RecoveryTrigger::AllRejected);
      first_stall = i;
    } else {
      EXPECT_EQ(r.control.status, Status::NoAdmissibleVelocity) << "cycle " << i;
    }
  }
  // Cycles 0-2 rejected everything; cycle 3 reads that and recovers.
  EXPECT_EQ(first_stall, 3);
}

TEST(Navigator, FailsAfterMaxRecoveriesWithoutProgressAndWhenNoPathExists) {
  const OccupancyGrid map = room(30, 60);
  NavigatorParams params;
  params.stall_time = 0.3;
  params.max_recoveries = 2;
  params.backup_distance = 0.0;  // recoveries that cannot move the robot
  params.rotate_limit = 0.0;
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  nav.set_goal(Vec2(5.5, 1.5));
  double t = 0.0;
  const RobotState held = at(2.0, 1.5);
  int stalls = 0;
  NavigatorMode mode = NavigatorMode::Following;
  for (int i = 0; i < 30 && mode != NavigatorMode::Failed; ++i, t += 0.15) {
    const CycleRecord& r = nav.step(held, nullptr, t);
    stalls = std::max(stalls, r.recoveries);
    mode = r.mode;
    if (mode == NavigatorMode::Failed) {
      EXPECT_EQ(r.failure, FailureReason::RecoveriesExhausted);
      EXPECT_EQ(r.trigger, RecoveryTrigger::NoProgress);  // held in place: no progress, not rejections
    }
  }
  EXPECT_EQ(mode, NavigatorMode::Failed);
  EXPECT_EQ(stalls, 3);
  // Failed holds until a new goal.
  EXPECT_EQ(nav.step(held, nullptr, t).mode, NavigatorMode::Failed);
  nav.set_goal(Vec2(5.0, 1.5));
  EXPECT_NE(nav.step(held, nullptr, t).mode, NavigatorMode::Failed);

  // A goal walled in on the known map: no path at any radius.
  const OccupancyGrid walled = room(30, 60, {{10, 40, 1, 12}, {20, 40, 1, 12}, {10, 40, 11, 1}, {10, 51, 11, 1}});
  Navigator boxed(RobotLimits{}, Footprint::circle(0.2), gdwa(), walled, MapMode::Known, LidarParams{});
  boxed.set_goal(Vec2(4.5, 1.5));
  const CycleRecord& r = boxed.step(at(1.0, 1.5), nullptr, 0.0);
  EXPECT_EQ(r.mode, NavigatorMode::Failed);
  EXPECT_EQ(r.failure, FailureReason::NoGlobalPath);
}

TEST(Navigator, AGoalWithNoPathIsPlannedForAgainOnlyEveryRetryPeriod) {
  // A wall across the room with one gap, and a mover sweeping the gap at first.
  const OccupancyGrid map = room(30, 60, {{0, 30, 12, 1}, {18, 30, 12, 1}});
  const Disc in_gap{Vec2(3.05, 1.5), 0.3, Vec2(0.0, 0.5)};
  NavigatorParams params;
  params.retry_period = 1.05;  // 7 cycles of the preset's dt, 0.15 s
  ASSERT_DOUBLE_EQ(gdwa().dt, 0.15);
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  const Vec2 goal(5.0, 1.5);
  nav.set_goal(goal);
  const RobotState held = at(1.0, 1.5);
  ASSERT_EQ(nav.step(held, nullptr, 0.0, {in_gap}).failure, FailureReason::NoGlobalPath);
  // The gap is open from now on; the goal, given again every cycle, is planned for only after retry_period.
  int found_at = -1;
  for (int i = 1; i <= 12 && found_at < 0; ++i) {
    nav.set_goal(goal);
    const CycleRecord& r = nav.step(held, nullptr, 0.15 * i);
    if (r.mode != NavigatorMode::Failed) {
      found_at = i;
      ASSERT_TRUE(r.path);
      EXPECT_LT((r.path->points().back() - goal).norm(), 1e-9);
    } else {
      EXPECT_EQ(r.failure, FailureReason::NoGlobalPath) << "cycle " << i;
    }
  }
  EXPECT_EQ(found_at, 7);
  // Another goal is planned for at once.
  Navigator other(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  other.set_goal(goal);
  ASSERT_EQ(other.step(held, nullptr, 0.0, {in_gap}).failure, FailureReason::NoGlobalPath);
  other.set_goal(Vec2(2.0, 0.5));
  EXPECT_NE(other.step(held, nullptr, 0.15).mode, NavigatorMode::Failed);
}

TEST(Navigator, ProgressResetsTheRecoveryCount) {
  const OccupancyGrid map = room(30, 80);
  NavigatorParams params;
  params.stall_time = 0.3;
  params.backup_distance = 0.0;
  params.rotate_limit = 0.0;
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
  nav.set_goal(Vec2(7.5, 1.5));
  double t = 0.0;
  const CycleRecord& first = hold(nav, at(1.0, 1.5), 3, t, 0.15);
  EXPECT_EQ(first.recoveries, 1);
  // 1 m on from where that recovery began, the count starts over.
  const CycleRecord& later = nav.step(at(2.1, 1.5), nullptr, t);
  EXPECT_EQ(later.recoveries, 0);
}

TEST(Navigator, RejectsBadInputNamingIt) {
  const OccupancyGrid map = room(30, 60);
  const LidarParams lidar;
  const auto make = [&](const NavigatorParams& p) {
    return Navigator(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, lidar, nullptr, p);
  };
  const auto bad = [&](auto mutate, const std::string& field) {
    NavigatorParams p;
    mutate(p);
    expect_error_naming([&] { make(p); }, field);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  bad([&](NavigatorParams& p) { p.path_margin = -0.1; }, "path_margin");
  bad([&](NavigatorParams& p) { p.replan_period = 0.0; }, "replan_period");
  bad([&](NavigatorParams& p) { p.retry_period = 0.0; }, "retry_period");
  bad([&](NavigatorParams& p) { p.retry_period = std::nan(""); }, "retry_period");
  bad([&](NavigatorParams& p) { p.stall_time = nan; }, "stall_time");
  bad([&](NavigatorParams& p) { p.stall_distance = -1.0; }, "stall_distance");
  bad([&](NavigatorParams& p) { p.give_up_length = -1.0; }, "give_up_length");
  bad([&](NavigatorParams& p) { p.keep_clear = nan; }, "keep_clear");
  bad([&](NavigatorParams& p) { p.sensed_close_radius = -1.0; }, "sensed_close_radius");
  bad([&](NavigatorParams& p) { p.backup_distance = -0.3; }, "backup_distance");
  bad([&](NavigatorParams& p) { p.backup_speed = 0.0; }, "backup_speed");
  bad([&](NavigatorParams& p) { p.rotate_limit = -1.0; }, "rotate_limit");
  bad([&](NavigatorParams& p) { p.wait_time = kInf; }, "wait_time");
  bad([&](NavigatorParams& p) { p.wait_radius = -1.0; }, "wait_radius");
  bad([&](NavigatorParams& p) { p.max_recoveries = -1; }, "max_recoveries");
  bad([&](NavigatorParams& p) { p.progress_reset = nan; }, "progress_reset");
  bad([&](NavigatorParams& p) { p.record_top_k = -2; }, "record_top_k");
  bad([&](NavigatorParams& p) { p.mover_route_horizon = -1.0; }, "mover_route_horizon");
  bad([&](NavigatorParams& p) { p.mover_route_lookahead = nan; }, "mover_route_lookahead");

  Navigator nav = make(NavigatorParams{});
  expect_error_naming([&] { nav.step(at(1.0, 1.0), nullptr, 0.0); }, "set_goal");
  expect_error_naming([&] { nav.set_global_path(GlobalPath({Vec2(0.5, 0.5), Vec2(1.0, 1.0)})); }, "set_goal");
  expect_error_naming([&] { nav.set_goal(Vec2(9.0, 1.0)); }, "off the map");
  expect_error_naming([&] { nav.set_goal(Vec2(nan, 1.0)); }, "goal x");
  nav.set_goal(Vec2(5.0, 1.0));
  Scan scan;
  scan.ranges.assign(static_cast<std::size_t>(lidar.beams) - 1, 1.0);
  expect_error_naming([&] { nav.step(at(1.0, 1.0), &scan, 0.0); }, "beams");
  scan.ranges.assign(static_cast<std::size_t>(lidar.beams), 1.0);
  scan.ranges[17] = nan;
  expect_error_naming([&] { nav.step(at(1.0, 1.0), &scan, 0.0); }, "ranges[17]");
  expect_error_naming([&] { nav.step(at(nan, 1.0), nullptr, 0.0); }, "state x");
  expect_error_naming([&] { nav.step(at(1.0, 1.0), nullptr, nan); }, "time");
  TerrainGrid other(10, 10, 0.1, Vec2(0.0, 0.0), std::vector<std::uint8_t>(100, 0));
  expect_error_naming(
      [&] { Navigator(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, lidar, nullptr, {}, other); },
      "terrain");
  PassingFactors factors = kDefaultPassingFactors;
  factors[2] = 1.5;
  TerrainGrid flat(30, 60, 0.1, Vec2(0.0, 0.0), std::vector<std::uint8_t>(1800, 0));
  expect_error_naming(
      [&] { Navigator(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, lidar, nullptr, {}, flat, factors); },
      "passing_factors[2]");
  expect_error_naming(
      [&] {
        Navigator(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, lidar, nullptr, {}, std::nullopt,
                  factors);
      },
      "passing_factors[2]");
}

TEST(PlannerTerrain, RejectsRolloutsIntoGradeFourAndCapsTheWindow) {
  // Grade 4 from x = 2 m on; grade 2 (factor 0.6) up to x = 1.5 m.
  std::vector<std::uint8_t> grades(30 * 60, 0);
  for (int row = 0; row < 30; ++row)
    for (int col = 0; col < 60; ++col) grades[static_cast<std::size_t>(row) * 60 + col] = col >= 20 ? 4 : (col < 15 ? 2 : 0);
  const auto terrain = std::make_shared<TerrainGrid>(30, 60, 0.1, Vec2(0.0, 0.0), grades);
  LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25), PlannerParams{});
  planner.set_terrain(terrain);
  const FieldClearance open;
  RobotState s = at(0.5, 1.5);
  s.twist = Twist{0.6, 0.0};
  const double cap = 0.6 * RobotLimits{}.v_max;
  for (const Twist& sample : planner.plan(s, Vec2(5.0, 1.5), open).samples) EXPECT_LE(sample.v, cap + 1e-12);
  // 30 cm from grade 4 at speed: the fast samples would run onto it before stopping.
  s = at(1.45, 1.5);
  s.twist = Twist{0.6, 0.0};
  const PlanResult& r = planner.plan(s, Vec2(5.0, 1.5), open);
  int terrain_rejects = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    if (r.reasons[i] != RejectReason::Terrain) continue;
    ++terrain_rejects;
    EXPECT_GT(r.samples[i].v, 0.0);
  }
  EXPECT_GT(terrain_rejects, 0);
  EXPECT_EQ(r.reject_counts[static_cast<std::size_t>(RejectReason::Terrain)], terrain_rejects);
  ASSERT_GE(r.best_index, 0);
  // Grade 4 counts in a rollout's clearance as a wall would: here, in open
  // space, its distance from the footprint all along a rollout that keeps
  // clear of it, and within the safety margin for one that the braking rule
  // admits though it runs onto it. The choice keeps clear where some sample does.
  const double margin = PlannerParams{}.safety_margin;
  int clear = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    if (r.reasons[i] != RejectReason::None) continue;
    double nearest = kInf;
    for (const Pose2& pose : planner.rollouts()[i]) nearest = std::min(nearest, 2.0 - pose.x - 0.25);
    if (nearest > margin) {
      EXPECT_NEAR(r.min_clearance[i], nearest, 1e-9) << "sample " << i;
      ++clear;
    } else {
      EXPECT_LE(r.min_clearance[i], margin) << "sample " << i;
    }
  }
  if (clear > 0) {
    EXPECT_GT(r.min_clearance[static_cast<std::size_t>(r.best_index)], 0.0);
  }
  // Whatever it chose, the footprint never reaches grade 4 before the robot could stop: drive it and see.
  RobotState d = s;
  for (int i = 0; i < 80; ++i) {
    const PlanResult& p = planner.plan(d, Vec2(5.0, 1.5), open);
    d.pose = unicycle_step(d.pose, p.command, 0.15);
    d.twist = p.command;
    ASSERT_LT(terrain->grade_at(d.pose.position()), 4) << "cycle " << i;
  }
  // Without terrain the same start goes straight for the goal at full speed.
  planner.set_terrain(nullptr);
  const PlanResult& free = planner.plan(s, Vec2(5.0, 1.5), open);
  EXPECT_EQ(free.reject_counts[static_cast<std::size_t>(RejectReason::Terrain)], 0);
  EXPECT_GT(free.command.v, cap);
}

namespace {

// States no command produces: a push, a slope or a bad report.
const std::vector<Twist> kWildTwists = {{5.0, 0.0}, {-1.0, 0.0}, {0.3, 10.0}, {0.3, -10.0}, {5.0, 10.0}, {-1.0, -10.0}};

// Inside [v_min, v_max] x [-omega_max, omega_max], or reversing no faster than a backup may.
void expect_inside_limits(const Twist& command, const RobotLimits& limits, NavigatorMode mode,
                          const NavigatorParams& params) {
  const double v_lo = mode == NavigatorMode::BackingUp || mode == NavigatorMode::Rotating
                          ? -std::min(params.backup_speed, limits.v_max)
                          : limits.v_min;
  EXPECT_GE(command.v, v_lo) << to_string(mode);
  EXPECT_LE(command.v, limits.v_max) << to_string(mode);
  EXPECT_LE(std::abs(command.omega), limits.omega_max) << to_string(mode);
}

}  // namespace

TEST(Navigator, CommandsStayInsideTheLimitsWhateverTheStateReports) {
  const OccupancyGrid map = room(30, 60, {{12, 30, 6, 3}});
  RobotLimits limits;
  limits.v_max = 0.8;
  NavigatorParams params;
  params.stall_time = 0.3;
  for (const Twist& wild : kWildTwists) {
    SCOPED_TRACE(::testing::Message() << "state twist " << wild.v << ", " << wild.omega);
    Navigator nav(limits, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{}, nullptr, params);
    nav.set_goal(Vec2(5.5, 1.5));
    double t = 0.0;
    RobotState state = at(1.0, 1.5);
    // Following, then held in place until a recovery backs up or rotates, then failing.
    for (int i = 0; i < 40; ++i, t += 0.15) {
      state.twist = wild;
      const CycleRecord& r = nav.step(state, nullptr, t);
      expect_inside_limits(r.command, limits, r.mode, params);
    }
    EXPECT_GT(nav.mode_counts()[static_cast<std::size_t>(NavigatorMode::BackingUp)] +
                  nav.mode_counts()[static_cast<std::size_t>(NavigatorMode::Rotating)],
              0);
  }
}

// Odometry drift puts the known map at a wrong place while the scan sees the
// world where it is. Here the map shows the wall across the room one cell
// (0.1 m) farther than it stands, within the half cell plus three range-noise
// stds that explain a hit radially, and the goal is where the body clears the
// mapped wall but not the real one: only this cycle's scan shows the
// difference, and no rollout the planner may choose reaches the real wall.
TEST(Controller, TheLiveScanCountsWhereTheKnownMapIsShifted) {
  const OccupancyGrid truth = room(30, 60, {{0, 30, 30, 2}});    // the wall at x in [3.0, 3.2] m
  const OccupancyGrid shifted = room(30, 60, {{0, 31, 30, 2}});  // the map's, at [3.1, 3.3] m
  LidarParams exact;
  const LaserScanner scanner(exact, std::make_shared<DistanceField>(truth));
  const Footprint body = Footprint::circle(0.2);
  PlannerParams params = gdwa();
  params.goal_tolerance = 0.02;
  Controller controller(RobotLimits{}, body, params, std::make_shared<const DistanceField>(shifted));
  controller.set_global_path(GlobalPath({Vec2(1.0, 1.5), Vec2(2.86, 1.5)}));
  controller.set_range_noise(0.02);  // hits within 0.05 + 3 x 0.02 m of the map's obstacles explain radially
  const FieldClearance real(std::make_shared<DistanceField>(truth));
  RobotState state{Pose2{2.0, 1.5, 0.0}, Twist{0.0, 0.0}};
  std::mt19937_64 rng(0);
  Scan scan;
  for (int i = 0; i < 80; ++i) {
    scanner.scan(state.pose, {}, 0.0, rng, scan);
    // 0.04 m from the mapped wall, 0.06 m into the real one.
    const CycleReport& report = controller.step(state, Vec2(2.86, 1.5), &scan);
    if (i == 0) {
      // The wall's hits within the rollouts' reach, and only they.
      EXPECT_GT(report.live_points, 100u);
      for (const Disc& d : controller.world().discs()) EXPECT_NEAR(d.center.x(), 3.0, 1e-9);
    }
    state.pose = unicycle_step(state.pose, report.command, gdwa().dt);
    state.twist = report.command;
    ASSERT_GT(real.clearance(body, state.pose, 0.0), 0.0) << "cycle " << i << " at x = " << state.pose.x;
  }
  EXPECT_GT(state.pose.x, 2.7);  // it did drive up to the wall
}

// A map 6 cm off (drift a few metres long) lies within the noise of one hit
// (4 stds of 3 cm): the hits on the wall's stretch around each, averaged,
// show it, and the planner gets the wall where the scan puts it. On a correct
// map at that resolution the average passes its threshold (2 stds of the
// mean) for a few hits only, and puts those within about the noise of the wall.
TEST(Controller, TheAveragedScanCountsAMapAFewCentimetresOff) {
  const auto wall = [](int col) {  // 3 m x 6 m in 2 cm cells, a wall 0.2 m thick from x = col * 0.02
    std::vector<std::uint8_t> cells(150 * 300, 0);
    for (int row = 0; row < 150; ++row)
      for (int c = col; c < col + 10; ++c) cells[static_cast<std::size_t>(row) * 300 + c] = 1;
    return OccupancyGrid(150, 300, 0.02, Vec2(0.0, 0.0), cells);
  };
  const OccupancyGrid truth = wall(150);  // x in [3.00, 3.20] m
  LidarParams lidar;
  lidar.noise_std = 0.03;
  lidar.dropout = 0.0;
  const LaserScanner scanner(lidar, std::make_shared<DistanceField>(truth));
  const RobotState state{Pose2{2.5, 1.5, 0.0}, Twist{0.0, 0.0}};
  std::mt19937_64 rng(3);
  Scan scan;
  for (const int col : {153, 150}) {  // the map 6 cm off, then right
    Controller controller(RobotLimits{}, Footprint::circle(0.2), gdwa(), std::make_shared<const DistanceField>(wall(col)));
    controller.set_global_path(GlobalPath({Vec2(1.0, 1.5), Vec2(2.7, 1.5)}));
    controller.set_range_noise(lidar.noise_std);
    std::size_t live = 0;
    std::vector<double> xs;
    for (int i = 0; i < 10; ++i) {
      scanner.scan(state.pose, {}, 0.0, rng, scan);
      live += controller.step(state, Vec2(2.7, 1.5), &scan).live_points;
      for (const Disc& d : controller.world().discs()) xs.push_back(d.center.x());
    }
    if (col == 150) {
      EXPECT_LT(live, 300u);
      // None farther short of the wall than about the noise: the average the point sits on.
      for (const double x : xs) EXPECT_GE(x, 3.0 - 1.5 * lidar.noise_std);
      continue;
    }
    ASSERT_GT(live, 500u);
    std::sort(xs.begin(), xs.end());
    // Where the wall stands, within the averaged noise; the few single hits counted lie nearer.
    EXPECT_NEAR(xs[xs.size() / 2], 3.0, 0.01);
    const auto within = std::count_if(xs.begin(), xs.end(), [](double x) { return std::abs(x - 3.0) <= 0.02; });
    EXPECT_GE(static_cast<double>(within), 0.9 * static_cast<double>(xs.size()));
  }
}

// A scan that agrees with a correct map adds no live point off its obstacles,
// noise and all: the along-the-beam test leaves a hit to its map's obstacles
// unless four noise stds along its beam, either way, hold none (a grazed
// corner included), and the few averages that pass their threshold lie
// within two noise stds of them.
TEST(Navigator, ACorrectMapsLivePointsLieOnItsObstacles) {
  const OccupancyGrid map = room(30, 60, {{0, 30, 30, 2}, {10, 12, 4, 4}});
  LidarParams lidar;
  lidar.noise_std = 0.02;
  const LaserScanner scanner(lidar, std::make_shared<DistanceField>(map));
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, lidar);
  nav.set_goal(Vec2(2.5, 2.5));
  Drive d{at(0.5, 0.5)};
  std::mt19937_64 rng(1);
  Scan scan;
  const DistanceField field(map);
  std::size_t live = 0, beams = 0;
  for (int i = 0; i < 60; ++i) {
    live += drive(nav, d, &scanner, rng, scan, 0.15).control.live_points;
    beams += scan.ranges.size();
    for (const Disc& disc : nav.controller().world().discs())
      EXPECT_LE(field.distance(disc.center), 2.0 * lidar.noise_std);
  }
  EXPECT_LT(static_cast<double>(live), 0.01 * static_cast<double>(beams));
}

// A robot off its map (out of an open side, round a mover) is guided back: the
// path starts where it stands and enters the map at its nearest point.
TEST(Navigator, ARobotOffTheMapIsGuidedBackOntoItAndToTheGoal) {
  const OccupancyGrid map = room(30, 60, {{10, 20, 10, 4}});  // 3 m x 6 m, a block in the middle
  Navigator nav(RobotLimits{}, Footprint::circle(0.2), gdwa(), map, MapMode::Known, LidarParams{});
  nav.set_goal(Vec2(5.0, 1.5));
  Drive d{at(-2.0, 4.5, 0.0)};  // 2 m left of the map and 1.5 m above it
  std::mt19937_64 rng(0);
  Scan scan;
  const CycleRecord& first = drive(nav, d, nullptr, rng, scan, 0.15);
  ASSERT_TRUE(nav.path());
  const std::vector<Vec2>& points = nav.path()->points();
  EXPECT_NEAR((points.front() - Vec2(-2.0, 4.5)).norm(), 0.0, 1e-9);
  int row, col;
  EXPECT_TRUE(map.cell_of(points[1], row, col)) << "enters the map at (" << points[1].x() << ", " << points[1].y() << ")";
  EXPECT_NE(first.mode, NavigatorMode::Failed);
  bool arrived = false;
  for (int i = 0; i < 400 && !arrived; ++i)
    arrived = drive(nav, d, nullptr, rng, scan, 0.15).mode == NavigatorMode::GoalReached;
  EXPECT_TRUE(arrived) << "ended at (" << d.state.pose.x << ", " << d.state.pose.y << ")";
}
