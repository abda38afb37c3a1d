// One control cycle of the classic DWA: 21 x 21 samples, 20 poses per rollout
// (dt 0.15 s, 3 s horizon), a 10 m x 10 m map at 0.1 m with 15 % of its cells
// in seeded random rectangles, a circle footprint of 0.25 m, the robot cruising
// at 0.6 m/s from 32 seeded starts in free space. LocalPlanner::plan is timed
// with each clearance source: the distance field (FieldClearance) and the exact
// FCL world (CollisionWorld); and with the field for the Jackal's rectangle,
// also from starts near the map's edge whose rollouts leave the grid, and
// from the same starts with the map padded so that they stay on it.
// Then PythonRobotics' DWA example with point obstacles (PeerScene below).
// Also what building the field of that map costs, updating it for one cell
// (with the field's bytes per cell), and building the FCL world.
//
//   build/cmake/cpp/bench/bench_planner   (median of 10 repetitions, in microseconds;
//   the targets: the field variant with the circle <= 30 us, the Jackal's
//   rectangle <= 300 us, the PythonRobotics case <= 150 us; the Jackal's
//   rectangle costs more, its exact clearance being an outline's, not a point's)
// A table of those figures next to their arithmetic floor follows (bench_floor.hpp).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/collision.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/presets.hpp"
#include "bench_floor.hpp"
#include "bench_maps.hpp"

namespace {

using namespace fgdwa;

// Seeded starts at least 0.2 m clear of obstacles, each heading roughly for its
// goal: how long a cycle takes depends on how soon the rollouts meet obstacles,
// so one start alone says little; the spread of 32 is the typical cycle.
struct Scene {
  static constexpr int kStarts = 32;
  std::mt19937 rng{42};
  OccupancyGrid grid = bench::rectangle_map(rng);  // 100 x 100 at 0.1 m, 15 % occupied
  DistanceField field{grid};
  std::vector<RobotState> states;
  std::vector<Vec2> goals;
  LocalPlanner planner;  // 21 x 21, dt 0.15, 3 s

