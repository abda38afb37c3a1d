#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "fgdwa/clearance.hpp"
#include "fgdwa/collision.hpp"
#include "fgdwa/presets.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

using test::kInf;

void expect_exact_cover(const OccupancyGrid& grid, const std::vector<CellRect>& rects) {
  std::vector<int> covered(grid.cells().size(), 0);
  for (const CellRect& r : rects) {
    ASSERT_GE(r.rows, 1);
    ASSERT_GE(r.cols, 1);
    ASSERT_TRUE(grid.in_bounds(r.row, r.col));
    ASSERT_TRUE(grid.in_bounds(r.row + r.rows - 1, r.col + r.cols - 1));
    for (int row = r.row; row < r.row + r.rows; ++row)
      for (int col = r.col; col < r.col + r.cols; ++col) ++covered[grid.index(row, col)];
  }
  for (int row = 0; row < grid.rows(); ++row)
    for (int col = 0; col < grid.cols(); ++col)
      ASSERT_EQ(covered[grid.index(row, col)], grid.occupied(row, col) ? 1 : 0) << "cell " << row << "," << col;
}

TEST(MergeOccupiedCells, CoversExactlyTheOccupiedCellsWithDisjointRectangles) {
  std::mt19937 rng(1001);
  std::uniform_int_distribution<int> size(1, 40);
  std::uniform_real_distribution<double> density(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const int rows = size(rng), cols = size(rng);
    const OccupancyGrid grid = trial % 2 ? test::random_cells(rng, rows, cols, 0.1, Vec2::Zero(), density(rng))
                                         : test::random_rectangles(rng, rows, cols, 0.1, Vec2::Zero(), 0.3, 6);
    expect_exact_cover(grid, merge_occupied_cells(grid));
  }
  const OccupancyGrid full(7, 9, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(63, 1));
  const auto one = merge_occupied_cells(full);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].rows, 7);
  EXPECT_EQ(one[0].cols, 9);
  EXPECT_TRUE(merge_occupied_cells(OccupancyGrid(3, 3, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(9, 0))).empty());
}

// Clustered obstacles (rectangles, as in real maps) collapse into few boxes,
// which is what keeps the FCL broadphase small.
TEST(MergeOccupiedCells, ClusteredMapNeedsFarFewerBoxesThanCells) {
  std::mt19937 rng(15);
  const OccupancyGrid grid = test::random_rectangles(rng, 100, 100, 0.1, Vec2::Zero(), 0.15);
  const auto boxes = merge_occupied_cells(grid);
  expect_exact_cover(grid, boxes);
  EXPECT_GE(grid.occupied_count(), 1400u);
  EXPECT_LT(boxes.size() * 4, grid.occupied_count()) << boxes.size() << " boxes for " << grid.occupied_count();
}

struct Query {
  Pose2 pose;
  bool near_obstacle;
};

// Half the poses anywhere in free space, half within 1 m of an obstacle cell.
std::vector<Query> random_queries(std::mt19937& rng, const OccupancyGrid& grid, int n) {
  std::uniform_real_distribution<double> x(0.0, grid.cols() * grid.resolution()),
      y(0.0, grid.rows() * grid.resolution()), angle(-M_PI, M_PI), offset(0.0, 1.0);
  std::vector<Vec2> obstacles;
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c)
      if (grid.occupied(r, c)) obstacles.push_back(grid.cell_center(r, c));
  std::uniform_int_distribution<std::size_t> pick(0, obstacles.size() - 1);
  std::vector<Query> out;
  while (static_cast<int>(out.size()) < n) {
    const bool near = out.size() % 2 == 1;
    Vec2 p;
    if (near) {
      const double a = angle(rng);
      p = obstacles[pick(rng)] + offset(rng) * Vec2(std::cos(a), std::sin(a));
    } else {
      p = grid.origin() + Vec2(x(rng), y(rng));
    }
    if (grid.occupied_at(p)) continue;
    out.push_back({Pose2{p.x(), p.y(), angle(rng)}, near});
  }
  return out;
}

class ClearanceAgreement : public ::testing::TestWithParam<int> {};

// FCL is exact (checked against a brute-force distance to the cell squares);
// the distance field never reports more room than there is, exactly as much
// where the footprint lies inside the grid, and at most a few millimetres less
// where a polygon's outline leaves it (the outline tolerance there). Case 2 has BARN's
// coarse 0.15 m cells, where a plain half-cell walk of the outline overstated
// the clearance by centimetres.
TEST_P(ClearanceAgreement, FieldNeverAboveFclAndWithinAFewMillimetres) {
  const Footprint footprint = GetParam() == 0
                                  ? Footprint::circle(0.25)
                                  : Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}});
  std::mt19937 rng(2024 + GetParam());
  const double cell = GetParam() == 2 ? 0.15 : 0.1;
  const OccupancyGrid grid = test::random_rectangles(rng, 100, 100, cell, Vec2::Zero(), 0.15);
  const auto field = std::make_shared<const DistanceField>(grid);
  const FieldClearance fast(field);
  const CollisionWorld exact(grid);

  int compared = 0, contacts = 0, inside = 0;
  double worst = 0.0;
  for (const Query& q : random_queries(rng, grid, 1000)) {
    const double d_fcl = exact.clearance(footprint, q.pose, 0.0);
    const double d_field = fast.clearance(footprint, q.pose, 0.0);
    const double d_brute = test::brute_footprint_distance(grid, footprint, q.pose);
    SCOPED_TRACE(::testing::Message() << "pose " << q.pose.x << "," << q.pose.y << "," << q.pose.theta << " fcl "
                                      << d_fcl << " field " << d_field << " brute " << d_brute);
    ASSERT_NEAR(d_fcl, d_brute, 1e-6);
    // The clearance term only looks below the 2 m cap.
    if (d_fcl < 2.0) {
      ASSERT_LE(d_field, d_fcl + 1e-9);
      ASSERT_LE(std::abs(std::max(d_field, 0.0) - d_fcl), 0.0025 + 1e-9);
      worst = std::max(worst, std::abs(std::max(d_field, 0.0) - d_fcl));
      ++compared;
      // Inside the grid the outline is measured exactly, segment against square.
      const double r = footprint.radius(), size = grid.cols() * grid.resolution();
      if (q.pose.x - r > 0.0 && q.pose.y - r > 0.0 && q.pose.x + r < size && q.pose.y + r < size) {
        ASSERT_NEAR(std::max(d_field, 0.0), d_fcl, 1e-6);
        ++inside;
      }
    }
    const bool hit = exact.in_collision(footprint, q.pose, 0.0);
    if (hit) ++contacts;
    if (d_fcl > 1e-9 || hit) {
      ASSERT_EQ(hit, d_fcl <= 0.0);
    }
  }
  EXPECT_GE(compared, 900);
  EXPECT_GE(inside, 700);
  EXPECT_GE(contacts, 50);  // the near-obstacle half exercises contact
  RecordProperty("worst_field_error", std::to_string(worst));
}

