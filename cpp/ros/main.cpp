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
  fgdwa_ros::NavigatorNode node(nh, private_nh, config);
  ros::spin();
  return 0;
}
