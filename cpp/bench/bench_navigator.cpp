// What one whole robot-side cycle costs in the noisy, moving world:
// Navigator::step with a map built from 541-beam scans with 3 cm range noise
// (log-odds update, ray tracing), moving obstacles segmented and tracked, the
// global path kept, and the FGDWA planner, for the circle robot and the Jackal.
//
// The robot drives for real: each benchmark iteration is one cycle of a closed
// loop (scan the true world, step the navigator, move the robot and the
// discs), restarted when the goal is reached or after 400 cycles. Only
// Navigator::step is timed (manual time); the scan and the motion are the world.
//
//   BM_NavigatorStep/circle    r 0.25 m circle, 1.2 m/s, on a 10 m x 10 m map at 0.1 m
//   BM_NavigatorStep/jackal    the Jackal's rectangle, speed capped at 1 m/s and rollouts of 1 s as in BARN
//   BM_NavigatorStep/jackal_20_movers   the same among 20 moving discs (the
//                              others have 4): every cycle tracks and predicts
//                              them all (target: a median <= 2 ms, map from scans)
//
// Arg 0: map known (obstacles the map lacks still come from the scans);
// arg 1: map built from the scans; both with each scan matched to the map and
// cells fading (fade_time 20 s). Arg 2: map built from the scans, each scan
// put in as odometry places it (the defaults: no matching, no fading): the
// cost of matching is the difference to arg 1. A table of medians and 95th percentiles
// follows the benchmarks (the targets: a median <= 0.5 ms for the circle robot
// and <= 1 ms for the Jackal; before those, 1 ms and 2 ms with the map built from
// scans and matched to it, with a 99th percentile <= 3 ms), then the
// slowest 1 % of cycles taken apart by stage (how many replanned, how many
// evaded), then each median next to its arithmetic floor (bench_floor.hpp).
//
//   build/cmake/cpp/bench/bench_navigator      (about 10 s)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench_floor.hpp"
#include "bench_maps.hpp"
#include "fgdwa/navigator.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/presets.hpp"

namespace fgdwa {
namespace {

constexpr double kNoise = 0.03;  // m, range noise std
constexpr int kEpisodeCycles = 400;

RobotLimits robot_limits(const std::string& robot) {
  if (robot == "circle") {
    RobotLimits limits;
    limits.v_max = 1.2;
    return limits;
  }
  RobotLimits limits = robot_preset("jackal").limits;
  limits.v_max = 1.0;
  return limits;
}

Footprint robot_footprint(const std::string& robot) {
  return robot == "circle" ? Footprint::circle(0.25) : robot_preset("jackal").footprint;
}

struct Loop {
  NavigatorParams params;
  RobotLimits limits;
  Footprint footprint;
  PlannerPreset preset = planner_preset("fgdwa");
  OccupancyGrid world;
  std::shared_ptr<const DistanceField> world_field;
  LidarParams lidar;
  LaserScanner scanner;
  MapMode mode;
  std::mt19937_64 noise{11};
  std::vector<Disc> discs;
  std::unique_ptr<Navigator> navigator;
  RobotState state;
  Scan scan;
  int cycle = 0;
  double time = 0.0;

  static LidarParams noisy_lidar() {
    LidarParams p;
    p.noise_std = kNoise;
    return p;
  }

  int movers;

  Loop(const std::string& robot, MapMode map_mode, OccupancyGrid grid, const NavigatorParams& navigator, int mover_count)
      : params(navigator),
        limits(robot_limits(robot)),
        footprint(robot_footprint(robot)),
        world(std::move(grid)),
        world_field(std::make_shared<const DistanceField>(world)),
        lidar(noisy_lidar()),
        scanner(lidar, world_field),
        mode(map_mode),
        movers(mover_count) {
    // The Jackal runs as in BARN (BarnSetup): rollouts of 1 s at 0.1 s.
    if (robot != "circle") preset.params.sim_time = 1.0;
    restart();
  }

  void restart() {
    // The known map lacks a third of the obstacles: those come from the scans.
    std::vector<std::uint8_t> known = world.cells();
    for (std::size_t i = 0; i < known.size(); ++i) known[i] = known[i] && (i % 3 != 0);
    const OccupancyGrid map(world.rows(), world.cols(), world.resolution(), world.origin(), known);
    navigator = std::make_unique<Navigator>(limits, footprint, preset.params, map, mode, lidar, preset.weight_policy(), params);
    navigator->set_goal(Vec2(9.3, 9.3));
    state = RobotState{Pose2{0.7, 0.7, M_PI / 4}, Twist{}};
    discs = {Disc{Vec2(5.0, 2.0), 0.3, Vec2(-0.4, 0.3)}, Disc{Vec2(2.0, 6.0), 0.4, Vec2(0.5, -0.2)},
             Disc{Vec2(7.0, 7.0), 0.35, Vec2(-0.3, -0.5)}, Disc{Vec2(4.0, 8.5), 0.3, Vec2(0.2, -0.6)}};
    // The rest anywhere but near the start and the goal, at 0.3-1.2 m/s: the same ones every restart.
    std::mt19937 placement(5);
    std::uniform_real_distribution<double> coordinate(1.0, 9.0), radius(0.25, 0.4), speed(0.3, 1.2), heading(-M_PI, M_PI);
    while (static_cast<int>(discs.size()) < movers) {
      const Vec2 centre(coordinate(placement), coordinate(placement));
      const double r = radius(placement), s = speed(placement), h = heading(placement);
      if ((centre - Vec2(0.7, 0.7)).norm() < 1.5 || (centre - Vec2(9.3, 9.3)).norm() < 1.5) continue;
      discs.push_back(Disc{centre, r, s * Vec2(std::cos(h), std::sin(h))});
    }
    cycle = 0;
    time = 0.0;
  }

