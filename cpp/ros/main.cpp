// fgdwa_node: fgdwa's Navigator as a ROS 1 local planner behind move_base's
// action interface (docs/ros.md).
#include <ros/ros.h>

#include "fgdwa/error.hpp"
#include "navigator_node.hpp"
#include "node_params.hpp"

int main(int argc, char** argv) {
  ros::init(argc, argv, "fgdwa_node");
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
  ros::spin();
  return 0;
}
