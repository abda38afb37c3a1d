#include "ros_convert.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fgdwa/error.hpp"

namespace fgdwa_ros {

double yaw_of(const geometry_msgs::Quaternion& q) {
  return std::atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z));
}

fgdwa::Pose2 pose_of(const geometry_msgs::Pose& pose) {
  return {pose.position.x, pose.position.y, yaw_of(pose.orientation)};
}

geometry_msgs::Pose to_pose(const fgdwa::Pose2& pose) {
  geometry_msgs::Pose out;
  out.position.x = pose.x;
  out.position.y = pose.y;
  out.orientation.z = std::sin(0.5 * pose.theta);
  out.orientation.w = std::cos(0.5 * pose.theta);
  return out;
}

fgdwa::Scan to_scan(const sensor_msgs::LaserScan& msg, const fgdwa::Pose2& laser_pose) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  fgdwa::Scan scan;
  scan.pose = laser_pose;
  scan.angle_min = msg.angle_min;
  scan.angle_increment = msg.angle_increment;
  scan.max_range = msg.range_max;
  scan.ranges.resize(msg.ranges.size());
  const double low = msg.range_min, high = msg.range_max;
  for (std::size_t i = 0; i < msg.ranges.size(); ++i) {
    const double r = msg.ranges[i];
    if (r == -inf)
      scan.ranges[i] = low;
    else
      scan.ranges[i] = (std::isfinite(r) && r >= low && r < high) ? r : inf;
  }
  return scan;
}

fgdwa::OccupancyGrid to_grid(const nav_msgs::OccupancyGrid& msg, int threshold) {
  const auto& info = msg.info;
  const double yaw = yaw_of(info.origin.orientation);
  if (std::abs(yaw) > 1e-9)
    throw fgdwa::Error("map: origin yaw = " + std::to_string(yaw) + " rad: fgdwa needs an unrotated map");
  if (msg.data.size() != static_cast<std::size_t>(info.width) * info.height || info.width == 0 || info.height == 0)
    throw fgdwa::Error("map: " + std::to_string(msg.data.size()) + " cells for " + std::to_string(info.width) +
                       " x " + std::to_string(info.height));
  std::vector<std::uint8_t> cells(msg.data.size());
  // Both are row-major with row 0 at the origin (the lowest y).
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = msg.data[i] >= threshold ? 1 : 0;
  return fgdwa::OccupancyGrid(static_cast<int>(info.height), static_cast<int>(info.width), info.resolution,
                              fgdwa::Vec2(info.origin.position.x, info.origin.position.y), std::move(cells));
}

nav_msgs::Path to_path(const fgdwa::GlobalPath& path, const std_msgs::Header& header) {
  nav_msgs::Path out;
  out.header = header;
  const auto& points = path.points();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const fgdwa::Vec2 next = points[std::min(i + 1, points.size() - 1)];
    const fgdwa::Vec2 prev = points[i + 1 < points.size() ? i : i - 1];
    geometry_msgs::PoseStamped pose;
    pose.header = header;
    pose.pose = to_pose({points[i].x(), points[i].y(), std::atan2(next.y() - prev.y(), next.x() - prev.x())});
    out.poses.push_back(pose);
  }
  return out;
}

nav_msgs::Path to_path(const fgdwa::Trajectory& poses, const std_msgs::Header& header) {
  nav_msgs::Path out;
  out.header = header;
  for (const fgdwa::Pose2& p : poses) {
    geometry_msgs::PoseStamped pose;
    pose.header = header;
    pose.pose = to_pose(p);
    out.poses.push_back(pose);
  }
  return out;
}

