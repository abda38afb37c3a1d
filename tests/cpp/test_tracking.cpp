// segment_scan and Tracker: clusters are the objects the lidar sees, their
// discs sit where the objects are (not on their near side), movers are found
// and followed at their speed, and static clutter is never called moving.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>
#include <memory>
#include <random>

#include <hwy/targets.h>

#include "assignment.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/tracking.hpp"
#include "test_support.hpp"

namespace fgdwa::test {
namespace {

constexpr double kNoise = 0.03;  // m, lidar range noise of every scenario
constexpr double kPeriod = 0.1;  // s, 10 Hz scans

LidarParams noisy_lidar() {
  LidarParams p;
  p.noise_std = kNoise;
  return p;
}

Scan scan_of(const LaserScanner& scanner, const Pose2& pose, const std::vector<Disc>& discs, double t,
             std::mt19937_64& rng) {
  Scan scan;
  scanner.scan(pose, discs, t, rng, scan);
  return scan;
}

// The cluster whose disc centre is nearest `p`.
const Cluster& nearest_cluster(const std::vector<Cluster>& clusters, const Vec2& p) {
  return *std::min_element(clusters.begin(), clusters.end(), [&](const Cluster& a, const Cluster& b) {
    return (a.center - p).norm() < (b.center - p).norm();
  });
}

const Track* nearest_track(const Tracker& tracker, const Vec2& p) {
  const Track* best = nullptr;
  for (const Track& t : tracker.tracks())
    if (!best || (t.position - p).norm() < (best->position - p).norm()) best = &t;
  return best;
}

Cluster cluster_at(const Vec2& center, double radius = 0.3) {
  Cluster c;
  c.points = {center};
  c.center = center;
  c.radius = radius;
  return c;
}

Vec2 centroid(const Cluster& c) {
  Vec2 sum = Vec2::Zero();
  for (const Vec2& p : c.points) sum += p;
  return sum / static_cast<double>(c.points.size());
}

// ---------------------------------------------------------------- segmentation

TEST(Segment, DiscsApartAreTwoClustersDiscsTouchingAreCutAtTheirNotch) {
  const LaserScanner scanner(LidarParams{}, nullptr);
  std::mt19937_64 rng(1);
  // Surfaces 0.4 m apart at 3 m: more than the 0.24 m gap there.
  const std::vector<Disc> apart = {Disc{Vec2(3.0, -0.5), 0.3, Vec2::Zero()}, Disc{Vec2(3.0, 0.5), 0.3, Vec2::Zero()}};
  const auto two = segment_scan(scan_of(scanner, Pose2{}, apart, 0.0, rng));
  ASSERT_EQ(two.size(), 2u);
  EXPECT_LT((nearest_cluster(two, Vec2(3.0, -0.5)).center - Vec2(3.0, -0.5)).norm(), 0.03);
  EXPECT_LT((nearest_cluster(two, Vec2(3.0, 0.5)).center - Vec2(3.0, 0.5)).norm(), 0.03);
  for (const Cluster& c : two) {
    EXPECT_LE(c.first_beam, c.last_beam);
    EXPECT_EQ(static_cast<int>(c.points.size()), c.last_beam - c.first_beam + 1);
    EXPECT_FALSE(c.occluded);
  }
  // 0.1 m apart: no beam passes between them, but each bulges toward the
  // sensor and the hits fall back where they meet.
  const std::vector<Disc> touching = {Disc{Vec2(3.0, -0.35), 0.3, Vec2::Zero()},
                                      Disc{Vec2(3.0, 0.35), 0.3, Vec2::Zero()}};
  const Scan scan = scan_of(scanner, Pose2{}, touching, 0.0, rng);
  const auto cut = segment_scan(scan);
  ASSERT_EQ(cut.size(), 2u);
  for (const Disc& d : touching) {
    const Cluster& c = nearest_cluster(cut, d.center);
    EXPECT_LT((c.center - d.center).norm(), 0.05);
    EXPECT_TRUE(c.occluded);  // the cut side may hide part of it
  }
  EXPECT_LT(cut[0].last_beam, cut[1].first_beam);
  SegmentParams deep;
  deep.notch_depth = 1.0;
  EXPECT_EQ(segment_scan(scan, deep).size(), 1u);
}

TEST(Segment, MoversTouchingOrAgainstAWallAreCutFromEachOther) {
  // A 10 m wall across the view at x = 4, two movers of 0.5 m radius touching
  // in front of it, and a third against it: one run of hits far longer than
  // max_size, which would drop them all.
  std::vector<std::uint8_t> cells(100 * 60, 0);
  for (int r = 0; r < 100; ++r) cells[r * 60 + 55] = 1;
  const auto world = std::make_shared<const DistanceField>(OccupancyGrid(100, 60, 0.1, Vec2(-1.5, -5.0), cells));
  const LaserScanner scanner(noisy_lidar(), world);
  const std::vector<Disc> movers = {Disc{Vec2(2.5, -0.52), 0.5, Vec2::Zero()}, Disc{Vec2(2.5, 0.52), 0.5, Vec2::Zero()},
                                    Disc{Vec2(3.45, 1.8), 0.5, Vec2::Zero()}};
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    std::mt19937_64 rng(seed);
    const auto clusters = segment_scan(scan_of(scanner, Pose2{}, movers, 0.0, rng));
    ASSERT_EQ(clusters.size(), 3u) << "seed " << seed;
    for (const Disc& d : movers) EXPECT_LT((nearest_cluster(clusters, d.center).center - d.center).norm(), 0.15);
  }
}

TEST(Segment, ANoisyWallOrCornerIsNotCutIntoObjects) {
  // A straight wall and a box's convex corner, 3 cm of range noise: no notch
  // anywhere, however many hits.
  std::vector<std::uint8_t> cells(80 * 80, 0);
  for (int r = 0; r < 30; ++r) cells[r * 80 + 30] = 1;  // x = 1.5 .. 1.6, y = -4 .. -1
  for (int r = 50; r < 70; ++r)
    for (int c = 50; c < 70; ++c) cells[r * 80 + c] = 1;  // a 2 m box, corner toward the sensor
  const auto world = std::make_shared<const DistanceField>(OccupancyGrid(80, 80, 0.1, Vec2(-1.5, -4.0), cells));
  const LaserScanner scanner(noisy_lidar(), world);
  SegmentParams lenient;
  lenient.max_size = 20.0;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    std::mt19937_64 rng(seed);
    Scan scan = scan_of(scanner, Pose2{-1.0, 0.0, 0.0}, {}, 0.0, rng);
    SegmentParams whole = lenient;
    whole.notch_depth = 1e3;
    EXPECT_EQ(segment_scan(scan, lenient).size(), segment_scan(scan, whole).size()) << "seed " << seed;
  }
}

