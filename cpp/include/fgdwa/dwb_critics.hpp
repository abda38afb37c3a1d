#pragma once
// Critics that score a rollout the way Nav2's DWB controller does
// (nav2_dwb_controller/dwb_critics: BaseObstacle, PathDist, GoalDist, PathAlign,
// GoalAlign), as a baseline planner (the `dwb` preset).
//
// DWB adds scale x cost over its critics and takes the lowest total; these
// critics are cost critics (CriticSense::Cost) that return DWB's cost, so with
// Normalization::None and the weight set to DWB's effective scale the planner's
// largest total (minus the weighted costs) is DWB's lowest. DWB's effective
// scale is the configured one for BaseObstacle, and the configured one times
// half the costmap resolution for the four map-grid critics (their costs are in
// cells; see the `dwb` preset).
//
// Where this differs from DWB, on purpose:
// - DWB reads clearance from its inflated costmap; here it is the footprint's
//   exact clearance from the planner's ClearanceSource, through the same
//   inflation formula.
// - DWB's map-grid critics measure from a 4-connected breadth-first sweep of
//   costmap cells (Manhattan steps, blocked by obstacles); here the distance is
//   Euclidean to the local path's polyline, in cells of `resolution`, not
//   rounded, and obstacles do not block it.
// - DWB rejects a trajectory that leaves its costmap or enters the inscribed
//   radius; here admissibility is the planner's (collision before stopping),
//   and the critics score every admissible rollout.
// Lifecycle as for every critic: prepare(context) once per cycle (the local
// path is cut there), score(rollout) per admissible rollout.
#include <cstdint>
#include <vector>

#include "fgdwa/critics.hpp"
#include "fgdwa/path.hpp"

namespace fgdwa {

// Which poses of a rollout the obstacle cost reads.
enum class DwbAggregation : std::uint8_t {
  Last,  // the last pose only: DWB's BaseObstacle with sum_scores false, its default
  Sum,   // every pose: sum_scores true
};
const char* to_string(DwbAggregation aggregation);
constexpr std::array<DwbAggregation, 2> enum_values(DwbAggregation) { return {DwbAggregation::Last, DwbAggregation::Sum}; }

struct DwbObstacleParams {
  double cost_scaling_factor = 3.0;
  double inflation_margin = 0.55;
  DwbAggregation aggregation = DwbAggregation::Last;

  static constexpr const char* kName = "dwb_obstacle";
  template <class V>
  static void fields(V& v) {
    using P = DwbObstacleParams;
    v.real("cost_scaling_factor", &P::cost_scaling_factor, "1/m", Bounds::positive(), "decay of the cost with clearance (Nav2 local costmap's inflation layer)");
    v.real("inflation_margin", &P::inflation_margin, "m", Bounds::positive(), "footprint clearance from which the cost is 0");
    v.choice("aggregation", &P::aggregation, "the last pose's cost (last, DWB's default) or every pose's summed (sum)");
  }
  void validate() const { validate_params(*this); }
};

// Nav2's inflation cost, with distances counted from the footprint rather than
// from its centre: 253 (inscribed) at clearance <= 0, 252 exp(-k c) for
// 0 < c < inflation_margin, 0 beyond.
double dwb_inflation_cost(double clearance, const DwbObstacleParams& params);

// dwb_obstacle: -(inflation cost of the last pose's clearance), or of every
// pose's summed; pose k is checked against obstacles (k + 1) dt ahead, as the
// planner does. Needs the context's world and footprint.
class DwbObstacleCritic : public Critic {
 public:
  explicit DwbObstacleCritic(const DwbObstacleParams& params = {});
  std::string name() const override { return "dwb_obstacle"; }
  CriticSense sense() const override { return CriticSense::Cost; }
  void prepare(const CriticContext& context) override;
  double score(const Rollout& rollout) const override;
  const DwbObstacleParams& params() const { return params_; }

