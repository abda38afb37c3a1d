// ScanMap and path_blocked: a map grown from scans sees what the lidar saw and
// nothing else; a path is blocked only by obstacles ahead of the robot.
#include <gtest/gtest.h>

#include <random>

#include "fgdwa/controller.hpp"
#include "fgdwa/mapping.hpp"
#include "fgdwa/perception.hpp"
#include "test_support.hpp"

namespace fgdwa::test {
namespace {

OccupancyGrid wall_grid() {
  // 20 x 40 cells of 0.1 m; a wall at column 25 (x in [2.5, 2.6)) over rows 5..14.
  std::vector<std::uint8_t> cells(20 * 40, 0);
  for (int r = 5; r < 15; ++r) cells[r * 40 + 25] = 1;
  return OccupancyGrid(20, 40, 0.1, Vec2(0.0, 0.0), cells);
}

TEST(ScanMap, MarksExactlyTheVisibleCellsOfAWall) {
  const OccupancyGrid truth = wall_grid();
  LaserScanner scanner(LidarParams{}, std::make_shared<const DistanceField>(truth));
  std::mt19937_64 rng(1);
  Scan scan;
  scanner.scan(Pose2{1.0, 1.0, 0.0}, {}, 0.0, rng, scan);

  ScanMap map(truth);
  EXPECT_EQ(map.grid().occupied_count(), 0u);
  const std::size_t added = map.integrate(scan);
  EXPECT_GT(added, 0u);
  EXPECT_EQ(map.occupied_count(), added);
  for (int r = 0; r < truth.rows(); ++r) {
    for (int c = 0; c < truth.cols(); ++c) {
      if (map.grid().occupied(r, c)) {
        EXPECT_TRUE(truth.occupied(r, c)) << "cell " << r << ", " << c;
      }
    }
  }
  // The wall's face toward the robot is seen over its whole height.
  for (int r = 5; r < 15; ++r) EXPECT_TRUE(map.grid().occupied(r, 25)) << "row " << r;
  // The same scan again adds nothing, and the field is the cached one.
  const auto field = map.field();
  EXPECT_EQ(map.integrate(scan), 0u);
  EXPECT_EQ(map.field(), field);
  EXPECT_NEAR(field->distance(Vec2(2.0, 1.0)), 0.5, 1e-12);
}

TEST(ScanMap, FieldIsRebuiltAfterNewCells) {
  ScanMap map(10, 10, 0.5, Vec2(0.0, 0.0));
  EXPECT_FALSE(map.field()->has_obstacles());
  EXPECT_EQ(map.mark({Vec2(2.2, 2.2), Vec2(2.3, 2.4), Vec2(100.0, 0.0)}), 1u);  // same cell twice, one outside
  const auto field = map.field();
  EXPECT_TRUE(field->has_obstacles());
  EXPECT_NEAR(field->distance(Vec2(3.5, 2.25)), 1.0, 1e-12);
  EXPECT_EQ(map.mark({Vec2(4.9, 4.9)}), 1u);
  EXPECT_NE(map.field(), field);
  EXPECT_EQ(map.occupied_count(), 2u);
}

TEST(ScanMap, BadLayoutIsAnError) {
  EXPECT_THROW(ScanMap(0, 10, 0.1, Vec2(0, 0)), Error);
  EXPECT_THROW(ScanMap(10, 10, -0.1, Vec2(0, 0)), Error);
}

TEST(PathBlocked, OnlyObstaclesAheadOfTheRobotBlock) {
  const DistanceField field(wall_grid());
  const GlobalPath through({Vec2(0.5, 1.0), Vec2(3.5, 1.0)});   // crosses the wall at x = 2.5
  const GlobalPath beside({Vec2(0.5, 0.2), Vec2(3.5, 0.2)});    // passes 0.3 m below it
  EXPECT_TRUE(path_blocked(through, Vec2(0.5, 1.0), field, 0.1));
  EXPECT_FALSE(path_blocked(through, Vec2(3.0, 1.0), field, 0.1));  // the wall is behind
  EXPECT_FALSE(path_blocked(beside, Vec2(0.5, 0.2), field, 0.25));
  EXPECT_TRUE(path_blocked(beside, Vec2(0.5, 0.2), field, 0.35));
  expect_error_naming([&] { path_blocked(beside, Vec2(NAN, 0.0), field, 0.1); }, "position");
}

TEST(Controller, SetMapMakesTheNewObstaclesCount) {
  const OccupancyGrid truth = wall_grid();
  PlannerParams params;
  params.dt = 0.1;
  params.sim_time = 1.0;
  Controller controller(RobotLimits{}, Footprint::circle(0.2), params);
  const RobotState state{Pose2{1.9, 1.0, 0.0}, Twist{1.0, 0.0}};
  const PlanResult& blind = controller.step(state, Vec2(3.5, 1.0), nullptr);
  EXPECT_NEAR(blind.command.v, 1.1, 1e-9);  // nothing in the way: the window's top speed
  controller.set_map(std::make_shared<const DistanceField>(truth));
  const PlanResult& seen = controller.step(state, Vec2(3.5, 1.0), nullptr);
  EXPECT_LT(seen.command.v, 1.0);  // the wall 0.4 m ahead makes it slow down
}

}  // namespace
}  // namespace fgdwa::test