TEST(Segment, WallsAreDroppedBySize) {
  // A 6 m wall across the view at x = 3.
  std::vector<std::uint8_t> cells(60 * 60, 0);
  for (int r = 0; r < 60; ++r) cells[r * 60 + 45] = 1;
  const auto world = std::make_shared<const DistanceField>(OccupancyGrid(60, 60, 0.1, Vec2(-1.5, -3.0), cells));
  const LaserScanner scanner(noisy_lidar(), world);
  std::mt19937_64 rng(2);
  const Scan scan = scan_of(scanner, Pose2{}, {Disc{Vec2(1.5, 0.0), 0.25, Vec2::Zero()}}, 0.0, rng);
  const auto clusters = segment_scan(scan);
  ASSERT_EQ(clusters.size(), 1u);  // the disc in front of it; the wall's two visible parts are too long
  EXPECT_LT((clusters[0].center - Vec2(1.5, 0.0)).norm(), 0.05);
  SegmentParams lenient;
  lenient.max_size = 10.0;
  EXPECT_EQ(segment_scan(scan, lenient).size(), 3u);
}

TEST(Segment, IsolatedHitsAreDroppedAsNoise) {
  Scan scan;
  scan.angle_min = -0.5 * M_PI;
  scan.angle_increment = M_PI / 360.0;
  scan.max_range = 10.0;
  scan.ranges.assign(361, kInf);
  for (int i : {40, 120, 300}) scan.ranges[i] = 2.0;    // lone hits
  for (int i = 180; i < 186; ++i) scan.ranges[i] = 2.5;  // a small object
  const auto clusters = segment_scan(scan);
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_EQ(clusters[0].first_beam, 180);
  EXPECT_EQ(clusters[0].last_beam, 185);
  SegmentParams every;
  every.min_points = 1;
  EXPECT_EQ(segment_scan(scan, every).size(), 4u);
}

TEST(Segment, KeepsTheNearestClustersInBeamOrder) {
  Scan scan;
  scan.angle_min = -0.5 * M_PI;
  scan.angle_increment = M_PI / 360.0;
  scan.max_range = 10.0;
  scan.ranges.assign(361, kInf);
  // Six small objects, 20 beams apart, at ranges 6, 2, 5, 3, 4, 1 m.
  const double ranges[] = {6.0, 2.0, 5.0, 3.0, 4.0, 1.0};
  for (int k = 0; k < 6; ++k)
    for (int i = 0; i < 4; ++i) scan.ranges[static_cast<std::size_t>(20 + 40 * k + i)] = ranges[k];
  ASSERT_EQ(segment_scan(scan).size(), 6u);
  SegmentParams bounded;
  bounded.max_clusters = 3;
  const auto clusters = segment_scan(scan, bounded);
  ASSERT_EQ(clusters.size(), 3u);
  // The 1, 2 and 3 m objects, in the order the beams met them.
  EXPECT_EQ(clusters[0].first_beam, 60);
  EXPECT_EQ(clusters[1].first_beam, 140);
  EXPECT_EQ(clusters[2].first_beam, 220);
  bounded.max_clusters = 0;
  EXPECT_THROW(bounded.validate(), Error);
}

TEST(Segment, MaskedBeamsAreSkipped) {
  const LaserScanner scanner(LidarParams{}, nullptr);
  std::mt19937_64 rng(3);
  const std::vector<Disc> discs = {Disc{Vec2(3.0, -0.6), 0.3, Vec2::Zero()}, Disc{Vec2(3.0, 0.6), 0.3, Vec2::Zero()}};
  const Scan scan = scan_of(scanner, Pose2{}, discs, 0.0, rng);
  // Mask out the hits of the disc at y < 0 (a known static object, say).
  std::vector<std::uint8_t> mask(scan.ranges.size(), 1);
  const auto hits = scan.hit_points();
  std::size_t k = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i)
    if (std::isfinite(scan.ranges[i]) && hits[k++].y() < 0.0) mask[i] = 0;
  const auto clusters = segment_scan(scan, SegmentParams{}, &mask);
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_GT(clusters[0].center.y(), 0.0);
  const std::vector<std::uint8_t> short_mask(10, 1);
  expect_error_naming([&] { segment_scan(scan, SegmentParams{}, &short_mask); }, "mask");
}

TEST(Segment, DiscFitFindsTheCentreBehindTheNearSide) {
  // The lidar sees the near half of a 0.3 m disc 3 m away, with 3 cm noise.
  const LaserScanner scanner(noisy_lidar(), nullptr);
  std::mt19937_64 rng(4);
  const Vec2 truth(2.6, 1.5);  // 3 m at 30 deg
  double sum_error = 0.0, sum_centroid_error = 0.0, worst = 0.0, worst_radius = 0.0;
  constexpr int kScans = 50;
  for (int k = 0; k < kScans; ++k) {
    const auto clusters = segment_scan(scan_of(scanner, Pose2{}, {Disc{truth, 0.3, Vec2::Zero()}}, 0.0, rng));
    ASSERT_EQ(clusters.size(), 1u);
    const Cluster& c = clusters[0];
    worst = std::max(worst, (c.center - truth).norm());
    worst_radius = std::max(worst_radius, std::abs(c.radius - 0.3));
    sum_error += (c.center - truth).norm();
    sum_centroid_error += (centroid(c) - truth).norm();
  }
  std::cout << "disc fit at 3 m, 3 cm noise: mean centre error " << sum_error / kScans << " m, worst " << worst
            << " m, worst radius error " << worst_radius << " m; centroid mean error " << sum_centroid_error / kScans
            << " m\n";
  EXPECT_LT(sum_error / kScans, 0.03);
  EXPECT_LT(worst, 0.06);
  EXPECT_LT(worst_radius, 0.05);
  EXPECT_GT(sum_centroid_error / kScans, 0.15);  // what fitting the centre corrects
}

TEST(Segment, FitsAndBoxesAreSaneAcrossSizesAndRanges) {
  const LaserScanner scanner(noisy_lidar(), nullptr);
  std::mt19937_64 rng(5);
  for (double radius : {0.1, 0.2, 0.4, 0.7}) {
    for (double range : {1.0, 3.0, 6.0}) {
      const Vec2 truth(range + radius, 0.2);
      const auto clusters = segment_scan(scan_of(scanner, Pose2{}, {Disc{truth, radius, Vec2::Zero()}}, 0.0, rng));
      ASSERT_EQ(clusters.size(), 1u) << "radius " << radius << ", range " << range;
      const Cluster& c = clusters[0];
      EXPECT_LT((c.center - truth).norm(), 0.1 + 0.5 * radius) << "radius " << radius << ", range " << range;
      // The visible half of the disc: about a diameter across the ray, a radius deep.
      EXPECT_NEAR(2.0 * c.box.half_extents.x(), 2.0 * radius, 0.15 + 0.2 * radius);
      EXPECT_LE(c.box.half_extents.y(), radius + 0.05);
      // The major axis runs across the ray (loosely when a few noisy hits make it).
      const double across = std::atan2(truth.y(), truth.x()) + 0.5 * M_PI;
      EXPECT_LT(std::abs(std::sin(c.box.angle - across)), c.points.size() >= 10 ? 0.3 : 0.6)
          << "radius " << radius << ", range " << range << ", " << c.points.size() << " points";
    }
  }
}

