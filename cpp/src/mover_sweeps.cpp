#include "mover_sweeps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fgdwa::detail {

SweptDisc sweep_of(const Disc& disc, double horizon) {
  // An accelerating centre strays from the chord by at most |a| horizon^2 / 8
  // (its path's second derivative is a or 0).
  return SweptDisc{disc.center, disc.center_at(horizon),
                   disc.radius + (disc.accel_time > 0.0 ? disc.acceleration.norm() * horizon * horizon / 8.0 : 0.0)};
}

double distance_to(const SweptDisc& sweep, const Vec2& p) {
  return point_segment_distance(p, sweep.from, sweep.to) - sweep.radius;
}

void close_swept_cells(const OccupancyGrid& grid, const SweptDisc& sweep, const Vec2& a, const Vec2& b, double keep,
                       std::vector<std::uint8_t>& cells) {
  const double res = grid.resolution();
  const Vec2 lo = sweep.from.cwiseMin(sweep.to) - Vec2::Constant(sweep.radius) - grid.origin();
  const Vec2 hi = sweep.from.cwiseMax(sweep.to) + Vec2::Constant(sweep.radius) - grid.origin();
  // Cell indices of the sweep's bounding box, clipped to the grid (a sweep may lie partly or wholly off it).
  const auto first = [res](double v) { return static_cast<long long>(std::floor(std::max(v / res, -1.0))); };
  const auto last = [res](double v, int n) { return static_cast<long long>(std::floor(std::min(v / res, double(n)))); };
  const long long c0 = std::max(0LL, first(lo.x())), c1 = std::min<long long>(grid.cols() - 1, last(hi.x(), grid.cols()));
  const long long r0 = std::max(0LL, first(lo.y())), r1 = std::min<long long>(grid.rows() - 1, last(hi.y(), grid.rows()));
  for (long long r = r0; r <= r1; ++r)
    for (long long c = c0; c <= c1; ++c) {
      const Vec2 centre = grid.cell_center(static_cast<int>(r), static_cast<int>(c));
      if (distance_to(sweep, centre) > 0.0 || (centre - a).norm() <= keep || (centre - b).norm() <= keep) continue;
      cells[grid.index(static_cast<int>(r), static_cast<int>(c))] = 1;
    }
}

bool path_meets_sweeps(const GlobalPath& path, const Vec2& position, const std::vector<SweptDisc>& sweeps,
                       double lookahead, double clearance, double goal_keep) {
  if (sweeps.empty()) return false;
  const double start = path.project(position).arc_length;
  const double end = std::min(start + lookahead, path.length() - goal_keep);
  constexpr double kStride = 0.05;  // m, the finest step along the path
  // Distances are 1-Lipschitz along the path: from a point d - clearance away
  // from every sweep, nothing nearer than `clearance` lies within that stride.
  for (double s = start; s <= end;) {
    const Vec2 p = path.point_at(s);
    double nearest = std::numeric_limits<double>::infinity();
    for (const SweptDisc& sweep : sweeps) nearest = std::min(nearest, distance_to(sweep, p));
    if (nearest < clearance) return true;
    s += std::max(kStride, nearest - clearance);
  }
  return false;
}

}  // namespace fgdwa::detail