INSTANTIATE_TEST_SUITE_P(CircleAndRectangle, ClearanceAgreement, ::testing::Values(0, 1, 2));

// The outline's pieces are skipped on bounds from their ends' distances; the
// clearance must still be the least of the edges' exact distances, over
// footprints from a sliver to a square and from many poses near obstacles,
// off the grid included. It is 0 exactly when an obstacle cell's centre lies
// inside the footprint or an edge touches one (the cells inside are found
// here by brute force over the outline's bounding box).
TEST(FieldClearance, PolygonClearanceIsTheLeastEdgeDistance) {
  std::mt19937 rng(515);
  const OccupancyGrid grid = test::random_rectangles(rng, 60, 60, 0.1, Vec2(-1.0, 0.5), 0.12);
  const auto field = std::make_shared<const DistanceField>(grid);
  const FieldClearance fast(field);
  std::uniform_real_distribution<double> side(0.02, 0.9), shift(-0.4, 0.4);  // shift: of the side, keeping the origin in
  int compared = 0, enclosed = 0;
  for (int shape = 0; shape < 40; ++shape) {
    const double w = side(rng), h = side(rng), dx = shift(rng) * w, dy = shift(rng) * h;
    const Footprint footprint = Footprint::polygon({{dx - w / 2, dy - h / 2}, {dx + w / 2, dy - h / 2},
                                                    {dx + w / 2 + 0.1 * w, dy + h / 2}, {dx - w / 2, dy + h / 2}});
    for (const Query& q : random_queries(rng, grid, 500)) {
      const std::vector<Vec2> v = test::placed_vertices(footprint, q.pose);
      double least = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < v.size(); ++i) least = std::min(least, field->segment_distance(v[i], v[(i + 1) % v.size()]));
      const double got = fast.clearance(footprint, q.pose, 0.0);
      SCOPED_TRACE(::testing::Message() << "shape " << shape << " pose " << q.pose.x << "," << q.pose.y << ","
                                        << q.pose.theta);
      bool cell_inside = false;
      Vec2 lo = v[0], hi = v[0];
      for (const Vec2& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
      for (int r = 0; r < grid.rows(); ++r)
        for (int c = 0; c < grid.cols(); ++c) {
          const Vec2 centre = grid.cell_center(r, c);
          if (grid.occupied(r, c) && (centre.array() >= lo.array()).all() && (centre.array() <= hi.array()).all())
            cell_inside = cell_inside || footprint.contains(q.pose, centre);
        }
      if (least > 0.0 && cell_inside) {
        ASSERT_EQ(got, 0.0);
        ++enclosed;
        continue;
      }
      ASSERT_NEAR(got, least, 1e-12);
      ++compared;
    }
  }
  EXPECT_GE(compared, 9000);
  EXPECT_GE(enclosed, 20);
}

// One obstacle cell, the footprint placed all around it: wherever the cell's
// centre lies inside, the clearance is 0, most of all where the cell sits just
// inside the outline (the interior check's bound is tightest there); wherever
// it lies outside, the clearance is the edges' distance.
TEST(FieldClearance, AnObstacleCellInsideTheFootprintIsContact) {
  std::vector<std::uint8_t> cells(400, 0);
  cells[10 * 20 + 10] = 1;  // x and y in [1.0, 1.1]
  const OccupancyGrid grid(20, 20, 0.1, Vec2::Zero(), cells);
  const auto field = std::make_shared<const DistanceField>(grid);
  const FieldClearance world(field);
  const Vec2 centre = grid.cell_center(10, 10);
  const Footprint footprints[] = {
      robot_preset("jackal").footprint,
      Footprint::polygon({{-0.3, -0.25}, {0.5, -0.25}, {0.5, 0.25}, {-0.3, 0.25}}),
      Footprint::polygon({{0.6, 0.0}, {-0.3, 0.45}, {-0.3, -0.45}})};
  std::mt19937 rng(516);
  std::uniform_real_distribution<double> offset(-0.6, 0.6), heading(-M_PI, M_PI);
  int inside_near_outline = 0, outside = 0;
  for (const Footprint& footprint : footprints)
    for (int i = 0; i < 20000; ++i) {
      const Pose2 pose{centre.x() + offset(rng), centre.y() + offset(rng), heading(rng)};
      const std::vector<Vec2> v = test::placed_vertices(footprint, pose);
      double least = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < v.size(); ++j) least = std::min(least, field->segment_distance(v[j], v[(j + 1) % v.size()]));
      const bool inside = footprint.contains(pose, centre);
      const double got = world.clearance(footprint, pose, 0.0);
      SCOPED_TRACE(::testing::Message() << "pose " << pose.x << "," << pose.y << "," << pose.theta << " least " << least);
      if (inside) {
        ASSERT_EQ(got, 0.0);
        inside_near_outline += least > 0.0 && least < 0.03;
      } else {
        ASSERT_NEAR(got, least, 1e-12);
        ++outside;
      }
    }
  EXPECT_GE(inside_near_outline, 300);
  EXPECT_GE(outside, 10000);
}

