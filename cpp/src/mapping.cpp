#include "fgdwa/mapping.hpp"

#include <algorithm>
#include <cmath>

#include "fgdwa/error.hpp"
#include "validation.hpp"

namespace fgdwa {

ScanMap::ScanMap(int rows, int cols, double resolution, Vec2 origin)
    : grid_(rows, cols, resolution, origin,
            std::vector<std::uint8_t>(static_cast<std::size_t>(std::max(rows, 0)) * std::max(cols, 0), 0)),
      cells_(grid_.cells()) {}

ScanMap::ScanMap(const OccupancyGrid& like) : ScanMap(like.rows(), like.cols(), like.resolution(), like.origin()) {}

bool ScanMap::mark_point(const Vec2& p) {
  int row = 0, col = 0;
  if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !grid_.cell_of(p, row, col)) return false;
  std::uint8_t& cell = cells_[grid_.index(row, col)];
  if (cell) return false;
  cell = 1;
  return true;
}

std::size_t ScanMap::integrate(const Scan& scan) {
  // A hit lies on an obstacle's surface, where rounding may put it in the free
  // cell beside; a micrometre further along the beam it is inside. No more:
  // a beam clipping a cell's corner stays in it for a short chord only.
  const double push = 1e-6 * grid_.resolution();
  std::size_t added = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double r = scan.ranges[i];
    if (!std::isfinite(r)) continue;
    const double a = scan.pose.theta + scan.angle_min + static_cast<double>(i) * scan.angle_increment;
    added += mark_point(Vec2(scan.pose.x + (r + push) * std::cos(a), scan.pose.y + (r + push) * std::sin(a)));
  }
  return commit(added);
}

std::size_t ScanMap::mark(const std::vector<Vec2>& points) {
  std::size_t added = 0;
  for (const Vec2& p : points) added += mark_point(p);
  return commit(added);
}

std::size_t ScanMap::commit(std::size_t added) {
  if (added) {
    occupied_ += added;
    stale_ = true;
    grid_ = OccupancyGrid(grid_.rows(), grid_.cols(), grid_.resolution(), grid_.origin(), cells_);
  }
  return added;
}

std::shared_ptr<const DistanceField> ScanMap::field() {
  if (stale_) {
    // After the first build, only the neighbourhoods of the new cells are recomputed.
    field_ = field_ ? std::make_shared<const DistanceField>(grid_, *field_) : std::make_shared<const DistanceField>(grid_);
    stale_ = false;
  }
  return field_;
}

bool path_blocked(const GlobalPath& path, const Vec2& position, const DistanceField& field, double clearance) {
  detail::require_finite("position x", position.x());
  detail::require_finite("position y", position.y());
  detail::require_finite("clearance", clearance);
  if (!field.has_obstacles()) return false;
  const double spacing = 0.5 * field.grid().resolution();
  const double end = path.length();
  for (double s = path.project(position).arc_length;; s += spacing) {
    if (field.distance(path.point_at(std::min(s, end))) < clearance) return true;
    if (s >= end) return false;
  }
}

}  // namespace fgdwa
