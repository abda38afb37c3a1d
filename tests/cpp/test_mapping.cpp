// ScanMap and path_blocked: a map grown from scans sees what the lidar saw and
// nothing else, forgets what went away, and is not fooled by range noise; a
// path is blocked only by obstacles ahead of the robot.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

// The scanner casts its beams in batches: each beam must read what it reads
// cast alone and where it first enters an occupied cell, and dropped beams and
// noise must be drawn beam by beam in order, whatever the others hit.
TEST(LaserScanner, EachBeamReadsWhatItReadsCastAloneAndTheDrawsKeepTheirOrder) {
  std::mt19937 cells_rng(7);
  const OccupancyGrid truth = random_cells(cells_rng, 60, 80, 0.1, Vec2(-1.0, -2.0), 0.04);
  LidarParams quiet;
  quiet.beams = 181;
  quiet.noise_std = 0.0;
  quiet.dropout = 0.0;
  quiet.max_range = 6.0;
  const auto world = std::make_shared<const DistanceField>(truth);
  const LaserScanner scanner(quiet, world);
  const std::vector<Disc> discs = {Disc{Vec2(2.0, 1.0), 0.3, Vec2(0.5, 0.0)}};
  std::uniform_real_distribution<double> x(-3.0, 9.0), y(-4.0, 6.0), heading(-3.2, 3.2);
  std::mt19937_64 rng(3);
  int hits = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Pose2 pose{x(rng), y(rng), heading(rng)};  // off the grid too
    Scan scan;
    std::mt19937_64 unused(0);
    scanner.scan(pose, discs, 0.4, unused, scan);
    ASSERT_EQ(scan.ranges.size(), 181u);
    for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
      const double angle = pose.theta + scan.angle_min + static_cast<double>(i) * scan.angle_increment;
      const double alone = scanner.cast(pose.position(), angle, discs, 0.4);
      ASSERT_EQ(scan.ranges[i], alone) << "trial " << trial << " beam " << i;
      // The nearest entry into an occupied cell, cell by cell (slabs), the disc aside.
      const Vec2 dir(std::cos(angle), std::sin(angle));
      double nearest = std::numeric_limits<double>::infinity();
      for (int row = 0; row < truth.rows(); ++row)
        for (int col = 0; col < truth.cols(); ++col) {
          if (!truth.occupied(row, col)) continue;
          const Vec2 lo = truth.origin() + 0.1 * Vec2(col, row), hi = lo + Vec2(0.1, 0.1);
          double enter = 0.0, leave = quiet.max_range;
          for (int a = 0; a < 2; ++a) {
            const double o = pose.position()[a], d = dir[a];
            if (d == 0.0) {
              if (o < lo[a] || o >= hi[a]) enter = leave + 1.0;
              continue;
            }
            const double t0 = (lo[a] - o) / d, t1 = (hi[a] - o) / d;
            enter = std::max(enter, std::min(t0, t1));
            leave = std::min(leave, std::max(t0, t1));
          }
          if (enter < leave) nearest = std::min(nearest, enter);
        }
      const double grid_alone = scanner.cast(pose.position(), angle, {}, 0.0);
      if (std::isinf(nearest)) {
        EXPECT_TRUE(std::isinf(grid_alone)) << "trial " << trial << " beam " << i;
      } else {
        EXPECT_NEAR(grid_alone, nearest, 1e-9) << "trial " << trial << " beam " << i;
        ++hits;
      }
    }
  }
  EXPECT_GT(hits, 1000);

  // Noise and drops: one uniform draw per beam, then a normal one for a kept hit.
  LidarParams noisy = quiet;
  noisy.noise_std = 0.02;
  noisy.dropout = 0.2;
  const LaserScanner noisy_scanner(noisy, world);
  const Pose2 pose{3.0, 1.0, 0.3};
  Scan clean, scan;
  std::mt19937_64 unused(0), draws(11), replay(11);
  scanner.scan(pose, discs, 0.4, unused, clean);
  noisy_scanner.scan(pose, discs, 0.4, draws, scan);
  std::normal_distribution<double> noise(0.0, noisy.noise_std);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  int dropped = 0;
  for (std::size_t i = 0; i < clean.ranges.size(); ++i) {
    double expected = clean.ranges[i];
    if (uniform(replay) < noisy.dropout) {
      expected = std::numeric_limits<double>::infinity();
      ++dropped;
    } else if (std::isfinite(expected)) {
      expected = std::clamp(expected + noise(replay), 0.0, noisy.max_range);
    }
    EXPECT_EQ(scan.ranges[i], expected) << "beam " << i;
  }
  EXPECT_GT(dropped, 10);
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
  EXPECT_EQ(map.changed_cells(), std::vector<std::size_t>{map.grid().index(9, 9)});
  const auto after = map.field();
  EXPECT_NE(after, field);
  EXPECT_EQ(map.occupied_count(), 2u);
  EXPECT_EQ(after->distance(Vec2(4.75, 4.75)), 0.0);
  // The field handed out before stays as it was.
  EXPECT_EQ(field->grid().occupied_count(), 1u);
  EXPECT_NEAR(field->distance(Vec2(4.75, 4.75)), std::hypot(2.25, 2.25), 1e-12);
}

