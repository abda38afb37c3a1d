// One full FGDWA control cycle and where its time goes.
//
// The world: bench_planner's map (10 m x 10 m at 0.1 m, 15 % of the cells in
// seeded random rectangles, seed 42; bench_maps.hpp). A global path from A*
// (inflation 0.25 m, the footprint's radius) between free points near the
// upper-left and lower-right corners is set on the planner. The robot (circle
// of 0.25 m, default limits) stands on the path, heading along it at 0.6 m/s.
// The true world is the map, so every lidar hit is explained by the map and
// no sensed obstacle reaches the planner (the table printed first shows the
// count of unexplained hits per position).
//
// The cycle, as a robot runs it: LaserScanner::scan, then Controller::step
// (controller.hpp) with the fgdwa preset's parameters and weight policy:
//   scan    LaserScanner::scan: 541 beams over 270 deg, max range 10 m, no noise
//   sensed  the hits the map does not explain, as a points_field for the planner
//   I, D    obstacle_density (detect window +-60 deg, R 2 m) and GlobalPath::deviation
//   fuzzy   FuzzyWeights::weights(I, D) -> clearance and similarity weights; set_weight on the planner
//   plan    LocalPlanner::plan with planner_preset("fgdwa").params: 21 x 21
//           samples, 20 steps (dt 0.15 s, sim_time 3 s), heading to key nodes,
//           critics heading, clearance, velocity and similarity (DTW of every
//           admissible rollout against 20 reference samples, no band).
//
// Each benchmark walks its argument's count of positions on the path in turn
// (1: the same place cycle after cycle, as a robot sees it; 16: positions from
// 10 % to 90 % of the path, a spread of situations), one cycle per iteration,
// so every figure is per cycle. How each stage of the breakdown is measured,
// with the public API only:
//   BM_Cycle          the whole cycle above.
//   BM_NavigatorCycle the same cycle through Navigator::step (known map, the
//                     same path handed over, stalls off since the robot never
//                     moves): the map stage, the blocked-path check every
//                     replan_period, the record with its 5 best rollouts.
//   BM_Scan           LaserScanner::scan alone.
//   BM_Sensed         what Controller::step does with the scan before the
//                     planner, redone with the public API: hit_points, the map's
//                     distance at each hit, points_field of those it leaves.
//   BM_DensityDeviation  obstacle_density on the position's scan + GlobalPath::deviation.
//   BM_Fuzzy          FuzzyWeights::weights(I, D) with the position's I and D.
//   BM_Plan           LocalPlanner::plan alone (with the two set_weight calls).
//   BM_PlanNoSimilarity  the same without the similarity critic. Critics do
//                     not change rollouts, clearance or admissibility, so
//                     BM_Plan - BM_PlanNoSimilarity is the similarity critic:
//                     its reference samples and one DTW per admissible sample.
//   BM_PlanEmptyWorld plan() against a FieldClearance with no obstacles.
//                     BM_Plan - BM_PlanEmptyWorld is checking the rollouts
//                     against the map: clearance queries and the sweep checks
//                     between poses. Valid as long as both worlds leave the same
//                     number of samples for the critics to score; the table
//                     printed before the benchmarks shows both counts.
//   BM_Rollouts       rollout generation: dynamic_window, sample_window, and the
//                     public rollout() of every sample into reused trajectories
//                     (the planner may generate them its own, faster, way).
//   BM_OtherCritics   heading, clearance and velocity critics built from the
//                     preset's configuration: prepare + score on the admissible
//                     rollouts recorded from the position's cycle.
//   rest              BM_Cycle minus scan, sensed, I + D, fuzzy, rollouts,
//                     clearance (difference), similarity (difference) and the
//                     other critics: admissibility, normalisation, choosing,
//                     key-node tracking, set_weight, the controller's glue.
// Cross-check: BM_Similarity replays the similarity critic directly (prepare,
// then score_all on the recorded admissible rollouts, as plan() does) outside the planner.
//
//   build/cmake/cpp/bench/bench_fgdwa      (about 25 s; the target for BM_Cycle is a median <= 0.15 ms)
//
// A summary table follows the benchmarks, then the whole cycle next to its
// arithmetic floor (bench_floor.hpp). ("Library was built as DEBUG" in the
// output is about Debian's libbenchmark itself; fgdwa builds as Release.)
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/controller.hpp"
#include "fgdwa/navigator.hpp"
#include "fgdwa/critics.hpp"
#include "fgdwa/dtw.hpp"
#include "fgdwa/global_planner.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/presets.hpp"
#include "fgdwa/weights.hpp"
#include "fgdwa/window.hpp"
#include "bench_floor.hpp"
#include "bench_maps.hpp"