  // at_edge: starts 0.4-0.8 m inside the map's border with goals 2 m beyond
  // it, so that the rollouts leave the grid (outside counts as free).
  explicit Scene(const Footprint& footprint = Footprint::circle(0.25), bool at_edge = false)
      : planner(RobotLimits{}, footprint, PlannerParams{}) {
    std::uniform_real_distribution<double> where(0.5, 9.5), jitter(-0.5, 0.5), inside(0.4, 0.8);
    std::uniform_int_distribution<int> side(0, 3);
    while (static_cast<int>(states.size()) < kStarts) {
      Vec2 start(where(rng), where(rng)), goal(where(rng), where(rng));
      if (at_edge) {
        const int s = side(rng);
        const double along = where(rng), in = inside(rng);
        const Vec2 outward = s == 0 ? Vec2(-1, 0) : s == 1 ? Vec2(1, 0) : s == 2 ? Vec2(0, -1) : Vec2(0, 1);
        start = s < 2 ? Vec2(s == 0 ? in : 10.0 - in, along) : Vec2(along, s == 2 ? in : 10.0 - in);
        goal = start + (in + 2.0) * outward;
      }
      if (field.distance(start) < 0.45 || (goal - start).norm() < (at_edge ? 2.0 : 3.0)) continue;
      const double heading = std::atan2(goal.y() - start.y(), goal.x() - start.x()) + jitter(rng);
      states.push_back(RobotState{Pose2{start.x(), start.y(), heading}, Twist{0.6, 0.0}});
      goals.push_back(goal);
    }
  }
};

// Per benchmark (its name with its argument), the work of one cycle, for the floor.
std::map<std::string, std::vector<bench::Work>>& cycle_work() {
  static std::map<std::string, std::vector<bench::Work>> all;
  return all;
}

// A cycle's work: every sample's rollout stepped and bounded pose by pose.
std::vector<bench::Work> rollout_work(const LocalPlanner& planner) {
  const double poses = static_cast<double>(planner.last_result().samples.size()) * planner.params().n_steps();
  return {bench::Work{"poses", poses, bench::pose_operations(planner.footprint())}};
}

// Plans from the first `starts` of the seeded starts in turn.
void plan_cycles(benchmark::State& bench, const std::string& name, Scene& scene, const ClearanceSource& world) {
  const std::size_t starts = static_cast<std::size_t>(bench.range(0));
  std::size_t i = 0, admissible = 0, cycles = 0;
  for (auto _ : bench) {
    const PlanResult& result = scene.planner.plan(scene.states[i], scene.goals[i], world);
    benchmark::DoNotOptimize(result.command);
    admissible += static_cast<std::size_t>(result.admissible_count());
    ++cycles;
    i = (i + 1) % starts;
  }
  bench.counters["samples"] = static_cast<double>(scene.planner.last_result().samples.size());
  bench.counters["admissible"] = static_cast<double>(admissible) / static_cast<double>(cycles);
  cycle_work()[name + "/" + std::to_string(bench.range(0))] = rollout_work(scene.planner);
}

void BM_PlanFieldClearance(benchmark::State& bench) {
  Scene scene;
  const FieldClearance world(std::make_shared<const DistanceField>(scene.grid));
  plan_cycles(bench, "BM_PlanFieldClearance", scene, world);
}

// The same cycle for a rectangle: the Jackal's 0.42 m x 0.33 m (robot preset
// "jackal", the BARN robot), with the default limits.
void BM_PlanFieldClearanceJackal(benchmark::State& bench) {
  Scene scene(robot_preset("jackal").footprint);
  const FieldClearance world(std::make_shared<const DistanceField>(scene.grid));
  plan_cycles(bench, "BM_PlanFieldClearanceJackal", scene, world);
}

// A circle near the map's edge, its rollouts leaving the grid.
void BM_PlanFieldClearanceAtEdge(benchmark::State& bench) {
  Scene scene(Footprint::circle(0.25), true);
  const FieldClearance world(std::make_shared<const DistanceField>(scene.grid));
  plan_cycles(bench, "BM_PlanFieldClearanceAtEdge", scene, world);
}

// The Jackal near the map's edge, its rollouts leaving the grid.
void BM_PlanFieldClearanceJackalAtEdge(benchmark::State& bench) {
  Scene scene(robot_preset("jackal").footprint, true);
  const FieldClearance world(std::make_shared<const DistanceField>(scene.grid));
  plan_cycles(bench, "BM_PlanFieldClearanceJackalAtEdge", scene, world);
}

// The same starts at the edge with the map padded by 4 m of free cells on
// every side, so that the rollouts stay on the grid: against the two cases
// above, what leaving the grid itself costs (the starts and the obstacles
// they see are the same; only where the grid ends differs).
DistanceField padded_field(const OccupancyGrid& grid, double margin) {
  const int pad = static_cast<int>(std::round(margin / grid.resolution()));
  const int rows = grid.rows() + 2 * pad, cols = grid.cols() + 2 * pad;
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(rows) * cols, 0);
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c) cells[static_cast<std::size_t>(r + pad) * cols + c + pad] = grid.occupied(r, c);
  const Vec2 origin = grid.origin() - Vec2(pad * grid.resolution(), pad * grid.resolution());
  return DistanceField(OccupancyGrid(rows, cols, grid.resolution(), origin, std::move(cells)));
}

void BM_PlanFieldClearanceAtEdgePadded(benchmark::State& bench) {
  Scene scene(Footprint::circle(0.25), true);
  const FieldClearance world(std::make_shared<const DistanceField>(padded_field(scene.grid, 4.0)));
  plan_cycles(bench, "BM_PlanFieldClearanceAtEdgePadded", scene, world);
}

void BM_PlanFieldClearanceJackalAtEdgePadded(benchmark::State& bench) {
  Scene scene(robot_preset("jackal").footprint, true);
  const FieldClearance world(std::make_shared<const DistanceField>(padded_field(scene.grid, 4.0)));
  plan_cycles(bench, "BM_PlanFieldClearanceJackalAtEdgePadded", scene, world);
}

