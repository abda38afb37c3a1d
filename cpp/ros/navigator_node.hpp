#pragma once
// fgdwa_node: one fgdwa::Navigator driven by ROS topics (docs/ros.md).
//
// Lifecycle: constructed once with its checked configuration; goals come
// through the move_base action or move_base_simple/goal. A goal's first
// control cycle builds the Navigator when there is none yet (it needs the
// first scan for the lidar's beams and, mapping "scan", the robot's position
// and the goal for the map's extent); later goals keep it and the map it has
// built, unless the goal lies off that map. Every control period (~planner/dt)
// while a goal is active: the newest scan and odometry -> Navigator::step ->
// cmd_vel, feedback, plans, markers, diagnostics. What keeps the robot from
// driving (a silent or broken sensor, a missing transform, a navigator that
// failed) makes it stand and wait, saying why, and it goes on when the
// trouble ends; a failed navigator is given its goal again (the navigator
// plans for it at most every ~navigator/retry_period). A goal ends succeeded
// (GoalReached), aborted with the reason (a trouble that outlasted ~patience,
// a goal that can never be driven to), or preempted; the robot is sent a stop
// each time.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <actionlib/server/simple_action_server.h>
#include <geometry_msgs/PoseStamped.h>
#include <move_base_msgs/MoveBaseAction.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <ros/ros.h>
#include <sensor_msgs/LaserScan.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include "fgdwa/navigator.hpp"
#include "node_params.hpp"

namespace fgdwa_ros {

class NavigatorNode {
 public:
  NavigatorNode(ros::NodeHandle nh, ros::NodeHandle private_nh, NodeConfig config);
  // The node is going down (SIGINT, SIGTERM): the robot is sent a stop and an
  // active goal is aborted with `reason`, so that no client waits on it.
  void shut_down(const std::string& reason);

 private:
  enum class Outcome { Succeeded, Aborted, Preempted };

  void on_scan(const sensor_msgs::LaserScan::ConstPtr& msg);
  void on_odom(const nav_msgs::Odometry::ConstPtr& msg);
  void on_map(const nav_msgs::OccupancyGrid::ConstPtr& msg);
  void on_action_goal();
  void on_action_preempt();
  void on_simple_goal(const geometry_msgs::PoseStamped::ConstPtr& msg);
  void on_timer(const ros::TimerEvent& event);

  // The goal in the global frame, or the reason it cannot be one.
  std::optional<fgdwa::Vec2> goal_in_global(const geometry_msgs::PoseStamped& goal, std::string& reason);
  void start(const fgdwa::Vec2& goal);
  // Ends the active goal: a stop on cmd_vel, the action's final state, a log line with the cycle times.
  void finish(Outcome outcome, const std::string& reason);
  // What keeps the robot from driving this cycle; `final` when waiting cannot help.
  struct Trouble {
    std::string reason;
    bool final = false;
  };
  // The cycle's control work: what keeps the robot from driving, or none.
  std::optional<Trouble> cycle(const ros::Time& now);
  // The robot stands for `reason`: said on ~events and the log when it begins
  // or changes, every cycle in the diagnostics; the goal aborts past ~patience.
  void wait(const ros::Time& now, const std::string& reason);
  // Builds the Navigator if there is none or the goal lies off its map; the trouble when it cannot.
  std::optional<Trouble> ensure_navigator(const fgdwa::Pose2& robot, const sensor_msgs::LaserScan& scan);
  // Where the laser was when `scan` was taken, in the global frame.
  std::optional<fgdwa::Pose2> laser_pose(const sensor_msgs::LaserScan& scan, std::string& reason);
  std::optional<fgdwa::RobotState> robot_state(std::string& reason);
  void publish_stop();
  // The scan matcher's correction as the TF ~map_frame -> ~global_frame (~publish_map_odom_tf).
  void publish_map_to_odom(const fgdwa::CycleRecord& record, const ros::Time& stamp);
  // cmd_vel is out already; the plans, markers and the cycle's diagnostics (`scan`: the one stepped on).
  void publish_cycle(const fgdwa::CycleRecord& record, const ros::Time& now, double step_ms, double cycle_ms,
                     const fgdwa::Scan& scan, const ros::Time& scan_stamp);
  void publish_event(const std::string& json);
  // The navigator's map on ~map when someone listens and its cells changed, at most map_rate a second.
  void publish_map(const ros::Time& now);

  ros::NodeHandle nh_, private_nh_;
  NodeConfig config_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  actionlib::SimpleActionServer<move_base_msgs::MoveBaseAction> action_;
  ros::Subscriber scan_sub_, odom_sub_, map_sub_, simple_goal_sub_;
  ros::Publisher cmd_pub_, global_plan_pub_, local_plan_pub_, markers_pub_, diagnostics_pub_, events_pub_;
  ros::Publisher evaluation_pub_, map_pub_, footprint_pub_;
  ros::Timer timer_;

  sensor_msgs::LaserScan::ConstPtr scan_;
  ros::Time scan_received_;
  nav_msgs::Odometry::ConstPtr odom_;
  ros::Time odom_received_;
  nav_msgs::OccupancyGrid::ConstPtr map_;
  bool map_changed_ = false;  // a map came after the navigator was built on the previous one

  std::unique_ptr<fgdwa::Navigator> navigator_;
  int navigators_ = 0;  // built so far; the cycle's diagnostics name theirs, and so does its event
  int goals_ = 0;       // goals started so far (each one set anew, even to the same point)
  int goal_sets_ = 0;   // set_goal() calls on navigators so far: goals and the retries after a failure
  long cycles_ = 0;     // cycles stepped so far, numbered in the diagnostics so that a gap in a recording shows
  fgdwa::Pose2 mount_;  // the laser in the base frame, looked up with the navigator
  std::string laser_frame_;
  bool active_ = false;
  bool waiting_ = false;       // the robot stands for wait_reason_, since waiting_since_
  ros::Time waiting_since_;
  std::string wait_reason_;
  bool from_action_ = false;
  fgdwa::Vec2 goal_ = fgdwa::Vec2::Zero();
  ros::Time goal_received_;
  int path_version_ = -1;
  int colour_critic_ = -1;  // ~rollout_colour_by as an index into the planner's critics, -1 for the total
  int map_version_ = -1;    // the world model's version last published on ~map (-1: none of this navigator's)
  ros::Time map_published_;
  ros::Time start_time_;
  std::vector<double> cycle_ms_;  // this goal's cycles
  std::vector<double> all_cycle_ms_;
};

}  // namespace fgdwa_ros