namespace {

using namespace fgdwa;

constexpr int kPositions = 16;
constexpr double kSpeed = 0.6;  // m/s
const std::vector<Disc> kNoDiscs;

// A free point near `corner`: the nearest cell centre at least `margin` from obstacles.
Vec2 free_point_near(const DistanceField& field, const Vec2& corner, double margin) {
  const OccupancyGrid& g = field.grid();
  Vec2 best = corner;
  double best_d = INFINITY;
  for (int r = 0; r < g.rows(); ++r)
    for (int c = 0; c < g.cols(); ++c) {
      const Vec2 p = g.cell_center(r, c);
      const double d = (p - corner).norm();
      if (d < best_d && field.distance(p) >= margin) best = p, best_d = d;
    }
  return best;
}

// What one position holds: the state, its planners (warm), and what its cycle
// saw, for the stage benchmarks to replay.
struct Position {
  RobotState state;
  Scan scan;
  double density = 0.0, deviation = 0.0;  // I and D, as the controller read them
  double beta = 0.0, delta = 0.0;          // the clearance and similarity weights it set
  std::size_t sensed_points = 0;           // hits the map does not explain
  int admissible_empty = 0;  // admissible samples against a world without obstacles
  CriticContext context;
  std::vector<Trajectory> trajectories;  // the admissible rollouts' poses
  std::vector<Rollout> admissible;       // pointing into `trajectories`
  Status status = Status::Ok;
  int samples = 0;
  Twist command;
};

struct Scene {
  std::mt19937 rng{42};
  OccupancyGrid grid = bench::rectangle_map(rng);  // 100 x 100 at 0.1 m, 15 % occupied, as in bench_planner
  std::shared_ptr<const DistanceField> field = std::make_shared<const DistanceField>(grid);
  FieldClearance world{field};
  FieldClearance empty_world;  // no obstacles at all
  PlannerPreset preset = planner_preset("fgdwa");
  std::shared_ptr<WeightPolicy> policy = preset.weight_policy();
  RobotLimits limits;
  Footprint footprint = Footprint::circle(0.25);
  LaserScanner scanner{LidarParams{}, field};
  DetectWindowParams window;
  std::mt19937_64 noise{1};  // unused: the lidar has no noise
  Vec2 start, goal;
  GlobalPlan global;
  std::unique_ptr<GlobalPath> path;
  std::vector<Position> positions;
  std::vector<Controller> controllers;  // the cycle
  std::vector<Navigator> navigators;    // the same cycle through the Navigator
  std::vector<LocalPlanner> planners, planners_no_similarity;  // the stage benchmarks' planners