  // One cycle; returns the seconds Navigator::step took.
  double step() {
    if (cycle >= kEpisodeCycles || navigator->record().mode == NavigatorMode::GoalReached ||
        navigator->record().mode == NavigatorMode::Failed)
      restart();
    scanner.scan(state.pose, discs, 0.0, noise, scan);
    const auto tic = std::chrono::steady_clock::now();
    const CycleRecord& record = navigator->step(state, &scan, time);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - tic).count();
    const double dt = preset.params.dt;
    state = RobotState{fgdwa::unicycle_step(state.pose, record.command, dt), record.command};
    for (Disc& d : discs) {
      d.center += dt * d.velocity;
      // Discs bounce off the map's border.
      for (int axis = 0; axis < 2; ++axis)
        if (d.center[axis] < 0.5 || d.center[axis] > 9.5) d.velocity[axis] = -d.velocity[axis];
    }
    ++cycle;
    time += dt;
    return seconds;
  }
};

std::map<std::string, std::vector<double>>& samples() {
  static std::map<std::string, std::vector<double>> all;
  return all;
}

void add(StageTimes& sum, const StageTimes& t) {
  sum.localise += t.localise;
  sum.tracking += t.tracking;
  sum.map += t.map;
  sum.global += t.global;
  sum.perception += t.perception;
  sum.plan += t.plan;
}

// The mean of each stage over n cycles, in ms, as the tables' stage columns.
void print_stage_means(const StageTimes& sum, double n) {
  std::printf("%22.3f %6.3f %6.3f %6.3f %6.3f %6.3f", 1e3 * sum.localise / n, 1e3 * sum.tracking / n, 1e3 * sum.map / n,
              1e3 * sum.global / n, 1e3 * sum.perception / n, 1e3 * sum.plan / n);
}

// Per configuration, the summed stage times and the cycles that replanned.
struct Stages {
  StageTimes times;
  int replans = 0;
  // For the floor: the cycles, and over those that planned, the samples and
  // the admissible ones; a rollout's poses, a pose's operations, the beams.
  double cycles = 0, samples = 0, admissible = 0;
  double steps = 0, pose_ops = 0, beams = 0;
};
std::map<std::string, Stages>& stages() {
  static std::map<std::string, Stages> all;
  return all;
}

// Per configuration, each cycle's stage times, whether it replanned and whether
// the planner evaded (every sample met a mover): what the slowest cycles spend their time on.
struct CycleStages {
  StageTimes times;
  bool replanned = false;
  bool evaded = false;
};
std::map<std::string, std::vector<CycleStages>>& cycle_stages() {
  static std::map<std::string, std::vector<CycleStages>> all;
  return all;
}

void BM_NavigatorStep(benchmark::State& bench, const std::string& robot, int movers) {
  const MapMode mode = bench.range(0) ? MapMode::Scan : MapMode::Known;
  NavigatorParams params;
  if (bench.range(0) < 2) {
    params.scan_match.enabled = true;
    params.occupancy.fade_time = 20.0;
  }
  std::mt19937 rng(3);
  OccupancyGrid grid = bench::rectangle_map(rng, 100, 0.1, 0.08);
  // Clear the corners for the start and the goal.
  std::vector<std::uint8_t> cells = grid.cells();
  for (int r = 0; r < 100; ++r)
    for (int c = 0; c < 100; ++c)
      if ((r < 15 && c < 15) || (r >= 85 && c >= 85)) cells[static_cast<std::size_t>(r) * 100 + c] = 0;
  Loop loop(robot, mode, OccupancyGrid(100, 100, 0.1, Vec2::Zero(), cells), params, movers);
  const std::string name = robot + (bench.range(0) == 0 ? " known" : bench.range(0) == 1 ? " scan" : " scan, odometry only") +
                           (movers > 4 ? ", " + std::to_string(movers) + " movers" : "");
  std::vector<double>& times = samples()[name];
  Stages& sum = stages()[name];
  std::vector<CycleStages>& each = cycle_stages()[name];
  int path_version = 0;
  for (auto _ : bench) {
    const double seconds = loop.step();
    bench.SetIterationTime(seconds);
    times.push_back(seconds);
    const CycleRecord& r = loop.navigator->record();
    add(sum.times, r.times);
    sum.replans += r.path_version != path_version;
    each.push_back(CycleStages{r.times, r.path_version != path_version,
                               r.planned && loop.navigator->plan_result().status == Status::Evading});
    path_version = r.path_version;
    ++sum.cycles;
    if (r.planned) {
      sum.samples += static_cast<double>(loop.navigator->plan_result().samples.size());
      sum.admissible += loop.navigator->plan_result().admissible_count();
    }
  }
  sum.steps = loop.preset.params.n_steps();
  sum.pose_ops = bench::pose_operations(loop.footprint);
  sum.beams = loop.lidar.beams;
}

BENCHMARK_CAPTURE(BM_NavigatorStep, circle, std::string("circle"), 4)->Arg(0)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMicrosecond)->Iterations(3000);
BENCHMARK_CAPTURE(BM_NavigatorStep, jackal, std::string("jackal"), 4)->Arg(0)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMicrosecond)->Iterations(3000);
BENCHMARK_CAPTURE(BM_NavigatorStep, jackal_20_movers, std::string("jackal"), 20)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMicrosecond)->Iterations(3000);

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
}

}  // namespace
}  // namespace fgdwa

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::printf("\nNavigator::step, 541 beams with %.0f cm range noise, moving discs tracked (ms):\n", 100 * fgdwa::kNoise);
  std::printf("%-40s %7s %7s %7s %7s %7s | mean per stage: %6s %6s %6s %6s %6s %6s | %s\n", "robot map", "cycles",
              "median", "p95", "p99", "max", "locate", "track", "map", "global", "percep", "plan", "replans");
  for (const auto& [name, times] : fgdwa::samples()) {
    if (times.empty()) continue;
    const fgdwa::Stages& s = fgdwa::stages()[name];
    const double n = static_cast<double>(times.size());
    std::printf("%-40s %7zu %7.3f %7.3f %7.3f %7.3f | ", name.c_str(), times.size(),
                1e3 * fgdwa::percentile(times, 0.5), 1e3 * fgdwa::percentile(times, 0.95),
                1e3 * fgdwa::percentile(times, 0.99), 1e3 * *std::max_element(times.begin(), times.end()));
    fgdwa::print_stage_means(s.times, n);
    std::printf(" | %d\n", s.replans);
  }
  // The cycles above the 99th percentile: the mean of each stage over them, and how many replanned.
  std::printf("\nThe slowest 1 %% of cycles (ms):\n");
  std::printf("%-40s %7s %7s | mean per stage: %6s %6s %6s %6s %6s %6s | %s %s\n", "robot map", "cycles", "mean",
              "locate", "track", "map", "global", "percep", "plan", "replanned", "evaded");
  for (const auto& [name, times] : fgdwa::samples()) {
    if (times.empty()) continue;
    const std::vector<fgdwa::CycleStages>& each = fgdwa::cycle_stages()[name];
    const double p99 = fgdwa::percentile(times, 0.99);
    fgdwa::StageTimes sum;
    double total = 0.0;
    int count = 0, replanned = 0, evaded = 0;
    for (std::size_t i = 0; i < times.size(); ++i) {
      if (times[i] <= p99) continue;
      fgdwa::add(sum, each[i].times);
      total += times[i];
      ++count;
      replanned += each[i].replanned;
      evaded += each[i].evaded;
    }
    if (count == 0) continue;
    std::printf("%-40s %7d %7.3f | ", name.c_str(), count, 1e3 * total / count);
    fgdwa::print_stage_means(sum, count);
    std::printf(" | %9d %6d\n", replanned, evaded);
  }
  // The floor counts a cycle's planning (every rollout stepped and bounded,
  // the DTW of the admissible ones) and the scan's beams marked in the map:
  // the means over the cycles. Tracking, the map's ray tracing and its field
  // are left out.
  const fgdwa::bench::Machine machine = fgdwa::bench::measured_machine();
  fgdwa::bench::print_floor_header(machine);
  for (const auto& [name, times] : fgdwa::samples()) {
    if (times.empty()) continue;
    const fgdwa::Stages& s = fgdwa::stages()[name];
    const std::vector<fgdwa::bench::Work> work = {
        {"poses", s.samples / s.cycles * s.steps, s.pose_ops, false},
        {"DTW cells", s.admissible / s.cycles * s.steps * s.steps, fgdwa::bench::kDtwCellOps, true},
        {"beams", s.beams, fgdwa::bench::kBeamOps, false}};
    const bool circle = name.rfind("circle", 0) == 0;
    fgdwa::bench::print_floor("Navigator::step, " + name, 1e6 * fgdwa::percentile(times, 0.5), work,
                              circle ? 500 : name.find("movers") != std::string::npos ? 2000 : 1000, machine);
  }
  return 0;
}