namespace {

geometry_msgs::Point point_of(const fgdwa::Pose2& p) {
  geometry_msgs::Point point;
  point.x = p.x;
  point.y = p.y;
  return point;
}

visualization_msgs::Marker marker(const std_msgs::Header& header, const char* ns, int type, double width) {
  visualization_msgs::Marker m;
  m.header = header;
  m.ns = ns;
  m.type = type;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = width;
  m.color.a = 1.0f;
  return m;
}

std_msgs::ColorRGBA rgba(float r, float g, float b, float a) {
  std_msgs::ColorRGBA c;
  c.r = r;
  c.g = g;
  c.b = b;
  c.a = a;
  return c;
}

bool admissible(const fgdwa::PlanResult& plan, std::size_t i) { return plan.reasons[i] == fgdwa::RejectReason::None; }

}  // namespace

fgdwa_ros::LocalPlanEvaluation evaluation(const fgdwa::CycleRecord& record, const fgdwa::PlanResult& plan,
                                          const std::vector<fgdwa::Trajectory>& rollouts,
                                          const std_msgs::Header& header) {
  fgdwa_ros::LocalPlanEvaluation out;
  out.header = header;
  out.mode = fgdwa::to_string(record.mode);
  out.status = fgdwa::to_string(record.control.status);
  out.planned = record.planned;
  out.command.linear.x = record.command.v;
  out.command.angular.z = record.command.omega;
  out.critic_names = plan.critic_names;
  out.best_index = -1;
  if (!record.planned) return out;
  const std::size_t critics = plan.critic_names.size();
  out.weights = plan.weights;
  out.critic_vetoes.assign(plan.critic_vetoes.begin(), plan.critic_vetoes.end());
  out.best_index = plan.best_index;
  out.twists.resize(plan.samples.size());
  for (std::size_t i = 0; i < plan.samples.size(); ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    fgdwa_ros::TrajectoryScore& score = out.twists[i];
    score.twist.linear.x = plan.samples[i].v;
    score.twist.angular.z = plan.samples[i].omega;
    if (i < rollouts.size()) {
      score.poses.resize(rollouts[i].size());
      for (std::size_t k = 0; k < rollouts[i].size(); ++k) {
        score.poses[k].x = rollouts[i][k].x;
        score.poses[k].y = rollouts[i][k].y;
        score.poses[k].theta = rollouts[i][k].theta;
      }
    }
    score.total = plan.total(row);
    if (!admissible(plan, i)) score.rejected = fgdwa::to_string(plan.reasons[i]);
    const int veto = plan.vetoed_by[i];
    if (veto >= 0) score.vetoed_by = plan.critic_names[static_cast<std::size_t>(veto)];
    score.scores.resize(critics);
    for (std::size_t j = 0; j < critics; ++j) {
      const auto c = static_cast<Eigen::Index>(j);
      fgdwa_ros::CriticScore& critic = score.scores[j];
      critic.name = plan.critic_names[j];
      critic.raw_score = plan.raw(row, c);
      critic.normalized_score = plan.normalized(row, c);
      critic.scale = plan.signed_weights[j];
      critic.term = plan.signed_weights[j] * plan.normalized(row, c);
    }
  }
  return out;
}

std_msgs::ColorRGBA colour_scale(double t) {
  // Blue, magenta, yellow: apart from the chosen rollout's green and readable on rviz's grey.
  static constexpr float stops[3][3] = {{0.15f, 0.25f, 1.0f}, {0.9f, 0.2f, 0.65f}, {1.0f, 0.9f, 0.1f}};
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.5;
  const int k = t < 0.5 ? 0 : 1;
  const float u = static_cast<float>(2.0 * t - k);
  return rgba(stops[k][0] + u * (stops[k + 1][0] - stops[k][0]), stops[k][1] + u * (stops[k + 1][1] - stops[k][1]),
              stops[k][2] + u * (stops[k + 1][2] - stops[k][2]), 1.0f);
}

