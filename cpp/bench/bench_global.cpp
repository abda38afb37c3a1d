// Global planning on a cluttered map: a 200 x 200 grid at 0.1 m (20 m x 20 m)
// with 20 % of its cells occupied uniformly at random (seed 7), start and goal
// at the centres of the lower-left and upper-right corner cells (their 2 x 2
// corner blocks cleared). Obstacles are NOT inflated (inflation radius 0): the
// robot is a point, so A* and OMPL search the same free cells.
//
// (a) BM_AStar: AStarPlanner::plan alone (the planner, its inflated grid and
//     distance field are built once, outside the timing), median of 20
//     repetitions; the target is a median <= 10 ms. Arg: line-of-sight
//     simplification off (0) / on (1, the default).
// (b) BM_Ompl/<planner>: 20 runs with OmplParams.seed = 0..19 and a 0.1 s
//     budget each; the reported time is the summed planning_time (setup, solve
//     and simplification; the planner's construction is not counted). Cost is
//     path length only (w_clearance = 0, no terrain grid, so the terrain term is
//     off), the same measure as A*'s cost, which is the length of its 8-connected
//     cell path (no terrain: every step costs its length). Counters: success
//     rate, and over the successful runs the mean and median of OMPL's cost / A*'s
//     cost, and of OMPL's cost / the length of A*'s simplified path (any-angle
//     shortcuts, the fairer yardstick for OMPL's straight edges). The budget is
//     wall-clock time, so on a busy machine the planners get fewer iterations
//     and the success rates drop: read them together with the load average
//     printed in the header; the same seed gives the same path only for the
//     same number of iterations.
//
//   build/cmake/cpp/bench/bench_global                  (all, about 30 s)
//   build/cmake/cpp/bench/bench_global --benchmark_filter=AStar
//
// Before the benchmarks the map and A*'s path are printed, after them a
// summary of the OMPL runs. ("Library was built as DEBUG" in the output is
// about Debian's libbenchmark itself; fgdwa builds as Release by default.)
#include <benchmark/benchmark.h>

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "fgdwa/global_planner.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/robot.hpp"
#include "bench_maps.hpp"

namespace {

using namespace fgdwa;

constexpr int kCells = 200;
constexpr double kResolution = 0.1;
constexpr double kObstacleFraction = 0.2;
constexpr unsigned kMapSeed = 7;
constexpr int kOmplSeeds = 20;
constexpr double kOmplBudget = 0.1;  // s per run

double polyline_length(const std::vector<Vec2>& path) {
  double length = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) length += (path[i] - path[i - 1]).norm();
  return length;
}

double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double mean(const std::vector<double>& v) {
  return v.empty() ? NAN : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

AStarParams astar_params(bool simplify) {
  AStarParams p;
  p.inflation_radius = 0.0;  // a point robot: obstacles are the occupied cells themselves
  p.simplify = simplify;
  return p;
}

struct Scene {
  OccupancyGrid grid;
  Vec2 start, goal;
  GlobalPlan astar;         // simplified, as the planner returns by default
  GlobalPlan astar_cells;   // the 8-connected cell path itself
  double astar_length = 0;  // length of the simplified path

  Scene() : grid(make_grid()), start(grid.cell_center(0, 0)), goal(grid.cell_center(kCells - 1, kCells - 1)) {
    astar = AStarPlanner(grid, astar_params(true)).plan(start, goal);
    astar_cells = AStarPlanner(grid, astar_params(false)).plan(start, goal);
    astar_length = polyline_length(astar.path);
  }

  static OccupancyGrid make_grid() {
    std::mt19937 rng(kMapSeed);
    return bench::random_cell_map(rng, kCells, kResolution, kObstacleFraction);
  }
};

const Scene& scene() {
  static const Scene s;
  return s;
}

void BM_AStar(benchmark::State& bench) {
  const Scene& s = scene();
  const AStarPlanner planner(s.grid, astar_params(bench.range(0) != 0));
  GlobalPlan plan;
  for (auto _ : bench) {
    plan = planner.plan(s.start, s.goal);
    benchmark::DoNotOptimize(plan.cost);
  }
  bench.counters["found"] = plan.status == GlobalStatus::Found ? 1.0 : 0.0;
  bench.counters["cost_m"] = plan.cost;
  bench.counters["length_m"] = polyline_length(plan.path);
  bench.counters["vertices"] = static_cast<double>(plan.path.size());
}
BENCHMARK(BM_AStar)->ArgName("simplify")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)
    ->MinTime(0.05)->Repetitions(20)->ReportAggregatesOnly(true);

