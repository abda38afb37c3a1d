#include "fgdwa/navigator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "beam_directions.hpp"
#include "mover_sweeps.hpp"
#include "validation.hpp"

namespace fgdwa {

const char* to_string(NavigatorMode mode) {
  switch (mode) {
    case NavigatorMode::Following: return "Following";
    case NavigatorMode::Replanning: return "Replanning";
    case NavigatorMode::BackingUp: return "BackingUp";
    case NavigatorMode::Rotating: return "Rotating";
    case NavigatorMode::Waiting: return "Waiting";
    case NavigatorMode::GoalReached: return "GoalReached";
    case NavigatorMode::Failed: return "Failed";
  }
  return "?";
}

const char* to_string(FailureReason reason) {
  switch (reason) {
    case FailureReason::None: return "None";
    case FailureReason::NoGlobalPath: return "NoGlobalPath";
    case FailureReason::RecoveriesExhausted: return "RecoveriesExhausted";
  }
  return "?";
}

const char* to_string(MapMode mode) {
  switch (mode) {
    case MapMode::Known: return "known";
    case MapMode::Scan: return "scan";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

int cycles_of(double seconds, double dt) { return static_cast<int>(std::lround(seconds / dt)); }

// The sweeps of this cycle's moving obstacles that the global path keeps off.
std::vector<detail::SweptDisc> mover_sweeps(const std::vector<Disc>& discs, const NavigatorParams& params) {
  std::vector<detail::SweptDisc> sweeps;
  if (!params.route_around_movers) return sweeps;
  for (const Disc& d : discs)
    if (d.moves()) sweeps.push_back(detail::sweep_of(d, params.mover_route_horizon));
  return sweeps;
}

// Moves `current` toward `target` by at most `step`.
double approach(double current, double target, double step) {
  return current + std::clamp(target - current, -step, step);
}

}  // namespace

Navigator::Navigator(const RobotLimits& limits, const Footprint& footprint, const PlannerParams& planner,
                     const OccupancyGrid& map, MapMode mode, const LidarParams& lidar,
                     std::shared_ptr<const WeightPolicy> policy, const NavigatorParams& params,
                     std::optional<TerrainGrid> terrain, const PassingFactors& passing_factors,
                     const DetectWindowParams& window)
    : limits_(limits),
      footprint_(footprint),
      params_(params),
      lidar_(lidar),
      mode_(mode),
      dt_(planner.dt),
      terrain_(std::move(terrain)),
      controller_(limits, footprint, planner, nullptr, std::move(policy), window),
      tracker_(params.tracker) {
  params_.validate();
  lidar_.validate();
  validate_passing_factors(passing_factors);
  controller_.set_range_noise(lidar_.noise_std);
  if (terrain_ && !terrain_->matches(map))
    throw Error("terrain: its cells must lie exactly on the map's (same size, resolution and origin)");
  OccupancyParams occupancy = params_.occupancy;
  occupancy.range_std = std::max(occupancy.range_std, lidar_.noise_std);
  // The map's fields keep free space past the edge only as far as a rollout
  // reaches: a wider margin costs every map update and buys nothing.
  occupancy.edge_margin = std::min(occupancy.edge_margin, limits_.v_max * planner.sim_time + footprint_.radius());
  if (mode_ == MapMode::Known) {
    known_map_ = std::make_unique<OccupancyGrid>(map);
    planning_map_ = std::make_unique<OccupancyGrid>(map);
    known_field_ = std::make_shared<DistanceField>(map, occupancy.edge_margin);
    controller_.set_map(known_field_);
    if (params_.learn_obstacles) scan_map_ = std::make_unique<ScanMap>(map, occupancy);
  } else {
    scan_map_ = std::make_unique<ScanMap>(map, occupancy);
  }
  if (terrain_) controller_.set_terrain(std::make_shared<TerrainGrid>(*terrain_), passing_factors);
  closed_.assign(static_cast<std::size_t>(map.rows()) * map.cols(), 0);
  // A path that keeps a margin beyond the footprint gives the local planner
  // room at the corners; where it closes every way, the footprint's radius;
  // a robot in a tight spot sits inside that band, so last the inscribed radius.
  radii_ = {footprint_.radius() + params_.path_margin, footprint_.radius(), footprint_.inscribed_radius()};
  replan_cycles_ = std::max(1, cycles_of(params_.replan_period, dt_));
  stall_cycles_ = cycles_of(params_.stall_time, dt_);
}

const OccupancyGrid& Navigator::map() const { return planning_map_ ? *planning_map_ : scan_map_->grid(); }

bool Navigator::needs_path() const { return controller_.planner().needs_path(); }

void Navigator::set_goal(const Vec2& goal) {
  detail::require_point("goal", goal);
  int row, col;
  if (!map().cell_of(goal, row, col))
    throw Error(detail::describe("goal",
                                 "(" + detail::format_number(goal.x()) + ", " + detail::format_number(goal.y()) + ")",
                                 "lies off the map"));
  goal_ = goal;
  has_goal_ = true;
  path_.reset();
  std::fill(closed_.begin(), closed_.end(), 0);
  recent_.clear();
  mode_now_ = NavigatorMode::Following;
  failure_ = FailureReason::None;
  recoveries_ = 0;
  rejected_cycles_ = 0;
  cycles_since_replan_ = replan_cycles_;
}

void Navigator::set_global_path(const GlobalPath& path) {
  if (!has_goal_) throw Error("set_global_path() before set_goal(): a path leads to a goal");
  adopt_path(path);
}

void Navigator::adopt_path(GlobalPath path) {
  path_ = std::make_shared<const GlobalPath>(std::move(path));
  controller_.set_global_path(*path_);
  ++path_version_;
}

bool Navigator::plan_path(const Vec2& from) {
  cycles_since_replan_ = 0;
  replan_now_ = false;
  const OccupancyGrid& base = map();
  const bool any_closed = std::any_of(closed_.begin(), closed_.end(), [](std::uint8_t c) { return c != 0; });
  const std::vector<detail::SweptDisc> sweeps = mover_sweeps(discs_now_, params_);
  std::optional<OccupancyGrid> with_closed;
  if (any_closed || !sweeps.empty()) {
    std::vector<std::uint8_t> cells = base.cells();
    if (any_closed)
      for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = cells[i] || closed_[i];
    // Left open near the robot and the goal, beyond the widest inflation: the
    // path must leave the one and reach the other whatever moves beside them.
    const double keep = radii_.front() + base.resolution();
    for (const detail::SweptDisc& sweep : sweeps) detail::close_swept_cells(base, sweep, from, goal_, keep, cells);
    with_closed.emplace(base.rows(), base.cols(), base.resolution(), base.origin(), std::move(cells));
  }
  const OccupancyGrid& grid = with_closed ? *with_closed : base;
  std::vector<std::uint8_t> unknown;
  if (scan_map_ && !known_map_ && params_.unknown_cost > 0.0) {
    unknown.resize(scan_map_->states().size());
    for (std::size_t i = 0; i < unknown.size(); ++i)
      unknown[i] = scan_map_->states()[i] == static_cast<std::uint8_t>(CellState::Unknown);
  }
  for (double radius : radii_) {
    AStarParams astar;
    astar.inflation_radius = radius;
    astar.unknown_cost = params_.unknown_cost;
    GlobalPlan plan;
    try {
      AStarPlanner planner(grid, astar, terrain_);
      planner.set_unknown(unknown);
      plan = planner.plan(from, goal_);
    } catch (const Error&) {
      continue;  // start or goal in a marked cell: no way from here on this map at this radius
    }
    if (plan.status == GlobalStatus::Found) {
      adopt_path(GlobalPath(std::move(plan.path)));
      return true;
    }
  }
  return false;
}

bool Navigator::path_ahead_blocked(const Vec2& position) {
  if (!path_) return true;
  if (detail::path_meets_sweeps(*path_, position, mover_sweeps(discs_now_, params_), params_.mover_route_lookahead,
                                footprint_.inscribed_radius(), params_.keep_clear))
    return true;
  const std::shared_ptr<const DistanceField>& field = controller_.map();
  if (!field) return false;
  // The same path on the same map, found clear from here or from farther back: still clear.
  const double from = path_->project(position).arc_length;
  if (clear_check_.map_version == map_version_ && clear_check_.path_version == path_version_ &&
      from >= clear_check_.from)
    return false;
  if (path_blocked(*path_, position, *field, footprint_.inscribed_radius())) return true;
  clear_check_ = ClearCheck{map_version_, path_version_, from};
  return false;
}

bool Navigator::stalled(const RobotState& state) {
  if (stall_cycles_ < 1) return false;
  // Every sample rejected cycle after cycle is a stall too, wherever the robot drifts.
  rejected_cycles_ = record_.planned && record_.status == Status::NoAdmissibleVelocity ? rejected_cycles_ + 1 : 0;
  if (rejected_cycles_ >= stall_cycles_) {
    rejected_cycles_ = 0;
    recent_.clear();
    return true;
  }
  remember_position(state.pose.position());
  if (static_cast<int>(recent_.size()) < stall_cycles_ + 1) return false;
  if ((state.pose.position() - recent_.front()).norm() >= params_.stall_distance) return false;
  recent_.clear();
  return true;
}

void Navigator::remember_position(const Vec2& position) {
  if (stall_cycles_ < 1) return;
  recent_.push_back(position);
  if (static_cast<int>(recent_.size()) > stall_cycles_ + 1) recent_.pop_front();
}

void Navigator::give_up_path_ahead(const Vec2& position) {
  const OccupancyGrid& grid = map();
  const double s0 = path_->project(position).arc_length;
  const double end = std::min(s0 + params_.give_up_length, path_->length());
  for (double s = s0; s <= end + 1e-9; s += 0.5 * grid.resolution()) {
    const Vec2 p = path_->point_at(s);
    if ((p - position).norm() < params_.keep_clear || (p - goal_).norm() < params_.keep_clear) continue;
    int row, col;
    if (grid.cell_of(p, row, col)) closed_[grid.index(row, col)] = 1;
  }
}

void Navigator::close_sensed_obstacles(const Vec2& position) {
  const OccupancyGrid& grid = map();
  for (const Vec2& hit : controller_.sensed_points()) {
    int row, col;
    if ((hit - position).norm() <= params_.sensed_close_radius && grid.cell_of(hit, row, col))
      closed_[grid.index(row, col)] = 1;
  }
}

double Navigator::contact_margin(const Pose2& pose) const {
  // As the planner does: the margin never asks for more room than the robot has.
  return fgdwa::contact_margin(controller_.world().clearance(footprint_, pose, 0.0),
                               controller_.planner().params().safety_margin);
}

bool Navigator::step_clear(const Pose2& pose, const Twist& command) const {
  const FieldClearance& seen = controller_.world();
  const double margin = contact_margin(pose);
  // A turn in place sweeps the outline: check it every few degrees (no turn, no
  // check: the start itself, within the margin when in contact, is not the step's).
  const double turn = command.omega * dt_;
  const int turns = turn == 0.0 ? 0 : std::max(1, static_cast<int>(std::ceil(std::abs(turn) * footprint_.radius() / 0.02)));
  for (int i = 1; i <= turns; ++i) {
    const Pose2 turned{pose.x, pose.y, pose.theta + turn * i / turns};
    if (seen.clearance(footprint_, turned, 0.0) <= margin) return false;
  }
  const Pose2 after = fgdwa::step(pose, command, dt_);
  const double length = std::hypot(after.x - pose.x, after.y - pose.y);
  const int pieces = std::max(1, static_cast<int>(std::ceil(length / 0.02)));
  for (int i = 1; i <= pieces; ++i) {
    const double f = double(i) / pieces;
    const Pose2 between{pose.x + f * (after.x - pose.x), pose.y + f * (after.y - pose.y), after.theta};
    if (seen.clearance(footprint_, between, 0.0) <= margin) return false;
  }
  return true;
}

double Navigator::open_heading(const Pose2& pose) const {
  // The direction, of 16, in which the footprint can travel farthest (up to
  // 2 m) in the robot's view of the world; ties go to the smaller turn.
  const FieldClearance& seen = controller_.world();
  const double margin = contact_margin(pose);
  double best_heading = pose.theta, best_reach = -1.0;
  for (int i = 0; i < 16; ++i) {
    const int k = (i + 1) / 2 * (i % 2 ? 1 : -1);  // 0, 1, -1, 2, -2, ...
    const double heading = pose.theta + k * (2.0 * M_PI / 16.0);
    double reach = 0.0;
    for (double s = 0.05; s <= 2.0 + 1e-9; s += 0.05) {
      const Pose2 p{pose.x + s * std::cos(heading), pose.y + s * std::sin(heading), heading};
      if (seen.clearance(footprint_, p, 0.0) <= margin) break;
      reach = s;
    }
    if (reach > best_reach + 1e-9) {
      best_reach = reach;
      best_heading = heading;
    }
  }
  return best_heading;
}

double Navigator::hit_tolerance() const { return 0.5 * map().resolution() + 3.0 * lidar_.noise_std; }

void Navigator::locate_hits(const Scan& scan) {
  const std::size_t n = scan.ranges.size();
  const double tolerance = hit_tolerance();
  // Only the tracker and the learnt map ask whether a hit is on the known map.
  const bool prior = known_field_ && known_field_->has_obstacles() && (scan_map_ || params_.track_moving);
  hits_.assign(n, Vec2::Zero());
  // A hit on the known map's obstacles is neither segmented (they are static)
  // nor marked in the scan map (it teaches nothing new, and hits that noise
  // carries past a thin obstacle would thicken it).
  segment_mask_.assign(n, 1);
  const std::vector<Vec2>& directions = detail::beam_directions(scan);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = scan.ranges[i];
    if (!std::isfinite(r)) continue;
    hits_[i] = Vec2(scan.pose.x + r * directions[i].x(), scan.pose.y + r * directions[i].y());
    if (prior && known_field_->distance(hits_[i]) <= tolerance) segment_mask_[i] = 0;
  }
  keep_hit_ = segment_mask_;
}

void Navigator::track(const Scan& scan, double time) {
  const std::size_t n = scan.ranges.size();
  // Every hit off the known map's obstacles is segmented (locate_hits), the
  // scan map's settled cells included: a slow mover that is not yet labelled
  // marks its cells scan after scan, and masking them would cut it up and
  // hide it from the tracker. An object cut by the field of view's edge is
  // tracked too; its cluster is occluded, so its centre weighs less in the
  // moving test.
  const double tolerance = hit_tolerance();
  std::vector<Cluster> clusters = segment_scan(scan, params_.segment, &segment_mask_);
  tracker_.update(clusters, time, &scan);
  record_.tracked = tracker_.moving_discs();
  // Nothing stands inside the robot: a track there is made of its own surroundings.
  record_.tracked.erase(std::remove_if(record_.tracked.begin(), record_.tracked.end(),
                                       [&](const Disc& d) { return footprint_.signed_distance(scan.pose, d.center) <= 0.0; }),
                        record_.tracked.end());
  if (record_.tracked.empty()) return;
  for (Disc& d : record_.tracked) d.radius += params_.mover_margin;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(scan.ranges[i])) continue;
    for (const Disc& d : record_.tracked)
      if ((hits_[i] - d.center).norm() <= d.radius + tolerance) keep_hit_[i] = 0;
  }
}

