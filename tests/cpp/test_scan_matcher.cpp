// ScanMatcher and Localiser: a scan placed off where it was taken is put back
// within a cell and half a degree; a scan that cannot say where it is (a
// corridor along its axis, no map, no hits) is refused; the search never
// leaves its window; the Localiser keeps the correction as map_to_odom. The
// vectorised score sums to the sequential sum's bits on every instruction set.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>
#include <random>

#include "fgdwa/localiser.hpp"
#include "fgdwa/navigator.hpp"
#include "fgdwa/presets.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/scan_matcher.hpp"
#include "match_score.hpp"
#include "test_support.hpp"

namespace fgdwa::test {
namespace {

constexpr double kDeg = M_PI / 180.0;

// A 10 m x 10 m room at 0.05 m with a wall round it and boxes inside.
OccupancyGrid room(std::uint64_t seed) {
  std::mt19937 rng(static_cast<std::mt19937::result_type>(seed));
  OccupancyGrid grid = random_rectangles(rng, 200, 200, 0.05, Vec2::Zero(), 0.04, 12, Vec2(5.0, 5.0), 1.0);
  std::vector<std::uint8_t> cells = grid.cells();
  for (int i = 0; i < 200; ++i) cells[i] = cells[199 * 200 + i] = cells[i * 200] = cells[i * 200 + 199] = 1;
  return OccupancyGrid(200, 200, 0.05, Vec2::Zero(), cells);
}

// Two walls along x, 2 m apart and 30 m long: seen from the middle, every
// shift along the corridor looks the same.
OccupancyGrid corridor() {
  std::vector<std::uint8_t> cells(60 * 600, 0);
  for (int c = 0; c < 600; ++c) cells[10 * 600 + c] = cells[50 * 600 + c] = 1;
  return OccupancyGrid(60, 600, 0.05, Vec2::Zero(), cells);
}

// A scan taken at `truth`, placed at `placed`.
Scan scan_taken(const OccupancyGrid& world, const Pose2& truth, const Pose2& placed, double noise, std::uint64_t seed) {
  LidarParams lidar;
  lidar.noise_std = noise;
  lidar.dropout = 0.0;
  LaserScanner scanner(lidar, std::make_shared<const DistanceField>(world));
  std::mt19937_64 rng(seed);
  Scan scan;
  scanner.scan(truth, {}, 0.0, rng, scan);
  scan.pose = placed;
  return scan;
}

ScanMatchParams on() {
  ScanMatchParams params;
  params.enabled = true;
  return params;
}

Pose2 offset(const Pose2& p, double dx, double dy, double dtheta) { return Pose2{p.x + dx, p.y + dy, p.theta + dtheta}; }

TEST(ScanMatcher, PutsAnOffsetScanBackWithinACellAndHalfADegree) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const OccupancyGrid world = room(seed);
    const DistanceField field(world);
    const Pose2 truth{5.0, 5.0, 0.3 * static_cast<double>(seed)};
    const Scan scan = scan_taken(world, truth, offset(truth, 0.1, -0.05, 0.03), 0.02, seed);
    const ScanMatch match = ScanMatcher(on()).match(ScanFrame(scan), field);
    ASSERT_EQ(match.status, MatchStatus::Accepted) << "seed " << seed << ": " << to_string(match.status);
    EXPECT_LE(std::abs(match.pose.x - truth.x), world.resolution()) << "seed " << seed;
    EXPECT_LE(std::abs(match.pose.y - truth.y), world.resolution()) << "seed " << seed;
    EXPECT_LE(std::abs(angle_difference(match.pose.theta, truth.theta)), 0.5 * kDeg) << "seed " << seed;
    EXPECT_GT(match.score, match.given_score);
  }
}

TEST(ScanMatcher, KeepsAScanThatIsAlreadyRight) {
  const OccupancyGrid world = room(3);
  const Pose2 truth{5.0, 5.0, 0.7};
  const ScanMatch match = ScanMatcher(on()).match(ScanFrame(scan_taken(world, truth, truth, 0.02, 3)), DistanceField(world));
  EXPECT_EQ(match.status, MatchStatus::NotBetter);
}

TEST(ScanMatcher, RefusesACorridorSeenAlongItsAxis) {
  const OccupancyGrid world = corridor();
  const DistanceField field(world);
  for (const double heading : {0.0, M_PI}) {
    const Pose2 truth{15.0, 1.5, heading};
    for (const Pose2& placed : {offset(truth, 0.1, 0.0, 0.0), offset(truth, 0.1, 0.05, 0.0)}) {
      const ScanMatch match = ScanMatcher(on()).match(ScanFrame(scan_taken(world, truth, placed, 0.02, 9)), field);
      EXPECT_FALSE(match.accepted()) << "heading " << heading << ": " << to_string(match.status);
    }
  }
}