// The planner's query with a cutoff, which LocalPlanner alone may call.
// The source as the planner asks it: the queries it makes without checks.
struct PlannerQueries : FieldClearance {
  using FieldClearance::clearance_below;
  using FieldClearance::FieldClearance;
  using FieldClearance::likely_moving_clearance;
  using FieldClearance::moving_clearance_below;
  using FieldClearance::moving_clearances;
  using FieldClearance::rollouts_lower_bounds;
};

// A query with a cutoff: below it the exact value's bits, at or above it a
// value from the cutoff up to the exact one. Counts the answers below the
// cutoff, and those the cutoff let stop short of the exact value.
struct CutoffTally {
  int below = 0, stopped = 0;
  void check(double exact, double answer, double cutoff) {
    if (exact < cutoff) {
      EXPECT_EQ(answer, exact);
      ++below;
    } else {
      EXPECT_GE(answer, cutoff);
      EXPECT_LE(answer, exact);
      stopped += answer < exact;
    }
  }
};

// Below the cutoff the same bits as clearance(); at or above it, a value
// between the cutoff and the clearance. With a sensed field beside the map,
// since the second field's cutoff is the first one's answer.
TEST(FieldClearance, ClearanceBelowACutoffIsTheClearanceBitForBit) {
  const Footprint rectangle = Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}});
  std::mt19937 rng(77);
  const OccupancyGrid grid = test::random_rectangles(rng, 80, 80, 0.1, Vec2::Zero(), 0.12);
  const OccupancyGrid sensed = test::random_cells(rng, 80, 80, 0.1, Vec2::Zero(), 0.01);
  PlannerQueries world(std::make_shared<const DistanceField>(grid));
  world.set_sensed(std::make_shared<const DistanceField>(sensed));
  std::uniform_real_distribution<double> cutoff(-0.05, 0.4);
  CutoffTally tally;
  for (const Query& q : random_queries(rng, grid, 2000)) {
    for (const Footprint& fp : {rectangle, Footprint::circle(0.2)}) {
      const double exact = world.clearance(fp, q.pose, 0.0);
      const double c = cutoff(rng);
      const double answer = world.clearance_below(fp, q.pose, 0.0, c);
      SCOPED_TRACE(::testing::Message() << "pose " << q.pose.x << "," << q.pose.y << "," << q.pose.theta << " cutoff "
                                        << c << " exact " << exact << " answer " << answer);
      tally.check(exact, answer, c);
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_GE(tally.below, 500);
  EXPECT_GE(tally.stopped, 500);  // the cutoff saved work
}

// A polygon's lower bounds over many poses (lanes carrying poses, the table
// gathered) equal those of each pose asked alone, bit for bit, on every
// instruction set the processor runs, on the grid, in its margin and beyond
// it, and never exceed the clearance, which is itself the same bits on every
// instruction set.
TEST(FieldClearance, PolygonBoundsOfManyPosesAreThoseOfEachAlone) {
  const Footprint rectangle = Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}});
  std::mt19937 rng(78);
  const OccupancyGrid grid = test::random_rectangles(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.12);
  const OccupancyGrid sensed = test::random_cells(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.01);
  FieldClearance world(std::make_shared<const DistanceField>(grid, 1.0));
  FieldClearance both(std::make_shared<const DistanceField>(grid, 1.0));
  both.set_sensed(std::make_shared<const DistanceField>(sensed, 0.0));
  std::uniform_real_distribution<double> x(-4.0, 10.0), y(-2.5, 9.5), heading(-M_PI, M_PI);
  Trajectory poses(1001);  // not a multiple of any vector's lanes
  for (Pose2& p : poses) p = Pose2{x(rng), y(rng), heading(rng)};
  // Poses on the grid alone, so that whole vectors take the gathered path.
  Trajectory on_grid(1001);
  std::uniform_real_distribution<double> grid_x(-0.9, 6.9), grid_y(0.6, 6.4);
  for (Pose2& p : on_grid) p = Pose2{grid_x(rng), grid_y(rng), heading(rng)};
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  std::vector<std::vector<double>> clearances;  // per instruction set: every pose's, in turn
  for (int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    SCOPED_TRACE(hwy::TargetName(target));
    clearances.emplace_back();
    for (const FieldClearance* source : {&world, &both})
      for (const Trajectory* set : {&poses, &on_grid}) {
        std::vector<double> bounds(set->size());
        source->clearance_lower_bounds(rectangle, *set, 0.1, bounds.data());
        for (std::size_t k = 0; k < set->size(); ++k) {
          const Pose2& pose = (*set)[k];
          double alone;
          source->clearance_lower_bounds(rectangle, Trajectory{pose}, 0.1, &alone);
          const double clearance = source->clearance(rectangle, pose, 0.0);
          ASSERT_EQ(bounds[k], alone) << "pose " << k;
          ASSERT_LE(bounds[k], clearance + 1e-12) << "pose " << k;
          clearances.back().push_back(clearance);
        }
      }
  }
  hwy::SetSupportedTargetsForTest(0);
  // The outline's samples are placed and bounded in vectors too: the clearance is the same bits everywhere.
  for (std::size_t t = 1; t < clearances.size(); ++t) EXPECT_EQ(clearances[t], clearances[0]) << hwy::TargetName(targets[t]);
}