// The disc fit takes its ranges and directions from a vectorised kernel:
// every instruction set the processor runs fits the same bits, on clusters of
// every size around the lane counts (the last few points go one by one).
TEST(Segment, DiscFitsAreTheSameBitsOnEveryInstructionSet) {
  const LaserScanner scanner(noisy_lidar(), nullptr);
  std::vector<Scan> scans;
  std::mt19937_64 rng(11);
  for (double radius : {0.05, 0.15, 0.3, 0.6})
    for (double range : {0.8, 2.5, 7.0}) {
      const std::vector<Disc> discs{Disc{Vec2(range + radius, 0.3), radius, Vec2::Zero()},
                                    Disc{Vec2(-0.5, range + radius), 0.5 * radius + 0.05, Vec2::Zero()}};
      scans.push_back(scan_of(scanner, Pose2{}, discs, 0.0, rng));
    }
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  std::vector<std::vector<double>> fits;
  std::size_t sizes = 0;
  for (const int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    std::vector<double> fit;
    for (const Scan& scan : scans)
      for (const Cluster& c : segment_scan(scan)) {
        fit.insert(fit.end(), {c.center.x(), c.center.y(), c.radius});
        sizes |= std::size_t{1} << std::min<std::size_t>(c.points.size() % 8, 63);
      }
    fits.push_back(fit);
  }
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_EQ(sizes, 0xFFu) << "cluster sizes must cover every remainder modulo 8";
  ASSERT_GE(fits[0].size(), 3u * scans.size());
  for (std::size_t t = 1; t < fits.size(); ++t) {
    ASSERT_EQ(fits[t].size(), fits[0].size()) << hwy::TargetName(targets[t]);
    EXPECT_EQ(std::memcmp(fits[t].data(), fits[0].data(), fits[0].size() * sizeof(double)), 0)
        << hwy::TargetName(targets[t]) << " against " << hwy::TargetName(targets[0]);
  }
}

TEST(Segment, AFullCircleScanJoinsTheObjectOnItsSeam) {
  LidarParams circle;
  circle.fov = 2.0 * M_PI;
  circle.beams = 720;
  const LaserScanner scanner(circle, nullptr);
  std::mt19937_64 rng(6);
  // Straight behind the sensor, where the first and last beams meet.
  const auto clusters = segment_scan(scan_of(scanner, Pose2{}, {Disc{Vec2(-2.0, 0.0), 0.3, Vec2::Zero()}}, 0.0, rng));
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_GT(clusters[0].first_beam, clusters[0].last_beam);  // it wraps
  EXPECT_LT((clusters[0].center - Vec2(-2.0, 0.0)).norm(), 0.03);
}

TEST(Segment, BadInputIsAnError) {
  Scan scan;
  scan.angle_increment = 0.01;
  scan.ranges = {1.0, 1.0, NAN, 1.0};
  expect_error_naming([&] { segment_scan(scan); }, "ranges[2]");
  scan.ranges = {1.0, -1.0};
  expect_error_naming([&] { segment_scan(scan); }, "ranges[1]");
  scan.ranges = {1.0};
  scan.pose.x = NAN;
  expect_error_naming([&] { segment_scan(scan); }, "pose x");
  scan.pose.x = 0.0;
  SegmentParams p;
  p.base_gap = -0.1;
  expect_error_naming([&] { segment_scan(scan, p); }, "base_gap");
  p = SegmentParams{};
  p.min_points = 0;
  expect_error_naming([&] { p.validate(); }, "min_points");
  p = SegmentParams{};
  p.min_radius = 1.0;  // above max_size / 2
  expect_error_naming([&] { p.validate(); }, "min_radius");
}

// -------------------------------------------------------------------- tracking

// Runs a tracker over `seconds` of 10 Hz scans of `discs` (placed at time t)
// taken from `sensor(t)`; calls `each(t, tracker)` after every update.
template <typename Sensor, typename Each>
void run(Tracker& tracker, const std::vector<Disc>& discs, double seconds, std::uint64_t seed, Sensor sensor,
         Each each) {
  const LaserScanner scanner(noisy_lidar(), nullptr);
  std::mt19937_64 rng(seed);
  const int steps = static_cast<int>(std::lround(seconds / kPeriod));
  for (int k = 0; k <= steps; ++k) {
    const double t = k * kPeriod;
    const Scan scan = scan_of(scanner, sensor(t), discs, t, rng);
    tracker.update(segment_scan(scan), t, &scan);
    each(t, tracker);
  }
}

const auto kStill = [](double) { return Pose2{}; };

TEST(Tracker, FollowsAMoverAtItsSpeedWithinASecond) {
  const Disc mover{Vec2(3.0, -1.0), 0.3, Vec2(0.1, 0.49)};  // 0.5 m/s
  double worst = 0.0, worst_filter = 0.0, worst_window = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Tracker tracker;
    run(tracker, {mover}, 1.0, seed, kStill, [](double, const Tracker&) {});
    ASSERT_EQ(tracker.tracks().size(), 1u) << "seed " << seed;
    const Track& t = tracker.tracks()[0];
    EXPECT_EQ(t.status, TrackStatus::Confirmed);
    EXPECT_TRUE(t.moving) << "seed " << seed;
    EXPECT_LT((t.position - mover.center_at(1.0)).norm(), 0.05) << "seed " << seed;
    const auto discs = tracker.moving_discs();
    ASSERT_EQ(discs.size(), 1u);
    EXPECT_GT(discs[0].radius, t.radius);  // grown by the position's uncertainty
    EXPECT_EQ(discs[0].velocity, t.predicted_velocity);
    worst_window = std::max(worst_window, (t.window_velocity - mover.velocity).norm());
    // Ahead it spreads as the filter's speed uncertainty does: room for a turn or a reversal.
    EXPECT_DOUBLE_EQ(discs[0].growth, tracker.params().uncertainty_sigmas * t.speed_std());
    EXPECT_GT(discs[0].growth, 0.1);
    worst = std::max(worst, (discs[0].velocity - mover.velocity).norm());
    worst_filter = std::max(worst_filter, (t.velocity - mover.velocity).norm());
  }
  std::cout << "0.5 m/s disc after 1 s at 10 Hz, 3 cm noise, worst over 5 seeds: velocity error " << worst
            << " m/s (the filter's: " << worst_filter << " m/s, the label's 1 s line's: " << worst_window << " m/s)\n";
  // Going straight, the last 0.3 s of centres do not depart from the second's
  // line by more than their noise: the prediction keeps the steadier slope.
  EXPECT_LT(worst, 0.05);
  EXPECT_LT(worst_window, 0.05);
  EXPECT_LT(worst_filter, 0.15);
}

// A disc coming at the sensor at 1.5 m/s from the first scan on, or at 0.7 m/s
// across it, is labelled moving within five scans: free space is compared with
// the oldest scan kept until one is half a window old, so a mover is not a
// static obstacle for the first half second it is seen.
TEST(Tracker, AMoverSeenFromTheFirstScanIsLabelledWithinFiveScans) {
  const std::vector<Disc> movers = {Disc{Vec2(4.0, 0.0), 0.5, Vec2(-1.5, 0.0)},
                                    Disc{Vec2(3.0, -1.0), 0.5, Vec2(0.0, 0.7)}};
  for (const Disc& mover : movers)
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      SCOPED_TRACE(::testing::Message() << "velocity " << mover.velocity.transpose() << ", seed " << seed);
      Tracker tracker;
      double labelled = std::numeric_limits<double>::infinity();
      run(tracker, {mover}, 0.4, seed, kStill, [&](double t, const Tracker& tr) {
        if (std::isinf(labelled) && !tr.moving_discs().empty()) labelled = t;
      });
      EXPECT_LE(labelled, 0.4 + 1e-9);
    }
}

