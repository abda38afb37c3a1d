// The Nav2 DWB critics on hand-made rollouts; every expected value is worked
// out by hand from the critic's definition in dwb_critics.hpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fgdwa/clearance.hpp"
#include "fgdwa/collision.hpp"
#include "fgdwa/dwb_critics.hpp"
#include "fgdwa/presets.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

using test::expect_error_naming;

Rollout rollout_of(const Trajectory& poses) {
  Rollout r;
  r.command = Twist{0.5, 0.0};
  r.poses = &poses;
  r.min_clearance = 1.0;
  r.free_distance = test::kInf;
  return r;
}

// The robot at `robot`, the global path `path` ending at the goal.
CriticContext context_on(const GlobalPath& path, const Pose2& robot) {
  CriticContext context;
  context.state.pose = robot;
  context.goal = path.points().back();
  context.target = context.goal;
  context.dt = 0.15;
  context.n_steps = 20;
  context.path = &path;
  context.v_max = 1.2;
  return context;
}

// Score of a rollout whose last pose is `last` (the others do not count).
template <typename C>
double score_ending_at(const C& critic, const Pose2& last) {
  const Trajectory poses = {Pose2{0.3, -0.7, 2.0}, last};
  return critic.score(rollout_of(poses));
}

void expect_points(const std::vector<Vec2>& got, const std::vector<Vec2>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].x(), want[i].x(), 1e-12) << "point " << i;
    EXPECT_NEAR(got[i].y(), want[i].y(), 1e-12) << "point " << i;
  }
}

const GlobalPath kStraight({Vec2(0, 0), Vec2(10, 0)});

TEST(DwbInflationCost, InscribedThenExponentialThenZero) {
  const DwbObstacleParams nav2;  // cost_scaling_factor 3, inflation_margin 0.55
  EXPECT_EQ(dwb_inflation_cost(0.0, nav2), 253.0);
  EXPECT_EQ(dwb_inflation_cost(-0.2, nav2), 253.0);
  EXPECT_NEAR(dwb_inflation_cost(0.1, nav2), 186.68619, 1e-5);  // 252 e^-0.3
  EXPECT_NEAR(dwb_inflation_cost(0.5, nav2), 56.22880, 1e-5);   // 252 e^-1.5
  EXPECT_EQ(dwb_inflation_cost(0.55, nav2), 0.0);
  EXPECT_EQ(dwb_inflation_cost(2.0, nav2), 0.0);
  EXPECT_EQ(dwb_inflation_cost(test::kInf, nav2), 0.0);
  DwbObstacleParams gentle;
  gentle.cost_scaling_factor = 1.0;
  gentle.inflation_margin = 1.0;
  EXPECT_NEAR(dwb_inflation_cost(0.1, gentle), 228.01903, 1e-5);  // 252 e^-0.1
  EXPECT_NEAR(dwb_inflation_cost(0.7, gentle), 125.13950, 1e-5);  // 252 e^-0.7
}

TEST(DwbObstacleCritic, CostOfTheLastPoseOrOfEveryPose) {
  // A point obstacle at (2, 0) and a robot of radius 0.25: clearance = 1.75 - x on the x axis.
  const FieldClearance world(nullptr, {Disc{Vec2(2.0, 0.0), 0.0, Vec2::Zero()}});
  const Footprint footprint = Footprint::circle(0.25);
  CriticContext context = context_on(kStraight, Pose2{});
  context.world = &world;
  context.footprint = &footprint;
  const Trajectory poses = {Pose2{1.0, 0, 0}, Pose2{1.65, 0, 0}, Pose2{1.70, 0, 0}};  // clearance 0.75, 0.1, 0.05

  DwbObstacleCritic last;
  last.prepare(context);
  EXPECT_NEAR(last.score(rollout_of(poses)), 216.89841, 1e-5);  // 252 e^-0.15
  const Trajectory touching = {Pose2{1.0, 0, 0}, Pose2{1.75, 0, 0}};
  EXPECT_EQ(last.score(rollout_of(touching)), 253.0);
  const Trajectory far = {Pose2{1.65, 0, 0}, Pose2{1.0, 0, 0}};
  EXPECT_EQ(last.score(rollout_of(far)), 0.0);  // only the last pose counts

  DwbObstacleParams sum_params;
  sum_params.aggregation = DwbAggregation::Sum;
  DwbObstacleCritic sum(sum_params);
  sum.prepare(context);
  EXPECT_NEAR(sum.score(rollout_of(poses)), (0.0 + 186.68619 + 216.89841), 1e-4);
  EXPECT_NEAR(sum.score(rollout_of(far)), 186.68619, 1e-5);
}