// Scale (a 200 m x 200 m building at 5 cm): a 4000 x 4000 map, 3 % of its
// cells occupied at random, planned corner to corner. Build and plan are timed
// once each; the memory is the A* planner's own (the map copy, the blocked
// cells) plus the peak its search added.
constexpr int kLargeSide = 4000;

OccupancyGrid large_map(int side = kLargeSide) {
  std::mt19937 rng(11);
  std::bernoulli_distribution occupied(0.03);
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(side) * side);
  for (auto& c : cells) c = occupied(rng) ? 1 : 0;
  for (int r = 0; r < 10; ++r)
    for (int c = 0; c < 10; ++c)
      cells[static_cast<std::size_t>(r) * side + c] = cells[static_cast<std::size_t>(side - 1 - r) * side + side - 1 - c] = 0;
  return OccupancyGrid(side, side, 0.05, Vec2(0, 0), std::move(cells));
}

// A line of /proc/self/status in MiB (the kernel writes kB); NaN if missing.
double status_mib(const std::string& key) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind(key, 0) == 0) return std::stod(line.substr(key.size())) / 1024.0;
  return NAN;
}

// The peak resident memory added since construction, in MiB. The peak
// (VmHWM) is reset to the present first: getrusage's ru_maxrss cannot be
// reset, and a benchmark run after a hungrier one (the field after A*) would
// see only what it added above that one's peak. Freed heap memory goes back
// to the system first too, or memory an earlier benchmark freed would be
// reused unseen. NaN where the reset is refused.
class AddedPeak {
 public:
  AddedPeak() {
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
    before_ = status_mib("VmRSS:");
    if (!(status_mib("VmHWM:") <= before_ + 1.0)) before_ = NAN;
  }
  double mib() const { return status_mib("VmHWM:") - before_; }

 private:
  double before_;
};

double seconds_since(std::chrono::steady_clock::time_point tic) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - tic).count();
}

void BM_AStarLargeMap(benchmark::State& bench) {
  constexpr int kSide = kLargeSide;
  const OccupancyGrid grid = large_map();
  AStarParams params;
  params.inflation_radius = 0.05;
  const AddedPeak peak;
  double build = 0.0, plan_time = 0.0;
  GlobalPlan plan;
  for (auto _ : bench) {
    const auto tic = std::chrono::steady_clock::now();
    const AStarPlanner planner(grid, params);
    build = seconds_since(tic);
    plan = planner.plan(Vec2(0.1, 0.1), Vec2(kSide * 0.05 - 0.1, kSide * 0.05 - 0.1));
    plan_time = plan.planning_time;
  }
  bench.counters["build_s"] = build;
  bench.counters["plan_s"] = plan_time;
  bench.counters["found"] = plan.status == GlobalStatus::Found ? 1.0 : 0.0;
  bench.counters["added_peak_MiB"] = peak.mib();
  std::printf("target (issue 15): A* on 4000 x 4000 within 2 s and 500 MB\n");
}
BENCHMARK(BM_AStarLargeMap)->Unit(benchmark::kMillisecond)->Iterations(1);