// The planner asks for every rollout's bounds at once (lanes carrying poses
// across rollouts): they equal each rollout's asked alone, bit for bit, for
// a circle and a polygon, from a map, sensed cells, still and moving discs,
// on every instruction set the processor runs; pose k of every rollout is
// (k + 1) dt ahead.
TEST(FieldClearance, BoundsOfAllRolloutsAtOnceAreThoseOfEachAlone) {
  const Footprint rectangle = Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}});
  std::mt19937 rng(79);
  const OccupancyGrid grid = test::random_rectangles(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.12);
  const OccupancyGrid sensed = test::random_cells(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.01);
  const std::vector<Disc> discs = {Disc{Vec2(2.0, 3.0), 0.0, Vec2::Zero()}, Disc{Vec2(4.0, 1.5), 0.3, Vec2::Zero()},
                                   Disc{Vec2(1.0, 1.0), 0.25, Vec2(0.5, 0.2)}};
  const PlannerQueries mapped(std::make_shared<const DistanceField>(grid, 1.0));
  PlannerQueries with_all(std::make_shared<const DistanceField>(grid, 1.0), discs);
  with_all.set_sensed(std::make_shared<const DistanceField>(sensed, 0.0));
  const PlannerQueries& everything = with_all;
  const PlannerQueries discs_alone(nullptr, discs);
  // 37 rollouts of 23 poses (neither a multiple of any vector's lanes), some
  // running off the grid.
  std::uniform_real_distribution<double> x(-2.0, 8.0), y(-0.5, 7.5), heading(-M_PI, M_PI), v(0.0, 1.0), w(-1.0, 1.0);
  std::vector<Trajectory> rollouts;
  for (int i = 0; i < 37; ++i) rollouts.push_back(rollout(Pose2{x(rng), y(rng), heading(rng)}, Twist{v(rng), w(rng)}, 0.1, 23));
  const std::size_t steps = 23;
  for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    SCOPED_TRACE(hwy::TargetName(target));
    for (const PlannerQueries* source : {&mapped, &everything, &discs_alone})
      for (const Footprint& fp : {Footprint::circle(0.25), rectangle}) {
        std::vector<double> at_once(rollouts.size() * steps, std::numeric_limits<double>::quiet_NaN());
        source->rollouts_lower_bounds(fp, rollouts.data(), rollouts.size(), steps, 0.1, at_once.data());
        std::size_t finite = 0;
        for (std::size_t i = 0; i < rollouts.size(); ++i) {
          std::vector<double> alone(steps);
          source->clearance_lower_bounds(fp, rollouts[i], 0.1, alone.data());
          for (std::size_t k = 0; k < steps; ++k) {
            ASSERT_EQ(at_once[i * steps + k], alone[k]) << "rollout " << i << " pose " << k;
            finite += std::isfinite(alone[k]);
            // Without movers a pose's bound does not depend on its time: asked
            // alone it takes the scalar look-up, not the vector one.
            if (source == &mapped) {
              double one = 0.0;
              source->clearance_lower_bounds(fp, Trajectory{rollouts[i][k]}, 0.1, &one);
              ASSERT_EQ(at_once[i * steps + k], one) << "rollout " << i << " pose " << k;
            }
          }
        }
        EXPECT_EQ(finite, at_once.size());
      }
  }
  hwy::SetSupportedTargetsForTest(0);
}

TEST(CollisionWorld, MovingDiscsMatchTheAnalyticDistance) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> pos(-3.0, 3.0), vel(-1.0, 1.0), rad(0.0, 0.5), angle(-M_PI, M_PI),
      time(0.01, 3.0);
  const Footprint footprints[] = {Footprint::circle(0.3),
                                  Footprint::polygon({{0.4, 0.0}, {-0.2, 0.25}, {-0.2, -0.25}})};
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<Disc> discs(1 + trial % 4);
    for (std::size_t i = 0; i < discs.size(); ++i) {
      discs[i].center = Vec2(pos(rng), pos(rng));
      discs[i].radius = i == 0 && trial % 3 == 0 ? 0.0 : rad(rng);  // some point obstacles
      discs[i].velocity = Vec2(vel(rng), vel(rng));
    }
    const CollisionWorld exact(OccupancyGrid(1, 1, 0.1, Vec2(50, 50), {0}), discs);
    const FieldClearance fast(nullptr, discs);
    const Pose2 pose{pos(rng), pos(rng), angle(rng)};
    const double t = time(rng);
    for (const Footprint& fp : footprints) {
      double analytic = kInf;
      for (const Disc& d : discs) analytic = std::min(analytic, fp.signed_distance(pose, d.center_at(t)) - d.radius);
      EXPECT_NEAR(fast.clearance(fp, pose, t), analytic, 1e-12);
      // FCL models a point obstacle as a disc a micrometre wide.
      EXPECT_NEAR(exact.clearance(fp, pose, t), std::max(analytic, 0.0), 2e-6) << "trial " << trial;
      if (std::abs(analytic) > 1e-5) {
        EXPECT_EQ(exact.in_collision(fp, pose, t), analytic < 0.0) << "trial " << trial;
      }
    }
  }
}

TEST(CollisionWorld, EmptyWorldIsInfinitelyFar) {
  const Footprint fp = Footprint::circle(0.25);
  const CollisionWorld none;
  EXPECT_TRUE(std::isinf(none.clearance(fp, Pose2{}, 0.0)));
  EXPECT_FALSE(none.in_collision(fp, Pose2{}, 0.0));
  const CollisionWorld empty_grid(OccupancyGrid(5, 5, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(25, 0)));
  EXPECT_TRUE(empty_grid.boxes().empty());
  EXPECT_TRUE(std::isinf(empty_grid.clearance(fp, Pose2{}, 0.0)));
  EXPECT_TRUE(std::isinf(FieldClearance().clearance(fp, Pose2{}, 0.0)));
}