TEST(DwbObstacleCritic, ReadsPoseKAtTimeKPlusOneSteps) {
  // The obstacle moves away at 1 m/s: with dt 0.1 the third pose is checked 0.3 s
  // ahead, the obstacle at (2.3, 0) and the clearance of (1.7, 0) 0.35.
  const FieldClearance world(nullptr, {Disc{Vec2(2.0, 0.0), 0.0, Vec2(1.0, 0.0)}});
  const Footprint footprint = Footprint::circle(0.25);
  CriticContext context = context_on(kStraight, Pose2{});
  context.world = &world;
  context.footprint = &footprint;
  context.dt = 0.1;
  DwbObstacleCritic critic;
  critic.prepare(context);
  const Trajectory poses = {Pose2{1.0, 0, 0}, Pose2{1.3, 0, 0}, Pose2{1.7, 0, 0}};
  EXPECT_NEAR(critic.score(rollout_of(poses)), 88.18431, 1e-5);  // 252 e^-1.05
}

TEST(DwbObstacleCritic, NeedsTheWorldAndTheFootprint) {
  DwbObstacleCritic critic;
  EXPECT_FALSE(critic.needs_path());
  expect_error_naming([&] { critic.prepare(CriticContext{}); }, "world");
}

TEST(DwbLocalPath, FromTheProjectionToTheWindowEdge) {
  DwbLocalPath local;
  dwb_local_path(kStraight, Vec2(0, 0), 1.5, local);
  expect_points(local.points, {Vec2(0, 0), Vec2(1.5, 0)});
  EXPECT_FALSE(local.reaches_end);
  // Off the path: it starts at the projection, and the window is centred on the robot.
  dwb_local_path(kStraight, Vec2(2, 0.3), 1.5, local);
  expect_points(local.points, {Vec2(2, 0), Vec2(3.5, 0)});
  // Round a corner, cut where the second leg leaves the window.
  const GlobalPath corner({Vec2(0, 0), Vec2(2, 0), Vec2(2, 4)});
  dwb_local_path(corner, Vec2(1.5, 0), 1.0, local);
  expect_points(local.points, {Vec2(1.5, 0), Vec2(2, 0), Vec2(2, 1)});
  EXPECT_FALSE(local.reaches_end);
  EXPECT_EQ(local.goal(), Vec2(2, 1));
  // The whole rest of a short path.
  const GlobalPath shorter({Vec2(0, 0), Vec2(1, 0)});
  dwb_local_path(shorter, Vec2(0, 0), 1.5, local);
  expect_points(local.points, {Vec2(0, 0), Vec2(1, 0)});
  EXPECT_TRUE(local.reaches_end);
}

TEST(DwbLocalPath, SkipsToWhereThePathEntersTheWindow) {
  // The nearest point (1.05, 0) is outside the window |x|, |y| <= 1; the path
  // enters it a third of the way along its last segment, at x = 1.
  const GlobalPath path({Vec2(1.05, -2), Vec2(1.05, 0.95), Vec2(0.9, 0.9)});
  DwbLocalPath local;
  dwb_local_path(path, Vec2(0, 0), 1.0, local);
  expect_points(local.points, {Vec2(1.0, 0.95 - 0.05 / 3.0), Vec2(0.9, 0.9)});
  EXPECT_TRUE(local.reaches_end);
  // Never inside: the projection alone.
  dwb_local_path(GlobalPath({Vec2(0, 0), Vec2(6, 0)}), Vec2(1, 1), 0.8, local);
  expect_points(local.points, {Vec2(1, 0)});
  EXPECT_FALSE(local.reaches_end);
}

TEST(PolylineDistance, ToSegmentsOrToASinglePoint) {
  const std::vector<Vec2> corner = {Vec2(0, 0), Vec2(2, 0), Vec2(2, 2)};
  EXPECT_NEAR(polyline_distance(corner, Vec2(1, 0.5)), 0.5, 1e-12);
  EXPECT_NEAR(polyline_distance(corner, Vec2(2.3, 1)), 0.3, 1e-12);
  EXPECT_NEAR(polyline_distance(corner, Vec2(3, -1)), std::sqrt(2.0), 1e-12);  // past the corner
  EXPECT_NEAR(polyline_distance({Vec2(1, 1)}, Vec2(4, 5)), 5.0, 1e-12);
}