void Navigator::start_recovery(const RobotState& state, const std::vector<Disc>& discs) {
  const Vec2 position = state.pose.position();
  ++recoveries_;
  recovery_origin_ = position;
  if (recoveries_ > params_.max_recoveries) {
    mode_now_ = NavigatorMode::Failed;
    failure_ = FailureReason::RecoveriesExhausted;
    return;
  }
  const bool moving_obstacle_near = std::any_of(discs.begin(), discs.end(), [&](const Disc& d) {
    return d.velocity.norm() > 0.05 && (d.center - position).norm() - d.radius <= params_.wait_radius;
  });
  if (moving_obstacle_near && params_.wait_time > 0.0) {
    // Letting a mover pass is not an attempt that failed.
    --recoveries_;
    mode_now_ = NavigatorMode::Waiting;
    wait_cycles_left_ = std::max(1, cycles_of(params_.wait_time, dt_));
    return;
  }
  if (path_) {
    give_up_path_ahead(position);
    close_sensed_obstacles(position);
  }
  backed_up_ = 0.0;
  backup_braking_ = false;
  rotated_ = 0.0;
  const Twist first_back = backup_command(state);
  if (params_.backup_distance > 0.0 && first_back.v < 0.0 && step_clear(state.pose, first_back)) {
    mode_now_ = NavigatorMode::BackingUp;
  } else if (params_.rotate_limit > 0.0) {
    mode_now_ = NavigatorMode::Rotating;
    rotate_goal_ = open_heading(state.pose);
  } else {
    replan_now_ = true;
  }
}