// A sensor turning at 2 rad/s brings a disc coming at it at 1.5 m/s out of
// its blind sector. Half a window before it came into view, where it now is
// lay in the blind sector too: only the scans since can show it displacing
// free space, and it is labelled moving within five scans of coming into view.
TEST(Tracker, AMoverComingIntoViewIsLabelledWithinFiveScans) {
  const Disc mover{Vec2(-4.0, 0.0), 0.5, Vec2(1.5, 0.0)};
  const auto turning = [](double t) { return Pose2{0.0, 0.0, 2.0 * t}; };
  const double half_fov = 0.5 * noisy_lidar().fov;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    Tracker tracker;
    double in_view = std::numeric_limits<double>::infinity(), labelled = in_view;
    run(tracker, {mover}, 1.5, seed, turning, [&](double t, const Tracker& tr) {
      const Vec2 c = mover.center_at(t);
      const double off_heading = std::abs(wrap_angle(std::atan2(c.y(), c.x()) - turning(t).theta));
      // Its whole near side within the field of view.
      if (std::isinf(in_view) && off_heading + std::asin(mover.radius / c.norm()) < half_fov) in_view = t;
      if (std::isinf(labelled) && !tr.moving_discs().empty()) labelled = t;
    });
    ASSERT_TRUE(std::isfinite(in_view));
    EXPECT_GT(in_view, 0.2);  // it does come out of the blind sector
    EXPECT_LE(labelled - in_view, 0.4 + 1e-9) << "in view at " << in_view << " s, labelled at " << labelled << " s";
  }
}

// A disc walks at 0.5 m/s for 2 s, then stands. Without a hold it is static
// again about a second after it stopped (when its window no longer moves);
// with moving_hold 2 s it stays a mover, nearly at rest, for 2 s more.
TEST(Tracker, AMoverThatStopsKeepsItsLabelForMovingHold) {
  const LaserScanner scanner(noisy_lidar(), nullptr);
  const Vec2 start(3.0, -1.0), velocity(0.0, 0.5);
  const double stop = 2.0;  // s
  const auto centre = [&](double t) { return start + std::min(t, stop) * velocity; };
  for (const double hold : {0.0, 2.0}) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      SCOPED_TRACE(::testing::Message() << "moving_hold " << hold << ", seed " << seed);
      TrackerParams params;
      params.moving_hold = hold;
      Tracker tracker(params);
      std::mt19937_64 rng(seed);
      double last_labelled = -1.0;
      for (int k = 0; k <= 60; ++k) {
        const double t = k * kPeriod;
        const Scan scan = scan_of(scanner, Pose2{}, {Disc{centre(t), 0.3}}, t, rng);
        tracker.update(segment_scan(scan), t, &scan);
        ASSERT_EQ(tracker.tracks().size(), 1u) << "t = " << t;
        if (tracker.tracks()[0].moving) last_labelled = t;
        if (t > stop + 1.5 && tracker.tracks()[0].moving) {
          const auto discs = tracker.moving_discs();
          ASSERT_EQ(discs.size(), 1u);
          EXPECT_LT(discs[0].velocity.norm(), 0.2) << "t = " << t;
        }
      }
      EXPECT_GE(last_labelled, stop + 0.5);
      if (hold == 0.0) {
        EXPECT_LE(last_labelled, stop + 1.2);
      } else {
        EXPECT_GE(last_labelled, stop + 2.5);
        EXPECT_LE(last_labelled, stop + 3.2);
      }
    }
  }
}

// A disc walking back and forth: 0.7 s after it turned, the prediction's
// 0.3 s window holds only the way back, while the label's 1 s window still
// straddles the turn (its slope about half the speed).
TEST(Tracker, ThePredictionFollowsAReversalBeforeTheLabelsWindow) {
  const LaserScanner scanner(noisy_lidar(), nullptr);
  const Vec2 start(3.0, -1.0), velocity(0.0, 0.5);
  const double turn = 2.0, after = 0.7;  // s
  const auto centre = [&](double t) { return start + (t <= turn ? t : 2.0 * turn - t) * velocity; };
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    Tracker tracker;
    std::mt19937_64 rng(seed);
    const int steps = static_cast<int>(std::lround((turn + after) / kPeriod));
    for (int k = 0; k <= steps; ++k) {
      const double t = k * kPeriod;
      const Scan scan = scan_of(scanner, Pose2{}, {Disc{centre(t), 0.3}}, t, rng);
      tracker.update(segment_scan(scan), t, &scan);
    }
    ASSERT_EQ(tracker.tracks().size(), 1u);
    const Track& t = tracker.tracks()[0];
    ASSERT_TRUE(t.moving);
    EXPECT_LT((t.predicted_velocity + velocity).norm(), 0.12) << t.predicted_velocity.transpose();
    EXPECT_GT(t.window_velocity.y(), -0.4);
    const auto discs = tracker.moving_discs();
    ASSERT_EQ(discs.size(), 1u);
    EXPECT_EQ(discs[0].velocity, t.predicted_velocity);
  }
}

// A disc going round a 1.5 m circle at 1.5 m/s (1.5 m/s^2 toward the centre):
// with hypothesis_time set, its track gets a second prediction that goes on
// bending, and 0.8 s ahead that one lies a quarter nearer (or more) where the disc will be than
// the straight one does. A disc going straight mostly gets none, and when it
// does, with little acceleration. By default there is only the straight one.
TEST(Tracker, ATurningMoverGetsASecondPredictionThatBends) {
  const Vec2 pivot(4.0, 0.0);
  const double r = 1.5, omega = 1.0;  // m, rad/s
  const auto on_circle = [&](double t) -> Vec2 { return pivot + r * Vec2(std::cos(M_PI + omega * t), std::sin(M_PI + omega * t)); };
  TrackerParams params;
  params.hypothesis_time = 1.0;
  const LaserScanner scanner(noisy_lidar(), nullptr);
  const double seen = 2.0, ahead = 0.8;  // s
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    Tracker tracker(params), plain;
    std::mt19937_64 rng(seed);
    for (int k = 0; k <= static_cast<int>(std::lround(seen / kPeriod)); ++k) {
      const double t = k * kPeriod;
      const Scan scan = scan_of(scanner, Pose2{}, {Disc{on_circle(t), 0.3}}, t, rng);
      const auto clusters = segment_scan(scan);
      tracker.update(clusters, t, &scan);
      plain.update(clusters, t, &scan);
    }
    ASSERT_EQ(plain.moving_discs().size(), 1u);
    const auto discs = tracker.moving_discs();
    ASSERT_EQ(discs.size(), 2u);
    const Track& track = tracker.tracks()[0];
    EXPECT_NEAR(track.acceleration.norm(), omega * omega * r, 0.6);
    EXPECT_EQ(discs[1].acceleration, track.acceleration);
    EXPECT_EQ(discs[1].velocity, track.current_velocity);
    EXPECT_EQ(discs[1].accel_time, params.hypothesis_time);
    EXPECT_EQ(discs[1].radius, discs[0].radius);
    const Vec2 truth = on_circle(seen + ahead);
    const double straight = (discs[0].center_at(ahead) - truth).norm(), bent = (discs[1].center_at(ahead) - truth).norm();
    // The straight line, through only the last 0.3 s of centres, is already
    // bent part of the way.
    EXPECT_LT(bent, 0.85 * straight) << "straight " << straight << " m off, bent " << bent << " m off";
  }
  int second = 0;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    Tracker tracker(params);
    run(tracker, {Disc{Vec2(3.0, -1.5), 0.3, Vec2(0.2, 1.0)}}, 2.0, seed, kStill, [](double, const Tracker&) {});
    const auto discs = tracker.moving_discs();
    ASSERT_GE(discs.size(), 1u);
    if (discs.size() == 2) {
      ++second;
      EXPECT_LT(discs[1].acceleration.norm(), 0.6) << "seed " << seed;
    }
  }
  EXPECT_LE(second, 6) << "of 20 straight runs";
}