// The same map's distance field (Arg: its side in cells, 4000 the map above):
// its build; its memory, what it holds (bytes_per_cell x cells) next to the
// peak resident memory its build and updates added, which is larger by
// whatever they hold only for a while; and what an update costs with nothing
// changed (every cell compared), with one cell named, and with a 5 m x 5 m
// area cleared and put back (its 10 000 cells named).
void BM_DistanceFieldLargeMap(benchmark::State& bench) {
  const int side = static_cast<int>(bench.range(0));
  OccupancyGrid grid = large_map(side);
  const AddedPeak peak;
  double build = 0.0, unchanged = 0.0, one_cell = 0.0, area = 0.0, bytes = 0.0;
  for (auto _ : bench) {
    auto tic = std::chrono::steady_clock::now();
    DistanceField field(grid);
    build = seconds_since(tic);
    bytes = field.bytes_per_cell();
    tic = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(field.update(grid));
    unchanged = seconds_since(tic);
    std::mt19937 rng(5);
    std::uniform_int_distribution<std::size_t> cell(0, grid.cells().size() - 1);
    constexpr int kFlips = 20;
    tic = std::chrono::steady_clock::now();
    for (int k = 0; k < kFlips; ++k) {
      const std::size_t i = cell(rng);
      grid.set(i, grid.cells()[i] == 0);
      benchmark::DoNotOptimize(field.update(grid, {i}));
      grid.set(i, grid.cells()[i] == 0);
      benchmark::DoNotOptimize(field.update(grid, {i}));
    }
    one_cell = seconds_since(tic) / (2 * kFlips);
    std::vector<std::size_t> block;
    std::vector<std::uint8_t> kept;
    for (int r = side / 4; r < side / 4 + 100; ++r)
      for (int c = side / 4; c < side / 4 + 100; ++c) {
        block.push_back(static_cast<std::size_t>(r) * side + c);
        kept.push_back(grid.cells()[block.back()]);
      }
    tic = std::chrono::steady_clock::now();
    for (std::size_t i : block) grid.set(i, false);
    benchmark::DoNotOptimize(field.update(grid, block));
    for (std::size_t k = 0; k < block.size(); ++k) grid.set(block[k], kept[k] != 0);
    benchmark::DoNotOptimize(field.update(grid, block));
    area = seconds_since(tic) / 2;
  }
  bench.counters["build_s"] = build;
  bench.counters["bytes_per_cell"] = bytes;
  bench.counters["held_MiB"] = bytes * static_cast<double>(grid.cells().size()) / (1 << 20);
  bench.counters["added_peak_MiB"] = peak.mib();
  bench.counters["update_unchanged_s"] = unchanged;
  bench.counters["update_one_cell_ms"] = one_cell * 1e3;
  bench.counters["update_5m_area_ms"] = area * 1e3;
  if (side == kLargeSide)
    std::printf("target (issue 15): a distance field within 32 bytes per cell; updates in proportion to the change\n");
}
BENCHMARK(BM_DistanceFieldLargeMap)->ArgName("side")->Arg(1000)->Arg(2000)->Arg(kLargeSide)->Unit(benchmark::kMillisecond)->Iterations(1);

struct OmplSummary {
  int runs = 0, found = 0;
  std::vector<double> ratio_cost, ratio_length, costs, times_found, times_all;
  double worst_cost_vs_length = 0.0;  // max |cost - polyline length| over found paths: is the cost a length?
};
std::map<std::string, OmplSummary>& ompl_summaries() {
  static std::map<std::string, OmplSummary> m;
  return m;
}
std::vector<std::string>& ompl_order() {
  static std::vector<std::string> v;
  return v;
}