Twist Navigator::backup_command(const RobotState& state) {
  // Reverse at up to backup_speed within the acceleration limits, braking in
  // time to stop after backup_distance.
  const double speed = std::max(0.0, -state.twist.v);
  const double brake = limits_.braking_v();
  const double remaining = params_.backup_distance - backed_up_;
  backup_braking_ = backup_braking_ || remaining <= speed * speed / (2.0 * brake) + speed * dt_;
  const double target = backup_braking_ ? 0.0 : params_.backup_speed;
  const double next = std::max(0.0, approach(speed, target, (target > speed ? limits_.acc_v : brake) * dt_));
  const double omega = approach(state.twist.omega, 0.0, limits_.braking_omega() * dt_);
  return Twist{-next, omega};
}

bool Navigator::standing_clear_of_movers(const RobotState& state, double duration) const {
  const double margin = controller_.planner().params().safety_margin;
  Pose2 pose = state.pose;
  Twist twist = state.twist;
  for (int k = 0; k * dt_ <= duration + 1e-9; ++k) {
    if (moving_disc_clearance(discs_now_, footprint_, pose, k * dt_) <= margin) return false;
    twist = braking_command(limits_, twist, dt_);
    pose = fgdwa::step(pose, twist, dt_);
  }
  return true;
}

