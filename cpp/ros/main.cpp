// fgdwa_node: fgdwa's Navigator as a ROS 1 local planner behind move_base's
// action interface (docs/ros.md).
#include <csignal>
#include <string>

#include <ros/ros.h>

#include "fgdwa/error.hpp"
#include "navigator_node.hpp"
#include "node_params.hpp"

namespace {

// The signal that asked the node to stop, 0 while it runs.
volatile std::sig_atomic_t stop_signal = 0;
void on_signal(int signal) { stop_signal = signal; }

}  // namespace

int main(int argc, char** argv) {
  // Our own SIGINT and SIGTERM handling: the robot is sent a stop before ROS shuts down.
  ros::init(argc, argv, "fgdwa_node", ros::init_options::NoSigintHandler);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  ros::NodeHandle nh, private_nh("~");
  fgdwa_ros::NodeConfig config;
  try {
    config = fgdwa_ros::read_config(private_nh);
  } catch (const fgdwa::Error& e) {
    ROS_FATAL("fgdwa_node: %s", e.what());
    return 2;
  }
  // With use_sim_time, time is 0 until the first /clock: every stamp and timeout
  // taken before it would be wrong, so the node starts once time runs.
  if (!ros::Time::waitForValid(ros::WallDuration(60.0))) {
    ROS_FATAL("fgdwa_node: use_sim_time is set but no /clock came in 60 s");
    return 3;
  }
  fgdwa_ros::NavigatorNode node(nh, private_nh, config);
  ros::AsyncSpinner spinner(1);
  spinner.start();
  while (ros::ok() && stop_signal == 0) ros::WallDuration(0.01).sleep();
  spinner.stop();
  if (stop_signal != 0) {
    node.shut_down(std::string("fgdwa_node shutting down (") + (stop_signal == SIGINT ? "SIGINT" : "SIGTERM") + ")");
    ros::WallDuration(0.2).sleep();  // the stop and the action's result on their way out
  }
  ros::shutdown();
  return 0;
}
