#include "navigator_node.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PolygonStamped.h>
#include <geometry_msgs/Twist.h>
#include <nav_msgs/Path.h>
#include <std_msgs/String.h>
#include <tf2_geometry_msgs/tf2_geometry_msgs.h>
#include <visualization_msgs/MarkerArray.h>

#include "fgdwa/error.hpp"
#include "fgdwa/presets.hpp"
#include "json.hpp"
#include "ros_convert.hpp"

namespace fgdwa_ros {

namespace {

std::string number(double value) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

std::string seconds(const ros::Time& t) { return number(t.toSec()); }

void add_value(diagnostic_msgs::DiagnosticStatus& status, const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue kv;
  kv.key = key;
  kv.value = value;
  status.values.push_back(kv);
}

// Median and 95th percentile of `values`, "median X ms, p95 Y ms over N cycles".
std::string cycle_summary(std::vector<double> values) {
  if (values.empty()) return "no cycles";
  std::sort(values.begin(), values.end());
  auto at = [&](double q) { return values[static_cast<std::size_t>(std::floor(q * (values.size() - 1) + 0.5))]; };
  char buffer[120];
  std::snprintf(buffer, sizeof buffer, "median %.3f ms, p95 %.3f ms over %zu cycles", at(0.5), at(0.95),
                values.size());
  return buffer;
}

}  // namespace

NavigatorNode::NavigatorNode(ros::NodeHandle nh, ros::NodeHandle private_nh, NodeConfig config)
    : nh_(nh),
      private_nh_(private_nh),
      config_(std::move(config)),
      tf_listener_(tf_buffer_, nh_),
      action_(nh_, "move_base", false),
      start_time_(ros::Time::now()) {
  const NodeParams& p = config_.node;
  cmd_pub_ = nh_.advertise<geometry_msgs::Twist>(p.cmd_vel_topic, 1);
  global_plan_pub_ = private_nh_.advertise<nav_msgs::Path>("global_plan", 1, true);
  local_plan_pub_ = private_nh_.advertise<nav_msgs::Path>("local_plan", 1);
  markers_pub_ = private_nh_.advertise<visualization_msgs::MarkerArray>("rollouts", 1);
  diagnostics_pub_ = nh_.advertise<diagnostic_msgs::DiagnosticArray>("diagnostics", 10);
  events_pub_ = private_nh_.advertise<std_msgs::String>("events", 10, true);
  evaluation_pub_ = private_nh_.advertise<fgdwa_ros::LocalPlanEvaluation>("evaluation", 1);
  map_pub_ = private_nh_.advertise<nav_msgs::OccupancyGrid>("map", 1, true);
  footprint_pub_ = private_nh_.advertise<geometry_msgs::PolygonStamped>("footprint", 1, true);
  {
    const auto& critics = config_.planner.critics;
    for (std::size_t i = 0; i < critics.size(); ++i)
      if (critics[i].name == p.rollout_colour_by) colour_critic_ = static_cast<int>(i);
    // Stamp 0: rviz places it with the newest transform of the base, whenever it arrives.
    std_msgs::Header header;
    header.frame_id = p.base_frame;
    footprint_pub_.publish(to_polygon(config_.footprint, header));
  }
  scan_sub_ = nh_.subscribe(p.scan_topic, 1, &NavigatorNode::on_scan, this);
  odom_sub_ = nh_.subscribe(p.odom_topic, 1, &NavigatorNode::on_odom, this);
  if (p.mapping == "known") map_sub_ = nh_.subscribe(p.map_topic, 1, &NavigatorNode::on_map, this);
  simple_goal_sub_ = nh_.subscribe("move_base_simple/goal", 1, &NavigatorNode::on_simple_goal, this);
  action_.registerGoalCallback([this] { on_action_goal(); });
  action_.registerPreemptCallback([this] { on_action_preempt(); });
  action_.start();
  timer_ = nh_.createTimer(ros::Duration(config_.planner.dt), &NavigatorNode::on_timer, this);
  publish_event("{\"event\": \"config\", \"time\": " + number(0.0) + ", \"config\": " + config_.to_json() + "}");
  // A node that starts (or restarts after a crash) holds the robot still until a goal comes.
  publish_stop();
  ROS_INFO("fgdwa_node: preset %s, robot %s, mapping %s, %g Hz; scan %s, odometry %s, goals on move_base "
           "(frame %s)", p.preset.c_str(), p.robot.c_str(), p.mapping.c_str(), 1.0 / config_.planner.dt,
           p.scan_topic.c_str(), p.odom_topic.c_str(), p.global_frame.c_str());
}

void NavigatorNode::on_scan(const sensor_msgs::LaserScan::ConstPtr& msg) {
  scan_ = msg;
  scan_received_ = ros::Time::now();
}

void NavigatorNode::on_odom(const nav_msgs::Odometry::ConstPtr& msg) {
  odom_ = msg;
  odom_received_ = ros::Time::now();
}

void NavigatorNode::on_map(const nav_msgs::OccupancyGrid::ConstPtr& msg) {
  map_ = msg;
  map_changed_ = navigator_ != nullptr;
}

std::optional<fgdwa::Vec2> NavigatorNode::goal_in_global(const geometry_msgs::PoseStamped& goal,
                                                         std::string& reason) {
  const auto& position = goal.pose.position;
  if (!std::isfinite(position.x) || !std::isfinite(position.y)) {
    reason = "goal position (" + number(position.x) + ", " + number(position.y) + ") is not finite";
    return std::nullopt;
  }
  const std::string& global = config_.node.global_frame;
  const std::string frame = goal.header.frame_id.empty() ? global : goal.header.frame_id;
  if (frame == global) return fgdwa::Vec2(position.x, position.y);
  std::string error;
  // The goal's own stamp, or the newest transform for an unstamped goal.
  if (!tf_buffer_.canTransform(global, frame, goal.header.stamp,
                               ros::Duration(config_.node.transform_timeout), &error)) {
    reason = "goal in frame '" + frame + "': no transform to '" + global + "' (" + error + ")";
    return std::nullopt;
  }
  geometry_msgs::PoseStamped out;
  geometry_msgs::PoseStamped in = goal;
  in.header.frame_id = frame;
  tf_buffer_.transform(in, out, global);
  return fgdwa::Vec2(out.pose.position.x, out.pose.position.y);
}

void NavigatorNode::on_action_goal() {
  // A new goal preempts the one still active, as move_base does.
  if (active_) finish(Outcome::Preempted, "replaced by a new goal on move_base");
  const auto goal = action_.acceptNewGoal();
  if (action_.isPreemptRequested()) {
    // Cancelled before it was accepted.
    action_.setPreempted(move_base_msgs::MoveBaseResult(), "cancelled before it started");
    return;
  }
  std::string reason;
  const auto position = goal_in_global(goal->target_pose, reason);
  if (!position) {
    ROS_WARN("fgdwa_node: goal refused: %s", reason.c_str());
    action_.setAborted(move_base_msgs::MoveBaseResult(), reason);
    publish_event("{\"event\": \"end\", \"outcome\": \"aborted\", \"reason\": \"goal refused\"}");
    return;
  }
  from_action_ = true;
  start(*position);
}

void NavigatorNode::on_action_preempt() {
  if (!action_.isActive()) return;
  if (active_ && from_action_) {
    finish(Outcome::Preempted, "cancelled by the action client");
  } else {
    action_.setPreempted(move_base_msgs::MoveBaseResult(), "cancelled by the action client");
  }
}

void NavigatorNode::on_simple_goal(const geometry_msgs::PoseStamped::ConstPtr& msg) {
  std::string reason;
  const auto position = goal_in_global(*msg, reason);
  if (!position) {
    ROS_WARN("fgdwa_node: goal on move_base_simple/goal refused: %s", reason.c_str());
    return;
  }
  if (active_) finish(Outcome::Preempted, "replaced by a goal on move_base_simple/goal");
  from_action_ = false;
  start(*position);
}

void NavigatorNode::start(const fgdwa::Vec2& goal) {
  goal_ = goal;
  ++goals_;
  goal_received_ = ros::Time::now();
  active_ = true;
  waiting_ = false;
  cycle_ms_.clear();
  if (navigator_) {
    try {
      navigator_->set_goal(goal);
      ++goal_sets_;
    } catch (const fgdwa::Error&) {
      navigator_.reset();  // off its map: the first cycle builds a navigator on a map holding it
    }
  }
  publish_event("{\"event\": \"goal\", \"time\": " + number((goal_received_ - start_time_).toSec()) +
                ", \"goal\": [" + number(goal.x()) + ", " + number(goal.y()) + "]}");
  ROS_INFO("fgdwa_node: goal (%.3f, %.3f) in %s", goal.x(), goal.y(), config_.node.global_frame.c_str());
}

void NavigatorNode::finish(Outcome outcome, const std::string& reason) {
  publish_stop();
  active_ = false;
  waiting_ = false;
  move_base_msgs::MoveBaseResult result;
  const char* word = outcome == Outcome::Succeeded ? "succeeded" : outcome == Outcome::Aborted ? "aborted"
                                                                                                 : "preempted";
  if (from_action_ && action_.isActive()) {
    if (outcome == Outcome::Succeeded) action_.setSucceeded(result, reason);
    if (outcome == Outcome::Aborted) action_.setAborted(result, reason);
    if (outcome == Outcome::Preempted) action_.setPreempted(result, reason);
  }
  const ros::Time now = ros::Time::now();
  publish_event("{\"event\": \"end\", \"time\": " + number((now - start_time_).toSec()) + ", \"stamp\": " +
                seconds(now) + ", \"outcome\": \"" + word + "\", \"reason\": " + json_text(reason) + "}");
  const std::string cycles = cycle_summary(cycle_ms_);
  if (outcome == Outcome::Aborted)
    ROS_WARN("fgdwa_node: goal aborted: %s (cycle time %s)", reason.c_str(), cycles.c_str());
  else
    ROS_INFO("fgdwa_node: goal %s: %s (cycle time %s)", word, reason.c_str(), cycles.c_str());
}

void NavigatorNode::shut_down(const std::string& reason) {
  timer_.stop();
  if (active_) {
    finish(Outcome::Aborted, reason);
  } else {
    publish_stop();
  }
  publish_event("{\"event\": \"shutdown\", \"time\": " + number((ros::Time::now() - start_time_).toSec()) +
                ", \"reason\": " + json_text(reason) + "}");
  ROS_INFO("fgdwa_node: %s; robot stopped", reason.c_str());
}

void NavigatorNode::on_timer(const ros::TimerEvent&) {
  if (!active_) return;
  const ros::Time now = ros::Time::now();
  std::optional<Trouble> trouble;
  try {
    trouble = cycle(now);
  } catch (const fgdwa::Error& e) {
    // Input the navigator refused (a scan of another size, a state that is not finite): it may pass.
    trouble = Trouble{e.what()};
  }
  if (!active_) return;  // the goal was reached this cycle
  if (!trouble) {
    if (waiting_) {
      waiting_ = false;
      const double waited = (now - waiting_since_).toSec();
      publish_event("{\"event\": \"resume\", \"time\": " + number((now - start_time_).toSec()) +
                    ", \"waited\": " + number(waited) + ", \"reason\": " + json_text(wait_reason_) + "}");
      ROS_INFO("fgdwa_node: going on after %.2f s of waiting (%s)", waited, wait_reason_.c_str());
    }
    return;
  }
  if (trouble->final) {
    finish(Outcome::Aborted, trouble->reason);
  } else {
    wait(now, trouble->reason);
  }
}

void NavigatorNode::wait(const ros::Time& now, const std::string& reason) {
  publish_stop();
  const bool began = !waiting_;
  if (began) {
    waiting_ = true;
    waiting_since_ = now;
  }
  const double waited = (now - waiting_since_).toSec();
  const double patience = config_.node.patience;
  if (waited > patience) {
    char buffer[120];
    std::snprintf(buffer, sizeof buffer, " for %.1f s (patience %.1f s)", waited, patience);
    finish(Outcome::Aborted, reason + buffer);
    return;
  }
  // The reason's words without its numbers (an age that grows every cycle) tell a new trouble from the same one.
  auto words = [](const std::string& text) { return text.substr(0, text.find_first_of("0123456789")); };
  if (began || words(reason) != words(wait_reason_)) {
    publish_event("{\"event\": \"wait\", \"time\": " + number((now - start_time_).toSec()) + ", \"stamp\": " +
                  seconds(now) + ", \"reason\": " +
                  json_text(reason) + ", \"patience\": " + number(patience) + "}");
    ROS_WARN("fgdwa_node: robot stopped, waiting: %s (the goal aborts after %.0f s of this)", reason.c_str(), patience);
  }
  wait_reason_ = reason;
  if (from_action_ && odom_) {
    move_base_msgs::MoveBaseFeedback feedback;
    feedback.base_position.header = odom_->header;
    feedback.base_position.pose = odom_->pose.pose;
    action_.publishFeedback(feedback);
  }
  diagnostic_msgs::DiagnosticArray array;
  array.header.stamp = now;
  array.header.frame_id = config_.node.global_frame;
  diagnostic_msgs::DiagnosticStatus status;
  status.name = "fgdwa_node: goal";
  status.hardware_id = ros::this_node::getName();
  status.level = diagnostic_msgs::DiagnosticStatus::WARN;
  status.message = "waiting: " + reason;
  add_value(status, "reason", reason);
  add_value(status, "waited", number(waited));
  add_value(status, "patience", number(patience));
  add_value(status, "goal", number(goal_.x()) + " " + number(goal_.y()));
  add_value(status, "goal_id", std::to_string(goals_));
  array.status.push_back(status);
  diagnostics_pub_.publish(array);
}

std::optional<fgdwa::RobotState> NavigatorNode::robot_state(std::string& reason) {
  geometry_msgs::PoseStamped pose;
  pose.header = odom_->header;
  pose.pose = odom_->pose.pose;
  const std::string& global = config_.node.global_frame;
  if (!pose.header.frame_id.empty() && pose.header.frame_id != global) {
    std::string error;
    if (!tf_buffer_.canTransform(global, pose.header.frame_id, pose.header.stamp,
                                 ros::Duration(config_.node.transform_timeout), &error)) {
      reason = "odometry in frame '" + pose.header.frame_id + "': no transform to '" + global + "' (" + error + ")";
      return std::nullopt;
    }
    geometry_msgs::PoseStamped out;
    tf_buffer_.transform(pose, out, global);
    pose = out;
  }
  fgdwa::RobotState state;
  state.pose = pose_of(pose.pose);
  state.twist = {odom_->twist.twist.linear.x, odom_->twist.twist.angular.z};
  return state;
}

std::optional<fgdwa::Pose2> NavigatorNode::laser_pose(const sensor_msgs::LaserScan& scan, std::string& reason) {
  const std::string& global = config_.node.global_frame;
  const std::string& base = config_.node.base_frame;
  const ros::Duration wait(config_.node.transform_timeout);
  std::string error;
  // The base where it was when the scan was taken; the newest transform if that is not known.
  ros::Time stamp = scan.header.stamp;
  if (!tf_buffer_.canTransform(global, base, stamp, wait, &error)) {
    stamp = ros::Time(0);
    if (!tf_buffer_.canTransform(global, base, stamp, ros::Duration(0), &error)) {
      reason = "no transform from '" + base + "' to '" + global + "' for the scan (" + error + ")";
      return std::nullopt;
    }
  }
  const auto base_tf = tf_buffer_.lookupTransform(global, base, stamp);
  const auto& t = base_tf.transform;
  const fgdwa::Pose2 base_pose{t.translation.x, t.translation.y, yaw_of(t.rotation)};
  return compose(base_pose, mount_);
}

std::optional<NavigatorNode::Trouble> NavigatorNode::ensure_navigator(const fgdwa::Pose2& robot,
                                                           const sensor_msgs::LaserScan& scan) {
  const NodeParams& p = config_.node;
  if (navigator_ && !map_changed_ && scan.header.frame_id == laser_frame_) return std::nullopt;
  // The laser's mounting on the base: static, looked up once per navigator.
  std::string error;
  if (!tf_buffer_.canTransform(p.base_frame, scan.header.frame_id, ros::Time(0),
                               ros::Duration(config_.node.transform_timeout), &error))
    return Trouble{"scan in frame '" + scan.header.frame_id + "': no transform to '" + p.base_frame + "' (" + error + ")"};
  const auto mount = tf_buffer_.lookupTransform(p.base_frame, scan.header.frame_id, ros::Time(0)).transform;
  const auto& q = mount.rotation;
  if (1.0 - 2.0 * (q.x * q.x + q.y * q.y) < 0.0)
    return Trouble{"scan in frame '" + scan.header.frame_id + "': the laser is mounted upside down; fgdwa_node "
                   "needs it upright (z up)", true};
  mount_ = {mount.translation.x, mount.translation.y, yaw_of(q)};
  laser_frame_ = scan.header.frame_id;

  const int beams = static_cast<int>(scan.ranges.size());
  if (beams < 2)
    return Trouble{"scan on '" + p.scan_topic + "' has " + std::to_string(beams) + " ranges: fgdwa needs 2 or more"};
  fgdwa::LidarParams lidar;
  lidar.beams = beams;
  lidar.fov = std::abs(scan.angle_increment) * (beams - 1);
  lidar.max_range = scan.range_max;
  lidar.noise_std = config_.lidar_noise_std;
  if (!(scan.angle_increment > 0.0f) || !(lidar.max_range > 0.0) || !std::isfinite(lidar.max_range))
    return Trouble{"scan on '" + p.scan_topic + "': angle_increment " + number(scan.angle_increment) + ", range_max " +
                   number(scan.range_max) + ": fgdwa needs both > 0 (beams counter-clockwise)"};

  std::unique_ptr<fgdwa::OccupancyGrid> layout;
  fgdwa::MapMode mode = fgdwa::MapMode::Scan;
  if (p.mapping == "known") {
    if (!map_) return std::nullopt;  // caller waits for the map
    if (map_->header.frame_id != p.global_frame && !map_->header.frame_id.empty())
      return Trouble{"map in frame '" + map_->header.frame_id + "': mapping known needs it in global_frame '" +
                     p.global_frame + "'"};
    layout = std::make_unique<fgdwa::OccupancyGrid>(to_grid(*map_, p.occupied_threshold));
    mode = fgdwa::MapMode::Known;
  } else {
    const double res = p.map_resolution, margin = p.map_margin;
    const double x0 = std::floor((std::min(robot.x, goal_.x()) - margin) / res) * res;
    const double y0 = std::floor((std::min(robot.y, goal_.y()) - margin) / res) * res;
    const int cols = static_cast<int>(std::ceil((std::max(robot.x, goal_.x()) + margin - x0) / res));
    const int rows = static_cast<int>(std::ceil((std::max(robot.y, goal_.y()) + margin - y0) / res));
    layout = std::make_unique<fgdwa::OccupancyGrid>(rows, cols, res, fgdwa::Vec2(x0, y0),
                                                    std::vector<std::uint8_t>(static_cast<std::size_t>(rows) * cols, 0));
  }
  const fgdwa::PlannerPreset preset = fgdwa::planner_preset(p.preset);
  std::shared_ptr<const fgdwa::WeightPolicy> policy;
  if (config_.fuzzy) policy = std::make_shared<fgdwa::FuzzyWeights>();
  navigator_ = std::make_unique<fgdwa::Navigator>(config_.limits, config_.footprint, config_.planner, *layout, mode,
                                                  lidar, policy, config_.navigator, std::nullopt,
                                                  fgdwa::kDefaultPassingFactors, config_.detect_window);
  map_changed_ = false;
  path_version_ = -1;
  map_version_ = -1;
  ++navigators_;
  try {
    navigator_->set_goal(goal_);
    ++goal_sets_;
  } catch (const fgdwa::Error& e) {
    navigator_.reset();
    return Trouble{std::string("goal on the known map: ") + e.what(), true};  // the map given holds no such goal
  }
  std::ostringstream event;
  event << "{\"event\": \"navigator\", \"id\": " << navigators_ << ", \"time\": " << number((ros::Time::now() - start_time_).toSec())
        << ", \"mapping\": \"" << p.mapping << "\", \"layout\": {\"origin\": [" << number(layout->origin().x()) << ", "
        << number(layout->origin().y()) << "], \"rows\": " << layout->rows() << ", \"cols\": " << layout->cols()
        << ", \"resolution\": " << number(layout->resolution()) << "}, \"lidar\": {\"beams\": " << beams
        << ", \"max_range\": " << number(lidar.max_range) << ", \"noise_std\": " << number(lidar.noise_std)
        << "}, \"laser_frame\": \"" << laser_frame_ << "\", \"mount\": [" << number(mount_.x) << ", "
        << number(mount_.y) << ", " << number(mount_.theta) << "], \"goal\": [" << number(goal_.x()) << ", "
        << number(goal_.y()) << "], \"config\": " << config_.to_json() << "}";
  publish_event(event.str());
  ROS_INFO("fgdwa_node: navigator on a %d x %d map of %.3f m cells (%s), lidar %d beams", layout->rows(),
           layout->cols(), layout->resolution(), p.mapping.c_str(), beams);
  return std::nullopt;
}

std::optional<NavigatorNode::Trouble> NavigatorNode::cycle(const ros::Time& now) {
  const auto tic = std::chrono::steady_clock::now();
  const NodeParams& p = config_.node;
  const double since_goal = (now - goal_received_).toSec();
  // Inputs first: a sensor that is missing or has gone silent stops the robot.
  auto silent = [&](const char* what, const std::string& topic, const ros::Time& received, double timeout,
                    bool present) -> std::optional<std::string> {
    const double age = present ? (now - received).toSec() : since_goal;
    if (age <= timeout) return std::nullopt;
    char buffer[200];
    std::snprintf(buffer, sizeof buffer, "no %s on '%s' for %.2f s (%s_timeout %.2f s)", what,
                  topic.c_str(), age, what, timeout);
    return std::string(buffer);
  };
  if (auto reason = silent("odom", p.odom_topic, odom_received_, p.odom_timeout, odom_ != nullptr)) return Trouble{*reason};
  if (auto reason = silent("scan", p.scan_topic, scan_received_, p.scan_timeout, scan_ != nullptr)) return Trouble{*reason};
  if (!odom_ || !scan_) {
    publish_stop();
    return std::nullopt;  // the first messages are still to come
  }
  const sensor_msgs::LaserScan::ConstPtr scan = scan_;
  if (scan->ranges.empty()) return Trouble{"scan on '" + p.scan_topic + "' has no ranges"};
  std::string reason;
  const auto state = robot_state(reason);
  if (!state) return Trouble{reason};
  if (auto problem = ensure_navigator(state->pose, *scan)) return problem;
  if (!navigator_) {
    if (since_goal > p.odom_timeout + p.scan_timeout && !map_)
      return Trouble{"no map on '" + p.map_topic + "' (mapping known)"};
    publish_stop();
    return std::nullopt;
  }
  // A cycle that finds no new scan (the lidar slower than the control rate, or
  // late) steps on the last one again: the planner always sees the newest scan,
  // and the fuzzy weights cannot do without one.
  const auto pose = laser_pose(*scan, reason);
  if (!pose) return Trouble{reason};
  const fgdwa::Scan converted = to_scan(*scan, *pose);
  const double time = (now - start_time_).toSec();
  const auto step_tic = std::chrono::steady_clock::now();
  const fgdwa::CycleRecord& record = navigator_->step(*state, &converted, time);
  const double step_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - step_tic).count();