 private:
  DwbObstacleParams params_;
  const ClearanceSource* world_ = nullptr;
  const Footprint* footprint_ = nullptr;
  double dt_ = 0.0;
};

struct DwbGridParams {
  double resolution = 0.05;
  double local_extent = 1.5;
  double forward_point_distance = 0.325;

  static constexpr const char* kName = "dwb_grid";
  template <class V>
  static void fields(V& v) {
    using P = DwbGridParams;
    v.real("resolution", &P::resolution, "m", Bounds::positive(), "cell size, the unit of the scores (Nav2's local costmap)");
    v.real("local_extent", &P::local_extent, "m", Bounds::positive(), "half the side of the square window the local path lives in (Nav2's 3 m x 3 m rolling costmap)");
    v.real("forward_point_distance", &P::forward_point_distance, "m", Bounds::positive(), "ahead of the last pose, for the align critics (DWB's default)");
  }
  void validate() const { validate_params(*this); }
};

// The part of the global path DWB's critics see: from the robot's projection
// onto the path onward, from where it is first inside the square window of
// half-size `half_extent` centred on the robot to where it first leaves it
// (DWB's walk along the plan over its rolling costmap). If no part of it is in
// the window, the projection alone, so the critics still pull toward the path.
struct DwbLocalPath {
  std::vector<Vec2> points;  // at least one
  bool reaches_end = false;  // the global path's end is inside the window
  const Vec2& goal() const { return points.back(); }
};
void dwb_local_path(const GlobalPath& path, const Vec2& robot, double half_extent, DwbLocalPath& out);

// Distance from p to a polyline (to its point when it has only one).
double polyline_distance(const std::vector<Vec2>& polyline, const Vec2& p);

// What the four map-grid critics share: the local path of the cycle.
class DwbGridCritic : public Critic {
 public:
  explicit DwbGridCritic(const DwbGridParams& params = {});
  bool needs_path() const override { return true; }
  CriticSense sense() const override { return CriticSense::Cost; }
  void prepare(const CriticContext& context) override;
  const DwbGridParams& params() const { return params_; }
  const DwbLocalPath& local_path() const { return local_; }

 protected:
  Vec2 forward_point(const Pose2& pose) const;
  double cells(double metres) const { return metres / params_.resolution; }

  DwbGridParams params_;
  DwbLocalPath local_;
};

// dwb_path_dist: -(cells from the last position to the local path).
class DwbPathDistCritic : public DwbGridCritic {
 public:
  using DwbGridCritic::DwbGridCritic;
  std::string name() const override { return "dwb_path_dist"; }
  double score(const Rollout& rollout) const override;
};

// dwb_goal_dist: -(cells from the last position to the local goal).
class DwbGoalDistCritic : public DwbGridCritic {
 public:
  using DwbGridCritic::DwbGridCritic;
  std::string name() const override { return "dwb_goal_dist"; }
  double score(const Rollout& rollout) const override;
};

// dwb_path_align: -(cells from the forward point to the local path); 0 for
// every rollout while the robot is within forward_point_distance of the goal,
// where DWB sets this critic's scale to 0 (keeping the nose on the path there
// makes the robot unsteady).
class DwbPathAlignCritic : public DwbGridCritic {
 public:
  using DwbGridCritic::DwbGridCritic;
  std::string name() const override { return "dwb_path_align"; }
  void prepare(const CriticContext& context) override;
  double score(const Rollout& rollout) const override;
  bool active() const { return active_; }

 private:
  bool active_ = true;
};

// dwb_goal_align: -(cells from the forward point to the local goal). When the
// local path reaches the global path's end, the target is moved
// forward_point_distance beyond it, along the direction from the robot to the
// goal, as DWB does: the nose is drawn past the goal so the centre stops on it.
class DwbGoalAlignCritic : public DwbGridCritic {
 public:
  using DwbGridCritic::DwbGridCritic;
  std::string name() const override { return "dwb_goal_align"; }
  void prepare(const CriticContext& context) override;
  double score(const Rollout& rollout) const override;
  const Vec2& target() const { return target_; }

 private:
  Vec2 target_ = Vec2::Zero();
};

}  // namespace fgdwa
