#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <utility>
#include <vector>

#include "fgdwa/global_planner.hpp"
#include "fgdwa/grid.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

using test::expect_error_naming;
using test::kInf;

TEST(OccupancyGrid, RejectsBadShapes) {
  expect_error_naming([] { OccupancyGrid(2, 3, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(5)); }, "cells");
  expect_error_naming([] { OccupancyGrid(2, 3, 0.1, Vec2::Zero(), std::vector<std::uint8_t>(7)); }, "cells");
  expect_error_naming([] { OccupancyGrid(0, 3, 0.1, Vec2::Zero(), {}); }, "rows");
  expect_error_naming([] { OccupancyGrid(-1, 3, 0.1, Vec2::Zero(), {}); }, "rows");
  expect_error_naming([] { OccupancyGrid(3, 0, 0.1, Vec2::Zero(), {}); }, "cols");
  for (double res : {0.0, -0.1, std::nan(""), kInf})
    expect_error_naming([&] { OccupancyGrid(1, 1, res, Vec2::Zero(), {0}); }, "resolution");
  expect_error_naming([] { OccupancyGrid(1, 1, 0.1, Vec2(std::nan(""), 0), {0}); }, "origin");
}

TEST(OccupancyGrid, RowZeroIsTheBottomRow) {
  // 2 rows x 3 cols; only (row 1, col 2) is occupied: the top-right cell.
  const OccupancyGrid grid(2, 3, 0.5, Vec2(-1.0, 2.0), {0, 0, 0, 0, 0, 7});
  EXPECT_EQ(grid.occupied_count(), 1u);
  EXPECT_TRUE(grid.occupied(1, 2));
  EXPECT_TRUE(grid.occupied_at(Vec2(0.4, 2.9)));
  EXPECT_FALSE(grid.occupied_at(Vec2(0.4, 2.4)));
  EXPECT_FALSE(grid.occupied_at(Vec2(0.6, 2.9)));  // outside the grid is free
  int row = -1, col = -1;
  ASSERT_TRUE(grid.cell_of(Vec2(-0.9, 2.6), row, col));
  EXPECT_EQ(row, 1);
  EXPECT_EQ(col, 0);
  EXPECT_FALSE(grid.cell_of(Vec2(-1.1, 2.6), row, col));
  EXPECT_TRUE(grid.cell_center(1, 2).isApprox(Vec2(0.25, 2.75)));
}

TEST(DistanceField, CellDistanceEqualsBruteForceCentreDistance) {
  std::mt19937 rng(31337);
  std::uniform_int_distribution<int> size(1, 16);
  std::uniform_real_distribution<double> density(0.0, 0.5), res(0.05, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const int rows = size(rng), cols = size(rng);
    const double resolution = res(rng);
    const OccupancyGrid grid = test::random_cells(rng, rows, cols, resolution, Vec2(-1.0, 0.5), density(rng));
    const DistanceField field(grid);
    EXPECT_EQ(field.has_obstacles(), grid.occupied_count() > 0);
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        double best = kInf;
        for (int r2 = 0; r2 < rows; ++r2)
          for (int c2 = 0; c2 < cols; ++c2)
            if (grid.occupied(r2, c2)) best = std::min(best, std::hypot(r - r2, c - c2) * resolution);
        if (std::isinf(best)) {
          ASSERT_TRUE(std::isinf(field.cell_distance(r, c)));
        } else {
          ASSERT_NEAR(field.cell_distance(r, c), best, 1e-12) << "trial " << trial << " cell " << r << "," << c;
        }
      }
  }
}

// A row and a column of 200 000 cells: squared offsets reach 4e10, past 32
// bits, and the transform's exact arithmetic must hold there, built and updated.
TEST(DistanceField, LongRowsAndColumnsAreExact) {
  constexpr int kLength = 200000;
  const std::vector<int> obstacles{3, 70001, 70002, 199990};
  for (const bool as_row : {true, false}) {
    std::vector<std::uint8_t> cells(kLength, 0);
    for (const int i : obstacles) cells[i] = 1;
    OccupancyGrid grid(as_row ? 1 : kLength, as_row ? kLength : 1, 0.01, Vec2(-5.0, 3.0), cells);
    DistanceField field(grid, 0.0);
    const auto check = [&](const std::vector<int>& present, const char* stage) {
      for (int i = 0; i < kLength; i += 997) {
        int nearest = kLength;
        for (const int o : present) nearest = std::min(nearest, std::abs(i - o));
        const double got = as_row ? field.cell_distance(0, i) : field.cell_distance(i, 0);
        ASSERT_NEAR(got, nearest * 0.01, 1e-9) << stage << (as_row ? " row" : " column") << " cell " << i;
      }
    };
    check(obstacles, "built");
    // The middle pair goes: the ends of the row are then the nearest for a
    // hundred thousand cells each.
    grid.set(70001, false);
    grid.set(70002, false);
    field.update(grid, {70001, 70002});
    check({3, 199990}, "updated");
  }
}