// A mover seen only in part (beside something nearer, or at the edge of the
// field of view) is still labelled: its centres weigh less, not nothing.
// A static one seen the same way, its centre wobbling twice as much, is not.
TEST(Tracker, AnAlwaysOccludedMoverIsLabelledAndAnOccludedPillarIsNot) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  const Vec2 velocity(0.6, 0.0);
  Tracker mover_tracker, pillar_tracker;
  double labelled_at = -1.0;
  bool pillar_ever_moving = false;
  for (int k = 0; k <= 30; ++k) {
    const double t = k * kPeriod;
    Cluster mover = cluster_at(Vec2(1.0, 2.0) + velocity * t + 0.03 * Vec2(noise(rng), noise(rng)));
    Cluster pillar = cluster_at(Vec2(4.0, -2.0) + 0.06 * Vec2(noise(rng), noise(rng)));
    mover.occluded = pillar.occluded = true;
    mover_tracker.update({mover}, t);
    pillar_tracker.update({pillar}, t);
    if (labelled_at < 0.0 && mover_tracker.tracks()[0].moving) labelled_at = t;
    pillar_ever_moving = pillar_ever_moving || pillar_tracker.tracks()[0].moving;
  }
  EXPECT_GE(labelled_at, 0.0) << "never labelled moving";
  EXPECT_LE(labelled_at, 1.5);
  EXPECT_FALSE(pillar_ever_moving);
  EXPECT_LT((mover_tracker.tracks()[0].window_velocity - velocity).norm(), 0.15);
}

TEST(Tracker, AStaticDiscIsNeverMovingAndSettlesAtRest) {
  double worst_window = 0.0, worst_filter = 0.0, sum_filter = 0.0;
  int samples = 0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Tracker tracker;
    run(tracker, {Disc{Vec2(3.0, 0.5), 0.2, Vec2::Zero()}}, 10.0, seed, kStill, [&](double t, const Tracker& tr) {
      ASSERT_EQ(tr.tracks().size(), 1u);
      const Track& track = tr.tracks()[0];
      EXPECT_FALSE(track.moving) << "seed " << seed << ", t " << t;
      if (t >= 1.0) {
        worst_window = std::max(worst_window, track.window_velocity.norm());
        worst_filter = std::max(worst_filter, track.velocity.norm());
        sum_filter += track.velocity.norm();
        ++samples;
      }
    });
    EXPECT_TRUE(tracker.moving_discs().empty());
  }
  std::cout << "static disc after 1 s, 5 seeds: fastest window speed " << worst_window << " m/s; filter speed mean "
            << sum_filter / samples << ", fastest " << worst_filter << " m/s\n";
  EXPECT_LT(worst_window, 0.08);
  EXPECT_LT(sum_filter / samples, 0.06);
}

TEST(Tracker, AStaticDiscSeenFromAMovingSensorIsNeverMoving) {
  // The sensor circles a 0.6 m disc 1.6 m from its centre at 1 m/s, facing it:
  // the side it sees turns at 0.6 rad/s, which moves the hits' centroid at
  // about 0.25 m/s while the disc stands still.
  const Vec2 pillar(0.0, 0.0);
  const double orbit = 1.6, omega = 1.0 / orbit;
  const auto sensor = [&](double t) {
    const double a = omega * t;
    return Pose2{pillar.x() + orbit * std::cos(a), pillar.y() + orbit * std::sin(a), a + M_PI};
  };
  const LaserScanner scanner(noisy_lidar(), nullptr);
  double worst_fit = 0.0, worst_centroid = 0.0;
  bool centroid_moving = false;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    Tracker fitted, centroids;
    std::mt19937_64 rng(seed);
    for (int k = 0; k <= 100; ++k) {
      const double t = k * kPeriod;
      const Scan scan = scan_of(scanner, sensor(t), {Disc{pillar, 0.6, Vec2::Zero()}}, t, rng);
      auto clusters = segment_scan(scan);
      fitted.update(clusters, t, &scan);
      for (Cluster& c : clusters) c.center = centroid(c);
      centroids.update(clusters, t);  // speed alone
      centroid_moving = centroid_moving || !centroids.moving_discs().empty();
      // Grazing hits at the disc's edges may split off as small fragments of
      // their own: no track at all may be called moving.
      for (const Track& track : fitted.tracks()) EXPECT_FALSE(track.moving) << "seed " << seed << ", t " << t;
      if (t >= 2.0) {
        worst_fit = std::max(worst_fit, nearest_track(fitted, pillar)->window_velocity.norm());
        worst_centroid = std::max(worst_centroid, nearest_track(centroids, pillar)->window_velocity.norm());
      }
    }
  }
  std::cout << "static 0.6 m disc from a circling sensor: fastest window speed after 2 s " << worst_fit
            << " m/s (with centroids: " << worst_centroid << " m/s)\n";
  EXPECT_LT(worst_fit, 0.1);
  // The bias the fit removes: centroids would call the pillar moving.
  EXPECT_GT(worst_centroid, 0.2);
  EXPECT_TRUE(centroid_moving);
}

