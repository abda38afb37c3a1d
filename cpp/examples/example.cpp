// Drives a simulated robot past a few boxes with the fgdwa local planner: a
// grid map, its distance field as the clearance source, and the planner's
// command applied with the same unicycle model each control cycle.
// Exits 0 when the goal is reached without touching an obstacle.
#include <cstdio>
#include <memory>
#include <vector>

#include <fgdwa/clearance.hpp>
#include <fgdwa/grid.hpp>
#include <fgdwa/planner.hpp>

int main() {
  // A 6 m x 4 m room at 0.1 m cells with three boxes between start and goal.
  const int rows = 40, cols = 60;
  std::vector<std::uint8_t> cells(rows * cols, 0);
  const auto box = [&](int row0, int col0, int height, int width) {
    for (int row = row0; row < row0 + height; ++row)
      for (int col = col0; col < col0 + width; ++col) cells[row * cols + col] = 1;
  };
  box(8, 18, 8, 5);
  box(22, 30, 10, 4);
  box(10, 40, 6, 6);
  const fgdwa::OccupancyGrid grid(rows, cols, 0.1, fgdwa::Vec2(0.0, 0.0), cells);
  const fgdwa::FieldClearance world(std::make_shared<const fgdwa::DistanceField>(grid));

  const fgdwa::RobotLimits limits;  // 1.2 m/s, 1 rad/s
  const fgdwa::Footprint footprint = fgdwa::Footprint::circle(0.25);
  fgdwa::PlannerParams params;
  params.critics = {{"heading", 0.5, {}}, {"clearance", 0.6, {}}, {"velocity", 1.0, {}}};
  fgdwa::LocalPlanner planner(limits, footprint, params);

  fgdwa::RobotState state;
  state.pose = fgdwa::Pose2{0.5, 0.5, 0.0};
  const fgdwa::Vec2 goal(5.5, 3.5);

  for (int cycle = 0; cycle < 400; ++cycle) {
    const fgdwa::PlanResult& result = planner.plan(state, goal, world);
    if (cycle % 10 == 0 || result.status != fgdwa::Status::Ok)
      std::printf("cycle %3d  pose (%.2f, %.2f, %+.2f)  command v %.2f m/s  omega %+.2f rad/s  %s (%d/%zu admissible)\n",
                  cycle, state.pose.x, state.pose.y, state.pose.theta, result.command.v, result.command.omega,
                  fgdwa::to_string(result.status), result.admissible_count(), result.samples.size());
    if (result.status == fgdwa::Status::GoalReached) {
      std::printf("goal reached after %d cycles\n", cycle);
      return 0;
    }
    state.pose = fgdwa::unicycle_step(state.pose, result.command, params.dt);
    state.twist = result.command;
    if (world.clearance(footprint, state.pose, 0.0) <= 0.0) {
      std::printf("collision at (%.2f, %.2f)\n", state.pose.x, state.pose.y);
      return 1;
    }
  }
  std::printf("goal not reached\n");
  return 1;
}
