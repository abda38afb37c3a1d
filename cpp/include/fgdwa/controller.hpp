#pragma once
// One control cycle as a robot runs it: the scan shows obstacles the
// map lacks and gives the detect window's density I, the global path gives the
// deviation D, the weight policy turns (I, D) into critics' weights, and the
// planner picks the command. Data flows one way; nothing reaches back.
//
// Lifecycle: construct once with the map; set_global_path when a path is
// planned, set_map when the map grows; step() every control period.
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/scan_frame.hpp"
#include "fgdwa/weights.hpp"

namespace fgdwa {

// One rollout the planner scored, as recorded, with why it scored so.
struct ScoredRollout {
  int sample = -1;  // index into the cycle's samples, -1 for none
  Twist command;
  double total = 0.0;  // the planner's total score (-inf: rejected, e.g. an evasion)
  Trajectory poses;
  std::vector<double> raw;    // per critic (PlanResult::critic_names): its raw score
  std::vector<double> terms;  // per critic: signed weight x normalised score; they sum to total
};

// One critic's weighted term over a cycle's admissible samples: how much it
// could sway the choice (max - min) and where the chosen sample sat in it.
struct CriticStats {
  double min = 0.0;
  double mean = 0.0;
  double max = 0.0;
};

// What one control cycle sensed, how it weighed it and what the planner chose.
struct CycleReport {
  Twist command;
  Status status = Status::Ok;
  Vec2 target = Vec2::Zero();  // what the heading critic aimed at
  int key_node = -1;
  double density = std::numeric_limits<double>::quiet_NaN();    // I; NaN without a scan
  double deviation = std::numeric_limits<double>::quiet_NaN();  // m, D; NaN without a global path
  double beta = std::numeric_limits<double>::quiet_NaN();       // clearance weight used; NaN without that critic
  double delta = std::numeric_limits<double>::quiet_NaN();      // similarity weight used; NaN without that critic
  // s, T: when the nearest moving disc, at its predicted velocity and growth,
  // first touches the robot's circle, both keeping their velocities; +inf without one on its way.
  double contact_time = std::numeric_limits<double>::infinity();
  std::size_t sensed_points = 0;                                // lidar hits the map and known discs do not explain
  std::size_t live_points = 0;  // hits near the map's obstacles but short of them: the map sits wrong there
  ScoredRollout choice;             // the chosen sample (sample -1, no poses, when none)
  std::vector<ScoredRollout> best;  // the keep_best() best admissible rollouts, best first
  std::array<int, kRejectReasonCount> reject_counts{};  // samples per reject reason
  std::vector<std::string> critic_names;  // the planner's critics, the order of every per-critic list
  std::vector<int> critic_vetoes;   // per critic: samples it vetoed
  std::vector<CriticStats> critic_stats;  // per critic: its terms over the admissible samples (zeros when none)
  double perception_time = 0.0;  // s, wall clock: sensed points, I, D and weights
  double plan_time = 0.0;        // s, wall clock: the local planner
};

// Threads: one per thread, like its LocalPlanner; the map field it is given
// may be shared if nothing updates it.
class Controller {
 public:
  // `map` may be null (no prior map); `policy` null keeps the params' weights.
  Controller(const RobotLimits& limits, const Footprint& footprint, const PlannerParams& params,
             std::shared_ptr<const DistanceField> map = nullptr, std::shared_ptr<const WeightPolicy> policy = nullptr,
             const DetectWindowParams& window = {});

  void set_global_path(const GlobalPath& path);
  // Replaces the map (null for none), e.g. with the field of a ScanMap after new
  // cells; the next step() reads it.
  void set_map(std::shared_ptr<const DistanceField> map);
  const std::shared_ptr<const DistanceField>& map() const { return map_; }
  // The lidar's range noise (m, std): a hit within half a cell plus three
  // standard deviations of the map's obstacles is explained by them.
  void set_range_noise(double std);
  // Slope terrain for the planner (LocalPlanner::set_terrain).
  void set_terrain(std::shared_ptr<const TerrainGrid> terrain, const PassingFactors& factors = kDefaultPassingFactors) {
    planner_.set_terrain(std::move(terrain), factors);
  }

  // How many of the best admissible rollouts each report keeps (0: none).
  void keep_best(int count);

  // One cycle from `state` toward `goal`. `scan` (may be null) is this cycle's
  // lidar scan; `discs` the moving obstacles the robot knows, placed now.
  const CycleReport& step(const RobotState& state, const Vec2& goal, const Scan* scan,
                          const std::vector<Disc>& discs = {});
  // The same with the scan already taken apart this cycle (null: no scan).
  const CycleReport& step(const RobotState& state, const Vec2& goal, const ScanFrame* frame,
                          const std::vector<Disc>& discs = {});
  const CycleReport& step(const RobotState& state, const Vec2& goal, std::nullptr_t,
                          const std::vector<Disc>& discs = {}) {
    return step(state, goal, static_cast<const ScanFrame*>(nullptr), discs);
  }

  const CycleReport& report() const { return report_; }
  // The planner's whole result of the last step (every sample, score and reason).
  const PlanResult& plan_result() const { return planner_.last_result(); }
  // The last scan's hits that neither the map nor the known discs explain.
  const std::vector<Vec2>& sensed_points() const { return unexplained_; }
  const LocalPlanner& planner() const { return planner_; }
  const FieldClearance& world() const { return world_; }

 private:
  // The plan's command, status, choice and best rollouts into the report.
  void summarize(const PlanResult& plan);
  void summarize_critics(const PlanResult& plan);  // reads order_: the admissible samples
  // One sample of the plan as recorded, its per-critic scores included.
  static void score(const PlanResult& plan, const std::vector<Trajectory>& rollouts, int sample, ScoredRollout& out);

  LocalPlanner planner_;
  std::shared_ptr<const DistanceField> map_;
  std::shared_ptr<const WeightPolicy> policy_;
  DetectWindowParams window_;
  double range_noise_ = 0.0;
  FieldClearance world_;
  CycleReport report_;
  int keep_best_ = 0;
  std::vector<Vec2> unexplained_;  // this cycle's lidar hits that the map does not explain
  // This cycle's hits short of the map's obstacles (LiveScanTest), as points
  // (zero-radius discs), then the known discs: what the planner's world holds.
  std::vector<Disc> live_;
  std::vector<double> offsets_;  // scratch: each beam's offset from the map (LiveScanTest::map_offset)
  struct LiveScanTest;
  // How many range-noise stds short of the map a hit must lie to count:
  // 4 leaves about one false hit in 30 000 beams.
  static constexpr double kLiveNoiseStds = 4.0;
  // m: the hits around one whose offsets from the map are averaged, and how
  // many of them an average needs.
  static constexpr double kLiveSurfaceRadius = 0.1;
  static constexpr int kLiveSurfaceHits = 5;
  // How many stds of their mean the averaged hits must lie short of the map:
  // 2 puts about 2 % of a correct map's hits on the surface they average to,
  // up to about one range-noise std short of it, and catches a map 1-2 cm off
  // beside the robot, which 4 let through into BARN's posts (8 seeds: 2
  // collisions in 2000 runs instead of 10).
  static constexpr double kLiveMeanStds = 2.0;
  std::vector<int> order_;         // scratch: admissible samples, best first
  ScanFrame frame_;                // a scan given whole, taken apart
};

}  // namespace fgdwa
