#include "fgdwa/controller.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "fgdwa/error.hpp"
#include "fgdwa/limits.hpp"
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

void Controller::keep_best(int count) {
  if (count < 0 || count > limits::kMaxWindowSamples)
    throw Error("keep_best = " + std::to_string(count) + ": must lie in [0, " + std::to_string(limits::kMaxWindowSamples) + "]");
  keep_best_ = count;
}

// A hit near the map's obstacles but off them along its beam by more than the
// range noise explains: the map sits at a wrong place (odometry drifted),
// the scan does not, so the hit is an obstacle of its own. Along the beam,
// because that is where the noise lies; a correct map's cells cover the
// surface, so a correct hit is inside them up to the noise.
struct Controller::LiveScanTest {
  LiveScanTest(const Controller& c, const RobotState& state)
      : field(c.map_.get()),
        pose(state.pose),
        footprint(c.planner_.footprint()),
        // Only hits a rollout can reach matter to the planner.
        reach(std::max(c.planner_.limits().v_max, std::abs(state.twist.v)) * c.planner_.params().sim_time +
              c.planner_.footprint().radius() + c.planner_.params().safety_margin),
        // A hundredth of a cell for a hit on a cell's edge, which rounding
        // may put on either side of it.
        slack(field ? 0.01 * field->grid().resolution() : 0.0),
        depth(kLiveNoiseStds * c.range_noise_ + slack),
        noise(c.range_noise_) {}

  // m, how far beyond beam j's hit, along the beam, the map's obstacle
  // begins (negative: the hit lies inside it, that far past its edge); NaN
  // if the edge is not within `depth` either way. To a quarter cell.
  double map_offset(const ScanFrame& frame, std::size_t j) const {
    const Vec2& hit = frame.beam_hits()[j];
    const Vec2& direction = frame.directions()[j];
    const OccupancyGrid& grid = field->grid();
    const double step = 0.25 * grid.resolution();
    const bool inside = grid.occupied_at(hit);
    for (double s = step; s <= depth; s += step)
      if (inside != grid.occupied_at(hit + (inside ? -s : s) * direction)) return inside ? -(s - 0.5 * step) : s - 0.5 * step;
    return std::numeric_limits<double>::quiet_NaN();
  }
  // Whether the map lies beyond beam i's stretch of surface by more than the
  // noise explains, the noise averaged over the hits within
  // kLiveSurfaceRadius of beam i's (a map a few centimetres off shows in
  // their mean, not in one hit); `at` gets beam i's point of the surface.
  // `offsets` holds map_offset() of every beam (NaN where none).
  bool surface_counts(const ScanFrame& frame, const std::vector<double>& offsets, std::size_t i, Vec2& at) const {
    if (std::isnan(offsets[i])) return false;
    const Vec2& hit = frame.beam_hits()[i];
    double sum = 0.0;
    int n = 0;
    const auto take = [&](std::size_t j) {
      if (!frame.has_hit(j) || (frame.beam_hits()[j] - hit).norm() > kLiveSurfaceRadius) return false;
      if (!std::isnan(offsets[j])) sum += offsets[j], ++n;
      return true;
    };
    take(i);
    for (std::size_t j = i; j-- > 0 && take(j);) {}
    for (std::size_t j = i + 1; j < frame.size() && take(j); ++j) {}
    if (n < kLiveSurfaceHits) return false;
    const double mean = sum / n;
    if (mean <= kLiveMeanStds * noise / std::sqrt(static_cast<double>(n)) + slack) return false;
    // The surface along beam i: the map's edge there, less the mean offset.
    at = hit + (offsets[i] - mean) * frame.directions()[i];
    return outside_robot(at);
  }