TEST(CollisionWorld, GridAndDiscsTogetherTakeTheNearest) {
  std::vector<std::uint8_t> cells(100, 0);
  cells[5 * 10 + 9] = 1;  // one cell, x in [0.9, 1.0], y in [0.5, 0.6]
  const OccupancyGrid grid(10, 10, 0.1, Vec2::Zero(), cells);
  const Footprint fp = Footprint::circle(0.1);
  const Pose2 pose{0.5, 0.55, 0.0};
  CollisionWorld world(grid, {Disc{Vec2(0.5, 0.0), 0.05, Vec2(0.0, 0.1)}});
  EXPECT_EQ(world.boxes().size(), 1u);
  // Now the cell (0.4 - 0.1 = 0.3) is nearer than the disc (0.55 - 0.15 = 0.4); the disc
  // drifts up at 0.1 m/s and at t = 3 s is 0.25 - 0.15 = 0.1 away.
  EXPECT_NEAR(world.clearance(fp, pose, 0.0), 0.3, 1e-6);
  EXPECT_NEAR(world.clearance(fp, pose, 3.0), 0.1, 1e-6);
  world.set_discs({});
  EXPECT_NEAR(world.clearance(fp, pose, 3.0), 0.3, 1e-6);
  EXPECT_THROW(world.set_discs({Disc{Vec2(0, 0), -1.0, Vec2::Zero()}}), Error);
}

// An arena's walls merge into boxes metres long. A footprint beside one is in
// contact exactly when its distance is zero: the referee counts a collision
// by in_collision, and a contact reported 0.14 m from a wall was a collision
// that never happened.
TEST(CollisionWorld, ContactBesideLongWallsIsExactlyZeroDistance) {
  // A room 8 m x 6 m inside walls 0.5 m thick, in 0.1 m cells.
  const int rows = 70, cols = 90;
  std::vector<std::uint8_t> cells(rows * cols, 0);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (r < 5 || r >= rows - 5 || c < 5 || c >= cols - 5) cells[r * cols + c] = 1;
  const OccupancyGrid grid(rows, cols, 0.1, Vec2(-4.5, -3.5), cells);
  const CollisionWorld exact(grid);
  ASSERT_LE(exact.boxes().size(), 4u);
  const Footprint footprints[] = {robot_preset("jackal").outline, Footprint::circle(0.25)};
  std::mt19937 rng(4141);
  // Centres within 0.45 m of the walls' inner faces (x = +-4, y = +-3), any heading.
  std::uniform_real_distribution<double> along(-1.0, 1.0), depth(-0.1, 0.45), angle(-M_PI, M_PI);
  int contacts = 0, clear = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int side = trial % 4;
    const double d = depth(rng);
    Pose2 pose{0.0, 0.0, angle(rng)};
    if (side < 2) {
      pose.x = side == 0 ? -4.0 + d : 4.0 - d;
      pose.y = 3.0 * along(rng);
    } else {
      pose.x = 4.0 * along(rng);
      pose.y = side == 2 ? -3.0 + d : 3.0 - d;
    }
    for (const Footprint& fp : footprints) {
      const double brute = test::brute_footprint_distance(grid, fp, pose);
      SCOPED_TRACE(::testing::Message() << "trial " << trial << " pose " << pose.x << "," << pose.y << ","
                                        << pose.theta << " brute " << brute);
      ASSERT_NEAR(exact.clearance(fp, pose, 0.0), brute, 1e-6);
      if (brute > 1e-6) {
        ASSERT_FALSE(exact.in_collision(fp, pose, 0.0));
        ++clear;
      } else if (brute == 0.0) {
        ++contacts;
        ASSERT_TRUE(exact.in_collision(fp, pose, 0.0));
      }
    }
  }
  EXPECT_GE(contacts, 1000);
  EXPECT_GE(clear, 1000);
}

// Discs that neither move nor grow are kept column by column and scanned in one
// vectorised loop; the clearance is still the plain minimum over every disc,
// bit for bit for a circle, and the lower bounds never exceed it.
TEST(FieldClearance, StillAndMovingDiscsGiveThePlainMinimumOverEveryDisc) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-5.0, 5.0), radius(0.0, 0.4), speed(-0.8, 0.8);
  const Footprint rectangle = Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}});
  for (int world = 0; world < 50; ++world) {
    std::vector<Disc> discs;
    const int count = 1 + world % 40;
    for (int j = 0; j < count; ++j) {
      Disc d{Vec2(u(rng), u(rng)), world % 3 == 0 ? 0.0 : radius(rng), Vec2::Zero()};
      if (j % 4 == 1) d.velocity = Vec2(speed(rng), speed(rng));  // every fourth one moves
      discs.push_back(d);
    }
    const FieldClearance source(nullptr, discs);
    for (int trial = 0; trial < 40; ++trial) {
      const Pose2 pose{u(rng), u(rng), M_PI * u(rng) / 5.0};
      const double t = 0.1 * (trial % 10);
      for (const Footprint& fp : {Footprint::circle(0.25), rectangle}) {
        double brute = std::numeric_limits<double>::infinity();
        for (const Disc& d : discs) brute = std::min(brute, fp.signed_distance(pose, d.center_at(t)) - d.radius_at(t));
        if (fp.is_circle())
          EXPECT_EQ(source.clearance(fp, pose, t), brute);
        else
          EXPECT_NEAR(source.clearance(fp, pose, t), brute, 1e-12);
      }
    }
    // Among discs alone a circle's bounds are its clearances, which the planner then takes as they are.
    EXPECT_TRUE(source.lower_bounds_exact(Footprint::circle(0.25)));
    EXPECT_FALSE(source.lower_bounds_exact(rectangle));
    const FieldClearance mapped(std::make_shared<const DistanceField>(OccupancyGrid(2, 2, 0.1, Vec2(0, 0), {1, 0, 0, 0})),
                                discs);
    EXPECT_FALSE(mapped.lower_bounds_exact(Footprint::circle(0.25)));  // a grid's bounds are bounds
    // Lower bounds along a rollout, pose k at (k + 1) dt.
    const Trajectory poses = rollout(Pose2{u(rng), u(rng), 0.3}, Twist{0.8, 0.4}, 0.1, 30);
    std::vector<double> bounds(poses.size());
    for (const Footprint& fp : {Footprint::circle(0.25), rectangle}) {
      source.clearance_lower_bounds(fp, poses, 0.1, bounds.data());
      for (std::size_t k = 0; k < poses.size(); ++k) {
        const double exact = source.clearance(fp, poses[k], 0.1 * static_cast<double>(k + 1));
        EXPECT_LE(bounds[k], exact + 1e-12);
        if (fp.is_circle()) {
          EXPECT_EQ(bounds[k], exact);  // a circle's bound is its clearance
        }
      }
    }
  }
}