visualization_msgs::MarkerArray rollout_markers(const fgdwa::CycleRecord& record, const fgdwa::PlanResult& plan,
                                                const std::vector<fgdwa::Trajectory>& rollouts, int critic,
                                                const std_msgs::Header& header) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.header = header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  if (!record.planned) return out;
  const std::size_t n = std::min(plan.samples.size(), rollouts.size());
  auto value = [&](std::size_t i) {
    const auto row = static_cast<Eigen::Index>(i);
    return critic < 0 ? plan.total(row)
                      : plan.signed_weights[static_cast<std::size_t>(critic)] * plan.normalized(row, critic);
  };
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t i = 0; i < n; ++i) {
    if (!admissible(plan, i)) continue;
    low = std::min(low, value(i));
    high = std::max(high, value(i));
  }
  auto fan = marker(header, "rollouts", visualization_msgs::Marker::LINE_LIST, 0.01);
  auto rejected = marker(header, "rejected", visualization_msgs::Marker::LINE_LIST, 0.005);
  rejected.color = rgba(0.6f, 0.6f, 0.6f, 0.25f);
  for (std::size_t i = 0; i < n; ++i) {
    const fgdwa::Trajectory& poses = rollouts[i];
    const bool ok = admissible(plan, i);
    const std_msgs::ColorRGBA colour = colour_scale(high - low > 1e-12 ? (value(i) - low) / (high - low) : 0.5);
    visualization_msgs::Marker& into = ok ? fan : rejected;
    for (std::size_t k = 0; k + 1 < poses.size(); ++k) {
      into.points.push_back(point_of(poses[k]));
      into.points.push_back(point_of(poses[k + 1]));
      if (ok) into.colors.insert(into.colors.end(), 2, colour);
    }
  }
  if (!fan.points.empty()) out.markers.push_back(fan);
  if (!rejected.points.empty()) out.markers.push_back(rejected);
  if (record.control.choice.poses.size() >= 2) {
    auto chosen = marker(header, "chosen", visualization_msgs::Marker::LINE_STRIP, 0.03);
    chosen.color = rgba(0.0f, 0.9f, 0.2f, 1.0f);
    for (const fgdwa::Pose2& p : record.control.choice.poses) chosen.points.push_back(point_of(p));
    out.markers.push_back(chosen);
  }
  return out;
}

nav_msgs::OccupancyGrid to_occupancy_grid(const fgdwa::OccupancyGrid& grid, const std::vector<std::uint8_t>& unknown,
                                          const std_msgs::Header& header) {
  nav_msgs::OccupancyGrid out;
  out.header = header;
  out.info.map_load_time = header.stamp;
  out.info.resolution = static_cast<float>(grid.resolution());
  out.info.width = static_cast<std::uint32_t>(grid.cols());
  out.info.height = static_cast<std::uint32_t>(grid.rows());
  out.info.origin.position.x = grid.origin().x();
  out.info.origin.position.y = grid.origin().y();
  out.info.origin.orientation.w = 1.0;
  const auto& cells = grid.cells();
  out.data.resize(cells.size());
  // Both row-major with row 0 at the origin (the lowest y).
  for (std::size_t i = 0; i < cells.size(); ++i)
    out.data[i] = cells[i] ? 100 : (i < unknown.size() && unknown[i] ? -1 : 0);
  return out;
}

geometry_msgs::PolygonStamped to_polygon(const fgdwa::Footprint& footprint, const std_msgs::Header& header,
                                         int circle_vertices) {
  geometry_msgs::PolygonStamped out;
  out.header = header;
  auto add = [&](double x, double y) {
    geometry_msgs::Point32 p;
    p.x = static_cast<float>(x);
    p.y = static_cast<float>(y);
    out.polygon.points.push_back(p);
  };
  if (footprint.is_circle()) {
    for (int k = 0; k < circle_vertices; ++k) {
      const double a = 2.0 * M_PI * k / circle_vertices;
      add(footprint.radius() * std::cos(a), footprint.radius() * std::sin(a));
    }
  } else {
    for (const fgdwa::Vec2& v : footprint.vertices()) add(v.x(), v.y());
  }
  return out;
}

}  // namespace fgdwa_ros