  bool in_reach(const Vec2& hit) const { return field && (hit - pose.position()).norm() <= reach; }
  // Whether one hit in reach lies short of the map by more than the noise.
  bool counts(const Vec2& hit, const Vec2& direction) const {
    // The stretch of the beam the noise may have moved the hit along: a
    // correct map has an obstacle square on it, a beam that grazes a corner
    // and a hit noise carried past one included.
    const Vec2 far = hit + depth * direction;
    if (field->grid().occupied_at(far) || field->segment_distance(hit - depth * direction, far) <= slack) return false;
    return outside_robot(hit);
  }
  // Nothing stands inside the robot: a hit there is the robot's own.
  bool outside_robot(const Vec2& point) const { return footprint.signed_distance(pose, point) > 0.0; }

  const DistanceField* field;
  Pose2 pose;
  const Footprint& footprint;
  double reach, slack, depth, noise;
};

const CycleReport& Controller::step(const RobotState& state, const Vec2& goal, const Scan* scan,
                                    const std::vector<Disc>& discs) {
  if (!scan) return step(state, goal, static_cast<const ScanFrame*>(nullptr), discs);
  frame_.assign(*scan);
  return step(state, goal, &frame_, discs);
}

const CycleReport& Controller::step(const RobotState& state, const Vec2& goal, const ScanFrame* frame,
                                    const std::vector<Disc>& discs) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  detail::require_finite_state(state);
  detail::require_point("goal", goal);
  report_.density = report_.deviation = report_.beta = report_.delta = std::numeric_limits<double>::quiet_NaN();
  report_.sensed_points = 0;
  report_.live_points = 0;
  live_.clear();
  if (frame) {
    // Hits on the map's obstacles or on known discs are explained; the rest are
    // obstacles the planner would not otherwise see.
    const double resolution = map_ ? map_->grid().resolution() : 0.1;
    const double tolerance = 0.5 * resolution + 3.0 * range_noise_;
    const LiveScanTest live{*this, state};
    unexplained_.clear();
    offsets_.assign(frame->size(), std::numeric_limits<double>::quiet_NaN());
    if (map_)
      for (std::size_t i = 0; i < frame->size(); ++i)
        if (frame->has_hit(i) && live.in_reach(frame->beam_hits()[i])) offsets_[i] = live.map_offset(*frame, i);
    for (std::size_t i = 0; i < frame->size(); ++i) {
      if (!frame->has_hit(i)) continue;
      const Vec2& hit = frame->beam_hits()[i];
      const auto on_disc = [&] {
        return std::any_of(discs.begin(), discs.end(),
                           [&](const Disc& d) { return (hit - d.center).norm() <= d.radius + tolerance; });
      };
      // Most hits lie on the map's obstacles: one table look-up settles them.
      if (map_ && (map_->upper_bound(hit) <= tolerance || map_->distance(hit) <= tolerance)) {
        if (!live.in_reach(hit) || on_disc()) continue;
        Vec2 surface;
        if (live.counts(hit, frame->directions()[i])) live_.push_back(Disc{hit, 0.0, Vec2::Zero(), 0.0});
        else if (live.surface_counts(*frame, offsets_, i, surface)) live_.push_back(Disc{surface, 0.0, Vec2::Zero(), 0.0});
        continue;
      }
      if (!on_disc()) unexplained_.push_back(hit);
    }
    world_.set_sensed(points_field(unexplained_, resolution));
    report_.sensed_points = unexplained_.size();
    report_.live_points = live_.size();
    report_.density = detail::obstacle_density_of_checked(frame->scan(), window_).density;
  } else {
    world_.set_sensed(nullptr);
  }
  if (live_.empty()) {
    world_.set_discs(discs);
  } else {
    live_.insert(live_.end(), discs.begin(), discs.end());
    world_.set_discs(live_);
  }
  if (planner_.global_path()) report_.deviation = planner_.global_path()->deviation(state.pose.position());
  // Time to contact as both keep their velocities: the mover's relative to the robot's.
  report_.contact_time = std::numeric_limits<double>::infinity();
  const Vec2 own = state.twist.v * Vec2(std::cos(state.pose.theta), std::sin(state.pose.theta));
  for (const Disc& d : discs)
    if (d.moves()) {
      Disc relative = d;
      relative.velocity -= own;
      report_.contact_time =
          std::min(report_.contact_time, relative.time_to_reach(state.pose.position(), planner_.footprint().radius()));
    }
  if (policy_) {
    if (!frame) throw Error("the weight policy reads the obstacle density I: step() needs a scan");
    const CriticWeights weights = policy_->weights(
        report_.density, std::isnan(report_.deviation) ? 0.0 : report_.deviation, report_.contact_time);
    for (const auto& [critic, weight] : weights)
      if (planner_.has_critic(critic)) planner_.set_weight(critic, weight);
  }
  if (planner_.has_critic("clearance")) report_.beta = planner_.weight("clearance");
  if (planner_.has_critic("similarity")) report_.delta = planner_.weight("similarity");
  const Clock::time_point planning = Clock::now();
  report_.perception_time = std::chrono::duration<double>(planning - start).count();
  const PlanResult& plan = planner_.plan(state, goal, world_);
  report_.plan_time = std::chrono::duration<double>(Clock::now() - planning).count();
  summarize(plan);
  return report_;
}

