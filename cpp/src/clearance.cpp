#include "fgdwa/clearance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "validation.hpp"

namespace fgdwa {

void Disc::validate() const {
  detail::require_finite("disc center x", center.x());
  detail::require_finite("disc center y", center.y());
  detail::require_non_negative("disc radius", radius);
  detail::require_finite("disc velocity x", velocity.x());
  detail::require_finite("disc velocity y", velocity.y());
}

FieldClearance::FieldClearance(std::shared_ptr<const DistanceField> field, std::vector<Disc> discs)
    : field_(std::move(field)) {
  set_discs(std::move(discs));
}

void FieldClearance::set_discs(std::vector<Disc> discs) {
  for (const Disc& d : discs) d.validate();
  discs_ = std::move(discs);
}

namespace {
double field_clearance(const DistanceField* field, const Footprint& footprint, const Pose2& pose) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!field || !field->has_obstacles()) return kInf;
  const double centre = field->distance(pose.position());
  if (footprint.is_circle()) return centre - footprint.radius();

  // Polygon: the distance from its outline, walked at half-cell spacing.
  const double res = field->grid().resolution();
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const auto world = [&](const Vec2& q) { return Vec2(pose.x + c * q.x() - s * q.y(), pose.y + s * q.x() + c * q.y()); };
  const auto& vertices = footprint.vertices();
  double best = kInf;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2 a = vertices[i], b = vertices[(i + 1) % vertices.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * res))));
    for (int k = 0; k < pieces; ++k) best = std::min(best, field->distance(world(a + (b - a) * (double(k) / pieces))));
  }
  if (best <= 0.0 || centre >= footprint.radius()) return best;
  // An obstacle cell can sit wholly inside a footprint wider than a cell.
  const OccupancyGrid& grid = field->grid();
  const double r = footprint.radius();
  int r0, c0, r1, c1;
  const Vec2 lo = pose.position() - Vec2(r, r), hi = pose.position() + Vec2(r, r);
  r0 = std::max(0, static_cast<int>(std::floor((lo.y() - grid.origin().y()) / res)));
  c0 = std::max(0, static_cast<int>(std::floor((lo.x() - grid.origin().x()) / res)));
  r1 = std::min(grid.rows() - 1, static_cast<int>(std::floor((hi.y() - grid.origin().y()) / res)));
  c1 = std::min(grid.cols() - 1, static_cast<int>(std::floor((hi.x() - grid.origin().x()) / res)));
  for (int row = r0; row <= r1; ++row)
    for (int col = c0; col <= c1; ++col)
      if (grid.occupied(row, col) && footprint.contains(pose, grid.cell_center(row, col))) return 0.0;
  return best;
}

}  // namespace

double FieldClearance::clearance_lower_bound(const Footprint& footprint, const Pose2& pose, double t) const {
  // Every point of the footprint lies within its circumscribed radius of the pose.
  const Vec2 p = pose.position();
  double best = std::numeric_limits<double>::infinity();
  if (field_) best = field_->lower_bound(p);
  if (sensed_) best = std::min(best, sensed_->lower_bound(p));
  best -= footprint.radius();
  for (const Disc& disc : discs_)
    best = std::min(best, (disc.center_at(t) - p).norm() - disc.radius - footprint.radius());
  return best;
}

void FieldClearance::clearance_lower_bounds(const Footprint& footprint, const Trajectory& poses, double dt,
                                            double* out) const {
  const double r = footprint.radius();
  const std::size_t n = poses.size();
  if (field_) {
    for (std::size_t k = 0; k < n; ++k) out[k] = field_->lower_bound(poses[k].position()) - r;
  } else {
    std::fill(out, out + n, std::numeric_limits<double>::infinity());
  }
  if (sensed_)
    for (std::size_t k = 0; k < n; ++k) out[k] = std::min(out[k], sensed_->lower_bound(poses[k].position()) - r);
  for (const Disc& disc : discs_)
    for (std::size_t k = 0; k < n; ++k)
      out[k] = std::min(out[k], (disc.center_at(static_cast<double>(k + 1) * dt) - poses[k].position()).norm() -
                                    disc.radius - r);
}

double FieldClearance::clearance(const Footprint& footprint, const Pose2& pose, double t) const {
  double best = field_clearance(field_.get(), footprint, pose);
  if (sensed_) best = std::min(best, field_clearance(sensed_.get(), footprint, pose));
  for (const Disc& disc : discs_)
    best = std::min(best, footprint.signed_distance(pose, disc.center_at(t)) - disc.radius);
  return best;
}

}  // namespace fgdwa