// A footprint among many still points (live lidar hits along a wall), kept
// in buckets: only those near enough are looked at, a polygon's settled by
// their distance from its bounding box, the rest measured. The least of each
// point's signed distance bit for bit; below a cutoff the same bits, above it
// a value from the cutoff up to that.
TEST(FieldClearance, StillPointsGiveTheLeastOfEachAloneBitForBit) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> along(-1.5, 1.5), off(-0.05, 0.05), u(-1.0, 1.0), radius(0.0, 0.1);
  const std::vector<Footprint> shapes = {
      Footprint::polygon({{-0.254, -0.215}, {0.254, -0.215}, {0.254, 0.215}, {-0.254, 0.215}}),
      Footprint::polygon({{-0.2, -0.2}, {0.4, 0.0}, {-0.2, 0.2}}), Footprint::circle(0.25)};
  for (int world = 0; world < 40; ++world) {
    // Points along a wall at y = 0.5, some with a radius, a few scattered.
    std::vector<Disc> discs;
    for (int j = 0; j < 20 + 10 * (world % 20); ++j)
      discs.push_back(Disc{Vec2(along(rng), 0.5 + off(rng)), j % 7 == 0 ? radius(rng) : 0.0, Vec2::Zero()});
    for (int j = 0; j < 5; ++j) discs.push_back(Disc{Vec2(2.0 * u(rng), 2.0 * u(rng)), 0.0, Vec2::Zero()});
    const PlannerQueries source(nullptr, discs);
    for (int trial = 0; trial < 50; ++trial) {
      const Pose2 pose{u(rng), 0.5 * u(rng), M_PI * u(rng)};
      for (const Footprint& fp : shapes) {
        double brute = std::numeric_limits<double>::infinity();
        for (const Disc& d : discs) brute = std::min(brute, fp.signed_distance(pose, d.center) - d.radius);
        EXPECT_EQ(source.clearance(fp, pose, 0.0), brute);
        for (const double cutoff : {brute - 0.01, brute + 1e-12, brute + 0.05}) {
          const double below = source.clearance_below(fp, pose, 0.0, cutoff);
          if (brute < cutoff) {
            EXPECT_EQ(below, brute);
          } else {
            EXPECT_GE(below, cutoff);
            EXPECT_LE(below, brute);
          }
        }
      }
    }
  }
}

// Rollouts' bounds among a map and many still points (bucketed, as live
// lidar hits are): the least of the map's and every point's, bit for bit, on
// every instruction set, for a circle (its distance to each) and a polygon
// (its circumscribed circle's).
TEST(FieldClearance, RolloutBoundsAmongManyStillPointsAreTheLeastOfMapAndEveryPoint) {
  std::mt19937 rng(31);
  // A sparse map, and hits along two walls it lacks (y = 1.5 and x = 0, in
  // buckets of several rows and columns): far from the map's obstacles the
  // walls are what lowers the bounds.
  const OccupancyGrid grid = test::random_cells(rng, 60, 80, 0.1, Vec2(-1.0, 0.5), 0.002);
  std::uniform_real_distribution<double> x(-1.0, 7.0), y(0.5, 6.5), heading(-M_PI, M_PI), v(0.0, 1.0), w(-1.0, 1.0),
      radius(0.0, 0.1), off(-0.03, 0.03);
  std::vector<Disc> points;
  for (int j = 0; j < 300; ++j) {
    const double along = 0.04 * (j / 2);
    const Vec2 at = j % 2 ? Vec2(along, 1.5 + off(rng)) : Vec2(off(rng), 1.5 + along);
    points.push_back(Disc{at, j % 5 == 0 ? radius(rng) : 0.0, Vec2::Zero()});
  }
  const auto field = std::make_shared<const DistanceField>(grid, 1.0);
  const PlannerQueries mapped(field), with_points(field, points);
  std::vector<Trajectory> rollouts;
  for (int i = 0; i < 41; ++i) rollouts.push_back(rollout(Pose2{x(rng), y(rng), heading(rng)}, Twist{v(rng), w(rng)}, 0.1, 15));
  const std::size_t steps = 15, n = rollouts.size() * steps;
  const Footprint rectangle = Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}});
  for (int64_t target : hwy::SupportedAndGeneratedTargets()) {
    hwy::SetSupportedTargetsForTest(target);
    SCOPED_TRACE(hwy::TargetName(target));
    for (const Footprint& fp : {Footprint::circle(0.25), rectangle}) {
      std::vector<double> map_only(n), both(n);
      mapped.rollouts_lower_bounds(fp, rollouts.data(), rollouts.size(), steps, 0.1, map_only.data());
      with_points.rollouts_lower_bounds(fp, rollouts.data(), rollouts.size(), steps, 0.1, both.data());
      std::size_t lowered = 0;
      for (std::size_t k = 0; k < n; ++k) {
        const Pose2& pose = rollouts[k / steps][k % steps];
        double least = map_only[k];
        for (const Disc& p : points) {
          const double dx = p.center.x() - pose.x, dy = p.center.y() - pose.y;
          least = std::min(least, (std::sqrt(dx * dx + dy * dy) - fp.radius()) - p.radius);
        }
        ASSERT_EQ(both[k], least) << "rollout " << k / steps << " pose " << k % steps;
        lowered += least < map_only[k];
      }
      EXPECT_GT(lowered, n / 10);  // the points matter, and not everywhere
      EXPECT_LT(lowered, n);
    }
  }
  hwy::SetSupportedTargetsForTest(0);
}

