// What the headers say may be shared: one planner per thread over one shared
// world, path and map planners give on every thread what they give alone.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <thread>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/global_planner.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/presets.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

constexpr int kThreads = 4;
constexpr int kCycles = 150;

struct SharedWorld {
  std::shared_ptr<const DistanceField> field;
  std::unique_ptr<FieldClearance> clearance;
  std::unique_ptr<GlobalPath> path;
};

SharedWorld make_world() {
  std::mt19937 rng(7);
  const OccupancyGrid grid = test::random_rectangles(rng, 100, 100, 0.1, Vec2(-5.0, -5.0), 0.12, 6, Vec2(0, 0), 0.5);
  SharedWorld w;
  w.field = std::make_shared<const DistanceField>(grid);
  std::vector<Disc> discs;
  std::uniform_real_distribution<double> u(-4.0, 4.0);
  for (int i = 0; i < 20; ++i) {
    Disc d;
    d.center = Vec2(u(rng), u(rng));
    d.radius = 0.15;
    if (i % 2) d.velocity = Vec2(0.1 * u(rng), 0.1 * u(rng));
    discs.push_back(d);
  }
  w.clearance = std::make_unique<FieldClearance>(w.field, discs);
  w.path = std::make_unique<GlobalPath>(std::vector<Vec2>{{0, 0}, {2, 1}, {3, 3}, {4.5, 4.5}});
  return w;
}

// The commands of one planner over seeded random states; `which` picks the
// preset and the seed, so threads run different planners.
std::vector<Twist> run_planner(const SharedWorld& world, int which) {
  const RobotPreset robot = robot_preset(which % 2 ? "jackal" : "default");
  const PlannerPreset preset = planner_preset(which % 2 ? "sgdwa" : "gdwa");
  LocalPlanner planner(robot.limits, robot.footprint, preset.params);
  planner.set_global_path(*world.path);
  std::mt19937 rng(100 + static_cast<unsigned>(which));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Twist> commands;
  for (int k = 0; k < kCycles; ++k) {
    RobotState state;
    state.pose = Pose2{0.3 * u(rng), 0.3 * u(rng), M_PI * u(rng)};
    state.twist = Twist{0.5 * robot.limits.v_max * (1.0 + u(rng)), robot.limits.omega_max * u(rng)};
    commands.push_back(planner.plan(state, Vec2(4.5, 4.5), *world.clearance).command);
  }
  return commands;
}

TEST(Threads, PlannersPerThreadOverASharedWorldGiveWhatTheyGiveAlone) {
  const SharedWorld world = make_world();
  std::vector<std::vector<Twist>> alone(kThreads), together(kThreads);
  for (int i = 0; i < kThreads; ++i) alone[static_cast<std::size_t>(i)] = run_planner(world, i);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i)
    threads.emplace_back([&, i] { together[static_cast<std::size_t>(i)] = run_planner(world, i); });
  for (auto& t : threads) t.join();
  for (std::size_t i = 0; i < alone.size(); ++i) {
    ASSERT_EQ(alone[i].size(), together[i].size());
    for (std::size_t k = 0; k < alone[i].size(); ++k) {
      EXPECT_EQ(alone[i][k].v, together[i][k].v) << "planner " << i << " cycle " << k;
      EXPECT_EQ(alone[i][k].omega, together[i][k].omega) << "planner " << i << " cycle " << k;
    }
  }
}

TEST(Threads, SharedGlobalPlannerAndScannerGiveWhatTheyGiveAlone) {
  const SharedWorld world = make_world();
  const AStarPlanner astar(world.field->grid(), AStarParams{});
  const LaserScanner scanner(LidarParams{}, world.field);
  const auto work = [&](int i, std::vector<Vec2>& path, std::vector<double>& ranges) {
    // A goal in the open, on a different column per thread.
    Vec2 goal(-4.0 + 0.5 * i, 4.5);
    while (world.field->distance(goal) < 0.5 && goal.y() > -4.5) goal.y() -= 0.1;
    path = astar.plan(Vec2(0, 0), goal).path;
    std::mt19937_64 rng(static_cast<unsigned>(i));
    Scan scan;
    scanner.scan(Pose2{0.0, 0.0, 0.3 * i}, world.clearance->discs(), 0.5, rng, scan);
    ranges = scan.ranges;
  };
  std::vector<std::vector<Vec2>> paths_alone(kThreads), paths(kThreads);
  std::vector<std::vector<double>> ranges_alone(kThreads), ranges(kThreads);
  for (int i = 0; i < kThreads; ++i)
    work(i, paths_alone[static_cast<std::size_t>(i)], ranges_alone[static_cast<std::size_t>(i)]);
  std::vector<std::thread> threads;
  for (int i = 0; i < kThreads; ++i)
    threads.emplace_back([&, i] { work(i, paths[static_cast<std::size_t>(i)], ranges[static_cast<std::size_t>(i)]); });
  for (auto& t : threads) t.join();
  for (std::size_t i = 0; i < paths.size(); ++i) {
    EXPECT_FALSE(paths_alone[i].empty()) << "A* from thread " << i;
    EXPECT_EQ(paths_alone[i], paths[i]) << "A* from thread " << i;
    EXPECT_EQ(ranges_alone[i], ranges[i]) << "scan from thread " << i;
  }
}

}  // namespace
}  // namespace fgdwa
