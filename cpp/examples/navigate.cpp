// Drives a simulated differential-drive robot to a goal with fgdwa::Navigator
// alone: no prior map (it is built from the scans), a global path planned and
// replanned on it, the fuzzy-weighted planner, and recovery if it stalls.
// The program plays the world: a lidar cast against the true rooms, the
// unicycle motion, and a collision check. Exits 0 when the goal is reached.
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

#include <fgdwa/navigator.hpp>
#include <fgdwa/perception.hpp>
#include <fgdwa/presets.hpp>

int main() {
  // Two 4 m x 6 m rooms joined by a door at the top of the wall between them.
  const int rows = 40, cols = 80;
  std::vector<std::uint8_t> cells(rows * cols, 0);
  for (int row = 0; row < 28; ++row) cells[row * cols + 40] = 1;
  for (int col = 0; col < cols; ++col) cells[col] = cells[(rows - 1) * cols + col] = 1;
  const fgdwa::OccupancyGrid truth(rows, cols, 0.1, fgdwa::Vec2(0.0, 0.0), cells);
  const auto truth_field = std::make_shared<const fgdwa::DistanceField>(truth);

  const fgdwa::PlannerPreset preset = fgdwa::planner_preset("fgdwa");
  const fgdwa::RobotLimits limits;  // 1.2 m/s, 1 rad/s
  const fgdwa::Footprint footprint = fgdwa::Footprint::circle(0.25);
  const fgdwa::LidarParams lidar;   // 270 degrees, 541 beams, 10 m
  fgdwa::Navigator navigator(limits, footprint, preset.params, truth, fgdwa::MapMode::Scan, lidar,
                             preset.weight_policy());
  navigator.set_goal(fgdwa::Vec2(7.0, 1.0));

  const fgdwa::LaserScanner scanner(lidar, truth_field);
  const fgdwa::FieldClearance world(truth_field);
  std::mt19937_64 rng(1);
  fgdwa::Scan scan;
  fgdwa::RobotState state;
  state.pose = fgdwa::Pose2{1.0, 1.0, 0.0};
  const double dt = preset.params.dt;
  for (int cycle = 0; cycle < 600; ++cycle) {
    scanner.scan(state.pose, {}, 0.0, rng, scan);
    const fgdwa::CycleRecord& record = navigator.step(state, &scan, cycle * dt);
    if (cycle % 10 == 0 || record.mode != fgdwa::NavigatorMode::Following)
      std::printf("t %5.2f s  pose (%.2f, %.2f, %+.2f)  v %+.2f  omega %+.2f  %-11s path v%d  I %.2f  beta %.2f\n",
                  record.time, state.pose.x, state.pose.y, state.pose.theta, record.command.v,
                  record.command.omega, fgdwa::to_string(record.mode), record.path_version, record.control.density,
                  record.control.beta);
    if (record.mode == fgdwa::NavigatorMode::GoalReached) {
      std::printf("goal reached at t = %.2f s, %d global paths\n", record.time, record.path_version);
      return 0;
    }
    if (record.mode == fgdwa::NavigatorMode::Failed) {
      std::printf("navigator failed: %s\n", fgdwa::to_string(record.failure));
      return 1;
    }
    state.pose = fgdwa::unicycle_step(state.pose, record.command, dt);
    state.twist = record.command;
    if (world.clearance(footprint, state.pose, 0.0) <= 0.0) {
      std::printf("collision at (%.2f, %.2f)\n", state.pose.x, state.pose.y);
      return 1;
    }
  }
  std::printf("goal not reached in time\n");
  return 1;
}
