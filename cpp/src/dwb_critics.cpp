#include "fgdwa/dwb_critics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fgdwa/clearance.hpp"
#include "validation.hpp"

namespace fgdwa {

namespace {
// Nav2's costmap values: an inscribed cell, and the top of the inflation decay.
constexpr double kInscribedCost = 253.0;
constexpr double kInflatedCost = 252.0;

void push_distinct(std::vector<Vec2>& points, const Vec2& p) {
  if (points.empty() || (points.back() - p).squaredNorm() > 0.0) points.push_back(p);
}
}  // namespace

const char* to_string(DwbAggregation aggregation) {
  switch (aggregation) {
    case DwbAggregation::Last: return "last";
    case DwbAggregation::Sum: return "sum";
  }
  return "?";
}

double dwb_inflation_cost(double clearance, const DwbObstacleParams& params) {
  if (clearance <= 0.0) return kInscribedCost;
  if (clearance >= params.inflation_margin) return 0.0;
  return kInflatedCost * std::exp(-params.cost_scaling_factor * clearance);
}

DwbObstacleCritic::DwbObstacleCritic(const DwbObstacleParams& params) : params_(params) { params_.validate(); }

void DwbObstacleCritic::prepare(const CriticContext& context) {
  if (!context.world || !context.footprint)
    throw Error("critic 'dwb_obstacle' needs the context's world and footprint");
  world_ = context.world;
  footprint_ = context.footprint;
  dt_ = context.dt;
}

double DwbObstacleCritic::score(const Rollout& rollout) const {
  const Trajectory& poses = *rollout.poses;
  if (poses.empty()) return 0.0;
  const auto cost_of = [&](std::size_t k) {
    return dwb_inflation_cost(world_->clearance(*footprint_, poses[k], static_cast<double>(k + 1) * dt_), params_);
  };
  if (params_.aggregation == DwbAggregation::Last) return cost_of(poses.size() - 1);
  double cost = 0.0;
  for (std::size_t k = 0; k < poses.size(); ++k) cost += cost_of(k);
  return cost;
}


void dwb_local_path(const GlobalPath& path, const Vec2& robot, double half_extent, DwbLocalPath& out) {
  out.points.clear();
  out.reaches_end = false;
  const PathProjection projection = path.project(robot);
  const std::vector<Vec2>& points = path.points();
  const Vec2 lo = robot - Vec2(half_extent, half_extent);
  const Vec2 hi = robot + Vec2(half_extent, half_extent);
  Vec2 from = projection.point;
  bool inside = false;
  for (std::size_t i = projection.segment; i < path.segment_count(); ++i) {
    const Vec2& to = points[i + 1];
    double t0, t1;
    if (clip_segment_to_box(from, to, lo, hi, t0, t1)) {
      if (!inside) push_distinct(out.points, from + t0 * (to - from));
      inside = true;
      push_distinct(out.points, from + t1 * (to - from));
      if (t1 < 1.0) return;  // leaves the window: DWB stops at the costmap's edge
    } else if (inside) {
      return;
    }
    from = to;
  }
  if (!inside) {
    out.points.push_back(projection.point);
    return;
  }
  out.reaches_end = true;
}

double polyline_distance(const std::vector<Vec2>& polyline, const Vec2& p) {
  if (polyline.size() == 1) return (p - polyline.front()).norm();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
    best = std::min(best, point_segment_distance(p, polyline[i], polyline[i + 1]));
  return best;
}

DwbGridCritic::DwbGridCritic(const DwbGridParams& params) : params_(params) { params_.validate(); }

void DwbGridCritic::prepare(const CriticContext& context) {
  if (!context.path) throw Error("critic '" + name() + "' needs a global path");
  dwb_local_path(*context.path, context.state.pose.position(), params_.local_extent, local_);
}

Vec2 DwbGridCritic::forward_point(const Pose2& pose) const {
  return pose.position() + params_.forward_point_distance * Vec2(std::cos(pose.theta), std::sin(pose.theta));
}

double DwbPathDistCritic::score(const Rollout& rollout) const {
  return cells(polyline_distance(local_.points, rollout.poses->back().position()));
}

double DwbGoalDistCritic::score(const Rollout& rollout) const {
  return cells((rollout.poses->back().position() - local_.goal()).norm());
}

void DwbPathAlignCritic::prepare(const CriticContext& context) {
  DwbGridCritic::prepare(context);
  active_ = (context.state.pose.position() - context.goal).norm() > params_.forward_point_distance;
}

double DwbPathAlignCritic::score(const Rollout& rollout) const {
  if (!active_) return 0.0;
  return cells(polyline_distance(local_.points, forward_point(rollout.poses->back())));
}

void DwbGoalAlignCritic::prepare(const CriticContext& context) {
  DwbGridCritic::prepare(context);
  target_ = local_.goal();
  const Vec2 to_goal = context.goal - context.state.pose.position();
  if (local_.reaches_end && to_goal.squaredNorm() > 0.0)
    target_ += params_.forward_point_distance * to_goal.normalized();
}

double DwbGoalAlignCritic::score(const Rollout& rollout) const {
  return cells((forward_point(rollout.poses->back()) - target_).norm());
}

}  // namespace fgdwa
