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
// m: how finely a polygon's outline is resolved where an obstacle is near it.
constexpr double kOutlineTolerance = 0.005;

double field_clearance(const DistanceField* field, const Footprint& footprint, const Pose2& pose) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!field || !field->has_obstacles()) return kInf;
  const double centre = field->distance(pose.position());
  if (footprint.is_circle()) return centre - footprint.radius();

  // Polygon: the distance from its outline, never above the true one. The
  // outline is sampled at half-cell spacing; the field is 1-Lipschitz, so a
  // piece of length L whose ends lie at da and db holds no point nearer than
  // (da + db - L) / 2. Pieces whose bound could still lower the result are
  // halved down to kOutlineTolerance, where the bound itself is taken.
  const double res = field->grid().resolution();
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const auto world = [&](const Vec2& q) { return Vec2(pose.x + c * q.x() - s * q.y(), pose.y + s * q.x() + c * q.y()); };
  const auto& vertices = footprint.vertices();
  double best = kInf;
  struct Piece {
    Vec2 a, b;
    double da, db;
  };
  // Reused across calls: this runs thousands of times per control cycle.
  thread_local std::vector<Piece> pending;
  pending.clear();
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2 a = world(vertices[i]), b = world(vertices[(i + 1) % vertices.size()]);
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / (0.5 * res))));
    Vec2 p = a;
    double dp = field->distance(p);
    for (int k = 1; k <= pieces; ++k) {
      const Vec2 q = a + (b - a) * (double(k) / pieces);
      const double dq = field->distance(q);
      pending.push_back({p, q, dp, dq});
      best = std::min(best, dp);
      p = q;
      dp = dq;
    }
  }
  while (!pending.empty()) {
    const Piece piece = pending.back();
    pending.pop_back();
    const double length = (piece.b - piece.a).norm();
    const double bound = 0.5 * (piece.da + piece.db - length);
    if (bound >= best) continue;
    if (length <= kOutlineTolerance) {
      best = bound;
      continue;
    }
    const Vec2 mid = 0.5 * (piece.a + piece.b);
    const double dm = field->distance(mid);
    best = std::min(best, dm);
    pending.push_back({piece.a, mid, piece.da, dm});
    pending.push_back({mid, piece.b, dm, piece.db});
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

// The static obstacles' distance bound at a point; +inf without either field.
double point_lower_bound(const DistanceField* field, const DistanceField* sensed, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  if (field) best = field->lower_bound(p);
  if (sensed) best = std::min(best, sensed->lower_bound(p));
  return best;
}

// Every point of the footprint lies in one of its cover discs (a circle is its
// own); a polygon's clearance may also sit up to half the outline tolerance
// under the truth.
double static_lower_bound(const DistanceField* field, const DistanceField* sensed, const Footprint& footprint,
                          const Pose2& pose) {
  if (footprint.is_circle()) return point_lower_bound(field, sensed, pose.position()) - footprint.radius();
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  double best = std::numeric_limits<double>::infinity();
  for (const Footprint::CoverDisc& d : footprint.cover()) {
    const Vec2 p(pose.x + c * d.centre.x() - s * d.centre.y(), pose.y + s * d.centre.x() + c * d.centre.y());
    best = std::min(best, point_lower_bound(field, sensed, p) - d.radius);
  }
  return best - 0.5 * kOutlineTolerance;
}

}  // namespace

double FieldClearance::clearance_lower_bound(const Footprint& footprint, const Pose2& pose, double t) const {
  const Vec2 p = pose.position();
  double best = static_lower_bound(field_.get(), sensed_.get(), footprint, pose);
  for (const Disc& disc : discs_)
    best = std::min(best, (disc.center_at(t) - p).norm() - disc.radius - footprint.radius());
  return best;
}

void FieldClearance::clearance_lower_bounds(const Footprint& footprint, const Trajectory& poses, double dt,
                                            double* out) const {
  const double r = footprint.radius();
  const std::size_t n = poses.size();
  if (!footprint.is_circle()) {
    for (std::size_t k = 0; k < n; ++k) out[k] = static_lower_bound(field_.get(), sensed_.get(), footprint, poses[k]);
  } else {
    // One field at a time in tight loops: this runs for every pose of every rollout.
    if (field_)
      for (std::size_t k = 0; k < n; ++k) out[k] = field_->lower_bound(poses[k].position()) - r;
    else
      std::fill(out, out + n, std::numeric_limits<double>::infinity());
    if (sensed_)
      for (std::size_t k = 0; k < n; ++k) out[k] = std::min(out[k], sensed_->lower_bound(poses[k].position()) - r);
  }
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