// A polygon against many movers: the nearest by the circumscribed circle is
// measured first and settles the others; the result is the least of each
// disc's clearance alone, bit for bit, with the discs in any order and more
// of them than fit on the stack.
TEST(FieldClearance, MovingDiscsGiveTheLeastOfEachAloneBitForBit) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-4.0, 4.0), radius(0.0, 0.5), speed(-1.0, 1.0), when(0.0, 3.0);
  const std::vector<Footprint> shapes = {
      Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}}),
      Footprint::polygon({{-0.2, -0.2}, {0.4, 0.0}, {-0.2, 0.2}})};
  for (int world = 0; world < 60; ++world) {
    std::vector<Disc> discs;
    for (int j = 0; j < 1 + world % 30; ++j) {
      Disc d{Vec2(u(rng), u(rng)), radius(rng), Vec2(speed(rng), speed(rng))};
      if (j % 3 == 2) d.growth = 0.1;
      if (j % 5 == 4) d.velocity = Vec2::Zero();  // still ones are not movers
      discs.push_back(d);
    }
    std::vector<Disc> reversed(discs.rbegin(), discs.rend());
    for (int trial = 0; trial < 50; ++trial) {
      const Pose2 pose{u(rng), u(rng), M_PI * u(rng) / 4.0};
      const double t = when(rng);
      for (const Footprint& fp : shapes) {
        double alone = std::numeric_limits<double>::infinity();
        for (const Disc& d : discs) alone = std::min(alone, moving_disc_clearance({d}, fp, pose, t));
        EXPECT_EQ(moving_disc_clearance(discs, fp, pose, t), alone);
        EXPECT_EQ(moving_disc_clearance(reversed, fp, pose, t), alone);
      }
    }
  }
}

// The movers' clearance with a cutoff: the same bits below it, else a value
// from the cutoff up to the clearance; for a polygon it often stops short.
TEST(FieldClearance, MovingClearanceBelowACutoffIsExactThere) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(-4.0, 4.0), radius(0.0, 0.5), speed(-1.0, 1.0), when(0.0, 3.0),
      cutoff(-0.2, 2.0);
  const std::vector<Footprint> shapes = {
      Footprint::circle(0.25), Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}}),
      Footprint::polygon({{-0.2, -0.2}, {0.4, 0.0}, {-0.2, 0.2}})};
  CutoffTally tally;
  for (int world = 0; world < 60; ++world) {
    std::vector<Disc> discs;
    for (int j = 0; j < 1 + world % 20; ++j) {
      Disc d{Vec2(u(rng), u(rng)), radius(rng), Vec2(speed(rng), speed(rng))};
      if (j % 3 == 2) d.growth = 0.1;
      discs.push_back(d);
    }
    const PlannerQueries source(nullptr, discs);
    for (int trial = 0; trial < 50; ++trial) {
      const Pose2 pose{u(rng), u(rng), M_PI * u(rng) / 4.0};
      const double t = when(rng), c = cutoff(rng);
      for (const Footprint& fp : shapes) {
        const double exact = source.moving_clearance(fp, pose, t);
        const double answer = source.moving_clearance_below(fp, pose, t, c);
        SCOPED_TRACE(::testing::Message() << "world " << world << " trial " << trial << " cutoff " << c);
        tally.check(exact, answer, c);
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
  EXPECT_GE(tally.below, 1000);
  EXPECT_GE(tally.stopped, 500);
}

// Both clearances from one pass over the movers are the bits each query
// gives alone, among movers that grow (some standing still but for their
// growth, some accelerating) and movers that do not.
TEST(FieldClearance, GrownAndLikelyClearancesAtOnceAreEachAloneBitForBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0), radius(0.0, 0.5), speed(-1.0, 1.0), when(0.0, 3.0);
  const std::vector<Footprint> shapes = {
      Footprint::circle(0.25), Footprint::polygon({{-0.12, -0.165}, {0.30, -0.165}, {0.30, 0.165}, {-0.12, 0.165}}),
      Footprint::polygon({{-0.2, -0.2}, {0.4, 0.0}, {-0.2, 0.2}})};
  int differ = 0;
  for (int world = 0; world < 60; ++world) {
    std::vector<Disc> discs;
    for (int j = 0; j < 1 + world % 20; ++j) {
      Disc d{Vec2(u(rng), u(rng)), radius(rng), Vec2(speed(rng), speed(rng))};
      if (world % 4 != 0 && j % 3 == 2) d.growth = 0.4;
      if (j % 5 == 4) d.velocity = Vec2::Zero();
      if (j % 7 == 6) d.acceleration = Vec2(speed(rng), speed(rng)), d.accel_time = 0.5;
      discs.push_back(d);
    }
    const PlannerQueries source(nullptr, discs);
    for (int trial = 0; trial < 50; ++trial) {
      const Pose2 pose{u(rng), u(rng), M_PI * u(rng) / 4.0};
      const double t = when(rng);
      for (const Footprint& fp : shapes) {
        double grown = 0.0, likely = 0.0;
        source.moving_clearances(fp, pose, t, grown, likely);
        SCOPED_TRACE(::testing::Message() << "world " << world << " trial " << trial);
        EXPECT_EQ(grown, source.moving_clearance(fp, pose, t));
        EXPECT_EQ(likely, source.likely_moving_clearance(fp, pose, t));
        differ += grown != likely;
        if (::testing::Test::HasFailure()) return;
      }
    }
  }
  EXPECT_GE(differ, 1000);  // the growth mattered
}

}  // namespace
}  // namespace fgdwa