TEST(DwbPathDistCritic, CellsFromTheLastPositionToTheLocalPath) {
  DwbPathDistCritic critic;
  EXPECT_TRUE(critic.needs_path());
  critic.prepare(context_on(kStraight, Pose2{0, 0, 0}));
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.1, 0}), 2.0, 1e-12);   // 0.1 m = 2 cells
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.25, 1}), 5.0, 1e-12);  // heading does not count
  EXPECT_NEAR(score_ending_at(critic, Pose2{0.7, 0.0, 0}), 0.0, 1e-12);
  // Past the window the path is cut at x = 1.5: 0.5 m = 10 cells from its end.
  EXPECT_NEAR(score_ending_at(critic, Pose2{2.0, 0.0, 0}), 10.0, 1e-12);
  DwbGridParams coarse;
  coarse.resolution = 0.1;
  DwbPathDistCritic coarser(coarse);
  coarser.prepare(context_on(kStraight, Pose2{0, 0, 0}));
  EXPECT_NEAR(score_ending_at(coarser, Pose2{1.0, 0.1, 0}), 1.0, 1e-12);
  expect_error_naming([] { DwbPathDistCritic().prepare(CriticContext{}); }, "global path");
}

TEST(DwbGoalDistCritic, CellsFromTheLastPositionToTheLocalGoal) {
  DwbGoalDistCritic critic;
  critic.prepare(context_on(kStraight, Pose2{0, 0, 0}));  // local goal (1.5, 0)
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.5, 0.2, 0}), 4.0, 1e-12);
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.2, 0.4, 0}), 10.0, 1e-12);
  EXPECT_NEAR(score_ending_at(critic, Pose2{0.0, 0.0, 0}), 30.0, 1e-12);
  EXPECT_NEAR(score_ending_at(critic, Pose2{2.5, 0.0, 0}), 20.0, 1e-12);  // overshooting costs too
  DwbGridParams narrow;
  narrow.local_extent = 1.0;
  DwbGoalDistCritic nearer(narrow);
  nearer.prepare(context_on(kStraight, Pose2{0, 0, 0}));  // local goal (1, 0)
  EXPECT_NEAR(score_ending_at(nearer, Pose2{1.0, 0.3, 0}), 6.0, 1e-12);
}

TEST(DwbPathAlignCritic, CellsFromTheForwardPointToTheLocalPath) {
  DwbPathAlignCritic critic;
  critic.prepare(context_on(kStraight, Pose2{0, 0, 0}));
  EXPECT_TRUE(critic.active());
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.1, 0}), 2.0, 1e-12);         // nose at (1.325, 0.1)
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.1, M_PI / 2}), 8.5, 1e-12);  // nose at (1, 0.425)
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.1, -M_PI / 2}), 4.5, 1e-12); // nose at (1, 0.225)
  DwbGridParams short_nose;
  short_nose.forward_point_distance = 0.1;
  DwbPathAlignCritic shorter(short_nose);
  shorter.prepare(context_on(kStraight, Pose2{0, 0, 0}));
  EXPECT_NEAR(score_ending_at(shorter, Pose2{1.0, 0.1, M_PI / 2}), 4.0, 1e-12);  // nose at (1, 0.2)
}

TEST(DwbPathAlignCritic, OffWithinTheForwardPointDistanceOfTheGoal) {
  DwbPathAlignCritic critic;
  critic.prepare(context_on(kStraight, Pose2{9.8, 0, 0}));  // 0.2 m from the goal
  EXPECT_FALSE(critic.active());
  EXPECT_EQ(score_ending_at(critic, Pose2{9.9, 0.3, 2.0}), 0.0);
  critic.prepare(context_on(kStraight, Pose2{9.6, 0, 0}));  // 0.4 m: on again
  EXPECT_TRUE(critic.active());
  EXPECT_NEAR(score_ending_at(critic, Pose2{9.7, 0.1, M_PI / 2}), 8.5, 1e-12);
}

TEST(DwbGoalAlignCritic, CellsFromTheForwardPointToTheLocalGoal) {
  DwbGoalAlignCritic critic;
  critic.prepare(context_on(kStraight, Pose2{0, 0, 0}));
  EXPECT_EQ(critic.target(), Vec2(1.5, 0));  // the goal is far: no shift
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.0, 0}), 3.5, 1e-12);  // nose at (1.325, 0)
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.5, 0.0, M_PI}), 6.5, 1e-12);  // nose at (1.175, 0)
}