TEST(Tracker, DrivingThroughStaticBoxesCallsNothingMovingButAWalker) {
  // Random boxes either side of a corridor; the robot drives along it, at
  // 0.5 m/s straight down the middle, and at 1 m/s weaving from side to side
  // (a BARN run's pace and turns). The boxes' outlines change as it passes
  // (faces appear, hide one another), which moves their clusters' centres:
  // speed alone calls some of them moving, the free-space test none. Weaving,
  // the robot sees a face edge-on and then from the side: the later hits'
  // range noise puts some beside the face, where the earlier beams grazed
  // past, and only a test that allows for it keeps the box static. A walker
  // crossing the corridor ahead is still found.
  struct Drive {
    double speed;    // m/s
    double weave;    // m, amplitude across the corridor
    double walker;   // s, when the walker steps in (for 3 s), 2 m ahead of the robot then
    double seconds;  // s
  };
  for (const Drive drive : {Drive{0.5, 0.0, 0.0, 20.0}, Drive{1.0, 0.25, 3.0, 10.0}}) {
    SCOPED_TRACE(::testing::Message() << drive.speed << " m/s, weave " << drive.weave << " m");
    const auto pose_at = [&](double t) {
      const double x = -5.0 + drive.speed * t, y = drive.weave * std::sin(1.5 * t);
      return Pose2{x, y, std::atan2(1.5 * drive.weave * std::cos(1.5 * t), drive.speed)};
    };
    int false_with_scans = 0, false_speed_alone = 0;
    for (std::uint32_t seed = 1; seed <= 3; ++seed) {
      std::mt19937 g(seed);
      constexpr int n = 240;  // 12 m of 0.05 m cells
      std::vector<std::uint8_t> cells(n * n, 0);
      std::uniform_int_distribution<int> at(0, n - 1), side(2, 12);
      for (int k = 0; k < 80; ++k) {
        const int r0 = at(g), c0 = at(g), h = side(g), w = side(g);
        for (int r = r0; r < std::min(n, r0 + h); ++r)
          for (int c = c0; c < std::min(n, c0 + w); ++c) cells[r * n + c] = 1;
      }
      for (int r = 110; r < 130; ++r)
        for (int c = 0; c < n; ++c) cells[r * n + c] = 0;  // the corridor, y in [-0.5, 0.5]
      const auto world = std::make_shared<const DistanceField>(OccupancyGrid(n, n, 0.05, Vec2(-6.0, -6.0), cells));
      const LaserScanner scanner(noisy_lidar(), world);
      std::mt19937_64 rng(seed);
      // Crosses the corridor from y = -0.45 at 0.3 m/s, from drive.walker for 3 s.
      const Vec2 walker_velocity(0.0, 0.3);
      const Disc walker{Vec2(pose_at(drive.walker).x + 2.0, -0.45) - drive.walker * walker_velocity, 0.25,
                        walker_velocity};
      const double walker_gone = drive.walker + 3.0;
      Tracker tracker, speed_alone;
      bool walker_found = false;
      for (int k = 0; k <= static_cast<int>(std::lround(drive.seconds / kPeriod)); ++k) {
        const double t = k * kPeriod;
        const bool walking = t >= drive.walker && t <= walker_gone;
        const std::vector<Disc> movers = walking ? std::vector<Disc>{walker} : std::vector<Disc>{};
        const Scan scan = scan_of(scanner, pose_at(t), movers, t, rng);
        const auto clusters = segment_scan(scan);
        tracker.update(clusters, t, &scan);
        speed_alone.update(clusters, t);
        // Near the walker (or where it vanished, for the second its track
        // coasts) a moving disc is the walker's, perhaps merged with a box
        // it passes; anywhere else it is a box called moving.
        const auto far_from_walker = [&](const Disc& d) {
          return t < drive.walker || (d.center - walker.center_at(std::min(t, walker_gone))).norm() > 1.0;
        };
        for (const Disc& d : tracker.moving_discs()) {
          walker_found = walker_found || (walking && (d.center - walker.center_at(t)).norm() < 0.1);
          false_with_scans += far_from_walker(d);
        }
        for (const Disc& d : speed_alone.moving_discs()) false_speed_alone += far_from_walker(d);
      }
      EXPECT_TRUE(walker_found) << "seed " << seed;
    }
    std::cout << "driving through boxes at " << drive.speed << " m/s, 3 runs of " << drive.seconds
              << " s: false moving discs " << false_with_scans << " (speed alone: " << false_speed_alone << ")\n";
    EXPECT_EQ(false_with_scans, 0);
    EXPECT_GT(false_speed_alone, 0);  // what the free-space test is for
  }
}

TEST(Tracker, CrossingMoversKeepTheirIds) {
  // Two discs on crossing paths pass each other 0.8 m apart at t = 5 s, the
  // second behind the first as seen from the sensor (partly hidden for about
  // a second).
  const Disc a{Vec2(3.0, -2.5), 0.25, Vec2(0.1, 0.5)};
  const Disc b{Vec2(3.8, 2.5), 0.25, Vec2(0.1, -0.5)};
  constexpr double kSeconds = 8.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    Tracker tracker;
    int id_a = -1, id_b = -1;
    run(tracker, {a, b}, kSeconds, seed, kStill, [&](double t, const Tracker& tr) {
      if (std::abs(t - 1.5) < 1e-9) {
        id_a = nearest_track(tr, a.center_at(t))->id;
        id_b = nearest_track(tr, b.center_at(t))->id;
        ASSERT_NE(id_a, id_b);
      }
      if (t > 1.5) {
        // Each id stays with its disc the whole way.
        for (const Track& track : tr.tracks()) {
          const Disc* own = track.id == id_a ? &a : track.id == id_b ? &b : nullptr;
          if (own) {
            EXPECT_LT((track.position - own->center_at(t)).norm(), 0.3) << "seed " << seed << ", t " << t;
          }
        }
      }
    });
    const Track* end_a = nearest_track(tracker, a.center_at(kSeconds));
    const Track* end_b = nearest_track(tracker, b.center_at(kSeconds));
    EXPECT_EQ(end_a->id, id_a) << "seed " << seed;
    EXPECT_EQ(end_b->id, id_b) << "seed " << seed;
    EXPECT_TRUE(end_a->moving && end_b->moving) << "seed " << seed;
  }
}

TEST(Tracker, TracksAreConfirmedThenLostThenRemoved) {
  TrackerParams p;  // confirm_hits 3
  p.lost_time = 0.5;
  Tracker tracker(p);
  const Vec2 at(2.0, 1.0);
  tracker.update({cluster_at(at)}, 0.0);
  ASSERT_EQ(tracker.tracks().size(), 1u);
  const int id = tracker.tracks()[0].id;
  EXPECT_EQ(tracker.tracks()[0].status, TrackStatus::Tentative);
  EXPECT_EQ(tracker.cluster_tracks(), std::vector<int>{id});
  tracker.update({cluster_at(at)}, 0.1);
  EXPECT_EQ(tracker.tracks()[0].status, TrackStatus::Tentative);
  tracker.update({cluster_at(at)}, 0.2);
  EXPECT_EQ(tracker.tracks()[0].status, TrackStatus::Confirmed);
  EXPECT_EQ(tracker.tracks()[0].hits, 3);
  EXPECT_NEAR(tracker.tracks()[0].age, 0.2, 1e-12);
  tracker.update({}, 0.65);  // unseen 0.45 s
  EXPECT_EQ(tracker.tracks()[0].status, TrackStatus::Confirmed);
  tracker.update({}, 0.75);  // unseen 0.55 s
  EXPECT_EQ(tracker.tracks()[0].status, TrackStatus::Lost);
  EXPECT_NEAR(tracker.tracks()[0].last_seen, 0.2, 1e-12);
  tracker.update({}, 1.15);  // unseen 0.95 s: still coasting
  ASSERT_EQ(tracker.tracks().size(), 1u);
  tracker.update({}, 1.25);  // unseen 1.05 s: gone
  EXPECT_TRUE(tracker.tracks().empty());

  // A lost track found again is the same track, confirmed again.
  tracker.update({cluster_at(at)}, 2.0);
  tracker.update({cluster_at(at)}, 2.1);
  tracker.update({cluster_at(at)}, 2.2);
  const int second = tracker.tracks()[0].id;
  EXPECT_NE(second, id);
  tracker.update({}, 2.8);
  EXPECT_EQ(tracker.tracks()[0].status, TrackStatus::Lost);
  tracker.update({cluster_at(at)}, 2.9);
  ASSERT_EQ(tracker.tracks().size(), 1u);
  EXPECT_EQ(tracker.tracks()[0].id, second);
  EXPECT_EQ(tracker.tracks()[0].status, TrackStatus::Confirmed);

  tracker.reset();
  EXPECT_TRUE(tracker.tracks().empty());
  tracker.update({cluster_at(at)}, 0.0);  // time may start over after reset
  EXPECT_GT(tracker.tracks()[0].id, second);  // ids are never reused
}

