#pragma once
// Between ROS messages and fgdwa's types. Pure functions: no node, no TF.
#include <string>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Quaternion.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Path.h>
#include <sensor_msgs/LaserScan.h>
#include <visualization_msgs/MarkerArray.h>

#include "fgdwa/geometry.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/navigator.hpp"
#include "fgdwa/perception.hpp"

namespace fgdwa_ros {

// Heading about z, rad; written out (not tf2::getYaw) so that fgdwa replay,
// reading the same quaternions from a bag, gets the same bits.
double yaw_of(const geometry_msgs::Quaternion& q);
fgdwa::Pose2 pose_of(const geometry_msgs::Pose& pose);
geometry_msgs::Pose to_pose(const fgdwa::Pose2& pose);
// `mount` (in the base frame) placed at `base`.
fgdwa::Pose2 compose(const fgdwa::Pose2& base, const fgdwa::Pose2& mount);

// A LaserScan as fgdwa's Scan taken at `laser_pose`. Readings follow REP 117:
// NaN, +inf, or outside [range_min, range_max) are no return (+inf); -inf is
// an object nearer than range_min, a hit at range_min.
fgdwa::Scan to_scan(const sensor_msgs::LaserScan& msg, const fgdwa::Pose2& laser_pose);

// A map's cells at least `threshold` (0-100) occupied are obstacles; unknown
// (-1) cells are free to the planner (the scans add what they find). Throws
// fgdwa::Error for a rotated origin or a size that does not match its data.
fgdwa::OccupancyGrid to_grid(const nav_msgs::OccupancyGrid& msg, int threshold);

nav_msgs::Path to_path(const fgdwa::GlobalPath& path, const std_msgs::Header& header);
nav_msgs::Path to_path(const fgdwa::Trajectory& poses, const std_msgs::Header& header);

// The rollout fan of one cycle: the record's best-scored rollouts (brighter
// the better) and the chosen one in green, replacing the previous cycle's.
visualization_msgs::MarkerArray rollout_markers(const fgdwa::CycleRecord& record, const std_msgs::Header& header);

}  // namespace fgdwa_ros
