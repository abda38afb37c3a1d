#include "ros_convert.hpp"

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

fgdwa::Pose2 compose(const fgdwa::Pose2& base, const fgdwa::Pose2& mount) {
  const double c = std::cos(base.theta), s = std::sin(base.theta);
  return {base.x + c * mount.x - s * mount.y, base.y + s * mount.x + c * mount.y,
          fgdwa::wrap_angle(base.theta + mount.theta)};
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
visualization_msgs::Marker line(const std_msgs::Header& header, int id, const fgdwa::Trajectory& poses, float r,
                                float g, float b, double width) {
  visualization_msgs::Marker m;
  m.header = header;
  m.ns = "rollouts";
  m.id = id;
  m.type = visualization_msgs::Marker::LINE_STRIP;
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1.0;
  m.scale.x = width;
  m.color.r = r;
  m.color.g = g;
  m.color.b = b;
  m.color.a = 1.0f;
  for (const fgdwa::Pose2& p : poses) {
    geometry_msgs::Point point;
    point.x = p.x;
    point.y = p.y;
    m.points.push_back(point);
  }
  return m;
}
}  // namespace

visualization_msgs::MarkerArray rollout_markers(const fgdwa::CycleRecord& record, const std_msgs::Header& header) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.header = header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  const std::size_t n = record.control.best.size();
  for (std::size_t i = 0; i < n; ++i) {
    // Best first: from bright orange down to dark red.
    const float shade = n > 1 ? 1.0f - 0.7f * static_cast<float>(i) / static_cast<float>(n - 1) : 1.0f;
    if (record.control.best[i].poses.size() >= 2)
      out.markers.push_back(line(header, static_cast<int>(i) + 1, record.control.best[i].poses, shade, 0.5f * shade, 0.0f,
                                 0.01));
  }
  if (record.control.choice.poses.size() >= 2)
    out.markers.push_back(line(header, 0, record.control.choice.poses, 0.0f, 0.9f, 0.2f, 0.03));
  return out;
}

}  // namespace fgdwa_ros