void BM_PlanCollisionWorld(benchmark::State& bench) {
  Scene scene;
  const CollisionWorld world(scene.grid);
  plan_cycles(bench, "BM_PlanCollisionWorld", scene, world);
}

// PythonRobotics' DWA example (PathPlanning/DynamicWindowApproach, the peer
// case of tests/cpp/test_closed_loop.cpp): its 15 point obstacles, a circle of
// 1 m, v <= 1 m/s, |omega| <= 40 deg/s, 0.2 m/s^2 and 40 deg/s^2, dt 0.1 s over
// 3 s (30 poses), 3 x 80 = 240 samples, heading 0.15, clearance 0.2 and
// velocity 1.0. The states are those of one closed-loop drive from (0, 0) to
// (10, 10), replayed cycle after cycle. The points are zero-radius discs, or
// the same points rasterised into a 0.1 m grid: the two should cost alike.
struct PeerScene {
  static constexpr double kDeg = M_PI / 180.0;
  std::vector<Disc> points;
  RobotLimits limits;
  PlannerParams params;
  std::vector<RobotState> states;
  const Vec2 goal{10.0, 10.0};

  PeerScene() {
    const double xy[][2] = {{-1, -1}, {0, 2},  {4, 2},  {5, 4},   {5, 5},   {5, 6},   {5, 9},  {8, 9},
                            {7, 9},   {8, 10}, {9, 11}, {12, 13}, {12, 12}, {15, 15}, {13, 13}};
    for (const auto& p : xy) points.push_back(Disc{Vec2(p[0], p[1]), 0.0, Vec2::Zero()});
    limits.v_max = 1.0;
    limits.omega_max = 40 * kDeg;
    limits.acc_v = 0.2;
    limits.acc_omega = 40 * kDeg;
    params.dt = 0.1;
    params.sim_time = 3.0;
    params.window = WindowParams{3, 80};
    params.goal_tolerance = 1.0;
    params.critics = {{"heading", 0.15, {}}, {"clearance", 0.2, {}}, {"velocity", 1.0, {}}};
    LocalPlanner planner = make_planner();
    const FieldClearance world(nullptr, points);
    RobotState state{Pose2{0.0, 0.0, M_PI / 8}, Twist{0.0, 0.0}};
    for (int cycle = 0; cycle < 1000; ++cycle) {
      states.push_back(state);
      const PlanResult& result = planner.plan(state, goal, world);
      if (result.status == Status::GoalReached) break;
      state = RobotState{unicycle_step(state.pose, result.command, params.dt), result.command};
    }
  }
  LocalPlanner make_planner() const { return LocalPlanner(limits, Footprint::circle(1.0), params); }
  // The points as occupied cells of a 0.1 m grid over (-2, -2)-(17, 17).
  OccupancyGrid rasterised() const {
    const double res = 0.1;
    const int cells = 190;
    std::vector<std::uint8_t> occupied(static_cast<std::size_t>(cells) * cells, 0);
    for (const Disc& d : points) {
      const int col = static_cast<int>(std::floor((d.center.x() + 2.0) / res));
      const int row = static_cast<int>(std::floor((d.center.y() + 2.0) / res));
      occupied[static_cast<std::size_t>(row) * cells + col] = 1;
    }
    return OccupancyGrid(cells, cells, res, Vec2(-2.0, -2.0), std::move(occupied));
  }
};

void plan_peer(benchmark::State& bench, const std::string& name, const ClearanceSource& world) {
  static const PeerScene scene;
  LocalPlanner planner = scene.make_planner();
  std::size_t i = 0;
  for (auto _ : bench) {
    benchmark::DoNotOptimize(planner.plan(scene.states[i], scene.goal, world).command);
    i = (i + 1) % scene.states.size();
  }
  bench.counters["samples"] = static_cast<double>(planner.last_result().samples.size());
  bench.counters["cycles"] = static_cast<double>(scene.states.size());
  // Against the points one by one, with one square root per pose (all radii equal).
  const double poses = static_cast<double>(planner.last_result().samples.size()) * planner.params().n_steps();
  cycle_work()[name] = {bench::Work{
      "poses", poses,
      bench::kPoseStepOps + static_cast<double>(scene.points.size()) * bench::kPointDistanceOps + 1 + bench::kPoseTestOps}};
}