  Scene() {
    // Upper-left to lower-right: on this map the other diagonal has no way
    // through for a 0.25 m robot.
    start = free_point_near(*field, Vec2(0.5, 9.5), 0.4);
    goal = free_point_near(*field, Vec2(9.5, 0.5), 0.4);
    global = AStarPlanner(grid, AStarParams{}).plan(start, goal);
    if (global.status != GlobalStatus::Found) throw std::runtime_error("bench_fgdwa: A* found no path on the map");
    path = std::make_unique<GlobalPath>(global.path);
    if (!policy) throw std::runtime_error("bench_fgdwa: the fgdwa preset has no weight policy");

    PlannerParams no_similarity = preset.params;
    no_similarity.critics.erase(std::remove_if(no_similarity.critics.begin(), no_similarity.critics.end(),
                                               [](const CriticConfig& c) { return c.name == "similarity"; }),
                                no_similarity.critics.end());
    // 16 places spread evenly over 10-90 % of the path; one where the
    // footprint would clear obstacles by less than 5 cm moves on along the
    // path in steps of 1 % until it does.
    const double length = path->length();
    positions.reserve(kPositions);
    controllers.reserve(kPositions);
    navigators.reserve(kPositions);
    planners.reserve(kPositions);
    planners_no_similarity.reserve(kPositions);
    for (int i = 0; i < kPositions; ++i) {
      double s = length * (0.1 + 0.8 * i / (kPositions - 1));
      while (field->distance(path->point_at(s)) < footprint.radius() + 0.05 && s < length) s += 0.01 * length;
      const Vec2 p = path->point_at(s);
      Position pos;
      pos.state = RobotState{Pose2{p.x(), p.y(), path->segment_direction(path->segment_at(s))}, Twist{kSpeed, 0.0}};
      positions.push_back(std::move(pos));
      // Its own copy of the map's field, as each navigator builds its own: the same memory to walk.
      controllers.emplace_back(limits, footprint, preset.params, std::make_shared<const DistanceField>(grid), policy,
                               window);
      controllers.back().set_global_path(*path);
      NavigatorParams held;
      held.stall_time = 0.0;
      navigators.emplace_back(limits, footprint, preset.params, grid, MapMode::Known, LidarParams{}, policy, held,
                              std::nullopt, kDefaultPassingFactors, window);
      navigators.back().set_goal(goal);
      navigators.back().set_global_path(*path);
      planners.emplace_back(limits, footprint, preset.params);
      planners.back().set_global_path(*path);
      planners_no_similarity.emplace_back(limits, footprint, no_similarity);
      planners_no_similarity.back().set_global_path(*path);
    }
    // Position 0 (the one Arg(1) uses) is the middle of the path.
    std::rotate(positions.begin(), positions.begin() + kPositions / 2, positions.end());
    // One cycle per position: warms the planners (buffers, key-node tracking)
    // and records what the stage benchmarks replay.
    for (int i = 0; i < kPositions; ++i) {
      Position& pos = positions[static_cast<std::size_t>(i)];
      LocalPlanner& planner = planners[static_cast<std::size_t>(i)];
      cycle(static_cast<std::size_t>(i));
      navigator_cycle(static_cast<std::size_t>(i));
      const CycleReport& report = controllers[static_cast<std::size_t>(i)].report();
      pos.density = report.density;
      pos.deviation = report.deviation;
      pos.beta = report.beta;
      pos.delta = report.delta;
      pos.sensed_points = report.sensed_points;
      for (LocalPlanner* pl : {&planner, &planners_no_similarity[static_cast<std::size_t>(i)]}) {
        pl->set_weight("clearance", pos.beta);
        if (pl == &planner) pl->set_weight("similarity", pos.delta);
        pl->plan(pos.state, goal, world);
      }
      pos.admissible_empty = planner.plan(pos.state, goal, empty_world).admissible_count();
      const PlanResult& result = planner.plan(pos.state, goal, world);
      pos.status = result.status;
      pos.samples = static_cast<int>(result.samples.size());
      pos.command = result.command;
      pos.context.state = pos.state;
      pos.context.goal = goal;
      pos.context.target = result.target;
      pos.context.dt = preset.params.dt;
      pos.context.n_steps = preset.params.n_steps();
      pos.context.path = path.get();
      pos.context.v_max = limits.v_max;
      for (std::size_t k = 0; k < result.samples.size(); ++k)
        if (result.reasons[k] == RejectReason::None) pos.trajectories.push_back(planner.rollouts()[k]);
      std::size_t t = 0;
      for (std::size_t k = 0; k < result.samples.size(); ++k) {
        if (result.reasons[k] != RejectReason::None) continue;
        Rollout r;
        r.command = result.samples[k];
        r.poses = &pos.trajectories[t++];
        r.min_clearance = result.min_clearance[k];
        r.free_distance = result.free_distance[k];
        pos.admissible.push_back(r);
      }
    }
  }

  void cycle(std::size_t i) {
    Position& pos = positions[i];
    scanner.scan(pos.state.pose, kNoDiscs, 0.0, noise, pos.scan);
    benchmark::DoNotOptimize(controllers[i].step(pos.state, goal, &pos.scan).command);
  }