TEST(ScanMatcher, RefusesWithoutAMapOrHits) {
  const OccupancyGrid empty(40, 40, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(1600, 0));
  const Scan blank = scan_taken(empty, Pose2{2.0, 2.0, 0.0}, Pose2{2.0, 2.0, 0.0}, 0.0, 1);
  EXPECT_EQ(ScanMatcher(on()).match(ScanFrame(blank), DistanceField(empty)).status, MatchStatus::NoMap);
  const OccupancyGrid world = room(2);
  EXPECT_EQ(ScanMatcher(on()).match(ScanFrame(blank), DistanceField(world)).status, MatchStatus::TooFewPoints);
  ScanMatchParams off;
  const Scan scan = scan_taken(world, Pose2{5.0, 5.0, 0.0}, Pose2{5.1, 5.0, 0.0}, 0.0, 1);
  EXPECT_EQ(ScanMatcher(off).match(ScanFrame(scan), DistanceField(world)).status, MatchStatus::Off);
}

TEST(ScanMatcher, NeverLeavesItsWindow) {
  const OccupancyGrid world = room(4);
  const DistanceField field(world);
  const ScanMatchParams params = on();
  const ScanMatcher matcher(params);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> far(-0.6, 0.6), turn(-0.3, 0.3);
  for (int k = 0; k < 20; ++k) {
    const Pose2 truth{5.0, 5.0, turn(rng) * 10.0};
    const Pose2 placed = offset(truth, far(rng), far(rng), turn(rng));
    const ScanMatch match = matcher.match(ScanFrame(scan_taken(world, truth, placed, 0.02, 40 + k)), field);
    EXPECT_LE(std::abs(match.pose.x - placed.x), params.window_xy + 1e-9) << "case " << k;
    EXPECT_LE(std::abs(match.pose.y - placed.y), params.window_xy + 1e-9) << "case " << k;
    EXPECT_LE(std::abs(angle_difference(match.pose.theta, placed.theta)), params.window_theta + 1e-9) << "case " << k;
  }
}

// Hits on and off a room's table, some beyond the weights' reach, in counts
// that fill no whole vector: every instruction set's lanes give the bits of
// summing one hit after another, with weights of at least 2^-7; weights
// below that are refused the lanes.
TEST(MatchScore, LanesSumToTheSequentialSumsBits) {
  const DistanceField field(room(3));
  const DistanceField::LowerBounds table = field.lower_bounds();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> where(-1.0, 11.0), weight(1.0 / 128.0, 1.0);
  std::vector<float> weights(4000);
  for (float& w : weights) w = static_cast<float>(weight(rng));
  ASSERT_TRUE(detail::exact_match_sums(weights.data(), weights.size(), 1000));
  std::vector<float> tiny = weights;
  tiny.back() = 1e-3f;
  EXPECT_FALSE(detail::exact_match_sums(tiny.data(), tiny.size(), 1000));
  EXPECT_FALSE(detail::exact_match_sums(weights.data(), weights.size(), std::size_t{1} << 22));
  for (const std::size_t m : {std::size_t{0}, std::size_t{1}, std::size_t{7}, std::size_t{61}, std::size_t{180}}) {
    std::vector<double> x(m), y(m);
    for (std::size_t k = 0; k < m; ++k) x[k] = where(rng), y[k] = where(rng);
    const double ox = (0.37 - table.origin_x) * table.inverse_piece, oy = (-0.21 - table.origin_y) * table.inverse_piece;
    double sequential = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      const std::uint16_t* at = table.piece_at(ox + x[k] * table.inverse_piece, oy + y[k] * table.inverse_piece);
      if (at && *at < weights.size()) sequential += weights[*at];
    }
    if (m == 180) {
      ASSERT_GT(sequential, 2.0);  // hits near the walls score
    }
    for (const int64_t target : hwy::SupportedAndGeneratedTargets()) {
      hwy::SetSupportedTargetsForTest(target);
      for (const bool in_lanes : {true, false})
        EXPECT_EQ(detail::match_score_sum(x.data(), y.data(), m, ox, oy, table, weights.data(), weights.size(), in_lanes),
                  sequential)
            << hwy::TargetName(target) << ", " << m << " hits, in lanes " << in_lanes;
    }
    hwy::SetSupportedTargetsForTest(0);
  }
}

TEST(ScanMatchParams, RefusesStepsBeyondTheWindow) {
  ScanMatchParams p;
  p.step_xy = 0.3;
  expect_error_naming([&] { p.validate(); }, "scan_match.step_xy");
  p = ScanMatchParams{};
  p.final_step_xy = 0.1;
  expect_error_naming([&] { p.validate(); }, "scan_match.final_step_xy");
  p = ScanMatchParams{};
  p.min_points = 500;
  expect_error_naming([&] { p.validate(); }, "scan_match.min_points");
  p = ScanMatchParams{};
  p.sigma = -1.0;
  expect_error_naming([&] { p.validate(); }, "scan_match.sigma");
}