void Controller::summarize(const PlanResult& plan) {
  report_.command = plan.command;
  report_.status = plan.status;
  report_.target = plan.target;
  report_.key_node = plan.key_node;
  report_.reject_counts = plan.reject_counts;
  report_.critic_names = plan.critic_names;
  report_.critic_vetoes = plan.critic_vetoes;
  const std::vector<Trajectory>& rollouts = planner_.rollouts();
  if (plan.best_index >= 0)
    score(plan, rollouts, plan.best_index, report_.choice);
  else
    report_.choice = ScoredRollout{};
  report_.best.resize(0);
  order_.clear();
  for (int i = 0; i < static_cast<int>(plan.samples.size()); ++i)
    if (plan.reasons[static_cast<std::size_t>(i)] == RejectReason::None) order_.push_back(i);
  const std::size_t k = std::min(order_.size(), static_cast<std::size_t>(keep_best_));
  std::partial_sort(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(k), order_.end(),
                    [&](int a, int b) { return plan.total(a) > plan.total(b); });
  report_.best.resize(k);
  for (std::size_t j = 0; j < k; ++j) score(plan, rollouts, order_[j], report_.best[j]);
  summarize_critics(plan);
}

void Controller::summarize_critics(const PlanResult& plan) {
  const std::size_t critics = plan.critic_names.size();
  report_.critic_stats.assign(critics, CriticStats{});
  if (order_.empty()) return;
  for (std::size_t j = 0; j < critics; ++j) {
    const auto c = static_cast<Eigen::Index>(j);
    CriticStats& stats = report_.critic_stats[j];
    stats.min = std::numeric_limits<double>::infinity();
    stats.max = -std::numeric_limits<double>::infinity();
    double sum = 0.0;
    for (const int i : order_) {
      const double term = plan.signed_weights[j] * plan.normalized(static_cast<Eigen::Index>(i), c);
      stats.min = std::min(stats.min, term);
      stats.max = std::max(stats.max, term);
      sum += term;
    }
    stats.mean = sum / static_cast<double>(order_.size());
  }
}

void Controller::score(const PlanResult& plan, const std::vector<Trajectory>& rollouts, int sample,
                       ScoredRollout& out) {
  const auto i = static_cast<Eigen::Index>(sample);
  const std::size_t critics = plan.critic_names.size();
  out.sample = sample;
  out.command = plan.samples[static_cast<std::size_t>(sample)];
  out.total = plan.total(i);
  out.poses = rollouts[static_cast<std::size_t>(sample)];
  out.raw.resize(critics);
  out.terms.resize(critics);
  for (std::size_t j = 0; j < critics; ++j) {
    const auto c = static_cast<Eigen::Index>(j);
    out.raw[j] = plan.raw(i, c);
    out.terms[j] = plan.signed_weights[j] * plan.normalized(i, c);
  }
}

}  // namespace fgdwa
