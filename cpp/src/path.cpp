#include "fgdwa/path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "validation.hpp"

namespace fgdwa {

const char* to_string(ReferenceSampling sampling) {
  switch (sampling) {
    case ReferenceSampling::Segment: return "segment";
    case ReferenceSampling::Polyline: return "polyline";
  }
  return "?";
}

GlobalPath::GlobalPath(std::vector<Vec2> points) {
  if (points.size() < 2)
    throw Error(detail::describe("global path points", points.size(), "a path needs at least 2 points"));
  if (points.size() > static_cast<std::size_t>(limits::kMaxPoints))
    throw Error(detail::describe("global path points", points.size(),
                                 "a path has at most " + std::to_string(limits::kMaxPoints)));
  detail::require_points("global path point", points.data(), points.size(), limits::kMaxCoordinate);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points_.empty() || (points[i] - points_.back()).norm() > 1e-12) points_.push_back(points[i]);
  }
  if (points_.size() < 2) throw Error("global path: all points coincide, the path has no length");
  cumulative_.assign(1, 0.0);
  for (std::size_t i = 1; i < points_.size(); ++i) {
    const Vec2 d = points_[i] - points_[i - 1];
    cumulative_.push_back(cumulative_.back() + d.norm());
    directions_.push_back(std::atan2(d.y(), d.x()));
  }
  if (cumulative_.back() > limits::kMaxPathLength)
    throw Error(detail::describe("global path length", cumulative_.back(),
                                 "must be <= " + detail::format_number(limits::kMaxPathLength) + " m"));
}

PathProjection GlobalPath::project(const Vec2& p) const {
  detail::require_query_point("point", p);
  PathProjection best;
  best.distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    const Vec2 a = points_[i], ab = points_[i + 1] - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const Vec2 q = a + t * ab;
    const double d = (p - q).norm();
    if (d < best.distance) {
      best.distance = d;
      best.point = q;
      best.segment = i;
      best.arc_length = cumulative_[i] + t * (cumulative_[i + 1] - cumulative_[i]);
    }
  }
  return best;
}

std::size_t GlobalPath::segment_at(double s) const {
  detail::require_finite("arc length", s);
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  const std::size_t i = it == cumulative_.begin() ? 0 : static_cast<std::size_t>(it - cumulative_.begin()) - 1;
  return std::min(i, segment_count() - 1);
}

Vec2 GlobalPath::point_at(double s) const {
  detail::require_finite("arc length", s);
  s = std::clamp(s, 0.0, length());
  const std::size_t i = segment_at(s);
  const double span = cumulative_[i + 1] - cumulative_[i];
  return points_[i] + (points_[i + 1] - points_[i]) * ((s - cumulative_[i]) / span);
}

std::vector<std::size_t> GlobalPath::key_nodes(double min_turn) const {
  detail::require_non_negative("min_turn", min_turn);
  std::vector<std::size_t> nodes;
  for (std::size_t i = 1; i + 1 < points_.size(); ++i)
    if (std::abs(angle_difference(directions_[i], directions_[i - 1])) > min_turn) nodes.push_back(i);
  nodes.push_back(points_.size() - 1);
  return nodes;
}

void reference_samples(const GlobalPath& path, const Vec2& robot, double v_ref, double dt, int n,
                       ReferenceSampling sampling, std::vector<Vec2>& out) {
  detail::require_query_point("robot", robot);
  detail::require_magnitude("v_ref", v_ref, limits::kMaxSpeed);
  detail::require_time_step("dt", dt);
  detail::require_count("n", n, 0, limits::kMaxRolloutSteps);
  out.resize(static_cast<std::size_t>(std::max(n, 0)));
  const PathProjection p = path.project(robot);
  const double spacing = v_ref * dt;
  if (sampling == ReferenceSampling::Segment) {
    const double theta = path.segment_direction(p.segment);
    const Vec2 step(std::cos(theta) * spacing, std::sin(theta) * spacing);
    for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = p.point + (i + 1) * step;
  } else {
    for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i)] = path.point_at(p.arc_length + (i + 1) * spacing);
  }
}

KeyNodeTracker::KeyNodeTracker(const GlobalPath& path, const KeyNodeParams& params)
    : path_(&path), params_(params), nodes_(path.key_nodes(params.min_turn)) {
  params_.validate();
}

Vec2 KeyNodeTracker::update(const Vec2& robot, const std::function<bool(const Vec2&, const Vec2&)>& in_sight) {
  detail::require_query_point("robot", robot);
  const double along = path_->project(robot).arc_length;
  while (current_ + 1 < nodes_.size()) {
    const std::size_t vertex = nodes_[current_];
    const bool passed = along > path_->arc_length_at_vertex(vertex);
    bool near = (robot - path_->points()[vertex]).norm() <= params_.reach_radius;
    if (near && !passed && params_.require_sight && in_sight)
      near = in_sight(robot, path_->points()[nodes_[current_ + 1]]);
    if (!near && !passed) break;
    ++current_;
  }
  return target();
}

}  // namespace fgdwa