TEST(Localiser, KeepsTheCorrectionAsMapToOdomAndLeavesTheOdometryAlone) {
  const OccupancyGrid world = room(5);
  const DistanceField field(world);
  const Pose2 truth{5.0, 5.0, 1.0};
  const Pose2 odom = offset(truth, -0.08, 0.06, -0.02);
  Localiser localiser(on());
  ScanFrame frame(scan_taken(world, truth, odom, 0.02, 5));
  const ScanMatch& match = localiser.update(frame, &field, 0.0);
  ASSERT_TRUE(match.accepted()) << to_string(match.status);
  const Pose2 on_map = localiser.to_map(odom);
  EXPECT_NEAR(on_map.x, truth.x, 0.05);
  EXPECT_NEAR(on_map.y, truth.y, 0.05);
  EXPECT_NEAR(angle_difference(on_map.theta, truth.theta), 0.0, 0.5 * kDeg);
  // The frame now sits on the map; the correction composes with any odometry pose.
  EXPECT_DOUBLE_EQ(frame.scan().pose.x, match.pose.x);
  const Pose2 expected = compose(localiser.map_to_odom(), Pose2{1.0, 2.0, 0.5});
  const Pose2 later = localiser.to_map(Pose2{1.0, 2.0, 0.5});
  EXPECT_DOUBLE_EQ(later.x, expected.x);
  // A refused match changes nothing.
  const Pose2 before = localiser.map_to_odom();
  ScanFrame none(scan_taken(world, truth, odom, 0.02, 6));
  const DistanceField empty(OccupancyGrid(10, 10, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(100, 0)));
  EXPECT_EQ(localiser.update(none, &empty, 0.0).status, MatchStatus::NoMap);
  EXPECT_EQ(localiser.map_to_odom().x, before.x);
  EXPECT_EQ(localiser.map_to_odom().theta, before.theta);
}

// The odometry drifts while the robot stands in a room it maps from its
// scans: the pose it plans from stays where it is, the correction follows
// the drift, and the odometry it was given is reported as given.
TEST(Navigator, TheCorrectionFollowsDriftingOdometry) {
  const OccupancyGrid world = room(6);
  const OccupancyGrid layout(world.rows(), world.cols(), world.resolution(), world.origin(),
                             std::vector<std::uint8_t>(world.cells().size(), 0));
  LidarParams lidar;
  lidar.noise_std = 0.02;
  lidar.dropout = 0.0;
  NavigatorParams params;
  params.scan_match.enabled = true;
  const PlannerPreset preset = planner_preset("fgdwa");
  Navigator nav(RobotLimits{}, Footprint::circle(0.25), preset.params, layout, MapMode::Scan, lidar, nullptr, params);
  nav.set_goal(Vec2(8.0, 8.0));
  const Pose2 truth{5.0, 5.0, 0.4};
  double worst_odometry = 0.0, worst_map = 0.0;
  for (int k = 0; k < 60; ++k) {
    // The odometry's error grows steadily: 0.19 m and 2.3 degrees after 40 cycles.
    const double g = std::min(k, 40) / 40.0;
    const Pose2 odometry = compose(truth, Pose2{0.15 * g, -0.12 * g, 0.04 * g});
    const Scan scan = scan_taken(world, truth, odometry, 0.02, 700 + k);
    const CycleRecord& r = nav.step(RobotState{odometry, Twist{}}, &scan, 0.1 * k);
    EXPECT_DOUBLE_EQ(r.odometry.x, odometry.x);
    EXPECT_DOUBLE_EQ(r.odometry.theta, odometry.theta);
    worst_odometry = std::max(worst_odometry, (odometry.position() - truth.position()).norm());
    worst_map = std::max(worst_map, (r.state.pose.position() - truth.position()).norm());
    EXPECT_LE(std::abs(angle_difference(r.state.pose.theta, truth.theta)), 1.0 * kDeg) << "cycle " << k;
  }
  EXPECT_GT(worst_odometry, 0.18);
  EXPECT_LE(worst_map, 0.06);
  // map_to_odom undoes the error.
  const Pose2 undo = compose(nav.record().map_to_odom, compose(truth, Pose2{0.15, -0.12, 0.04}));
  EXPECT_NEAR(undo.x, truth.x, 0.05);
  EXPECT_NEAR(undo.y, truth.y, 0.05);
}

// Without matching, the pose planned from is the odometry's and the correction the identity.
TEST(Navigator, WithoutMatchingTheOdometryIsThePose) {
  const OccupancyGrid world = room(6);
  LidarParams lidar;
  lidar.noise_std = 0.02;
  NavigatorParams params;
  params.scan_match.enabled = false;
  const PlannerPreset preset = planner_preset("fgdwa");
  Navigator nav(RobotLimits{}, Footprint::circle(0.25), preset.params, world, MapMode::Known, lidar, nullptr, params);
  nav.set_goal(Vec2(8.0, 8.0));
  const Pose2 odometry{5.1, 4.9, 0.45};
  const Scan scan = scan_taken(world, Pose2{5.0, 5.0, 0.4}, odometry, 0.02, 1);
  const CycleRecord& r = nav.step(RobotState{odometry, Twist{}}, &scan, 0.0);
  EXPECT_EQ(r.match.status, MatchStatus::Off);
  EXPECT_EQ(r.state.pose.x, odometry.x);
  EXPECT_EQ(r.map_to_odom.x, 0.0);
  EXPECT_EQ(r.map_to_odom.theta, 0.0);
}

}  // namespace
}  // namespace fgdwa::test