  geometry_msgs::Twist cmd;
  cmd.linear.x = record.command.v;
  cmd.angular.z = record.command.omega;
  cmd_pub_.publish(cmd);
  publish_map_to_odom(record, scan->header.stamp);
  if (from_action_) {
    move_base_msgs::MoveBaseFeedback feedback;
    feedback.base_position.header.frame_id = p.global_frame;
    feedback.base_position.header.stamp = odom_->header.stamp;
    feedback.base_position.pose = to_pose(state->pose);
    action_.publishFeedback(feedback);
  }
  const double cycle_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - tic).count();
  cycle_ms_.push_back(cycle_ms);
  all_cycle_ms_.push_back(cycle_ms);
  publish_cycle(record, now, step_ms, cycle_ms, converted, scan->header.stamp);
  if (record.mode == fgdwa::NavigatorMode::GoalReached) {
    finish(Outcome::Succeeded, "goal reached");
  } else if (record.mode == fgdwa::NavigatorMode::Failed) {
    // Tried again from the next cycle on, from here: a path may appear, a
    // recovery may get further (the navigator bounds how often it plans).
    navigator_->set_goal(goal_);
    ++goal_sets_;
    return Trouble{std::string("navigator failed: ") + fgdwa::to_string(record.failure)};
  }
  return std::nullopt;
}