// A mover that vanishes where the scan sees through its predicted centre is
// dropped by that scan; one hidden behind something nearer coasts as before.
TEST(Tracker, AMissedTrackIsDroppedWhereTheScanSeesThroughIt) {
  const Disc mover{Vec2(3.0, -1.0), 0.4, Vec2(0.0, 1.0)};
  const Disc screen{Vec2(1.5, 0.0), 0.5};  // hides the mover from about t = 0.6 s
  const LaserScanner scanner(noisy_lidar(), nullptr);
  for (const bool hidden : {false, true}) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      SCOPED_TRACE(::testing::Message() << (hidden ? "hidden" : "vanished") << ", seed " << seed);
      Tracker tracker;
      std::mt19937_64 rng(seed);
      double t = 0.0;
      for (; t < 0.45; t += kPeriod) {
        const Scan scan = scan_of(scanner, Pose2{}, {mover}, t, rng);
        tracker.update(segment_scan(scan), t, &scan);
      }
      ASSERT_EQ(tracker.moving_discs().size(), 1u);
      const int id = tracker.tracks()[0].id;
      // Gone (a wrapped animation's jump), or behind the screen.
      const std::vector<Disc> scene = hidden ? std::vector<Disc>{screen, mover} : std::vector<Disc>{};
      const Scan scan = scan_of(scanner, Pose2{}, scene, t, rng);
      tracker.update(segment_scan(scan), t, &scan);
      const Track* kept = nullptr;
      for (const Track& track : tracker.tracks())
        if (track.id == id) kept = &track;
      if (hidden) {
        ASSERT_NE(kept, nullptr);
        EXPECT_LT(kept->last_seen, t);  // coasting
      } else {
        EXPECT_EQ(kept, nullptr);
        EXPECT_TRUE(tracker.moving_discs().empty());
      }
    }
  }
}

// A mover passing behind something nearer is seen as an arc: fitted on its
// own, a smaller disc pulled toward the hits. The tracker refits it with the
// track's radius, so its centre stays within centimetres and its radius holds.
TEST(Tracker, AnOccludedMoverIsRefittedWithItsTracksRadius) {
  const Disc mover{Vec2(4.0, -1.5), 0.5, Vec2(0.0, 0.8)};
  const Disc screen{Vec2(2.0, 0.0), 0.25};  // cuts the mover's near side from about y = -0.6 to 0.6
  const LaserScanner scanner(noisy_lidar(), nullptr);
  double worst_raw = 0.0, worst_track = 0.0;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SCOPED_TRACE(::testing::Message() << "seed " << seed);
    Tracker tracker;
    std::mt19937_64 rng(seed);
    double radius_before = 0.0;
    for (int k = 0; k <= 35; ++k) {
      const double t = k * kPeriod;
      const Disc now{mover.center_at(t), mover.radius};
      const Scan scan = scan_of(scanner, Pose2{}, {screen, mover}, t, rng);
      const auto clusters = segment_scan(scan);
      tracker.update(clusters, t, &scan);
      const Track* track = nearest_track(tracker, now.center);
      ASSERT_NE(track, nullptr);
      if (t < 0.9) radius_before = track->radius;
      const Cluster& seen = nearest_cluster(clusters, now.center);
      // Half hidden or more: the screen covers the mover's centre line.
      if (!seen.occluded || std::abs(now.center.y()) > 0.3 || t < 0.9) continue;
      worst_raw = std::max(worst_raw, (seen.center - now.center).norm());
      worst_track = std::max(worst_track, (track->position - now.center).norm());
      EXPECT_NEAR(track->radius, radius_before, 1e-12);
    }
  }
  std::cout << "half-hidden 0.5 m disc: worst centre error " << worst_raw << " m fitted alone, " << worst_track
            << " m tracked\n";
  EXPECT_GT(worst_raw, 0.1);
  EXPECT_LT(worst_track, 0.08);
}

TEST(Tracker, AssignmentIsGloballyOptimal) {
  // Two tracks at x = 0 and x = 1; next scan clusters at x = 0.55 and 1.5. The
  // nearest pair (the track at 1 and 0.55) would leave 1.5 beyond the other's
  // reach; the best assignment gives each track the cluster on its side.
  TrackerParams p;
  p.gate_sigmas = 100.0;
  p.max_speed = 10.0;
  Tracker tracker(p);
  for (int k = 0; k < 3; ++k) tracker.update({cluster_at(Vec2(0.0, 0.0)), cluster_at(Vec2(1.0, 0.0))}, 0.1 * k);
  const std::vector<int> ids = tracker.cluster_tracks();
  tracker.update({cluster_at(Vec2(0.55, 0.0)), cluster_at(Vec2(1.5, 0.0))}, 0.3);
  EXPECT_EQ(tracker.cluster_tracks(), ids);
  EXPECT_EQ(tracker.tracks().size(), 2u);
}

TEST(Tracker, ImpossiblyFastAssociationsAreRejected) {
  TrackerParams p;
  p.gate_sigmas = 100.0;  // leave it to max_speed
  Tracker tracker(p);
  for (int k = 0; k < 3; ++k) tracker.update({cluster_at(Vec2(2.0, 0.0))}, 0.1 * k);
  // 0.8 m in 0.1 s is 8 m/s: a different object.
  tracker.update({cluster_at(Vec2(2.8, 0.0))}, 0.3);
  ASSERT_EQ(tracker.tracks().size(), 2u);
  EXPECT_NE(tracker.cluster_tracks()[0], tracker.tracks()[0].id);
  p.max_speed = 10.0;
  Tracker lenient(p);
  for (int k = 0; k < 3; ++k) lenient.update({cluster_at(Vec2(2.0, 0.0))}, 0.1 * k);
  lenient.update({cluster_at(Vec2(2.8, 0.0))}, 0.3);
  EXPECT_EQ(lenient.tracks().size(), 1u);
}

