#include "fgdwa/controller.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "fgdwa/error.hpp"
#include "checked_scan.hpp"
#include "validation.hpp"

namespace fgdwa {

Controller::Controller(const RobotLimits& limits, const Footprint& footprint, const PlannerParams& params,
                       std::shared_ptr<const DistanceField> map, std::shared_ptr<const WeightPolicy> policy,
                       const DetectWindowParams& window)
    : planner_(limits, footprint, params), map_(std::move(map)), policy_(std::move(policy)), window_(window),
      world_(map_) {
  window_.validate();
}

void Controller::set_global_path(const GlobalPath& path) { planner_.set_global_path(path); }

void Controller::set_map(std::shared_ptr<const DistanceField> map) {
  map_ = std::move(map);
  world_.set_field(map_);
}

void Controller::set_range_noise(double std) {
  if (!(std::isfinite(std) && std >= 0.0))
    throw Error("range noise = " + std::to_string(std) + ": must be a finite std >= 0 (m)");
  range_noise_ = std;
}

const PlanResult& Controller::step(const RobotState& state, const Vec2& goal, const Scan* scan,
                                   const std::vector<Disc>& discs) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  detail::require_finite_state(state);
  detail::require_point("goal", goal);
  if (scan) scan->validate();
  report_ = CycleReport{};
  world_.set_discs(discs);
  if (scan) {
    // Hits on the map's obstacles or on known discs are explained; the rest are
    // obstacles the planner would not otherwise see.
    const double resolution = map_ ? map_->grid().resolution() : 0.1;
    const double tolerance = 0.5 * resolution + 3.0 * range_noise_;
    unexplained_.clear();
    detail::hit_points_of_checked(*scan, hits_);
    for (const Vec2& hit : hits_) {
      // Most hits lie on the map's obstacles: one table look-up settles them.
      if (map_ && (map_->upper_bound(hit) <= tolerance || map_->distance(hit) <= tolerance)) continue;
      const bool on_disc = std::any_of(discs.begin(), discs.end(), [&](const Disc& d) {
        return (hit - d.center).norm() <= d.radius + tolerance;
      });
      if (!on_disc) unexplained_.push_back(hit);
    }
    world_.set_sensed(points_field(unexplained_, resolution));
    report_.sensed_points = unexplained_.size();
    report_.density = detail::obstacle_density_of_checked(*scan, window_).density;
  } else {
    world_.set_sensed(nullptr);
  }
  if (planner_.global_path()) report_.deviation = planner_.global_path()->deviation(state.pose.position());
  if (policy_) {
    if (!scan) throw Error("the weight policy reads the obstacle density I: step() needs a scan");
    const CriticWeights weights = policy_->weights(report_.density, std::isnan(report_.deviation) ? 0.0 : report_.deviation);
    for (const auto& [critic, weight] : weights)
      if (planner_.has_critic(critic)) planner_.set_weight(critic, weight);
  }
  if (planner_.has_critic("clearance")) report_.beta = planner_.weight("clearance");
  if (planner_.has_critic("similarity")) report_.delta = planner_.weight("similarity");
  const Clock::time_point planning = Clock::now();
  report_.perception_time = std::chrono::duration<double>(planning - start).count();
  const PlanResult& result = planner_.plan(state, goal, world_);
  report_.plan_time = std::chrono::duration<double>(Clock::now() - planning).count();
  return result;
}

}  // namespace fgdwa