  void navigator_cycle(std::size_t i) {
    Position& pos = positions[i];
    scanner.scan(pos.state.pose, kNoDiscs, 0.0, noise, pos.scan);
    benchmark::DoNotOptimize(navigators[i].step(pos.state, &pos.scan, 0.0).command);
  }
};

Scene& scene() {
  static Scene s;
  return s;
}

// Runs `body(position index)` once per iteration over the first range(0) positions.
template <class Body>
void over_positions(benchmark::State& bench, Body body) {
  const std::size_t n = static_cast<std::size_t>(bench.range(0));
  std::size_t i = 0;
  for (auto _ : bench) {
    body(i);
    i = (i + 1) % n;
  }
}

void BM_Cycle(benchmark::State& bench) {
  Scene& s = scene();
  over_positions(bench, [&](std::size_t i) { s.cycle(i); });
}

void BM_NavigatorCycle(benchmark::State& bench) {
  Scene& s = scene();
  over_positions(bench, [&](std::size_t i) { s.navigator_cycle(i); });
}

void BM_Scan(benchmark::State& bench) {
  Scene& s = scene();
  Scan scan;
  over_positions(bench, [&](std::size_t i) {
    s.scanner.scan(s.positions[i].state.pose, kNoDiscs, 0.0, s.noise, scan);
    benchmark::DoNotOptimize(scan.ranges.data());
  });
}

// As Controller::step: a hit within half a cell of the map's obstacles is
// explained (the lidar has no noise to add), settled by the table's upper
// bound where it can be.
void BM_Sensed(benchmark::State& bench) {
  Scene& s = scene();
  const double tolerance = 0.5 * s.grid.resolution();
  std::vector<Vec2> unexplained;
  over_positions(bench, [&](std::size_t i) {
    unexplained.clear();
    for (const Vec2& hit : s.positions[i].scan.hit_points())
      if (s.field->upper_bound(hit) > tolerance && s.field->distance(hit) > tolerance) unexplained.push_back(hit);
    benchmark::DoNotOptimize(points_field(unexplained, s.grid.resolution()));
  });
}

void BM_DensityDeviation(benchmark::State& bench) {
  Scene& s = scene();
  over_positions(bench, [&](std::size_t i) {
    const Position& pos = s.positions[i];
    benchmark::DoNotOptimize(obstacle_density(pos.scan, s.window).density);
    benchmark::DoNotOptimize(s.path->deviation(pos.state.pose.position()));
  });
}

void BM_Fuzzy(benchmark::State& bench) {
  Scene& s = scene();
  over_positions(bench, [&](std::size_t i) {
    benchmark::DoNotOptimize(s.policy->weights(s.positions[i].density, s.positions[i].deviation));
  });
}

void BM_Rollouts(benchmark::State& bench) {
  Scene& s = scene();
  const PlannerParams& p = s.preset.params;
  const int n_steps = p.n_steps();
  std::vector<Twist> samples;
  std::vector<Trajectory> trajectories(static_cast<std::size_t>(p.window.n_v * p.window.n_omega));
  over_positions(bench, [&](std::size_t i) {
    const RobotState& st = s.positions[i].state;
    sample_window(dynamic_window(s.limits, st.twist, p.dt), st.twist, p.window, samples);
    for (std::size_t k = 0; k < samples.size(); ++k) rollout(st.pose, samples[k], p.dt, n_steps, trajectories[k]);
    benchmark::DoNotOptimize(trajectories.data());
  });
}

void score_with(benchmark::State& bench, std::vector<std::unique_ptr<Critic>>& critics) {
  Scene& s = scene();
  std::vector<double> scores;
  over_positions(bench, [&](std::size_t i) {
    const Position& pos = s.positions[i];
    double sum = 0.0;
    scores.resize(pos.admissible.size());
    for (auto& critic : critics) {
      critic->prepare(pos.context);
      critic->score_all(pos.admissible, scores.data());
      for (double score : scores) sum += score;
    }
    benchmark::DoNotOptimize(sum);
  });
}

void BM_Similarity(benchmark::State& bench) {
  std::vector<std::unique_ptr<Critic>> critics;
  for (const CriticConfig& c : scene().preset.params.critics)
    if (c.name == "similarity") critics.push_back(make_critic(c));
  score_with(bench, critics);
}

void BM_OtherCritics(benchmark::State& bench) {
  std::vector<std::unique_ptr<Critic>> critics;
  for (const CriticConfig& c : scene().preset.params.critics)
    if (c.name != "similarity") critics.push_back(make_critic(c));
  score_with(bench, critics);
}

void plan_with(benchmark::State& bench, std::vector<LocalPlanner>& planners, bool similarity,
               const ClearanceSource& world) {
  Scene& s = scene();
  over_positions(bench, [&](std::size_t i) {
    const Position& pos = s.positions[i];
    planners[i].set_weight("clearance", pos.beta);
    if (similarity) planners[i].set_weight("similarity", pos.delta);
    benchmark::DoNotOptimize(planners[i].plan(pos.state, s.goal, world).command);
  });
}

void BM_Plan(benchmark::State& bench) { plan_with(bench, scene().planners, true, scene().world); }
void BM_PlanNoSimilarity(benchmark::State& bench) {
  plan_with(bench, scene().planners_no_similarity, false, scene().world);
}
void BM_PlanEmptyWorld(benchmark::State& bench) { plan_with(bench, scene().planners, true, scene().empty_world); }

double smallest(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }

// 20 repetitions of >= 30 ms each. Besides mean, median, stddev and cv, the
// minimum over repetitions: interference from other work on the machine only
// ever adds time, so the minimum is the steadiest estimate of a stage's own cost.
#define FGDWA_STAGE(fn)                                                                                 \
  BENCHMARK(fn)->ArgName("positions")->Arg(1)->Arg(kPositions)->Unit(benchmark::kMicrosecond)->MinTime( \
      0.03)->Repetitions(20)->ComputeStatistics("min", smallest)->ReportAggregatesOnly(true)
FGDWA_STAGE(BM_Cycle);
FGDWA_STAGE(BM_NavigatorCycle);
FGDWA_STAGE(BM_Scan);
FGDWA_STAGE(BM_Sensed);
FGDWA_STAGE(BM_DensityDeviation);
FGDWA_STAGE(BM_Fuzzy);
FGDWA_STAGE(BM_Plan);
FGDWA_STAGE(BM_PlanNoSimilarity);
FGDWA_STAGE(BM_PlanEmptyWorld);
FGDWA_STAGE(BM_Rollouts);
FGDWA_STAGE(BM_OtherCritics);
FGDWA_STAGE(BM_Similarity);

// Keeps the median and the coefficient of variation of every benchmark for the summary.
class SummaryReporter : public benchmark::ConsoleReporter {
 public:
  struct Figure {
    double median = NAN, min = NAN, cv = NAN;  // real time over the repetitions: median and minimum (us), cv
  };
  std::map<std::string, Figure> figures;  // "BM_Cycle/positions:1"

  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type != Run::RT_Aggregate) continue;
      const std::string key = run.run_name.function_name + "/" + run.run_name.args;
      // Times in the benchmark's unit (microseconds); the cv aggregate holds a fraction.
      if (run.aggregate_name == "median") figures[key].median = run.GetAdjustedRealTime();
      if (run.aggregate_name == "min") figures[key].min = run.GetAdjustedRealTime();
      if (run.aggregate_name == "cv") figures[key].cv = run.real_accumulated_time;
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

void print_scene() {
  Scene& s = scene();
  std::printf("Map: 100 x 100 at 0.1 m, %zu cells occupied (%.1f %%), rectangles, seed 42\n", s.grid.occupied_count(),
              100.0 * static_cast<double>(s.grid.occupied_count()) / 1e4);
  std::printf("Global path (A*, inflation 0.25 m): (%.2f, %.2f) -> (%.2f, %.2f), %zu vertices, %.2f m, %zu key nodes\n",
              s.start.x(), s.start.y(), s.goal.x(), s.goal.y(), s.path->points().size(), s.path->length(),
              s.planners[0].key_nodes().size());
  std::printf("Preset fgdwa: %d x %d samples, %d steps of %.2f s; critics:", s.preset.params.window.n_v,
              s.preset.params.window.n_omega, s.preset.params.n_steps(), s.preset.params.dt);
  for (const CriticConfig& c : s.preset.params.critics) std::printf(" %s", c.name.c_str());
  std::printf("; weights: %s\n", s.policy->name().c_str());
  std::printf("%3s %7s %7s %7s %6s %6s %6s %6s %6s %7s %7s %6s  %s\n", "pos", "x", "y", "theta", "I", "D", "beta",
              "delta", "sensed", "admis", "empty", "v", "status");
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    const Position& p = s.positions[i];
    std::printf("%3zu %7.2f %7.2f %7.2f %6.3f %6.3f %6.3f %6.3f %6zu %3zu/%-3d %7d %6.3f  %s\n", i, p.state.pose.x,
                p.state.pose.y, p.state.pose.theta, p.density, p.deviation, p.beta, p.delta,
                p.sensed_points, p.admissible.size(), p.samples, p.admissible_empty, p.command.v,
                to_string(p.status));
  }
  std::printf("(sensed: lidar hits the map does not explain; admis: admissible samples of all; empty: admissible\n"
              " against no obstacles; v: the chosen speed)\n\n");
}