TEST(DistanceField, PointDistanceIsWithinOneCellOfTheExactDistance) {
  std::mt19937 rng(4242);
  std::uniform_int_distribution<int> size(1, 30);
  std::uniform_real_distribution<double> density(0.01, 0.3), res(0.05, 0.5), u(-0.3, 1.3);
  double worst = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const int rows = size(rng), cols = size(rng);
    const double resolution = res(rng);
    const Vec2 origin(-2.0, 1.0);
    const OccupancyGrid grid = test::random_cells(rng, rows, cols, resolution, origin, density(rng));
    const DistanceField field(grid);
    if (!field.has_obstacles()) continue;
    // Points over the grid and up to 30 % of its size beyond every side.
    for (int i = 0; i < 50; ++i) {
      const Vec2 p = origin + Vec2(u(rng) * cols * resolution, u(rng) * rows * resolution);
      const double exact = test::brute_point_distance(grid, p);
      const double estimate = field.distance(p);
      ASSERT_GE(estimate, 0.0);
      ASSERT_LE(std::abs(estimate - exact), resolution + 1e-12)
          << "trial " << trial << " p " << p.transpose() << " exact " << exact;
      worst = std::max(worst, std::abs(estimate - exact) / resolution);
      if (grid.occupied_at(p)) {
        ASSERT_EQ(estimate, 0.0);
      }
    }
  }
  RecordProperty("worst_error_in_cells", std::to_string(worst));
}

// Outside the grid the distance is exact, blocks of rows and columns skipped
// or not: grids of many blocks, sparse obstacles, points up to three sizes out.
TEST(DistanceField, PointDistanceOutsideTheGridIsExact) {
  std::mt19937 rng(77);
  std::uniform_int_distribution<int> size(20, 120);
  std::uniform_real_distribution<double> density(0.0005, 0.05), u(-3.0, 4.0);
  for (int trial = 0; trial < 60; ++trial) {
    const int rows = size(rng), cols = size(rng);
    const OccupancyGrid grid = test::random_cells(rng, rows, cols, 0.1, Vec2(-1.0, 2.0), density(rng));
    // With no margin the walks outward measure every point off the grid; with
    // one, the margin's look-up data the near ones.
    const DistanceField walked(grid, 0.0), margined(grid);
    if (!walked.has_obstacles()) continue;
    for (int i = 0; i < 100; ++i) {
      const Vec2 p = grid.origin() + Vec2(u(rng) * cols * 0.1, u(rng) * rows * 0.1);
      const double exact = test::brute_point_distance(grid, p);
      ASSERT_NEAR(walked.distance(p), exact, 1e-9) << "trial " << trial << " p " << p.transpose();
      ASSERT_NEAR(margined.distance(p), exact, 1e-9) << "trial " << trial << " p " << p.transpose();
    }
  }
}

