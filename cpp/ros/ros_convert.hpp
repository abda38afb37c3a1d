#pragma once
// Between ROS messages and fgdwa's types. Pure functions: no node, no TF.
#include <string>

#include <cstdint>
#include <vector>

#include <fgdwa_ros/LocalPlanEvaluation.h>
#include <geometry_msgs/PolygonStamped.h>
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
#include "fgdwa/planner.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa_ros {

// compose(base, mount): `mount` (in the base frame) placed at `base`.
using fgdwa::compose;

// Heading about z, rad; written out (not tf2::getYaw) so that fgdwa replay,
// reading the same quaternions from a bag, gets the same bits.
double yaw_of(const geometry_msgs::Quaternion& q);
fgdwa::Pose2 pose_of(const geometry_msgs::Pose& pose);
geometry_msgs::Pose to_pose(const fgdwa::Pose2& pose);

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

// One cycle's evaluation: every sample of `plan` with its rollout (`rollouts`,
// one per sample, as the planner made them) and each critic's raw score,
// normalised score, signed weight and term. `record` gives the mode, the
// command and whether the planner ran; when it did not, no samples.
fgdwa_ros::LocalPlanEvaluation evaluation(const fgdwa::CycleRecord& record, const fgdwa::PlanResult& plan,
                                          const std::vector<fgdwa::Trajectory>& rollouts,
                                          const std_msgs::Header& header);

// What colours the rollout fan: the total (critic -1) or critic `critic`'s term.
// Per cycle, the lowest value over the admissible samples is blue, the middle
// magenta, the highest yellow (the more it raises the total, the yellower);
// all equal: magenta.
std_msgs::ColorRGBA colour_scale(double t);

// The rollout fan of one cycle, replacing the previous one's: the admissible
// rollouts as one line list coloured by `critic` (-1: the total) as
// colour_scale says, in sample order; the rejected ones in faint grey; the
// chosen one in green. Nothing but the clearing when the planner did not run.
visualization_msgs::MarkerArray rollout_markers(const fgdwa::CycleRecord& record, const fgdwa::PlanResult& plan,
                                                const std::vector<fgdwa::Trajectory>& rollouts, int critic,
                                                const std_msgs::Header& header);

// A map as costmaps publish it: occupied 100, free 0, and -1 where `unknown`
// (one entry per cell, or empty when every cell is known) is set.
nav_msgs::OccupancyGrid to_occupancy_grid(const fgdwa::OccupancyGrid& grid, const std::vector<std::uint8_t>& unknown,
                                          const std_msgs::Header& header);

// The footprint in the base frame; a circle as a polygon of `circle_vertices` vertices.
geometry_msgs::PolygonStamped to_polygon(const fgdwa::Footprint& footprint, const std_msgs::Header& header,
                                         int circle_vertices = 32);

}  // namespace fgdwa_ros
