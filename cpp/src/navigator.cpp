#include "fgdwa/navigator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "validation.hpp"

namespace fgdwa {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <class P>
const P& validated(const P& params) {
  params.validate();
  return params;
}

// The map's fields keep free space past the edge only as far as a rollout
// reaches: a wider margin costs every map update and buys nothing.
double field_edge_margin(const NavigatorParams& params, const RobotLimits& limits, const Footprint& footprint,
                         const PlannerParams& planner) {
  return std::min(params.occupancy.edge_margin, limits.v_max * planner.sim_time + footprint.radius());
}

}  // namespace

Navigator::Navigator(const RobotLimits& limits, const Footprint& footprint, const PlannerParams& planner,
                     const OccupancyGrid& map, MapMode mode, const LidarParams& lidar,
                     std::shared_ptr<const WeightPolicy> policy, const NavigatorParams& params,
                     std::optional<TerrainGrid> terrain, const PassingFactors& passing_factors,
                     const DetectWindowParams& window)
    : limits_(limits),
      footprint_(footprint.padded(validated(params).footprint_padding)),
      params_(validated(params)),
      lidar_(validated(lidar)),
      dt_(planner.dt),
      controller_(limits, footprint_, planner, nullptr, std::move(policy), window),
      localiser_(params_.scan_match),
      world_(map, mode, params_, lidar_, footprint_, field_edge_margin(params_, limits_, footprint_, planner)),
      route_(map, footprint_, params_, dt_, terrain),
      recovery_(limits_, footprint_, params_, dt_, controller_.planner().params().safety_margin,
                controller_.planner().params().goal_tolerance) {
  validate_passing_factors(passing_factors);
  if (terrain && !terrain->matches(map))
    throw Error("terrain: its cells must lie exactly on the map's (same size, resolution and origin)");
  controller_.set_range_noise(lidar_.noise_std);
  controller_.keep_best(params_.record_top_k);
  if (std::shared_ptr<const DistanceField> field = world_.field()) controller_.set_map(std::move(field));
  if (terrain) controller_.set_terrain(std::make_shared<TerrainGrid>(std::move(*terrain)), passing_factors);
}

void Navigator::set_goal(const Vec2& goal) {
  detail::require_point("goal", goal);
  int row, col;
  if (!map().cell_of(goal, row, col))
    throw Error(detail::describe("goal",
                                 "(" + detail::format_number(goal.x()) + ", " + detail::format_number(goal.y()) + ")",
                                 "lies off the map"));
  goal_ = goal;
  has_goal_ = true;
  route_.set_goal(goal);
  recovery_.reset();
}

void Navigator::set_global_path(const GlobalPath& path) {
  if (!has_goal_) throw Error("set_global_path() before set_goal(): a path leads to a goal");
  route_.adopt(path);
  controller_.set_global_path(*route_.path());
  controller_path_version_ = route_.version();
}

const CycleRecord& Navigator::step(const RobotState& odometry, const Scan* scan, double time,
                                   const std::vector<Disc>& discs) {
  if (!has_goal_) throw Error("step() before set_goal(): the navigator has no goal");
  detail::require_finite_state(odometry);
  detail::require_finite("time", time);
  if (time < last_time_)
    throw Error(detail::describe("time", time, "must not be before the last step's " + detail::format_number(last_time_) + " s"));
  if (scan) frame_.assign(*scan, lidar_.beams);
  const ScanFrame* frame = scan ? &frame_ : nullptr;
  for (const Disc& d : discs) d.validate();

  // Where the robot is on its map: the scan matched to the map as it was
  // before this scan, the odometry corrected by what the match found.
  Clock::time_point tic = Clock::now();
  if (frame) {
    std::shared_ptr<const DistanceField> field = world_.field();
    record_.match = localiser_.update(frame_, field.get(), world_.hit_depth());
  } else {
    record_.match = ScanMatch{};
    record_.match.status = MatchStatus::Off;
  }
  RobotState state = odometry;
  state.pose = localiser_.to_map(odometry.pose);
  record_.odometry = odometry.pose;
  record_.map_to_odom = localiser_.map_to_odom();
  record_.times.localise = seconds_since(tic);
  const Vec2 position = state.pose.position();
  const int version_before = route_.version();
  // Read before the record takes this cycle: whether the last cycle's planner rejected every sample.
  const bool rejected_all = record_.planned && record_.control.status == Status::NoAdmissibleVelocity;
  record_.time = last_time_ = time;
  record_.state = state;
  record_.planned = false;

  // The world: tracks of the movers, the map with this scan in it.
  const WorldUpdate& seen = world_.update(frame, time, discs);
  tic = Clock::now();
  if (seen.new_cells) {
    // The controller lets go of the map while it changes, so that a field no
    // one else holds is updated in place.
    controller_.set_map(nullptr);
    controller_.set_map(world_.field());
  }
  record_.times.tracking = seen.tracking_time;
  record_.times.map = seen.map_time + seconds_since(tic);

  // Recovery, then the route the planner drives on.
  tic = Clock::now();
  if (frame && !scanned_) {
    scanned_ = true;
    if (params_.track_moving) recovery_.watch(params_.start_watch_time);
  }
  const RecoveryStep recovery = recovery_.step(state, goal_, controller_.world(), seen.movers, rejected_all);
  if (recovery.give_up_ahead) route_.give_up_ahead(position, controller_.sensed_points(), world_.map());
  if (recovery.replan) route_.request_replan();
  bool drive = recovery.drive;
  Twist command = recovery.command;
  // The start's watch plans the route already: the robot drives on it once the watch ends.
  const bool watching = recovery_.trigger() == RecoveryTrigger::Start;
  if (!route_.update(position, (drive || watching) && controller_.planner().needs_path(), world_, seen.movers)) {
    recovery_.fail(FailureReason::NoGlobalPath);
    command = braking_command(limits_, state.twist, dt_);
    drive = false;
  }
  if (route_.version() != controller_path_version_) {
    controller_.set_global_path(*route_.path());
    controller_path_version_ = route_.version();
  }
  record_.times.global = seconds_since(tic);

  // The controller drives, or the record says it did not.
  if (drive) {
    record_.control = controller_.step(state, goal_, frame, seen.movers);
    command = record_.control.command;
    if (route_.version() != version_before) recovery_.replanned();
  } else {
    idle_report(position);
  }
  record_.planned = drive;
  record_.times.perception = record_.control.perception_time;
  record_.times.plan = record_.control.plan_time;
  record_.command = command;
  record_.mode = recovery_.mode();
  record_.failure = recovery_.failure();
  record_.trigger = recovery_.trigger();
  record_.recoveries = recovery_.recoveries();
  record_.path = route_.path();
  record_.path_version = route_.version();
  record_.new_cells = seen.new_cells;
  record_.tracked = seen.tracked;
  recovery_.end_cycle();
  return record_;
}

void Navigator::idle_report(const Vec2& position) {
  CycleReport& report = record_.control;
  report = CycleReport{};
  report.target = goal_;
  report.critic_names = controller_.plan_result().critic_names;
  report.critic_vetoes.assign(report.critic_names.size(), 0);
  report.critic_stats.assign(report.critic_names.size(), CriticStats{});
  if (route_.path()) report.deviation = route_.path()->deviation(position);
}

}  // namespace fgdwa