// The free margin kept around the grid: whole cells, within the budget, and
// a field with one answers as a field of the grid padded with free cells by
// hand, while grid() and cell_distances() stay the grid's as given.
TEST(DistanceField, EdgeMarginAnswersAsAGridPaddedWithFreeCells) {
  std::mt19937 rng(31);
  const OccupancyGrid grid = test::random_cells(rng, 40, 70, 0.1, Vec2(-1.0, 2.0), 0.05);
  const DistanceField field(grid, 1.25), none(grid, 0.0), wide(grid);
  EXPECT_DOUBLE_EQ(field.edge_margin(), 1.3);  // 13 whole cells
  EXPECT_EQ(none.edge_margin(), 0.0);
  EXPECT_NEAR(wide.edge_margin(), DistanceField::kDefaultEdgeMargin, 1e-12);
  EXPECT_EQ(field.grid().rows(), 40);
  EXPECT_EQ(field.grid().cells(), grid.cells());
  EXPECT_EQ(field.cell_distances(), none.cell_distances());
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(66) * 96, 0);
  for (int r = 0; r < 40; ++r)
    for (int c = 0; c < 70; ++c) cells[static_cast<std::size_t>(r + 13) * 96 + c + 13] = grid.occupied(r, c);
  const DistanceField by_hand(OccupancyGrid(66, 96, 0.1, Vec2(-2.3, 0.7), std::move(cells)), 0.0);
  std::uniform_real_distribution<double> x(-4.0, 9.0), y(-1.0, 9.0);
  for (int i = 0; i < 5000; ++i) {
    const Vec2 p(x(rng), y(rng));
    ASSERT_NEAR(field.distance(p), by_hand.distance(p), 1e-12) << p.transpose();
    ASSERT_LE(field.lower_bound(p), field.distance(p) + 1e-12) << p.transpose();
    ASSERT_NEAR(field.segment_distance(p, p + Vec2(0.07, -0.05)), by_hand.segment_distance(p, p + Vec2(0.07, -0.05)), 1e-12);
  }
  // A large grid keeps at most a sixteenth more cells: 1000 x 1000 at 5 cm gets
  // 15 of the 60 cells 3 m asks for.
  const OccupancyGrid large(1000, 1000, 0.05, Vec2(0.0, 0.0), std::vector<std::uint8_t>(1000000, 0));
  EXPECT_NEAR(DistanceField(large).edge_margin(), 15 * 0.05, 1e-12);
  for (const double bad : {-0.1, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_THROW(DistanceField(grid, bad), Error);
}

// inflate() blocks exactly the cells whose centre lies within the radius of
// an obstacle square, as the distance field measures it, without building one.
TEST(Inflate, BlocksTheCellsTheDistanceFieldPutsWithinTheRadius) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> size(1, 70);
  std::uniform_real_distribution<double> density(0.0, 0.1), res(0.02, 0.3), radius(0.0, 1.0);
  for (int trial = 0; trial < 80; ++trial) {
    // Every third trial: 10 cm cells and a radius of whole half cells, where
    // centres lie exactly at the radius and rounding decides.
    const bool ties = trial % 3 == 0;
    const OccupancyGrid grid =
        test::random_cells(rng, size(rng), size(rng), ties ? 0.1 : res(rng), Vec2(-1.0, 0.5), density(rng));
    const DistanceField field(grid);
    const double r = trial % 10 == 0 ? 0.0 : ties ? 0.05 * (trial % 7) : radius(rng);
    const std::vector<std::uint8_t> blocked = inflate(grid, r);
    for (int row = 0; row < grid.rows(); ++row)
      for (int col = 0; col < grid.cols(); ++col) {
        const bool expected = grid.occupied(row, col) || field.distance(grid.cell_center(row, col)) < r;
        ASSERT_EQ(blocked[grid.index(row, col)] != 0, expected)
            << "trial " << trial << " cell " << row << ", " << col << " radius " << r;
      }
  }
}

TEST(DistanceField, NoObstaclesIsInfinite) {
  const OccupancyGrid grid(4, 5, 0.2, Vec2::Zero(), std::vector<std::uint8_t>(20, 0));
  const DistanceField field(grid);
  EXPECT_FALSE(field.has_obstacles());
  for (double d : field.cell_distances()) EXPECT_TRUE(std::isinf(d));
  EXPECT_TRUE(std::isinf(field.distance(Vec2(0.5, 0.5))));
  EXPECT_TRUE(std::isinf(field.distance(Vec2(-3.0, 9.0))));
}

TEST(DistanceField, SingleObstacleHandCase) {
  // One occupied cell at (row 2, col 2) of a 5 x 5 grid of 1 m cells.
  std::vector<std::uint8_t> cells(25, 0);
  cells[2 * 5 + 2] = 1;
  const DistanceField field(OccupancyGrid(5, 5, 1.0, Vec2::Zero(), cells));
  EXPECT_EQ(field.cell_distance(2, 2), 0.0);
  EXPECT_DOUBLE_EQ(field.cell_distance(0, 0), std::sqrt(8.0));
  EXPECT_DOUBLE_EQ(field.cell_distance(2, 4), 2.0);
  EXPECT_EQ(field.distance(Vec2(2.5, 2.5)), 0.0);
  // From a cell centre straight out, the estimate is exact: centre distance less half a cell.
  EXPECT_NEAR(field.distance(Vec2(4.5, 2.5)), 1.5, 1e-12);
  // Beyond the grid, straight out from the obstacle: the exact distance is 4.5 m.
  EXPECT_NEAR(field.distance(Vec2(7.5, 2.5)), 4.5, 1.0);
  EXPECT_NEAR(field.distance(Vec2(-4.0, -4.0)), std::hypot(6.0, 6.0), 1.0);
}

// Issue 15's budget for a large map: 5 cm cells, 3 % occupied at random.
TEST(DistanceField, HoldsAtMost32BytesPerCellAt5Centimetres) {
  std::mt19937 rng(15);
  const OccupancyGrid grid = test::random_cells(rng, 400, 500, 0.05, Vec2(-3.0, 1.0), 0.03);
  const DistanceField field(grid);
  EXPECT_EQ(field.bound_subdivisions(), 2);
  EXPECT_LE(field.bytes_per_cell(), 32.0) << "its edge margin " << field.edge_margin() << " m";
}