namespace fgdwa {
namespace {

// An accelerating disc, worked out by hand: from (1, 2) at (1, 0) m/s with
// (0, 2) m/s^2 for 1 s, it is at (1.5, 2.25) after 0.5 s (2 x 0.5^2 / 2 up),
// at (2, 3) after 1 s moving at (1, 2) m/s, which holds: (3, 5) after 2 s.
TEST(Disc, AnAccelerationLastsItsTimeThenTheVelocityReachedHolds) {
  const Disc d{Vec2(1.0, 2.0), 0.3, Vec2(1.0, 0.0), 0.0, Vec2(0.0, 2.0), 1.0};
  EXPECT_TRUE(d.center_at(0.5).isApprox(Vec2(1.5, 2.25), 1e-12));
  EXPECT_TRUE(d.center_at(1.0).isApprox(Vec2(2.0, 3.0), 1e-12));
  EXPECT_TRUE(d.center_at(2.0).isApprox(Vec2(3.0, 5.0), 1e-12));
  EXPECT_TRUE(d.center_at(0.0).isApprox(d.center, 1e-12));
  EXPECT_DOUBLE_EQ(d.top_speed(), std::sqrt(5.0));  // (1, 2) m/s at the end
  // Braking from 2 m/s to 1 m/s: fastest now. Reversing from 1 m/s to -3 m/s: fastest at the end.
  EXPECT_DOUBLE_EQ((Disc{Vec2::Zero(), 0.3, Vec2(2.0, 0.0), 0.0, Vec2(-2.0, 0.0), 0.5}).top_speed(), 2.0);
  EXPECT_DOUBLE_EQ((Disc{Vec2::Zero(), 0.3, Vec2(1.0, 0.0), 0.0, Vec2(-4.0, 0.0), 1.0}).top_speed(), 3.0);
  EXPECT_TRUE(d.moves());
  EXPECT_TRUE((Disc{Vec2::Zero(), 0.3, Vec2::Zero(), 0.0, Vec2(1.0, 0.0), 0.5}).moves());
  // Without a time to act in, an acceleration is nothing.
  EXPECT_FALSE((Disc{Vec2::Zero(), 0.3, Vec2::Zero(), 0.0, Vec2(1.0, 0.0), 0.0}).moves());
  // The exact world places it there too.
  const CollisionWorld world(OccupancyGrid(10, 10, 1.0, Vec2(-50.0, -50.0), std::vector<std::uint8_t>(100, 0)), {d});
  EXPECT_NEAR(world.moving_clearance(Footprint::circle(0.2), Pose2{3.0, 6.0, 0.0}, 2.0), 1.0 - 0.3 - 0.2, 1e-9);
}

// A disc at rest 5 m off, pulled toward the point at 2 m/s^2, reaches 1 m of
// it when 5 - t^2 = 1: at 2 s. Pulled for 1 s only, it has 4 m to go at 2 m/s
// by then and reaches 1 m at 2.5 s.
TEST(Disc, TimeToReachThroughAnAccelerationAsWorkedOutByHand) {
  EXPECT_NEAR((Disc{Vec2(5.0, 0.0), 0.0, Vec2::Zero(), 0.0, Vec2(-2.0, 0.0), 10.0}).time_to_reach(Vec2::Zero(), 1.0),
              2.0, 1e-9);
  EXPECT_NEAR((Disc{Vec2(5.0, 0.0), 0.0, Vec2::Zero(), 0.0, Vec2(-2.0, 0.0), 1.0}).time_to_reach(Vec2::Zero(), 1.0),
              2.5, 1e-9);
  // Braking before it arrives: at 2 m/s braking at 1 m/s^2 it stops after 2 m, 1 m short of 0.5 m away.
  EXPECT_TRUE(std::isinf(
      (Disc{Vec2(3.5, 0.0), 0.0, Vec2(-2.0, 0.0), 0.0, Vec2(1.0, 0.0), 2.0}).time_to_reach(Vec2::Zero(), 0.5)));
}

// Against a fine search of the gap over time, for random discs that turn,
// brake or reverse: the first contact, never one after it.
TEST(Disc, TimeToReachThroughAnAccelerationIsTheFirstContact) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int met = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Disc d{Vec2(4.0 * u(rng), 4.0 * u(rng)), 0.3 + 0.2 * u(rng), Vec2(2.0 * u(rng), 2.0 * u(rng)),
                 0.1 + 0.1 * u(rng), Vec2(3.0 * u(rng), 3.0 * u(rng)), 1.0 + 0.5 * u(rng)};
    const Vec2 point(u(rng), u(rng));
    const double reach = 0.25;
    const double t = d.time_to_reach(point, reach);
    const auto gap = [&](double s) { return (d.center_at(s) - point).norm() - d.radius_at(s) - reach; };
    double first = kInf;
    for (double s = 0.0; s <= 20.0; s += 1e-4)
      if (gap(s) <= 0.0) {
        first = s;
        break;
      }
    SCOPED_TRACE(::testing::Message() << "trial " << trial);
    if (std::isinf(first)) {
      // Never within 20 s on the search's grid: a later contact only, or none.
      EXPECT_TRUE(std::isinf(t) || t > 20.0 - 1e-3) << t;
      continue;
    }
    ++met;
    EXPECT_NEAR(t, first, 1.1e-4);
    EXPECT_LE(gap(t), 1e-9);
  }
  EXPECT_GT(met, 20);  // the trials do reach the point, often enough
}

TEST(Disc, AnAccelerationOutOfBoundsIsRefusedByName) {
  const auto with = [](Vec2 a, double time) { return Disc{Vec2::Zero(), 0.3, Vec2::Zero(), 0.0, a, time}; };
  test::expect_error_naming([&] { with(Vec2(std::nan(""), 0.0), 1.0).validate(); }, "disc acceleration");
  test::expect_error_naming([&] { with(Vec2(1.0, 0.0), -1.0).validate(); }, "disc accel_time");
  test::expect_error_naming([&] { with(Vec2(1.0, 0.0), std::nan("")).validate(); }, "disc accel_time");
  test::expect_error_naming([&] { with(Vec2(9e3, 0.0), 1.0).validate(); }, "disc velocity after accel_time");
  test::expect_error_naming([&] { FieldClearance(nullptr, {with(Vec2(1.0, 0.0), -1.0)}); }, "disc accel_time");
}

}  // namespace
}  // namespace fgdwa
