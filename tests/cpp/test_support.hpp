#pragma once
// Seeded worlds and brute-force references shared by the C++ tests.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "fgdwa/error.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa::test {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Runs `f`, expecting fgdwa::Error whose message mentions `field`.
template <typename F>
void expect_error_naming(F&& f, const std::string& field) {
  try {
    f();
    ADD_FAILURE() << "no fgdwa::Error thrown; expected one naming '" << field << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(field), std::string::npos)
        << "message '" << e.what() << "' does not name '" << field << "'";
  }
}

// Free cells but for the boxes, each {first row, first column, rows, columns}.
inline OccupancyGrid grid_with_boxes(int rows, int cols, double resolution, Vec2 origin,
                                     const std::vector<std::array<int, 4>>& boxes) {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(rows) * cols, 0);
  for (const auto& b : boxes)
    for (int row = b[0]; row < b[0] + b[2]; ++row)
      for (int col = b[1]; col < b[1] + b[3]; ++col) cells[static_cast<std::size_t>(row) * cols + col] = 1;
  return OccupancyGrid(rows, cols, resolution, origin, std::move(cells));
}

// Cells with independent probability `density`.
inline OccupancyGrid random_cells(std::mt19937& rng, int rows, int cols, double resolution, Vec2 origin,
                                  double density) {
  std::bernoulli_distribution occupied(density);
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(rows) * cols);
  for (auto& c : cells) c = occupied(rng) ? 1 : 0;
  return OccupancyGrid(rows, cols, resolution, origin, std::move(cells));
}

// Random axis-aligned rectangles (1..max_side cells a side) until `fill` of the
// cells are occupied: clustered like real maps. Cells within `keep_free` of
// `free_point` stay free so a robot can start there.
inline OccupancyGrid random_rectangles(std::mt19937& rng, int rows, int cols, double resolution, Vec2 origin,
                                       double fill, int max_side = 8, Vec2 free_point = Vec2(kInf, kInf),
                                       double keep_free = 0.0) {
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(rows) * cols, 0);
  std::uniform_int_distribution<int> side(1, max_side), row_of(0, rows - 1), col_of(0, cols - 1);
  const auto centre = [&](int r, int c) -> Vec2 { return origin + Vec2((c + 0.5) * resolution, (r + 0.5) * resolution); };
  const std::size_t target = static_cast<std::size_t>(fill * rows * cols);
  std::size_t count = 0;
  while (count < target) {
    const int r0 = row_of(rng), c0 = col_of(rng), h = side(rng), w = side(rng);
    for (int r = r0; r < std::min(rows, r0 + h); ++r)
      for (int c = c0; c < std::min(cols, c0 + w); ++c) {
        auto& cell = cells[static_cast<std::size_t>(r) * cols + c];
        if (cell || (centre(r, c) - free_point).norm() <= keep_free + resolution) continue;
        cell = 1;
        ++count;
      }
  }
  return OccupancyGrid(rows, cols, resolution, origin, std::move(cells));
}

inline double point_box_distance(const Vec2& p, const Vec2& lo, const Vec2& hi) {
  const double dx = std::max({lo.x() - p.x(), 0.0, p.x() - hi.x()});
  const double dy = std::max({lo.y() - p.y(), 0.0, p.y() - hi.y()});
  return std::hypot(dx, dy);
}

// Exact distance from `p` to the union of the occupied squares.
inline double brute_point_distance(const OccupancyGrid& grid, const Vec2& p) {
  double best = kInf;
  const double res = grid.resolution();
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c)
      if (grid.occupied(r, c)) {
        const Vec2 lo = grid.origin() + Vec2(c * res, r * res);
        best = std::min(best, point_box_distance(p, lo, lo + Vec2(res, res)));
      }
  return best;
}

// Footprint corners (or nothing for a circle) placed at `pose`.
inline std::vector<Vec2> placed_vertices(const Footprint& fp, const Pose2& pose) {
  std::vector<Vec2> out;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  for (const Vec2& q : fp.vertices()) out.emplace_back(pose.x + c * q.x() - s * q.y(), pose.y + s * q.x() + c * q.y());
  return out;
}

inline double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Whether two convex polygons overlap (separating axis theorem).
inline bool convex_overlap(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  const auto separated = [](const std::vector<Vec2>& p, const std::vector<Vec2>& q) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec2 e = p[(i + 1) % p.size()] - p[i];
      const Vec2 n(-e.y(), e.x());
      double pmin = kInf, pmax = -kInf, qmin = kInf, qmax = -kInf;
      for (const Vec2& v : p) pmin = std::min(pmin, n.dot(v)), pmax = std::max(pmax, n.dot(v));
      for (const Vec2& v : q) qmin = std::min(qmin, n.dot(v)), qmax = std::max(qmax, n.dot(v));
      if (pmax < qmin || qmax < pmin) return true;
    }
    return false;
  };
  return !separated(a, b) && !separated(b, a);
}

// Distance between two convex polygons, 0 when they overlap.
inline double convex_distance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
  if (convex_overlap(a, b)) return 0.0;
  double best = kInf;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) {
      best = std::min(best, point_segment_distance(a[i], b[j], b[(j + 1) % b.size()]));
      best = std::min(best, point_segment_distance(b[j], a[i], a[(i + 1) % a.size()]));
    }
  return best;
}

// Exact distance from the footprint at `pose` to the occupied squares, 0 on contact.
inline double brute_footprint_distance(const OccupancyGrid& grid, const Footprint& fp, const Pose2& pose) {
  if (fp.is_circle()) return std::max(brute_point_distance(grid, pose.position()) - fp.radius(), 0.0);
  const std::vector<Vec2> poly = placed_vertices(fp, pose);
  const double res = grid.resolution();
  double best = kInf;
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c)
      if (grid.occupied(r, c)) {
        const Vec2 lo = grid.origin() + Vec2(c * res, r * res);
        // Far squares cannot beat the current best: skip the polygon test.
        if (point_box_distance(pose.position(), lo, lo + Vec2(res, res)) - fp.radius() >= best) continue;
        const std::vector<Vec2> square = {lo, lo + Vec2(res, 0), lo + Vec2(res, res), lo + Vec2(0, res)};
        best = std::min(best, convex_distance(poly, square));
      }
  return best;
}

}  // namespace fgdwa::test