void BM_PeerPointObstacles(benchmark::State& bench) {
  const PeerScene scene;
  plan_peer(bench, "BM_PeerPointObstacles", FieldClearance(nullptr, scene.points));
}

void BM_PeerRasterised(benchmark::State& bench) {
  const PeerScene scene;
  plan_peer(bench, "BM_PeerRasterised", FieldClearance(std::make_shared<const DistanceField>(scene.rasterised())));
}

// Building the clearance sources is a per-map cost, not a per-cycle one.
void BM_BuildDistanceField(benchmark::State& bench) {
  const Scene scene;
  for (auto _ : bench) benchmark::DoNotOptimize(DistanceField(scene.grid).has_obstacles());
}

// What a noisy hit costs the field: a random cell flips and flips back (two
// updates per iteration), as a scan map's cells come and go.
void BM_UpdateDistanceField(benchmark::State& bench) {
  const Scene scene;
  OccupancyGrid grid = scene.grid;
  DistanceField field(grid);
  std::mt19937 rng(3);
  std::uniform_int_distribution<std::size_t> cell(0, grid.cells().size() - 1);
  for (auto _ : bench) {
    const std::size_t i = cell(rng);
    for (int k = 0; k < 2; ++k) {
      grid.set(i, grid.cells()[i] == 0);
      benchmark::DoNotOptimize(field.update(grid, {i}));
    }
  }
  bench.counters["cells"] = static_cast<double>(grid.cells().size());
  bench.counters["bytes_per_cell"] = field.bytes_per_cell();
}

void BM_BuildCollisionWorld(benchmark::State& bench) {
  const Scene scene;
  for (auto _ : bench) benchmark::DoNotOptimize(CollisionWorld(scene.grid).boxes().size());
}

// Argument: how many starts the cycles go through (1: a single start, as a
// robot sees cycle after cycle; 32: a spread of situations).
BENCHMARK(BM_PlanFieldClearance)->Arg(1)->Arg(32)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanFieldClearanceJackal)->Arg(1)->Arg(32)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanFieldClearanceAtEdge)->Arg(32)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanFieldClearanceJackalAtEdge)->Arg(32)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanFieldClearanceAtEdgePadded)->Arg(32)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanFieldClearanceJackalAtEdgePadded)->Arg(32)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanCollisionWorld)->Arg(1)->Arg(32)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PeerPointObstacles)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PeerRasterised)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_BuildDistanceField)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_UpdateDistanceField)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_BuildCollisionWorld)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);

// Keeps every benchmark's median (microseconds) for the floor table.
class MedianReporter : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> medians;  // by the run's name without its aggregate

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs)
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
        medians[run.run_name.function_name + (run.run_name.args.empty() ? "" : "/" + run.run_name.args)] =
            run.GetAdjustedRealTime();
    ConsoleReporter::ReportRuns(runs);
  }
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  const struct {
    const char* figure;
    std::string run;  // the benchmark and its argument
    double target_us;
  } figures[] = {
      {"classic DWA, circle, 1 start", "BM_PlanFieldClearance/1", 30},
      {"classic DWA, circle, 32 starts", "BM_PlanFieldClearance/32", 30},
      {"Jackal rectangle, 1 start", "BM_PlanFieldClearanceJackal/1", 300},
      {"Jackal rectangle, 32 starts", "BM_PlanFieldClearanceJackal/32", 300},
      {"PythonRobotics case, points", "BM_PeerPointObstacles", 150},
  };
  const bench::Machine machine = bench::measured_machine();
  bool header = false;
  for (const auto& f : figures) {
    const auto median = reporter.medians.find(f.run);
    const auto work = cycle_work().find(f.run);
    if (median == reporter.medians.end() || work == cycle_work().end()) continue;
    if (!header) bench::print_floor_header(machine);
    header = true;
    bench::print_floor(f.figure, median->second, work->second, f.target_us, machine);
  }
  return 0;
}