TEST(DwbGoalAlignCritic, TargetsForwardPointDistanceBeyondANearGoal) {
  const GlobalPath shorter({Vec2(0, 0), Vec2(1, 0)});
  DwbGoalAlignCritic critic;
  critic.prepare(context_on(shorter, Pose2{0, 0, 0}));
  EXPECT_NEAR((critic.target() - Vec2(1.325, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.0, 0}), 0.0, 1e-12);  // centre on the goal, nose past it
  // Nose at (1, 0.325): 0.325 sqrt 2 m from the target.
  EXPECT_NEAR(score_ending_at(critic, Pose2{1.0, 0.0, M_PI / 2}), 0.325 * std::sqrt(2.0) / 0.05, 1e-12);
  // The shift follows the direction from the robot to the goal: (0.8, -0.6) from (0, 0.75).
  critic.prepare(context_on(shorter, Pose2{0, 0.75, 0}));
  EXPECT_NEAR((critic.target() - Vec2(1.26, -0.195)).norm(), 0.0, 1e-12);
}

TEST(MakeCritic, BuildsTheDwbCriticsWithTheirParameters) {
  const auto names = critic_names();
  for (const char* expected : {"dwb_obstacle", "dwb_path_dist", "dwb_goal_dist", "dwb_path_align", "dwb_goal_align"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  auto obstacle = make_critic({"dwb_obstacle", 0.02, {{"cost_scaling_factor", 2.0}, {"inflation_margin", 0.4}}});
  const DwbObstacleParams& o = dynamic_cast<DwbObstacleCritic&>(*obstacle).params();
  EXPECT_EQ(o.cost_scaling_factor, 2.0);
  EXPECT_EQ(o.inflation_margin, 0.4);
  EXPECT_EQ(o.aggregation, DwbAggregation::Last);
  auto summed = make_critic({"dwb_obstacle", 0.02, {}, {{"aggregation", "sum"}}});
  EXPECT_EQ(dynamic_cast<DwbObstacleCritic&>(*summed).params().aggregation, DwbAggregation::Sum);
  auto align = make_critic({"dwb_path_align", 0.8, {{"resolution", 0.1}, {"local_extent", 2.0},
                                                     {"forward_point_distance", 0.2}}});
  const DwbGridParams& g = dynamic_cast<DwbGridCritic&>(*align).params();
  EXPECT_EQ(g.resolution, 0.1);
  EXPECT_EQ(g.local_extent, 2.0);
  EXPECT_EQ(g.forward_point_distance, 0.2);
  EXPECT_EQ(dynamic_cast<DwbGridCritic&>(*make_critic({"dwb_goal_align", 1.0, {}})).params().forward_point_distance,
            0.325);
}

TEST(MakeCritic, RejectsBadDwbParametersByName) {
  // Only the align critics have a forward point.
  expect_error_naming([] { make_critic({"dwb_path_dist", 1.0, {{"forward_point_distance", 0.3}}}); },
                      "forward_point_distance");
  expect_error_naming([] { make_critic({"dwb_goal_dist", 1.0, {{"forward_point_distance", 0.3}}}); },
                      "forward_point_distance");
  expect_error_naming([] { make_critic({"dwb_obstacle", 1.0, {{"resolution", 0.05}}}); }, "resolution");
  for (const char* name : {"dwb_path_dist", "dwb_goal_dist", "dwb_path_align", "dwb_goal_align"}) {
    for (double bad : {0.0, -0.05, test::kInf, std::nan("")}) {
      expect_error_naming([&] { make_critic({name, 1.0, {{"resolution", bad}}}); }, "resolution");
      expect_error_naming([&] { make_critic({name, 1.0, {{"local_extent", bad}}}); }, "local_extent");
    }
  }
  for (const char* name : {"dwb_path_align", "dwb_goal_align"})
    for (double bad : {0.0, -0.3, std::nan("")})
      expect_error_naming([&] { make_critic({name, 1.0, {{"forward_point_distance", bad}}}); },
                          "forward_point_distance");
  for (double bad : {0.0, -3.0, test::kInf}) {
    expect_error_naming([&] { make_critic({"dwb_obstacle", 1.0, {{"cost_scaling_factor", bad}}}); },
                        "cost_scaling_factor");
    expect_error_naming([&] { make_critic({"dwb_obstacle", 1.0, {{"inflation_margin", bad}}}); },
                        "inflation_margin");
  }
  expect_error_naming([] { make_critic({"dwb_obstacle", 1.0, {}, {{"aggregation", "max"}}}); }, "aggregation");
  expect_error_naming([] { make_critic({"dwb_goal_dist", 1.0, {}, {{"aggregation", "sum"}}}); }, "aggregation");
}

// A corridor 1 m wide between walls at y = 1 and y = 2, 13 m long; the global
// path runs down its middle and the robot starts 0.15 m off it, turned away.
struct CorridorRun {
  bool reached = false;
  int cycles = 0;
  int contacts = 0;
  double min_clearance = test::kInf;
  double max_deviation_late = 0.0;  // m from the path once past x = 4
  double distance = 0.0;
};

CorridorRun drive_corridor(const PlannerParams& params) {
  const int rows = 30, cols = 130;
  std::vector<std::uint8_t> cells(rows * cols, 0);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) cells[static_cast<std::size_t>(r * cols + c)] = (r < 10 || r >= 20) ? 1 : 0;
  const OccupancyGrid grid(rows, cols, 0.1, Vec2::Zero(), cells);
  const FieldClearance sensed(std::make_shared<DistanceField>(grid));
  const CollisionWorld truth(grid);
  const Footprint footprint = Footprint::circle(0.25);
  const RobotLimits limits;
  LocalPlanner planner(limits, footprint, params);
  const GlobalPath path({Vec2(1.0, 1.5), Vec2(12.0, 1.5)});
  planner.set_global_path(path);
  const Vec2 goal(12.0, 1.5);
  RobotState state{Pose2{1.0, 1.35, -0.2}, Twist{}};
  CorridorRun run;
  for (run.cycles = 0; run.cycles < 600; ++run.cycles) {
    const PlanResult& result = planner.plan(state, goal, sensed);
    if (result.status == Status::GoalReached) {
      run.reached = true;
      break;
    }
    const Pose2 next = unicycle_step(state.pose, result.command, params.dt);
    run.distance += (next.position() - state.pose.position()).norm();
    state = RobotState{next, result.command};
    if (truth.in_collision(footprint, state.pose)) ++run.contacts;
    run.min_clearance = std::min(run.min_clearance, truth.clearance(footprint, state.pose, 0.0));
    if (state.pose.x > 4.0) run.max_deviation_late = std::max(run.max_deviation_late, path.deviation(state.pose.position()));
  }
  return run;
}

TEST(DwbPreset, NavTwoCriticsAndScalesUnnormalised) {
  const PlannerPreset preset = planner_preset("dwb");
  EXPECT_FALSE(preset.fuzzy);
  EXPECT_EQ(preset.params.normalization, Normalization::None);
  EXPECT_EQ(preset.params.heading_target, HeadingTarget::KeyNodes);
  EXPECT_EQ(preset.params.dt, 0.15);
  EXPECT_EQ(preset.params.sim_time, 3.0);
  // nav2_params.yaml's scales; the map-grid ones times half the 0.05 m resolution.
  const std::vector<std::pair<std::string, double>> want = {
      {"dwb_obstacle", 0.02}, {"dwb_path_align", 0.8}, {"dwb_goal_align", 0.6}, {"dwb_path_dist", 0.8},
      {"dwb_goal_dist", 0.6}};
  ASSERT_EQ(preset.params.critics.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_EQ(preset.params.critics[i].name, want[i].first);
    EXPECT_NEAR(preset.params.critics[i].weight, want[i].second, 1e-12) << want[i].first;
  }
  const auto names = preset_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "dwb"), names.end());
}

TEST(DwbPreset, FollowsAStraightCorridorPathToTheGoal) {
  const CorridorRun run = drive_corridor(planner_preset("dwb").params);
  EXPECT_TRUE(run.reached) << "after " << run.cycles << " cycles";
  EXPECT_EQ(run.contacts, 0);
  EXPECT_GT(run.min_clearance, 0.0);
  EXPECT_LT(run.max_deviation_late, 0.05);
  EXPECT_LT(run.distance, 11.5);  // 11 m of path, plus the way back onto it
  RecordProperty("cycles", run.cycles);
  RecordProperty("distance_m", std::to_string(run.distance));
  RecordProperty("max_deviation_late_m", std::to_string(run.max_deviation_late));
  RecordProperty("min_clearance_m", std::to_string(run.min_clearance));
}

TEST(DwbPreset, RefusesToRunWithoutAGlobalPath) {
  PlannerParams params = planner_preset("dwb").params;
  params.heading_target = HeadingTarget::Goal;
  LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25), params);
  const FieldClearance empty;
  expect_error_naming([&] { planner.plan(RobotState{}, Vec2(5, 0), empty); }, "dwb_path_align");
}

}  // namespace
}  // namespace fgdwa