TEST(Tracker, MovingDiscsExplainTheirHitsOnly) {
  Tracker tracker;
  const Disc mover{Vec2(3.0, -1.0), 0.3, Vec2(0.0, 0.6)};
  const Disc pillar{Vec2(2.0, 1.5), 0.2, Vec2::Zero()};
  run(tracker, {mover, pillar}, 1.5, 7, kStill, [](double, const Tracker&) {});
  ASSERT_EQ(tracker.moving_discs().size(), 1u);
  const Vec2 now = mover.center_at(1.5);
  EXPECT_TRUE(tracker.explains(now + Vec2(-0.3, 0.0)));   // its near surface
  EXPECT_FALSE(tracker.explains(now + Vec2(-0.8, 0.0)));  // half a metre in front
  EXPECT_TRUE(tracker.explains(now + Vec2(-0.8, 0.0), 0.6));
  EXPECT_FALSE(tracker.explains(pillar.center + Vec2(-0.2, 0.0)));  // static: the map's
}

TEST(Tracker, BadInputIsAnError) {
  TrackerParams p;
  p.gate = -1.0;
  expect_error_naming([&] { Tracker{p}; }, "gate");
  p = TrackerParams{};
  p.confirm_hits = 0;
  expect_error_naming([&] { Tracker{p}; }, "confirm_hits");
  p = TrackerParams{};
  p.measurement_std = NAN;
  expect_error_naming([&] { Tracker{p}; }, "measurement_std");
  p = TrackerParams{};
  p.prediction_window = 0.0;
  expect_error_naming([&] { Tracker{p}; }, "prediction_window");
  Tracker tracker;
  expect_error_naming([&] { tracker.update({}, NAN); }, "time");
  tracker.update({}, 1.0);
  expect_error_naming([&] { tracker.update({}, 0.5); }, "time");
  expect_error_naming([&] { tracker.update({cluster_at(Vec2(NAN, 0.0))}, 1.0); }, "cluster[0] center x");
  expect_error_naming([&] { tracker.update({cluster_at(Vec2(0.0, 0.0), -0.1)}, 1.0); }, "cluster[0] radius");
  Scan bad;
  bad.ranges = {1.0, NAN};
  expect_error_naming([&] { tracker.update({}, 2.0, &bad); }, "scan ranges");
  Cluster stray = cluster_at(Vec2(1.0, 0.0));
  stray.points.push_back(Vec2(NAN, 0.0));
  expect_error_naming([&] { tracker.update({stray}, 2.0); }, "cluster[0] points");
  expect_error_naming([&] { tracker.explains(Vec2(0.0, NAN)); }, "point y");
  expect_error_naming([&] { tracker.explains(Vec2(0.0, 0.0), -1.0); }, "margin");
  EXPECT_TRUE(tracker.tracks().empty());  // a rejected update changes nothing
}

TEST(Cluster, ValidateNamesTheField) {
  EXPECT_NO_THROW(cluster_at(Vec2(1.0, 2.0)).validate());
  expect_error_naming([&] { cluster_at(Vec2(0.0, 0.0), NAN).validate(); }, "cluster radius");
  expect_error_naming([&] { cluster_at(Vec2(0.0, NAN)).validate(); }, "cluster center y");
  expect_error_naming([&] { cluster_at(Vec2(2e7, 0.0)).validate("detection"); }, "detection center x");
}

TEST(Tracker, CostOfOneScan) {
  // Printed, not asserted: segment + update for a 541-beam scan with two movers
  // and a pillar.
  const LaserScanner scanner(noisy_lidar(), nullptr);
  std::mt19937_64 rng(8);
  const std::vector<Disc> discs = {Disc{Vec2(3.0, -1.5), 0.3, Vec2(0.0, 0.4)},
                                   Disc{Vec2(5.0, 3.0), 0.25, Vec2(-0.3, 0.0)}, Disc{Vec2(2.0, -2.5), 0.2, Vec2::Zero()}};
  std::vector<Scan> scans;
  constexpr int kScans = 80;  // all three stay in view
  for (int k = 0; k < kScans; ++k) scans.push_back(scan_of(scanner, Pose2{}, discs, k * kPeriod, rng));
  Tracker tracker;
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < kScans; ++k) tracker.update(segment_scan(scans[k]), k * kPeriod, &scans[k]);
  const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
  std::cout << "segment_scan + Tracker::update, 541 beams, 3 objects: " << us / kScans << " us per scan\n";
  EXPECT_EQ(tracker.moving_discs().size(), 2u);
}

// The least total over every way of pairing rows with distinct columns
// through allowed pairs, each row left out at its price.
double cheapest_assignment(const Eigen::MatrixXd& cost, const std::vector<double>& unassigned, int row,
                           std::vector<bool>& taken) {
  if (row == cost.rows()) return 0.0;
  double best = unassigned[static_cast<std::size_t>(row)] + cheapest_assignment(cost, unassigned, row + 1, taken);
  for (int c = 0; c < cost.cols(); ++c) {
    if (taken[static_cast<std::size_t>(c)] || !std::isfinite(cost(row, c))) continue;
    taken[static_cast<std::size_t>(c)] = true;
    best = std::min(best, cost(row, c) + cheapest_assignment(cost, unassigned, row + 1, taken));
    taken[static_cast<std::size_t>(c)] = false;
  }
  return best;
}

// Tracks meet clusters through a gate, so most pairs are forbidden and the
// problem falls apart into independent ones, solved one by one: together
// they must still reach the least total, with allowed pairs and each column
// used once, whatever the sizes and however the allowed pairs link up.
TEST(Assignment, IndependentProblemsTogetherReachTheLeastTotal) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> price(0.0, 9.0);
  std::uniform_int_distribution<int> size(0, 6);
  int linked_problems = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int rows = size(rng), cols = size(rng);
    const double allowed_share = std::uniform_real_distribution<double>(0.1, 0.9)(rng);
    Eigen::MatrixXd cost(rows, cols);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c)
        cost(r, c) = std::bernoulli_distribution(allowed_share)(rng) ? price(rng) : std::numeric_limits<double>::infinity();
    std::vector<double> unassigned(static_cast<std::size_t>(rows));
    for (double& u : unassigned) u = price(rng);
    const std::vector<int> chosen = detail::assign(cost, unassigned);
    ASSERT_EQ(chosen.size(), static_cast<std::size_t>(rows));
    std::vector<bool> used(static_cast<std::size_t>(cols), false);
    double total = 0.0;
    for (int r = 0; r < rows; ++r) {
      const int c = chosen[static_cast<std::size_t>(r)];
      if (c < 0) {
        total += unassigned[static_cast<std::size_t>(r)];
        continue;
      }
      ASSERT_LT(c, cols);
      ASSERT_TRUE(std::isfinite(cost(r, c))) << "trial " << trial << ": a forbidden pair was chosen";
      ASSERT_FALSE(used[static_cast<std::size_t>(c)]) << "trial " << trial << ": a column was chosen twice";
      used[static_cast<std::size_t>(c)] = true;
      total += cost(r, c);
    }
    std::vector<bool> taken(static_cast<std::size_t>(cols), false);
    EXPECT_NEAR(total, cheapest_assignment(cost, unassigned, 0, taken), 1e-9) << "trial " << trial;
    linked_problems += rows > 1 && cols > 1;
  }
  EXPECT_GT(linked_problems, 1500);
}

}  // namespace
}  // namespace fgdwa::test
