// One control cycle of the classic DWA: 21 x 21 samples, 20 poses per rollout
// (dt 0.15 s, 3 s horizon), a 10 m x 10 m map at 0.1 m with 15 % of its cells
// in seeded random rectangles, a circle footprint of 0.25 m, the robot cruising
// at 0.6 m/s. LocalPlanner::plan is timed with each clearance source: the
// distance field (FieldClearance) and the exact FCL world (CollisionWorld).
//
//   build/cpp/cpp/bench/bench_planner   (median of 10 repetitions, in microseconds)
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/collision.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/planner.hpp"

namespace {

using namespace fgdwa;

constexpr int kCells = 100;
constexpr double kResolution = 0.1;

// Obstacles come as rectangles of 1-8 cells a side, as in real maps; cells within
// 0.6 m of the start stay free so the robot starts clear of them.
OccupancyGrid random_map(unsigned seed, const Vec2& start) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> side(1, 8), cell(0, kCells - 1);
  std::vector<std::uint8_t> cells(kCells * kCells, 0);
  const std::size_t target = static_cast<std::size_t>(0.15 * kCells * kCells);
  std::size_t occupied = 0;
  while (occupied < target) {
    const int r0 = cell(rng), c0 = cell(rng), h = side(rng), w = side(rng);
    for (int r = r0; r < std::min(kCells, r0 + h); ++r)
      for (int c = c0; c < std::min(kCells, c0 + w); ++c) {
        const Vec2 centre((c + 0.5) * kResolution, (r + 0.5) * kResolution);
        auto& value = cells[static_cast<std::size_t>(r) * kCells + c];
        if (value || (centre - start).norm() < 0.6) continue;
        value = 1;
        ++occupied;
      }
  }
  return OccupancyGrid(kCells, kCells, kResolution, Vec2::Zero(), std::move(cells));
}

struct Scene {
  Vec2 start{5.0, 5.0};
  Vec2 goal{9.5, 9.0};
  OccupancyGrid grid = random_map(42, start);
  RobotState state{Pose2{start.x(), start.y(), 0.7}, Twist{0.6, 0.0}};
  LocalPlanner planner{RobotLimits{}, Footprint::circle(0.25), PlannerParams{}};  // 21 x 21, dt 0.15, 3 s
};

void report(benchmark::State& bench, const PlanResult& result) {
  bench.counters["samples"] = static_cast<double>(result.samples.size());
  bench.counters["admissible"] = result.admissible_count();
}

void BM_PlanFieldClearance(benchmark::State& bench) {
  Scene scene;
  const FieldClearance world(std::make_shared<const DistanceField>(scene.grid));
  for (auto _ : bench) benchmark::DoNotOptimize(scene.planner.plan(scene.state, scene.goal, world).command);
  report(bench, scene.planner.last_result());
}

void BM_PlanCollisionWorld(benchmark::State& bench) {
  Scene scene;
  const CollisionWorld world(scene.grid);
  for (auto _ : bench) benchmark::DoNotOptimize(scene.planner.plan(scene.state, scene.goal, world).command);
  report(bench, scene.planner.last_result());
}

// Building the clearance sources is a per-map cost, not a per-cycle one.
void BM_BuildDistanceField(benchmark::State& bench) {
  const Scene scene;
  for (auto _ : bench) benchmark::DoNotOptimize(DistanceField(scene.grid).has_obstacles());
}

void BM_BuildCollisionWorld(benchmark::State& bench) {
  const Scene scene;
  for (auto _ : bench) benchmark::DoNotOptimize(CollisionWorld(scene.grid).boxes().size());
}

BENCHMARK(BM_PlanFieldClearance)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_PlanCollisionWorld)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_BuildDistanceField)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);
BENCHMARK(BM_BuildCollisionWorld)->Unit(benchmark::kMicrosecond)->Repetitions(10)->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