TEST(ScanMap, BadLayoutIsAnError) {
  EXPECT_THROW(ScanMap(0, 10, 0.1, Vec2(0, 0)), Error);
  EXPECT_THROW(ScanMap(10, 10, -0.1, Vec2(0, 0)), Error);
}

Scan scan_of(const OccupancyGrid& truth, const Pose2& pose, double noise_std, std::uint64_t seed) {
  LidarParams lidar;
  lidar.noise_std = noise_std;
  LaserScanner scanner(lidar, std::make_shared<const DistanceField>(truth));
  std::mt19937_64 rng(seed);
  Scan scan;
  scanner.scan(pose, {}, 0.0, rng, scan);
  return scan;
}

void expect_field_equals_fresh_build(const ScanMap& map, const DistanceField& field) {
  const DistanceField fresh(map.grid());
  const std::vector<double> got = field.cell_distances(), expected = fresh.cell_distances();
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) ASSERT_EQ(got[i], expected[i]) << "cell " << i;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> x(-0.5, 4.5), y(-0.5, 2.5);
  for (int i = 0; i < 500; ++i) {
    const Vec2 p(x(rng), y(rng));
    ASSERT_EQ(field.distance(p), fresh.distance(p)) << p.transpose();
  }
}

TEST(ScanMap, ARemovedObstacleClearsAndTheFieldFollows) {
  // A wall farther back, so that the beams through the removed one end on something.
  std::vector<std::uint8_t> back(20 * 40, 0);
  for (int r = 0; r < 20; ++r) back[r * 40 + 38] = 1;
  const OccupancyGrid behind(20, 40, 0.1, Vec2(0.0, 0.0), back);
  std::vector<std::uint8_t> both = back;
  for (int r = 5; r < 15; ++r) both[r * 40 + 25] = 1;
  const OccupancyGrid before(20, 40, 0.1, Vec2(0.0, 0.0), both);

  const Pose2 pose{1.0, 1.0, 0.0};
  ScanMap map(before);
  for (int k = 0; k < 3; ++k) map.integrate(scan_of(before, pose, 0.0, k));
  for (int r = 5; r < 15; ++r) ASSERT_EQ(map.state(r, 25), CellState::Occupied) << "row " << r;
  auto field = map.field();
  EXPECT_NEAR(field->distance(Vec2(2.0, 1.0)), 0.5, 1e-12);

  int scans = 0;
  bool cleared = false;
  while (!cleared && scans < 20) {
    map.integrate(scan_of(behind, pose, 0.0, 100 + scans));
    ++scans;
    cleared = true;
    for (int r = 6; r < 14; ++r) cleared = cleared && map.state(r, 25) == CellState::Free;
  }
  EXPECT_TRUE(cleared) << "the removed wall is still in the map after " << scans << " scans";
  // Three hits put a cell at 3 x 0.85; each miss takes 0.4 off, down to the free threshold -0.5.
  EXPECT_LE(scans, 9);
  const auto after = map.field();
  EXPECT_NE(after, field);
  expect_field_equals_fresh_build(map, *after);
  EXPECT_GT(after->distance(Vec2(2.0, 1.0)), 1.5);
}

// Noisy scans from a robot driving past a wall, the field taken and let go
// every cycle as a navigator does (so it is updated in place), or kept a
// cycle (so the update goes to a copy): each cycle's field is a fresh build's.
TEST(ScanMap, TheFieldFollowsNoisyScansExactlyInPlaceOrInACopy) {
  const OccupancyGrid truth = wall_grid();
  OccupancyParams params;
  params.range_std = 0.03;
  ScanMap map(truth, params);
  std::shared_ptr<const DistanceField> kept;
  const DistanceField* last = nullptr;
  int in_place = 0;
  for (int k = 0; k < 40; ++k) {
    map.integrate(scan_of(truth, Pose2{0.5 + 0.04 * k, 0.3 + 0.02 * k, 0.1}, 0.03, 300 + k));
    const auto field = map.field();
    in_place += field.get() == last;
    expect_field_equals_fresh_build(map, *field);
    last = field.get();
    kept = k % 5 == 0 ? field : nullptr;
  }
  EXPECT_GT(in_place, 0);
  EXPECT_GT(map.occupied_count(), 5u);
}

