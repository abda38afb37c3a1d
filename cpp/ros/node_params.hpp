#pragma once
// What fgdwa_node runs with, read once at start-up from its private namespace
// on the parameter server: the node's own settings (topics, frames, timeouts,
// map) at the top level, and fgdwa's parameter structs under the names of
// their C++ fields (~limits/v_max, ~planner/window/n_v, ~navigator/occupancy/hit,
// ~detect_window/radius, ~lidar/noise_std). ~robot and ~preset pick the
// starting values; every parameter given replaces one of them. Everything is
// checked by the structs' own validate() before the node starts.
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "fgdwa/navigator.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa_ros {

struct NodeParams {
  std::string preset = "fgdwa";             // planner preset, fgdwa::preset_names()
  std::string robot = "jackal";             // robot preset (limits, footprint), fgdwa::robot_names()
  std::string scan_topic = "front/scan";    // sensor_msgs/LaserScan
  std::string odom_topic = "odometry/filtered";  // nav_msgs/Odometry
  std::string cmd_vel_topic = "cmd_vel";    // geometry_msgs/Twist out
  std::string map_topic = "map";            // nav_msgs/OccupancyGrid, mapping "known" only
  std::string global_frame = "odom";        // the frame the robot plans in; goals are transformed into it
  std::string base_frame = "base_link";     // the robot's body frame (odometry's child frame)
  std::string map_frame = "map";            // the frame of the navigator's map, above global_frame
  // The navigator's correction of the odometry (scan matching) as the TF
  // map_frame -> global_frame, as a localiser publishes map -> odom; off when
  // a localiser of your own publishes it. The odometry is never changed.
  bool publish_map_odom_tf = true;
  std::string mapping = "scan";             // "scan": the map is built from the scans; "known": map_topic's grid
  double map_resolution = 0.05;             // m, cells of the map built from scans
  double map_margin = 5.0;                  // m kept around the robot and the goal by the map built from scans
  int occupied_threshold = 65;              // known map: a cell of at least this occupancy (0-100) is an obstacle
  double scan_timeout = 0.5;                // s without a new scan before the robot stops and waits for it
  double odom_timeout = 0.5;                // s without new odometry, the same
  double transform_timeout = 0.1;           // s waited for a transform (goal, laser) in one cycle
  // s a goal is kept while the robot cannot drive to it (a silent sensor, a
  // missing transform, no path, recoveries exhausted): it stands, says why,
  // and goes on when the trouble ends; longer than the BARN challenge's 100 s.
  double patience = 120.0;
  std::string rollout_colour_by = "total";  // ~rollouts' colour: "total" or one of ~planner/critics' names
  void validate() const;
};

struct NodeConfig {
  NodeParams node;
  fgdwa::RobotLimits limits;
  fgdwa::Footprint footprint = fgdwa::Footprint::circle(0.25);
  fgdwa::PlannerParams planner;
  bool fuzzy = false;  // the preset's weights come from the fuzzy controller each cycle
  fgdwa::NavigatorParams navigator;
  double lidar_noise_std = 0.03;  // m, the lidar's range noise (~lidar/noise_std; a UST-10's is about 0.03)
  fgdwa::DetectWindowParams detect_window;

  // Every setting as one JSON object (names as on the parameter server), so a
  // recording of the node can be replayed with the same settings.
  std::string to_json() const;
};

// Reads and checks the configuration under `private_nh` (the node's ~).
// Throws fgdwa::Error naming the parameter and its value: a wrong type, an
// unknown name (a typo would otherwise be ignored), a value validate() refuses.
NodeConfig read_config(const ros::NodeHandle& private_nh);

}  // namespace fgdwa_ros