Twist Navigator::rotate_command(const RobotState& state) {
  const double error = wrap_angle(rotate_goal_ - state.pose.theta);
  const double brake = limits_.braking_omega();
  // The fastest turn that still stops at the goal heading.
  const double reachable = std::sqrt(2.0 * brake * std::abs(error));
  const double target = std::copysign(std::min({limits_.omega_max, reachable, std::abs(error) / dt_}), error);
  const double omega = approach(state.twist.omega, target, limits_.acc_omega * dt_);
  const double v = state.twist.v >= 0.0 ? std::max(0.0, state.twist.v - limits_.braking_v() * dt_)
                                        : std::min(0.0, state.twist.v + limits_.braking_v() * dt_);
  return Twist{v, omega};
}

const CycleRecord& Navigator::step(const RobotState& state, const Scan* scan, double time,
                                   const std::vector<Disc>& discs) {
  if (!has_goal_) throw Error("step() before set_goal(): the navigator has no goal");
  detail::require_finite_state(state);
  detail::require_finite("time", time);
  if (scan) {
    if (scan->ranges.size() != static_cast<std::size_t>(lidar_.beams))
      throw Error("scan: " + std::to_string(scan->ranges.size()) + " ranges, but the lidar has " +
                  std::to_string(lidar_.beams) + " beams");
    scan->validate();
  }
  for (const Disc& d : discs) d.validate();

  const int version_before = path_version_;
  record_.time = time;
  record_.state = state;
  record_.planned = false;
  record_.chosen = -1;
  record_.chosen_rollout.clear();
  record_.best.clear();
  record_.reject_counts.fill(0);
  record_.critic_vetoes.assign(controller_.planner().last_result().critic_names.size(), 0);
  record_.new_cells = 0;
  record_.times = StageTimes{};
  const Vec2 position = state.pose.position();

  Clock::time_point tic = Clock::now();
  discs_now_ = discs;
  record_.tracked.clear();
  const bool tracking = params_.track_moving && scan;
  if (scan) locate_hits(*scan);
  if (tracking) {
    track(*scan, time);
    discs_now_.insert(discs_now_.end(), record_.tracked.begin(), record_.tracked.end());
  }
  record_.times.tracking = seconds_since(tic);

  tic = Clock::now();
  if (scan_map_ && scan) {
    record_.new_cells = scan_map_->integrate(*scan, &keep_hit_);
    if (record_.new_cells) {
      // The planner lets go of the map while it changes, so that a field no one
      // else holds is updated in place.
      controller_.set_map(nullptr);
      if (known_map_) {
        // The known map with what the scans found that it lacks.
        const std::vector<std::size_t>& changed = scan_map_->changed_cells();
        for (const std::size_t i : changed)
          planning_map_->set(i, known_map_->cells()[i] != 0 || scan_map_->grid().cells()[i] != 0);
        if (!planning_field_ || planning_field_.use_count() > 1)
          planning_field_ = std::make_shared<DistanceField>(planning_field_ ? *planning_field_ : *known_field_);
        planning_field_->update(*planning_map_, changed);
        controller_.set_map(planning_field_);
      } else {
        controller_.set_map(scan_map_->field());
      }
      ++map_version_;
    }
  }
  record_.times.map = seconds_since(tic);

  if (recoveries_ > 0 && (position - recovery_origin_).norm() >= params_.progress_reset) recoveries_ = 0;
  const double goal_tolerance = controller_.planner().params().goal_tolerance;
  if (mode_now_ != NavigatorMode::Failed && (goal_ - position).norm() <= goal_tolerance)
    mode_now_ = NavigatorMode::GoalReached;

  Twist command;
  bool run_planner = false;
  tic = Clock::now();
  switch (mode_now_) {
    case NavigatorMode::GoalReached:
    case NavigatorMode::Failed:
      command = braking_command(limits_, state.twist, dt_);
      break;
    case NavigatorMode::Following:
    case NavigatorMode::Replanning:
      if (stalled(state)) {
        start_recovery(state, discs_now_);
        if (mode_now_ == NavigatorMode::Failed) {
          command = braking_command(limits_, state.twist, dt_);
          break;
        }
        if (mode_now_ != NavigatorMode::Following && mode_now_ != NavigatorMode::Replanning) break;
      }
      mode_now_ = NavigatorMode::Following;
      run_planner = true;
      break;
    default:
      remember_position(position);
      break;
  }
  // A recovery in progress gives this cycle's command, or ends and hands over.
  if (mode_now_ == NavigatorMode::BackingUp) {
    command = backup_command(state);
    if (command.v < 0.0 && step_clear(state.pose, command)) {
      backed_up_ += -command.v * dt_;
    } else {
      // Done, or the rear closed: the planner takes over from here.
      mode_now_ = NavigatorMode::Following;
      replan_now_ = true;
      run_planner = true;
    }
  } else if (mode_now_ == NavigatorMode::Rotating) {
    command = rotate_command(state);
    const bool done = std::abs(wrap_angle(rotate_goal_ - state.pose.theta)) < 0.05 && std::abs(command.omega) < 1e-3;
    if (done || rotated_ >= params_.rotate_limit || !step_clear(state.pose, command)) {
      mode_now_ = NavigatorMode::Following;
      replan_now_ = true;
      run_planner = true;
    } else {
      rotated_ += std::abs(command.omega) * dt_;
    }
  } else if (mode_now_ == NavigatorMode::Waiting) {
    // A mover coming at the robot ends the wait: the planner gets it out of the way.
    if (wait_cycles_left_ > 0 && standing_clear_of_movers(state, wait_cycles_left_-- * dt_)) {
      command = braking_command(limits_, state.twist, dt_);
    } else {
      mode_now_ = NavigatorMode::Following;
      replan_now_ = true;
      run_planner = true;
    }
  }
  ++cycles_since_replan_;
  const bool recovering = mode_now_ == NavigatorMode::BackingUp || mode_now_ == NavigatorMode::Rotating ||
                          mode_now_ == NavigatorMode::Waiting;
  if (run_planner && needs_path() && !recovering) {
    const bool due = cycles_since_replan_ >= replan_cycles_;
    if (!path_ || replan_now_ || (due && path_ahead_blocked(position))) {
      if (!plan_path(position) && !path_) {
        mode_now_ = NavigatorMode::Failed;
        failure_ = FailureReason::NoGlobalPath;
        command = braking_command(limits_, state.twist, dt_);
        run_planner = false;
      }
    }
  }
  record_.times.global = seconds_since(tic);

  if (run_planner) {
    const PlanResult& plan = controller_.step(state, goal_, scan, discs_now_);
    const CycleReport& report = controller_.report();
    record_.times.perception = report.perception_time;
    record_.times.plan = report.plan_time;
    command = plan.command;
    record_.planned = true;
    record_.status = plan.status;
    record_.target = plan.target;
    record_.key_node = plan.key_node;
    record_.density = report.density;
    record_.deviation = report.deviation;
    record_.beta = report.beta;
    record_.delta = report.delta;
    record_.reject_counts = plan.reject_counts;
    record_.critic_vetoes = plan.critic_vetoes;
    record_.chosen = plan.best_index;
    const std::vector<Trajectory>& rollouts = controller_.planner().rollouts();
    if (plan.best_index >= 0) record_.chosen_rollout = rollouts[static_cast<std::size_t>(plan.best_index)];
    order_.clear();
    for (int i = 0; i < static_cast<int>(plan.samples.size()); ++i)
      if (plan.reasons[static_cast<std::size_t>(i)] == RejectReason::None) order_.push_back(i);
    const std::size_t k = std::min(order_.size(), static_cast<std::size_t>(params_.record_top_k));
    std::partial_sort(order_.begin(), order_.begin() + static_cast<std::ptrdiff_t>(k), order_.end(),
                      [&](int a, int b) { return plan.total(a) > plan.total(b); });
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t i = static_cast<std::size_t>(order_[j]);
      record_.best.push_back(ScoredRollout{order_[j], plan.samples[i], plan.total(static_cast<Eigen::Index>(i)), rollouts[i]});
    }
    if (mode_now_ == NavigatorMode::Following && path_version_ != version_before)
      mode_now_ = NavigatorMode::Replanning;
  } else {
    record_.status = Status::Ok;
    record_.target = goal_;
    record_.key_node = -1;
    record_.density = record_.deviation = record_.beta = record_.delta = std::numeric_limits<double>::quiet_NaN();
    if (path_) record_.deviation = path_->deviation(position);
  }
  record_.command = command;
  record_.mode = mode_now_;
  record_.failure = failure_;
  record_.path = path_;
  record_.path_version = path_version_;
  record_.recoveries = recoveries_;
  ++mode_counts_[static_cast<std::size_t>(mode_now_)];
  if (mode_now_ == NavigatorMode::Replanning) mode_now_ = NavigatorMode::Following;
  return record_;
}

}  // namespace fgdwa