void NavigatorNode::publish_stop() { cmd_pub_.publish(geometry_msgs::Twist()); }

void NavigatorNode::publish_map_to_odom(const fgdwa::CycleRecord& record, const ros::Time& stamp) {
  if (!config_.node.publish_map_odom_tf || !config_.navigator.scan_match.enabled) return;
  geometry_msgs::TransformStamped tf;
  tf.header.stamp = stamp;
  tf.header.frame_id = config_.node.map_frame;
  tf.child_frame_id = config_.node.global_frame;
  const geometry_msgs::Pose pose = to_pose(record.map_to_odom);
  tf.transform.translation.x = pose.position.x;
  tf.transform.translation.y = pose.position.y;
  tf.transform.rotation = pose.orientation;
  tf_broadcaster_.sendTransform(tf);
}

void NavigatorNode::publish_cycle(const fgdwa::CycleRecord& record, const ros::Time& now, double step_ms,
                                  double cycle_ms, const fgdwa::Scan& scan, const ros::Time& scan_stamp) {
  std_msgs::Header header;
  header.stamp = now;
  header.frame_id = config_.node.global_frame;
  if (record.path && navigator_->path_version() != path_version_) {
    global_plan_pub_.publish(to_path(*record.path, header));
    path_version_ = navigator_->path_version();
  }
  if (local_plan_pub_.getNumSubscribers() > 0) local_plan_pub_.publish(to_path(record.control.choice.poses, header));
  const fgdwa::PlanResult& plan = navigator_->plan_result();
  const std::vector<fgdwa::Trajectory>& rollouts = navigator_->planner().rollouts();
  if (markers_pub_.getNumSubscribers() > 0)
    markers_pub_.publish(rollout_markers(record, plan, rollouts, colour_critic_, header));
  if (evaluation_pub_.getNumSubscribers() > 0) evaluation_pub_.publish(evaluation(record, plan, rollouts, header));
  publish_map(now);

  diagnostic_msgs::DiagnosticArray array;
  array.header = header;
  diagnostic_msgs::DiagnosticStatus status;
  status.name = "fgdwa_node: cycle";
  status.hardware_id = ros::this_node::getName();
  const bool recovering = record.mode == fgdwa::NavigatorMode::BackingUp ||
                          record.mode == fgdwa::NavigatorMode::Rotating;
  status.level = record.mode == fgdwa::NavigatorMode::Failed ? diagnostic_msgs::DiagnosticStatus::ERROR
                 : recovering                                 ? diagnostic_msgs::DiagnosticStatus::WARN
                                                              : diagnostic_msgs::DiagnosticStatus::OK;
  status.message = std::string(fgdwa::to_string(record.mode)) + " (" + fgdwa::to_string(record.control.status) + ")";
  auto add = [&](const std::string& key, const std::string& value) { add_value(status, key, value); };
  add("cycle", std::to_string(++cycles_));
  add("time", number(record.time));
  add("mode", fgdwa::to_string(record.mode));
  add("status", fgdwa::to_string(record.control.status));
  add("failure", fgdwa::to_string(record.failure));
  add("v", number(record.command.v));
  add("omega", number(record.command.omega));
  add("x", number(record.state.pose.x));
  add("y", number(record.state.pose.y));
  add("theta", number(record.state.pose.theta));
  add("map_to_odom", number(record.map_to_odom.x) + " " + number(record.map_to_odom.y) + " " +
                         number(record.map_to_odom.theta));
  add("scan_match", fgdwa::to_string(record.match.status));
  add("navigator", std::to_string(navigators_));
  add("goal", number(goal_.x()) + " " + number(goal_.y()));
  add("goal_id", std::to_string(goals_));
  add("goal_set", std::to_string(goal_sets_));
  add("odom_stamp", seconds(odom_->header.stamp));
  // Which inputs the cycle stepped on, so that fgdwa replay can step on the same ones.
  add("scan_stamp", seconds(scan_stamp));
  add("scan_pose", number(scan.pose.x) + " " + number(scan.pose.y) + " " + number(scan.pose.theta));
  add("density", json_number(record.control.density));
  add("deviation", json_number(record.control.deviation));
  add("beta", json_number(record.control.beta));
  add("delta", json_number(record.control.delta));
  add("admissible", std::to_string(record.control.reject_counts[0]));
  add("path_version", std::to_string(record.path_version));
  add("recoveries", std::to_string(record.recoveries));
  add("step_ms", number(step_ms));
  const fgdwa::StageTimes& t = record.times;
  add("stages_ms", number(1e3 * t.tracking) + " " + number(1e3 * t.map) + " " + number(1e3 * t.global) + " " +
                       number(1e3 * t.perception) + " " + number(1e3 * t.plan));
  add("cycle_ms", number(cycle_ms));
  array.status.push_back(status);
  diagnostics_pub_.publish(array);
}

void NavigatorNode::publish_map(const ros::Time& now) {
  constexpr double map_rate = 2.0;  // Hz at most: a 5 cm map of BARN's field is about 40 kB, a city block's megabytes
  const fgdwa::WorldModel& world = navigator_->world_model();
  if (map_pub_.getNumSubscribers() == 0 || world.version() == map_version_) return;
  if (map_version_ >= 0 && (now - map_published_).toSec() < 1.0 / map_rate) return;
  std_msgs::Header header;
  header.stamp = now;
  header.frame_id = config_.node.global_frame;
  map_pub_.publish(to_occupancy_grid(world.map(), world.unknown_cells(), header));
  map_version_ = world.version();
  map_published_ = now;
}

void NavigatorNode::publish_event(const std::string& json) {
  std_msgs::String msg;
  msg.data = json;
  events_pub_.publish(msg);
}

}  // namespace fgdwa_ros