// A field taken once and then not asked for while the map changes more times
// than it has cells (the scan map stops listing them then) still comes out exact.
TEST(ScanMap, AFieldLeftUntakenThroughManyChangesStillComesOutExact) {
  std::vector<std::uint8_t> wall(3 * 8, 0);
  for (int r = 0; r < 3; ++r) wall[r * 8 + 6] = 1;
  const OccupancyGrid with(3, 8, 0.1, Vec2(0.0, 0.0), wall);
  const OccupancyGrid without(3, 8, 0.1, Vec2(0.0, 0.0), std::vector<std::uint8_t>(3 * 8, 0));
  ScanMap map(with);
  EXPECT_FALSE(map.field()->has_obstacles());
  std::size_t flips = 0;
  for (int k = 0; k < 400 && flips <= 2 * with.cells().size(); ++k) {
    map.integrate(scan_of((k / 12) % 2 ? without : with, Pose2{0.15, 0.15, 0.0}, 0.0, 500 + k));
    flips += map.changed_cells().size();
  }
  EXPECT_GT(flips, 2 * with.cells().size());
  expect_field_equals_fresh_build(map, *map.field());
}

TEST(ScanMap, RangeNoiseDoesNotNarrowTheFreeSide) {
  // 3 cm noise: half the readings fall short of the wall's face, in the free
  // cell before it. That cell must stay free, or every gap narrows by a cell.
  const OccupancyGrid truth = wall_grid();
  OccupancyParams params;
  params.range_std = 0.03;
  ScanMap map(truth, params);
  for (int k = 0; k < 60; ++k) {
    const Pose2 pose{0.8 + 0.01 * k, 0.6 + 0.013 * k, 0.1 * std::sin(0.3 * k)};
    map.integrate(scan_of(truth, pose, 0.03, 1000 + k));
  }
  // Up close, a hundred beams cross the cell before the face in every scan and
  // a few of them read short.
  for (int k = 0; k < 30; ++k) map.integrate(scan_of(truth, Pose2{2.2, 1.0, 0.0}, 0.03, 2000 + k));
  for (int r = 0; r < truth.rows(); ++r)
    for (int c = 0; c < 25; ++c) EXPECT_NE(map.state(r, c), CellState::Occupied) << "cell " << r << ", " << c;
  for (int r = 5; r < 15; ++r) EXPECT_EQ(map.state(r, 25), CellState::Occupied) << "row " << r;
  expect_field_equals_fresh_build(map, *map.field());
}

TEST(ScanMap, HitsOnlyWithoutClearingAndUnmarkedBeamsStillClear) {
  const OccupancyGrid truth = wall_grid();
  const Scan scan = scan_of(truth, Pose2{1.0, 1.0, 0.0}, 0.0, 1);
  OccupancyParams hits_only;
  hits_only.clear = false;
  ScanMap static_map(truth, hits_only);
  static_map.integrate(scan);
  EXPECT_EQ(static_map.state(10, 15), CellState::Unknown);  // passed by beams, but nothing clears
  EXPECT_EQ(static_map.state(10, 25), CellState::Occupied);

  ScanMap map(truth);
  const std::vector<std::uint8_t> none(scan.ranges.size(), 0);
  EXPECT_EQ(map.integrate(scan, &none), 0u);
  EXPECT_EQ(map.occupied_count(), 0u);
  EXPECT_EQ(map.state(10, 15), CellState::Free);
  EXPECT_GT(map.known_count(), 100u);
  const std::vector<std::uint8_t> wrong_size(3, 1);
  EXPECT_THROW(map.integrate(scan, &wrong_size), Error);
}

TEST(ScanMap, ABeamWithNoReturnClearsUpToItsRange) {
  ScanMap map(20, 40, 0.1, Vec2(0.0, 0.0));
  EXPECT_EQ(map.mark({Vec2(3.05, 1.05)}), 1u);
  Scan scan;
  scan.pose = Pose2{1.0, 1.0, 0.0};
  scan.angle_min = 0.0;
  scan.angle_increment = 0.0;
  scan.max_range = 10.0;
  scan.ranges = {std::numeric_limits<double>::infinity()};
  for (int k = 0; k < 4; ++k) map.integrate(scan);
  EXPECT_EQ(map.state(10, 30), CellState::Free);
  EXPECT_EQ(map.state(10, 39), CellState::Free);  // the beam is clipped to the layout
  EXPECT_EQ(map.state(11, 30), CellState::Unknown);
}