void BM_Ompl(benchmark::State& bench, const std::string& name) {
  const Scene& s = scene();
  OmplSummary summary;
  for (auto _ : bench) {
    summary = OmplSummary{};
    double elapsed = 0.0;
    for (int seed = 0; seed < kOmplSeeds; ++seed) {
      OmplParams params;
      params.planner = name;
      params.time_limit = kOmplBudget;
      params.seed = static_cast<std::uint32_t>(seed);
      params.inflation_radius = 0.0;
      params.w_length = 1.0;
      params.w_clearance = 0.0;  // cost = path length; no terrain grid is given, so no terrain term
      // A circle footprint plans over R^2 on the inflated grid; with inflation 0 its radius is unused.
      const OmplPlanner planner(s.grid, Footprint::circle(0.25), params);
      const GlobalPlan plan = planner.plan(s.start, s.goal);
      elapsed += plan.planning_time;
      ++summary.runs;
      summary.times_all.push_back(plan.planning_time);
      if (plan.status != GlobalStatus::Found) continue;
      ++summary.found;
      summary.costs.push_back(plan.cost);
      summary.times_found.push_back(plan.planning_time);
      summary.ratio_cost.push_back(plan.cost / s.astar.cost);
      summary.ratio_length.push_back(plan.cost / s.astar_length);
      summary.worst_cost_vs_length =
          std::max(summary.worst_cost_vs_length, std::abs(plan.cost - polyline_length(plan.path)));
    }
    bench.SetIterationTime(elapsed);
  }
  bench.counters["success"] = static_cast<double>(summary.found) / summary.runs;
  bench.counters["vsA*cost_mean"] = mean(summary.ratio_cost);
  bench.counters["vsA*cost_med"] = median(summary.ratio_cost);
  bench.counters["vsA*len_med"] = median(summary.ratio_length);
  if (!ompl_summaries().count(name)) ompl_order().push_back(name);
  ompl_summaries()[name] = summary;
}
// One iteration = 20 seeded runs, ~2 s.
#define FGDWA_OMPL(planner)                                                                              \
  BENCHMARK_CAPTURE(BM_Ompl, planner, std::string(#planner))->Iterations(1)->UseManualTime()->Unit(      \
      benchmark::kMillisecond)
FGDWA_OMPL(RRTstar);
FGDWA_OMPL(InformedRRTstar);
FGDWA_OMPL(BITstar);
FGDWA_OMPL(RRTConnect);

void print_scene() {
  const Scene& s = scene();
  std::printf("Map: %d x %d cells at %.2f m, %zu occupied (%.1f %%), seed %u; inflation radius 0 (point robot)\n",
              kCells, kCells, kResolution, s.grid.occupied_count(),
              100.0 * static_cast<double>(s.grid.occupied_count()) / (kCells * kCells), kMapSeed);
  std::printf("Start (%.2f, %.2f), goal (%.2f, %.2f), straight-line distance %.3f m\n", s.start.x(), s.start.y(),
              s.goal.x(), s.goal.y(), (s.goal - s.start).norm());
  std::printf("A*: %s, cost %.4f m; its cell path has %zu cells and length %.4f m (cost - length = %.2g: "
              "without terrain the cost is the length)\n",
              to_string(s.astar.status), s.astar.cost, s.astar_cells.path.size(), polyline_length(s.astar_cells.path),
              s.astar.cost - polyline_length(s.astar_cells.path));
  std::printf("A* simplified path: %zu vertices, length %.4f m:\n ", s.astar.path.size(), s.astar_length);
  for (std::size_t i = 0; i < s.astar.path.size(); ++i)
    std::printf(" (%.2f, %.2f)%s", s.astar.path[i].x(), s.astar.path[i].y(), (i + 1) % 8 == 0 ? "\n " : "");
  std::printf("\n\n");
}

void print_ompl_summary() {
  if (ompl_order().empty()) return;
  const Scene& s = scene();
  std::printf("\nOMPL, %d seeds x %.2f s budget, cost = path length; A* cost %.3f m, A* simplified length %.3f m\n",
              kOmplSeeds, kOmplBudget, s.astar.cost, s.astar_length);
  std::printf("%-16s %8s %11s %11s %11s %11s %11s %12s %14s\n", "planner", "success", "cost mean", "cost median",
              "/A* mean", "/A* median", "/A*len med", "time med ms", "|cost-len| max");
  for (const std::string& name : ompl_order()) {
    const OmplSummary& r = ompl_summaries()[name];
    std::printf("%-16s %5d/%-2d %11.3f %11.3f %11.3f %11.3f %11.3f %12.1f %14.2g\n", name.c_str(), r.found, r.runs,
                mean(r.costs), median(r.costs), mean(r.ratio_cost), median(r.ratio_cost), median(r.ratio_length),
                1e3 * median(r.times_all), r.worst_cost_vs_length);
  }
  std::printf("(/A*: OMPL cost over A*'s cost, successful runs only; /A*len: over A*'s simplified path length;\n"
              " time: planning_time per run incl. setup and simplification, all runs; |cost-len|: OMPL's cost\n"
              " against its path's polyline length, which should agree when the cost is length only)\n");
}

}  // namespace

int main(int argc, char** argv) {
  // Large blocks always from mmap, back to the system when freed. glibc raises
  // this threshold after the first large free, and buffers freed later (a
  // vector's as it grows) then stay resident in the heap: a benchmark's peak
  // would depend on which ran before it.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  print_scene();
  benchmark::RunSpecifiedBenchmarks();
  print_ompl_summary();
  benchmark::Shutdown();
  return 0;
}