void print_summary(const SummaryReporter& reporter) {
  if (reporter.figures.empty()) return;
  using Figure = SummaryReporter::Figure;
  const auto get = [&](const std::string& fn, int n) {
    auto it = reporter.figures.find(fn + "/positions:" + std::to_string(n));
    return it == reporter.figures.end() ? Figure{} : it->second;
  };
  const auto minus = [](const Figure& a, const Figure& b) { return Figure{a.median - b.median, a.min - b.min, NAN}; };
  std::printf("\nSummary: per cycle, microseconds of real time over the repetitions: median, cv (stddev / mean;\n"
              "none for differences) and minimum, with each one's share of the whole cycle's\n");
  for (int n : {1, kPositions}) {
    const Figure cycle = get("BM_Cycle", n), plan = get("BM_Plan", n);
    const std::vector<std::pair<std::string, Figure>> stages = {
        {"scan (541 beams)", get("BM_Scan", n)},
        {"sensed obstacles (hits off the map)", get("BM_Sensed", n)},
        {"density I + deviation D", get("BM_DensityDeviation", n)},
        {"fuzzy weights", get("BM_Fuzzy", n)},
        {"rollout generation", get("BM_Rollouts", n)},
        {"clearance (plan - plan, no obstacles)", minus(plan, get("BM_PlanEmptyWorld", n))},
        {"similarity/DTW (plan - plan, no sim.)", minus(plan, get("BM_PlanNoSimilarity", n))},
        {"heading/clearance/velocity critics", get("BM_OtherCritics", n)},
    };
    std::printf("\n%d position%s\n%-38s %9s %6s %6s %9s %6s\n", n, n > 1 ? "s" : "", "stage", "median", "cv",
                "share", "min", "share");
    const auto row = [&](const std::string& label, const Figure& f) {
      std::printf("%-38s %9.1f %5.1f%% %5.0f%% %9.1f %5.0f%%\n", label.c_str(), f.median, 100 * f.cv,
                  100 * f.median / cycle.median, f.min, 100 * f.min / cycle.min);
    };
    Figure rest{cycle.median, cycle.min, NAN};
    for (const auto& [label, f] : stages) {
      row(label, f);
      rest = minus(rest, f);
    }
    row("rest (cycle - stages above)", rest);
    row("whole cycle", cycle);
    row("  of which plan()", plan);
    row("  cross-check: similarity critic alone", get("BM_Similarity", n));
    row("Navigator::step (same cycle)", get("BM_NavigatorCycle", n));
  }
  std::printf("target: whole cycle median <= 150 us; DTW instruction set: %s\n", dtw_instruction_set());

  // The floor counts the planner's work (every rollout's poses stepped and
  // bounded, the DTW of every admissible rollout against the reference), not
  // the simulated scan nor the critics: the positions' mean.
  const bench::Machine machine = bench::measured_machine();
  bench::print_floor_header(machine);
  const Scene& s = scene();
  const double steps = s.preset.params.n_steps();
  for (int n : {1, kPositions}) {
    double samples = 0, admissible = 0;
    for (int i = 0; i < n; ++i) {
      samples += s.positions[static_cast<std::size_t>(i)].samples;
      admissible += static_cast<double>(s.positions[static_cast<std::size_t>(i)].admissible.size());
    }
    const std::vector<bench::Work> work = {
        {"poses", samples / n * steps, bench::pose_operations(s.footprint), false},
        {"DTW cells", admissible / n * steps * steps, bench::kDtwCellOps, true}};
    bench::print_floor("whole cycle, " + std::to_string(n) + (n > 1 ? " positions" : " position"),
                       get("BM_Cycle", n).median, work, 150, machine);
  }
}

}  // namespace

int main(int argc, char** argv) {
  // Repetitions of all benchmarks run interleaved in random order by default,
  // so that a load that comes and goes on the machine spreads over every stage
  // instead of inflating a few, which the differences above would magnify. A
  // later --benchmark_enable_random_interleaving=false on the command line wins.
  std::vector<char*> args(argv, argv + argc);
  char interleave[] = "--benchmark_enable_random_interleaving=true";
  args.insert(args.begin() + 1, interleave);
  argc = static_cast<int>(args.size());
  argv = args.data();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  print_scene();
  SummaryReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  print_summary(reporter);
  benchmark::Shutdown();
  return 0;
}