// A field updated from an earlier one answers exactly as one built afresh,
// whether the map gained a few cells (a robot's scan map), many, or lost some.
TEST(DistanceField, UpdatedFromAnEarlierFieldEqualsAFreshOne) {
  std::mt19937 rng(21);
  OccupancyGrid grid = test::random_rectangles(rng, 50, 70, 0.15, Vec2(-1.0, 2.0), 0.1);
  std::vector<std::uint8_t> cells = grid.cells();
  std::uniform_int_distribution<std::size_t> cell(0, cells.size() - 1);
  std::uniform_real_distribution<double> x(-2.0, 10.0), y(1.0, 10.5), step(-0.3, 0.3);
  auto previous = std::make_shared<const DistanceField>(grid);
  const std::vector<std::pair<int, int>> rounds = {{3, 0}, {1, 0}, {40, 0}, {0, 25}, {400, 0}};  // cells added, removed
  for (const auto& [added, removed] : rounds) {
    for (int k = 0; k < added; ++k) cells[cell(rng)] = 1;
    for (int k = 0; k < removed; ++k) cells[cell(rng)] = 0;
    grid = OccupancyGrid(50, 70, 0.15, Vec2(-1.0, 2.0), cells);
    const DistanceField fresh(grid);
    const auto updated = std::make_shared<const DistanceField>(grid, *previous);
    ASSERT_EQ(updated->cell_distances(), fresh.cell_distances());
    for (int i = 0; i < 30000; ++i) {
      const Vec2 p(x(rng), y(rng)), q = p + Vec2(step(rng), step(rng));
      ASSERT_EQ(updated->distance(p), fresh.distance(p)) << p.transpose();
      ASSERT_EQ(updated->lower_bound(p), fresh.lower_bound(p)) << p.transpose();
      const double a = updated->segment_distance(p, q), b = fresh.segment_distance(p, q);
      ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << p.transpose();
    }
    previous = updated;
  }
  // Another layout cannot serve.
  const OccupancyGrid other(50, 71, 0.15, Vec2(-1.0, 2.0), std::vector<std::uint8_t>(50 * 71, 0));
  expect_error_naming([&] { DistanceField(other, *previous); }, "layout");
}

// One field updated in place, round after round, by the listed cells alone
// (duplicates and unchanged cells among them), through an empty map and back,
// answers as a fresh build every round.
TEST(DistanceField, UpdatedInPlaceByTheChangedCellsEqualsAFreshOne) {
  std::mt19937 rng(22);
  const int rows = 40, cols = 60;
  const Vec2 origin(0.5, -1.0);
  OccupancyGrid grid = test::random_rectangles(rng, rows, cols, 0.1, origin, 0.15);
  DistanceField field(grid);
  std::uniform_int_distribution<std::size_t> cell(0, grid.cells().size() - 1);
  std::uniform_real_distribution<double> x(-0.5, 7.5), y(-2.0, 4.0);
  std::bernoulli_distribution coin(0.5);
  for (int round = 0; round < 60; ++round) {
    std::vector<std::size_t> listed;
    if (round == 20 || round == 21) {  // everything cleared, then one cell back
      for (std::size_t i = 0; i < grid.cells().size(); ++i) listed.push_back(i);
      for (const std::size_t i : listed) grid.set(i, round == 21 && i == listed.size() / 2);
    } else {
      const int n = round % 5 == 0 ? 300 : 1 + round % 7;
      for (int k = 0; k < n; ++k) {
        const std::size_t i = cell(rng);
        grid.set(i, coin(rng));
        listed.push_back(i);
        if (k % 3 == 0) listed.push_back(i);    // listed twice
        if (k % 4 == 0) listed.push_back(cell(rng));  // listed, perhaps unchanged
      }
    }
    field.update(grid, listed);
    const DistanceField fresh(grid);
    ASSERT_EQ(field.grid().cells(), grid.cells()) << "round " << round;
    ASSERT_EQ(field.has_obstacles(), fresh.has_obstacles()) << "round " << round;
    ASSERT_EQ(field.cell_distances(), fresh.cell_distances()) << "round " << round;
    for (int i = 0; i < 3000; ++i) {
      const Vec2 p(x(rng), y(rng)), q = p + Vec2(0.07, -0.05);
      ASSERT_EQ(field.distance(p), fresh.distance(p)) << "round " << round << " at " << p.transpose();
      ASSERT_EQ(field.lower_bound(p), fresh.lower_bound(p)) << "round " << round << " at " << p.transpose();
      const double a = field.segment_distance(p, q), b = fresh.segment_distance(p, q);
      ASSERT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << "round " << round << " at " << p.transpose();
    }
  }
  expect_error_naming([&] { field.update(grid, {grid.cells().size()}); }, "cell");
}

}  // namespace
}  // namespace fgdwa