TEST(OccupancyParams, BadValuesAreErrors) {
  const auto bad = [](auto change) {
    OccupancyParams p;
    change(p);
    return ScanMap(4, 4, 0.1, Vec2(0, 0), p);
  };
  EXPECT_THROW(bad([](OccupancyParams& p) { p.hit = -1.0; }), Error);
  EXPECT_THROW(bad([](OccupancyParams& p) { p.miss = 0.1; }), Error);
  EXPECT_THROW(bad([](OccupancyParams& p) { p.free = 1.0; }), Error);
  EXPECT_THROW(bad([](OccupancyParams& p) { p.clamp_max = 0.1; }), Error);
  EXPECT_THROW(bad([](OccupancyParams& p) { p.range_std = std::nan(""); }), Error);
  EXPECT_THROW(bad([](OccupancyParams& p) { p.clear_range = -1.0; }), Error);
  EXPECT_THROW(bad([](OccupancyParams& p) { p.hit = 0.2; }), Error);  // below the occupied threshold
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

TEST(Controller, KeepBestTakesACountWithinTheWindowsSamples) {
  Controller controller(RobotLimits{}, Footprint::circle(0.2), PlannerParams{});
  controller.keep_best(0);
  controller.keep_best(5);
  fgdwa::test::expect_error_naming([&] { controller.keep_best(-1); }, "keep_best");
  fgdwa::test::expect_error_naming([&] { controller.keep_best(limits::kMaxWindowSamples + 1); }, "keep_best");
}

TEST(Controller, SetMapMakesTheNewObstaclesCount) {
  const OccupancyGrid truth = wall_grid();
  PlannerParams params;
  params.dt = 0.1;
  params.sim_time = 1.0;
  Controller controller(RobotLimits{}, Footprint::circle(0.2), params);
  const RobotState state{Pose2{1.9, 1.0, 0.0}, Twist{1.0, 0.0}};
  const CycleReport& blind = controller.step(state, Vec2(3.5, 1.0), nullptr);
  EXPECT_NEAR(blind.command.v, 1.1, 1e-9);  // nothing in the way: the window's top speed
  controller.set_map(std::make_shared<const DistanceField>(truth));
  const CycleReport& seen = controller.step(state, Vec2(3.5, 1.0), nullptr);
  EXPECT_LT(seen.command.v, 1.0);  // the wall 0.4 m ahead makes it slow down
}

// An occupied cell no beam reaches fades: unknown again after fade_time
// ln(l / occupied); a cell hit every scan, and every cell without a time or
// with fade_time inf, stays.
TEST(ScanMap, CellsNoBeamReachesFadeToUnknown) {
  const OccupancyGrid truth = wall_grid();
  OccupancyParams params;
  params.fade_time = 2.0;
  ScanMap fading(truth, params);
  params.fade_time = std::numeric_limits<double>::infinity();
  ScanMap lasting(truth, params);
  ScanMap timeless(truth, OccupancyParams{});
  const Pose2 facing{1.0, 1.0, 0.0}, away{1.0, 1.0, M_PI};  // the wall lies in the blind cone behind `away`
  for (int k = 0; k < 3; ++k)
    for (ScanMap* map : {&fading, &lasting, &timeless}) map->integrate(scan_of(truth, facing, 0.0, k), nullptr, 0.1 * k);
  ASSERT_EQ(fading.state(10, 25), CellState::Occupied);
  // 3 hits: l = 2.55, below 0.5 after 2 s ln(5.1) = 3.26 s.
  double t = 0.2;
  for (int k = 0; t < 3.0; ++k) {
    t += 0.1;
    fading.integrate(scan_of(truth, away, 0.0, 10 + k), nullptr, t);
    lasting.integrate(scan_of(truth, away, 0.0, 10 + k), nullptr, t);
    timeless.integrate(scan_of(truth, away, 0.0, 10 + k));
  }
  EXPECT_EQ(fading.state(10, 25), CellState::Occupied);
  for (int k = 0; t < 4.0; ++k) {
    t += 0.1;
    fading.integrate(scan_of(truth, away, 0.0, 50 + k), nullptr, t);
  }
  for (int r = 5; r < 15; ++r) {
    EXPECT_EQ(fading.state(r, 25), CellState::Unknown) << "row " << r;
    EXPECT_EQ(lasting.state(r, 25), CellState::Occupied) << "row " << r;
    EXPECT_EQ(timeless.state(r, 25), CellState::Occupied) << "row " << r;
  }
  EXPECT_FALSE(fading.grid().occupied(10, 25));
  expect_field_equals_fresh_build(fading, *fading.field());
  // Seen again, it is back at once; a wall seen every scan never fades.
  for (int k = 0; k < 60; ++k) fading.integrate(scan_of(truth, facing, 0.0, 100 + k), nullptr, t + 0.1 * k);
  for (int r = 6; r < 14; ++r) EXPECT_EQ(fading.state(r, 25), CellState::Occupied) << "row " << r;
}

}  // namespace
}  // namespace fgdwa::test
