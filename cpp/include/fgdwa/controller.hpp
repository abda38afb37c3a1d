#pragma once
// One control cycle as a robot runs it: the scan shows obstacles the
// map lacks and gives the detect window's density I, the global path gives the
// deviation D, the weight policy turns (I, D) into critics' weights, and the
// planner picks the command. Data flows one way; nothing reaches back.
//
// Lifecycle: construct once with the map; set_global_path when a path is
// planned, set_map when the map grows; step() every control period.
#include <limits>
#include <memory>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/weights.hpp"

namespace fgdwa {

struct CycleReport {
  double density = std::numeric_limits<double>::quiet_NaN();    // I; NaN without a scan
  double deviation = std::numeric_limits<double>::quiet_NaN();  // m, D; NaN without a global path
  double beta = std::numeric_limits<double>::quiet_NaN();       // clearance weight used; NaN without that critic
  double delta = std::numeric_limits<double>::quiet_NaN();      // similarity weight used; NaN without that critic
  std::size_t sensed_points = 0;                                // lidar hits the map and known discs do not explain
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

  // One cycle from `state` toward `goal`. `scan` (may be null) is this cycle's
  // lidar scan; `discs` the moving obstacles the robot knows, placed now.
  const PlanResult& step(const RobotState& state, const Vec2& goal, const Scan* scan,
                         const std::vector<Disc>& discs = {});

  const CycleReport& report() const { return report_; }
  // The last scan's hits that neither the map nor the known discs explain.
  const std::vector<Vec2>& sensed_points() const { return unexplained_; }
  const LocalPlanner& planner() const { return planner_; }
  const FieldClearance& world() const { return world_; }

 private:
  LocalPlanner planner_;
  std::shared_ptr<const DistanceField> map_;
  std::shared_ptr<const WeightPolicy> policy_;
  DetectWindowParams window_;
  double range_noise_ = 0.0;
  FieldClearance world_;
  CycleReport report_;
  std::vector<Vec2> hits_, unexplained_;  // this cycle's lidar hits, and those the map does not explain
};

}  // namespace fgdwa
