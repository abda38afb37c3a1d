#include "fgdwa/planner.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "admissibility.hpp"
#include "step_sweep.hpp"
#include "validation.hpp"

namespace fgdwa {

const char* to_string(Status status) {
  switch (status) {
    case Status::Ok: return "Ok";
    case Status::NoAdmissibleVelocity: return "NoAdmissibleVelocity";
    case Status::Evading: return "Evading";
    case Status::GoalReached: return "GoalReached";
  }
  return "?";
}

const char* to_string(HeadingTarget target) {
  switch (target) {
    case HeadingTarget::Goal: return "goal";
    case HeadingTarget::KeyNodes: return "key_nodes";
  }
  return "?";
}

const char* to_string(WheelModel wheels) {
  switch (wheels) {
    case WheelModel::Ramp: return "ramp";
    case WheelModel::Instant: return "instant";
  }
  return "?";
}

const char* to_string(RejectReason reason) {
  switch (reason) {
    case RejectReason::None: return "None";
    case RejectReason::Collision: return "Collision";
    case RejectReason::Terrain: return "Terrain";
    case RejectReason::Critic: return "Critic";
    case RejectReason::Moving: return "Moving";
  }
  return "?";
}

const char* to_string(Normalization normalization) {
  switch (normalization) {
    case Normalization::Sum: return "sum";
    case Normalization::MinMax: return "minmax";
    case Normalization::None: return "none";
  }
  return "?";
}

const char* to_string(BrakingModel braking) {
  switch (braking) {
    case BrakingModel::Continuous: return "continuous";
    case BrakingModel::Discrete: return "discrete";
  }
  return "?";
}

void validate_passing_factors(const PassingFactors& factors) {
  for (std::size_t g = 0; g < factors.size(); ++g) {
    const std::string field = "passing_factors[" + std::to_string(g) + "]";
    detail::require_non_negative(field, factors[g]);
    if (factors[g] > 1.0) throw Error(detail::describe(field, factors[g], "must be <= 1"));
  }
}

int PlannerParams::n_steps() const { return static_cast<int>(std::lround(sim_time / dt)); }

void PlannerParams::check_relations(const ParamPath& path) const {
  if (sim_time / dt > static_cast<double>(limits::kMaxRolloutSteps))
    fail_param(path.field("sim_time"), detail::format_number(sim_time),
               "covers more than " + std::to_string(limits::kMaxRolloutSteps) + " steps of dt = " +
                   detail::format_number(dt) + " (s)");
  if (n_steps() < 1)
    fail_param(path.field("sim_time"), detail::format_number(sim_time), "must be at least one dt (s)");
  const double poses = static_cast<double>(window.n_v) * window.n_omega * n_steps();
  if (poses > static_cast<double>(limits::kMaxRolloutPoses))
    fail_param(path.field("sim_time"), detail::format_number(sim_time),
               "with dt = " + detail::format_number(dt) + " s and " + std::to_string(window.n_v) + " x " +
                   std::to_string(window.n_omega) + " samples, a cycle rolls out " + detail::format_number(poses) +
                   " poses, more than " + std::to_string(limits::kMaxRolloutPoses) +
                   ": fewer samples, a longer dt or a shorter sim_time");
  if (critics.empty()) throw Error(path.field("critics") + ": at least one critic is needed");
  for (std::size_t i = 0; i < critics.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (critics[i].name == critics[j].name)
        throw Error(path.field("critics") + ": '" + critics[i].name + "' is listed twice");
}

LocalPlanner::LocalPlanner(const RobotLimits& limits, const Footprint& footprint, const PlannerParams& params)
    : limits_(limits), footprint_(footprint), params_(params) {
  limits_.validate();
  params_.validate();
  n_steps_ = params_.n_steps();
  for (const CriticConfig& config : params_.critics) {
    critics_.push_back(make_critic(config));
    result_.critic_names.push_back(config.name);
    result_.weights.push_back(config.weight);
    result_.senses.push_back(critics_.back()->sense());
    if (config.name == "velocity") speed_critic_ = critics_.size() - 1;
  }
}

std::size_t LocalPlanner::critic_index(const std::string& name) const {
  for (std::size_t i = 0; i < result_.critic_names.size(); ++i)
    if (result_.critic_names[i] == name) return i;
  throw Error("the planner has no critic '" + name + "'");
}

double contact_margin(double clearance, double safety_margin) {
  if (clearance > 1e-3) return std::min(safety_margin, clearance - 1e-3);
  // Only a negative clearance measures how deep a robot is: a polygon's, or an
  // FCL world's, stops at zero in contact, where closing in cannot be told.
  if (clearance < 0.0) return clearance - kContactSlack;
  return std::max(clearance - kContactSlack, 0.0);
}

bool LocalPlanner::has_critic(const std::string& critic) const {
  return std::find(result_.critic_names.begin(), result_.critic_names.end(), critic) != result_.critic_names.end();
}

void LocalPlanner::set_weight(const std::string& critic, double weight) {
  detail::require_finite("weight of critic '" + critic + "'", weight);
  result_.weights[critic_index(critic)] = weight;
}

double LocalPlanner::weight(const std::string& critic) const { return result_.weights[critic_index(critic)]; }

void LocalPlanner::set_global_path(const GlobalPath& path) {
  path_ = std::make_unique<GlobalPath>(path);
  tracker_ = std::make_unique<KeyNodeTracker>(*path_, params_.key_nodes);
}

bool LocalPlanner::needs_path() const {
  return params_.heading_target == HeadingTarget::KeyNodes ||
         std::any_of(critics_.begin(), critics_.end(), [](const auto& c) { return c->needs_path(); });
}

void LocalPlanner::clear_global_path() {
  tracker_.reset();
  path_.reset();
}

void LocalPlanner::set_terrain(std::shared_ptr<const TerrainGrid> terrain, const PassingFactors& factors) {
  validate_passing_factors(factors);
  passing_factors_ = factors;
  terrain_ = std::move(terrain);
  impassable_.reset();
  if (!terrain_) return;
  std::vector<std::uint8_t> cells(terrain_->grades().size());
  for (std::size_t i = 0; i < cells.size(); ++i) cells[i] = terrain_->grades()[i] >= TerrainGrid::kMaxGrade;
  impassable_ = std::make_unique<FieldClearance>(std::make_shared<DistanceField>(
      OccupancyGrid(terrain_->rows(), terrain_->cols(), terrain_->resolution(), terrain_->origin(), std::move(cells))));
}

int LocalPlanner::first_terrain_contact(const Trajectory& poses, bool centre_only) const {
  if (centre_only) {
    for (std::size_t k = 0; k < poses.size(); ++k)
      if (terrain_->grade_at(poses[k].position()) >= TerrainGrid::kMaxGrade) return static_cast<int>(k);
    return n_steps_;
  }
  const DistanceField::LowerBounds bound = impassable_->field()->lower_bounds();
  for (std::size_t k = 0; k < poses.size(); ++k) {
    const Pose2& pose = poses[k];
    // Poses lie at most v_max dt apart, well inside the footprint's reach, so
    // the footprint at the poses covers the centre's way between them.
    if (bound(pose.x, pose.y) > footprint_.radius()) continue;
    if (impassable_->clearance(footprint_, pose, 0.0) <= 0.0) return static_cast<int>(k);
  }
  return n_steps_;
}

double LocalPlanner::impassable_clearance(const Trajectory& poses, int last, double below) const {
  const DistanceField::LowerBounds bound = impassable_->field()->lower_bounds();
  double best = below;
  for (int k = 0; k <= last && k < static_cast<int>(poses.size()); ++k) {
    const Pose2& pose = poses[static_cast<std::size_t>(k)];
    if (bound(pose.x, pose.y) - footprint_.radius() >= best) continue;
    best = std::min(best, impassable_->clearance(footprint_, pose, 0.0));
  }
  return best;
}

const std::vector<std::size_t>& LocalPlanner::key_nodes() const {
  static const std::vector<std::size_t> none;
  return tracker_ ? tracker_->nodes() : none;
}

const PlanResult& LocalPlanner::plan(const RobotState& state, const Vec2& goal, const ClearanceSource& world) {
  detail::require_finite_state(state);
  if (params_.heading_target == HeadingTarget::Goal) return run_cycle(state, goal, goal, -1, world);
  if (!tracker_) throw Error("heading_target = key_nodes needs a global path: call set_global_path first");
  // In sight: the footprint, heading for b, stays clear every 10 cm of the way.
  const auto in_sight = [&](const Vec2& a, const Vec2& b) {
    const Vec2 d = b - a;
    const double length = d.norm();
    const double heading = std::atan2(d.y(), d.x());
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / 0.1)));
    for (int k = 1; k <= pieces; ++k) {
      const Vec2 p = a + d * (double(k) / pieces);
      if (world.clearance(footprint_, Pose2{p.x(), p.y(), heading}, 0.0) <= 0.0) return false;
    }
    return true;
  };
  const Vec2 target = tracker_->update(state.pose.position(), in_sight);
  return run_cycle(state, goal, target, static_cast<int>(tracker_->current()), world);
}

const PlanResult& LocalPlanner::plan(const RobotState& state, const Vec2& goal, const Vec2& target,
                                     const ClearanceSource& world) {
  detail::require_finite_state(state);
  detail::require_point("target", target);
  return run_cycle(state, goal, target, -1, world);
}

const PlanResult& LocalPlanner::run_cycle(const RobotState& state, const Vec2& goal, const Vec2& target, int key_node,
                                          const ClearanceSource& world) {
  detail::require_point("goal", goal);
  result_.target = target;
  result_.key_node = key_node;
  result_.best_index = -1;
  result_.reject_counts.fill(0);
  if ((goal - state.pose.position()).norm() <= params_.goal_tolerance) {
    result_.status = Status::GoalReached;
    result_.command = braking_command(limits_, state.twist, params_.dt);
    // No samples this cycle: the per-sample diagnostics of the last one must go too.
    result_.samples.clear();
    rollouts_.clear();
    result_.reasons.clear();
    result_.min_clearance.clear();
    result_.free_distance.clear();
    result_.moving_contact.clear();
    result_.vetoed_by.clear();
    result_.critic_vetoes.assign(critics_.size(), 0);
    result_.signed_weights.assign(critics_.size(), 0.0);
    result_.raw.resize(0, static_cast<Eigen::Index>(critics_.size()));
    result_.normalized.resize(0, static_cast<Eigen::Index>(critics_.size()));
    result_.total.resize(0);
    return result_;
  }

  VelocityWindow window = dynamic_window(limits_, state.twist, params_.dt);
  if (terrain_) {
    // The slope under the robot holds it to a fraction of v_max, whatever it was doing.
    const double cap = passing_factors_[static_cast<std::size_t>(terrain_->grade_at(state.pose.position()))] * limits_.v_max;
    window.v_hi = std::min(window.v_hi, cap);
    window.v_lo = std::min(window.v_lo, window.v_hi);
  }
  // Near the goal, no faster than the robot can stop on it: braking once inside
  // the goal region then never carries it out again (the navigator stops
  // there for good).
  const double stop_cap = std::sqrt(2.0 * limits_.braking_v() * (goal - state.pose.position()).norm());
  window.v_hi = std::max(std::min(window.v_hi, stop_cap), window.v_lo);
  sample_window(window, state.twist, params_.window, result_.samples);
  evaluate_rollouts(state, goal, world);

  CriticContext context;
  context.state = state;
  context.goal = goal;
  context.target = target;
  context.dt = params_.dt;
  context.n_steps = n_steps_;
  context.path = path_.get();
  context.v_max = limits_.v_max;
  context.world = &world;
  context.footprint = &footprint_;
  score_and_choose(context);

  const int evasion = result_.best_index < 0 ? best_evasion(world) : -1;
  if (evasion >= 0) {
    result_.best_index = evasion;
    result_.status = Status::Evading;
    result_.command = result_.samples[static_cast<std::size_t>(evasion)];
  } else if (result_.best_index < 0) {
    result_.status = Status::NoAdmissibleVelocity;
    result_.command = braking_command(limits_, state.twist, params_.dt);
  } else {
    result_.status = Status::Ok;
    result_.command = result_.samples[static_cast<std::size_t>(result_.best_index)];
  }
  return result_;
}

void LocalPlanner::evaluate_rollouts(const RobotState& state, const Vec2& goal, const ClearanceSource& world) {
  const std::size_t n = result_.samples.size();
  rollouts_.resize(n);
  result_.reasons.resize(n);
  result_.min_clearance.resize(n);
  result_.moving_contact.resize(n);
  escape_.assign(n, -std::numeric_limits<double>::infinity());
  fixed_clearance_.assign(n, -std::numeric_limits<double>::infinity());
  shallowest_.assign(n, -std::numeric_limits<double>::infinity());
  result_.free_distance.resize(n);
  const double inf = std::numeric_limits<double>::infinity();
  // A start already in contact is not held against the first step, so the robot can still leave.
  // Contact is judged against the safety margin: the robot's motion between
  // control cycles (braking included) strays from the checked rollout by a few
  // millimetres, so a rollout grazing an obstacle is not trusted.
  // The margin never asks for more room than the robot already has, so a robot
  // that came within it can still move on without closing in. One already
  // within a millimetre, or overlapping by a measured depth (a map can grow
  // under a robot: a conservative cell newly seen beside it), may still turn or
  // move away, closing in by no more than kContactSlack (contact_margin): with a
  // margin clamped at zero every motion there counted as contact, turning in
  // place included, and the robot stood still for good.
  // The braking rule and the sweep hold against what stands still; moving
  // obstacles are checked on their own below, since braking cannot keep them off.
  const ClearanceSource& fixed = world.static_part();
  const double clearance_now = fixed.clearance(footprint_, state.pose, 0.0);
  const double margin = contact_margin(clearance_now, params_.safety_margin);
  margin_ = margin;
  const double start_clearance = clearance_now - margin;
  const double obstacle_travel = fixed.obstacle_speed() * params_.dt;
  mover_speed_ = world.obstacle_speed();
  const bool moving_world = params_.moving_horizon > 0.0 && mover_speed_ > 0.0;
  moving_horizon_ = params_.moving_horizon;
  if (moving_world && params_.moving_reach > 0.0)
    moving_horizon_ = std::min(moving_horizon_, params_.moving_reach / mover_speed_);
  const double moving_at_start = moving_world ? world.moving_clearance(footprint_, state.pose, 0.0) : inf;
  const std::size_t steps = static_cast<std::size_t>(n_steps_);
  bounds_.resize(n * steps);
  exact_.resize(static_cast<std::size_t>(n_steps_));
  at_least_.resize(static_cast<std::size_t>(n_steps_));
  // A footprint already over grade-4 cells may still leave: only its centre is held to them then.
  const bool terrain_centre_only = impassable_ && impassable_->clearance(footprint_, state.pose, 0.0) <= 0.0;
  const double cos_start = std::cos(state.pose.theta), sin_start = std::sin(state.pose.theta);
  // Samples come v-major: the headings of the first row serve every row, and
  // the speeds of a row's first sample the whole row.
  const std::size_t n_omega = static_cast<std::size_t>(params_.window.n_omega);
  const bool bounds_exact = fixed.lower_bounds_exact(footprint_);
  const bool instant = params_.wheels == WheelModel::Instant;
  response_ = instant ? 0.0 : params_.response_time;
  start_twist_ = state.twist;
  speed_profiles(state.twist.v, n_omega, instant);
  headings_.resize(std::min(n_omega, n));
  for (std::size_t j = 0; j < headings_.size(); ++j) {
    const double omega = result_.samples[j].omega;
    headings_[j].assign(state.pose.theta, cos_start, sin_start, instant ? omega : state.twist.omega, omega,
                        limits_.acc_omega, limits_.braking_omega(), params_.dt, n_steps_, response_);
    rollouts_sharing(state.pose, j, n_omega);
  }
  // Cheap lower bounds first, for every pose of every rollout at once; exact
  // clearances only where a bound cannot settle contact or the minimum. The
  // result is the same as evaluating every pose exactly.
  fixed.rollouts_lower_bounds(footprint_, rollouts_.data(), n, steps, params_.dt, bounds_.data());
  for (std::size_t i = 0; i < n; ++i) {
    const Twist& cmd = result_.samples[i];
    const Trajectory& poses = rollouts_[i];
    const SpeedProfile& speed = profiles_[i / n_omega];
    const double* const travel = travel_.data() + (i / n_omega) * (steps + 1);
    const double max_turn = headings_[i % n_omega].max_turn;
    // No step turns or drives farther than the rollout's longest: the sweep's
    // end clearances vouch for every step with those (the rest is measured).
    const detail::StepSweep step(footprint_, margin, max_turn, speed.longest, obstacle_travel);
    const double* const bounds = bounds_.data() + i * steps;
    if (bounds_exact)
      for (int k = 0; k < n_steps_; ++k) exact_[static_cast<std::size_t>(k)] = bounds[static_cast<std::size_t>(k)] - margin;
    else
      std::fill(exact_.begin(), exact_.end(), std::numeric_limits<double>::quiet_NaN());
    std::fill(at_least_.begin(), at_least_.end(), -inf);
    const auto exact = [&](int k) {
      double& c = exact_[static_cast<std::size_t>(k)];
      if (std::isnan(c))
        c = fixed.clearance(footprint_, poses[static_cast<std::size_t>(k)], (k + 1) * params_.dt) - margin;
      return c;
    };
    // min(clearance at pose k, cutoff): the source may stop short of the exact
    // value once it is sure of the cutoff.
    const auto below = [&](int k, double cutoff) {
      double& c = exact_[static_cast<std::size_t>(k)];
      double& reached = at_least_[static_cast<std::size_t>(k)];
      if (std::isnan(c) && reached < cutoff) {
        // The bound may reach the cutoff already (the previous pose's exact
        // clearance lowered the cutoff below what the bound was held to).
        if (bounds[static_cast<std::size_t>(k)] - margin >= cutoff) {
          reached = cutoff;
          return cutoff;
        }
        // A nanometre above the cutoff, so that a value the source stops at
        // still reaches the cutoff after the margin is taken off.
        const double raw_cutoff = cutoff + margin + 1e-9;
        const double raw =
            fixed.clearance_below(footprint_, poses[static_cast<std::size_t>(k)], (k + 1) * params_.dt, raw_cutoff);
        if (raw < raw_cutoff) c = raw - margin;
        else reached = cutoff;
      }
      return std::isnan(c) ? cutoff : std::min(c, cutoff);
    };
    // Clearance from the margin between a step's poses, exact below the
    // cutoff (a nanometre above it, so that a value the source stops at
    // still reaches the cutoff after the margin is taken off).
    const auto sweep_below = [&](const Pose2& pose, double t, double cutoff) {
      return fixed.clearance_below(footprint_, pose, t, cutoff + margin + 1e-9) - margin;
    };
    double free_distance = inf;
    int last = n_steps_ - 1;  // the last pose reached: the first in contact, or the end
    // Most poses are settled by their bound and the previous one, with room
    // to spare: skip those in one tight pass (step.clear_by_bounds implies
    // the loop's first test), and let the loop take over at the first other.
    int settled = 0;
    if (start_clearance > 0.0) {
      double previous = start_clearance;
      while (settled < n_steps_) {
        const double bound = bounds[static_cast<std::size_t>(settled)] - margin;
        if (!step.clear_by_bounds(previous, bound)) break;
        previous = bound;
        ++settled;
      }
    }
    for (int k = settled; k < n_steps_; ++k) {
      // Bounds and clearances count from the margin.
      const double bound = bounds[static_cast<std::size_t>(k)] - margin;
      const double previous_bound = k == 0 ? start_clearance : bounds[static_cast<std::size_t>(k - 1)] - margin;
      const bool leaving_contact = k == 0 && start_clearance <= 0.0;
      if (bound > 0.0 && (leaving_contact || step.covered(previous_bound, bound)))
        continue;  // clear at pose k and on the way there
      // The previous pose's clearance if known, else what it is known to
      // reach, may already settle the step with a little clearance at pose k:
      // that much is all the check needs to know there.
      const double known = k == 0 ? start_clearance : exact_[static_cast<std::size_t>(k - 1)];
      const double previous_low =
          std::isnan(known) ? std::max(previous_bound, at_least_[static_cast<std::size_t>(k - 1)]) : known;
      double c = leaving_contact ? exact(k) : below(k, step.settling_clearance(previous_low));
      if (c > 0.0 && !leaving_contact && step.covered(previous_low, c)) continue;
      c = exact(k);
      const Pose2& from = k == 0 ? state.pose : poses[static_cast<std::size_t>(k - 1)];
      const bool clear = c > 0.0 && (leaving_contact || detail::step_clear(sweep_below, footprint_, step, from,
                                                                   k == 0 ? start_clearance : exact(k - 1),
                                                                   poses[static_cast<std::size_t>(k)], c,
                                                                   k * params_.dt, params_.dt));
      if (!clear) {
        // Contact at or before pose k + 1: the robot travels k full steps in free space.
        free_distance = travel[k];
        last = k;
        break;
      }
    }
    // The smallest clearance over poses 0..last, and no further than the goal:
    // the robot stops there, so what lies beyond (a wall behind a goal) must
    // not turn it away from the goal. Admissibility above still holds the
    // whole rollout, braking included. Start from the pose with the smallest
    // bound, then visit only poses whose bound is below the best so far.
    const double reach2 = params_.goal_tolerance * params_.goal_tolerance;
    int scored_last = last;
    for (int k = 0; k < last; ++k)
      if ((poses[static_cast<std::size_t>(k)].position() - goal).squaredNorm() <= reach2) {
        scored_last = k;
        break;
      }
    int first_guess = 0;
    double lowest = bounds[0];
    for (int k = 1; k <= scored_last; ++k) {
      const double b = bounds[static_cast<std::size_t>(k)];
      first_guess = b < lowest ? k : first_guess;
      lowest = std::min(b, lowest);
    }
    double min_clearance = exact(first_guess);
    for (int k = 0; k <= scored_last; ++k)
      if (bounds[static_cast<std::size_t>(k)] - margin < min_clearance) min_clearance = below(k, min_clearance);
    result_.min_clearance[i] = min_clearance + margin;
    result_.free_distance[i] = free_distance;
    // Where the first period leaves the robot, and from there it must be able to stop.
    Twist reached{speed.reached, instant ? cmd.omega : state.twist.omega};
    response_step(reached.omega, cmd.omega, limits_.acc_omega, limits_.braking_omega(), response_, params_.dt);
    // Lagging wheels brake late: they cover about v times the lag before braking bites.
    const double lag_travel = std::abs(reached.v) * response_;
    const auto admissible = [&](double free) {
      return free >= lag_travel && detail::is_admissible_unchecked(cmd, reached, speed.first, free - lag_travel, limits_,
                                                                   params_.dt, params_.braking);
    };
    RejectReason reason = admissible(free_distance) ? RejectReason::None : RejectReason::Collision;
    if (reason == RejectReason::None && impassable_) {
      const int k = first_terrain_contact(poses, terrain_centre_only);
      if (k < n_steps_ && !admissible(travel[k])) reason = RejectReason::Terrain;
      // A pit is as impassable as a wall: the clearance critic keeps the robot
      // off its edge too, leaving it room to get out of a mover's way there.
      if (!terrain_centre_only)
        result_.min_clearance[i] = impassable_clearance(poses, std::min(last, k), result_.min_clearance[i]);
    }
    fixed_clearance_[i] = result_.min_clearance[i];
    result_.moving_contact[i] = std::numeric_limits<double>::infinity();
    if (reason == RejectReason::None && moving_world) {
      double closest = std::numeric_limits<double>::infinity();
      const Twist fastest{speed.longest / params_.dt, max_turn / params_.dt};
      result_.moving_contact[i] = first_moving_contact(fastest, poses, world, std::max(margin, 0.0), last,
                                                       moving_at_start, result_.min_clearance[i], closest, escape_[i],
                                                       shallowest_[i]);
      // An evasion must not trade the mover for a wall.
      escape_[i] = std::min(escape_[i], result_.min_clearance[i]);
      result_.min_clearance[i] = std::min(result_.min_clearance[i], closest);
      if (std::isfinite(result_.moving_contact[i])) reason = RejectReason::Moving;
    }
    result_.reasons[i] = reason;
    ++result_.reject_counts[static_cast<std::size_t>(result_.reasons[i])];
  }
}

double LocalPlanner::first_moving_contact(const Twist& cmd, const Trajectory& poses, const ClearanceSource& world,
                                          double margin, int last, double at_start, double fixed_clearance,
                                          double& closest, double& escape, double& shallowest) const {
  const double half_step = half_step_motion(cmd, mover_speed_);
  double contact = std::numeric_limits<double>::infinity();
  closest = at_start;
  escape = closest;
  shallowest = closest;
  if (closest - margin <= 0.0) contact = 0.0;
  // A clearance from here up decides no contact (a nanometre over, for the
  // sums' rounding) and, taken the least of with fixed_clearance, changes
  // nothing: the source may stop short of it there.
  const double cutoff = std::max(fixed_clearance, margin + half_step) + 1e-9;
  for (int k = 0; k <= last; ++k) {
    const double t = (k + 1) * params_.dt;
    const double c = world.moving_clearance_below(footprint_, poses[static_cast<std::size_t>(k)], t, cutoff);
    closest = std::min(closest, c);
    if (t - params_.dt < moving_horizon_) {
      escape = c;
      shallowest = std::min(shallowest, c);
      if (std::isinf(contact) && c - margin <= half_step) contact = t;
    }
  }
  return contact;
}

// Each pose adds to the one before, so one rollout at a time waits on its own
// sums: four go side by side, their additions independent. The same
// operations as rollout() per pose, so the same bits.
void LocalPlanner::rollouts_sharing(const Pose2& start, std::size_t first, std::size_t stride) {
  const RolloutHeadings& h = headings_[first];
  const std::size_t n = result_.samples.size(), steps = h.theta.size(), row = stride;
  std::size_t i = first;
  for (; i + 3 * stride < n; i += 4 * stride) {
    Trajectory* out[4];
    const double* step[4];
    double x[4], y[4];
    for (std::size_t l = 0; l < 4; ++l) {
      out[l] = &rollouts_[i + l * stride];
      out[l]->resize(steps);
      step[l] = lengths_.data() + (i + l * stride) / row * steps;
      x[l] = start.x;
      y[l] = start.y;
    }
    for (std::size_t k = 0; k < steps; ++k)
      for (std::size_t l = 0; l < 4; ++l) {
        x[l] += step[l][k] * h.cos[k];
        y[l] += step[l][k] * h.sin[k];
        (*out[l])[k] = Pose2{x[l], y[l], h.theta[k]};
      }
  }
  for (; i < n; i += stride) {
    const double* step = lengths_.data() + i / row * steps;
    Trajectory& out = rollouts_[i];
    out.resize(steps);
    double x = start.x, y = start.y;
    for (std::size_t k = 0; k < steps; ++k) {
      x += step[k] * h.cos[k];
      y += step[k] * h.sin[k];
      out[k] = Pose2{x, y, h.theta[k]};
    }
  }
}

void LocalPlanner::speed_profiles(double v_now, std::size_t row, bool instant) {
  const std::size_t n = result_.samples.size(), steps = static_cast<std::size_t>(n_steps_);
  const std::size_t rows = (n + row - 1) / row;
  lengths_.resize(rows * steps);
  travel_.resize(rows * (steps + 1));
  profiles_.resize(rows);
  for (std::size_t r = 0; r < rows; ++r) {
    const double target = result_.samples[r * row].v;
    double* length = lengths_.data() + r * steps;
    double* travel = travel_.data() + r * (steps + 1);
    SpeedProfile& p = profiles_[r];
    double v = instant ? target : v_now;
    p.longest = std::abs(target) * params_.dt;
    travel[0] = 0.0;
    for (std::size_t k = 0; k < steps; ++k) {
      length[k] = (v == target ? target : response_step(v, target, limits_.acc_v, limits_.braking_v(), response_, params_.dt)) * params_.dt;
      if (k == 0) p.reached = v;
      p.longest = std::max(p.longest, std::abs(length[k]));
      travel[k + 1] = travel[k] + std::abs(length[k]);
    }
    p.first = steps ? std::abs(length[0]) : 0.0;
  }
}

namespace {

// The command a robot reaches from `from` heading for `to` within one period dt.
double ramp(double from, double to, double rise, double fall, double dt) {
  if (to > from) return std::min(to, from + rise * dt);
  return std::max(to, from - fall * dt);
}

}  // namespace

double LocalPlanner::half_step_motion(const Twist& twist, double obstacle_speed) const {
  return 0.5 * params_.dt * (std::abs(twist.v) + footprint_.radius() * std::abs(twist.omega) + obstacle_speed);
}

void LocalPlanner::escape_after(std::size_t i, const ClearanceSource& world, int passes, const Escapes& rivals,
                                EscapeTurns& turns, Escapes& out) const {
  // Where the first period, ramping from the measured twist, leaves the wheels.
  Twist first = params_.wheels == WheelModel::Instant ? result_.samples[i] : start_twist_;
  response_step(first.v, result_.samples[i].v, limits_.acc_v, limits_.braking_v(), response_, params_.dt);
  response_step(first.omega, result_.samples[i].omega, limits_.acc_omega, limits_.braking_omega(), response_, params_.dt);
  const Trajectory& poses = rollouts_[i];
  // A contact in the first period cannot be helped by what follows it: of
  // those ways into a mover the shallowest is the least harm, not the one
  // that comes out farthest beyond it (straight through an oncoming disc).
  if (!(result_.moving_contact[i] > params_.dt) || poses.empty()) {
    out.fill(Escape{result_.moving_contact[i], shallowest_[i]});
    return;
  }
  out.fill(Escape{result_.moving_contact[i], -std::numeric_limits<double>::infinity()});
  const ClearanceSource& fixed = world.static_part();
  const double moving_margin = std::max(margin_, 0.0);  // as first_moving_contact counts it
  // No footprint point moves farther than the path driven plus the
  // circumscribed radius times the angle turned, so from the first pose's
  // clearance the fixed world cannot come within the margin before the two
  // have used up the room: those steps need no look-up (the same answer).
  const double room_at_first = fixed.clearance(footprint_, poses[0], params_.dt) - margin_ - 1e-9;
  const double reach = footprint_.radius();
  const int n_targets = kEscapeTargets;
  const std::size_t steps = static_cast<std::size_t>(std::max(n_steps_, 1));
  if (!(turns.theta0 == poses[0].theta && turns.omega0 == first.omega)) {
    turns.theta0 = poses[0].theta;
    turns.omega0 = first.omega;
    for (auto* column : {&turns.omega, &turns.theta, &turns.cos, &turns.sin})
      column->resize(static_cast<std::size_t>(n_targets) * steps);
    for (int b = 0; b < n_targets; ++b) {
      const double omega_target = limits_.omega_max * (2.0 * b / (n_targets - 1) - 1.0);
      double omega = first.omega, theta = poses[0].theta;
      for (int k = 1; k < n_steps_; ++k) {
        const std::size_t j = static_cast<std::size_t>(b) * steps + static_cast<std::size_t>(k);
        omega = ramp(omega, omega_target, limits_.acc_omega, limits_.braking_omega(), params_.dt);
        // As unicycle_step turns, then drives along the new heading.
        theta = wrap_angle(theta + omega * params_.dt);
        turns.omega[j] = omega, turns.theta[j] = theta, turns.cos[j] = std::cos(theta), turns.sin[j] = std::sin(theta);
      }
    }
  }
  // One continuation's steps 1 .. n_steps - 1: each pose, how far any
  // footprint point moved to reach it, and its clearance from the movers
  // (grown, then likely).
  thread_local Trajectory step_pose;
  thread_local std::vector<double> step_moved, step_clearance[2];
  step_pose.resize(steps);
  for (auto* column : {&step_moved, &step_clearance[0], &step_clearance[1]}) column->resize(steps);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const auto beats = [](const Escape& best, double contact, double room) {
    return contact > best.contact || (contact == best.contact && room > best.room);
  };
  for (int b = 0; b < n_targets; ++b) {
    const double* const omegas = turns.omega.data() + static_cast<std::size_t>(b) * steps;
    const double* const thetas = turns.theta.data() + static_cast<std::size_t>(b) * steps;
    const double* const cosines = turns.cos.data() + static_cast<std::size_t>(b) * steps;
    const double* const sines = turns.sin.data() + static_cast<std::size_t>(b) * steps;
    for (int a = 0; a < n_targets; ++a) {
      const double v_target = limits_.v_min + (limits_.v_max - limits_.v_min) * a / (n_targets - 1);
      Pose2 pose = poses[0];
      Twist twist = first;
      // Per ranking: the movers' contact (s, +inf: none), the least room to
      // them up to it, the last step the walls must leave clear (the one
      // before the contact), and whether the ranking is done with this
      // continuation (it met a mover, or is beaten if it did not).
      std::array<double, 2> contact{kInf, kInf}, room{kInf, kInf}, beaten_at{};
      std::array<int, 2> walls_to{n_steps_ - 1, n_steps_ - 1};
      std::array<bool, 2> done{false, passes < 2};
      // Room only shrinks along a continuation: once it is below what a way
      // out already keeps (this sample's best, or the samples' before it,
      // whose tie this one would lose only at equal room), it cannot win.
      for (int p = 0; p < passes; ++p)
        beaten_at[p] = std::max(std::isinf(out[p].contact) ? out[p].room : -kInf,
                                std::isinf(rivals[p].contact) ? std::nextafter(rivals[p].room, -kInf) : -kInf);
      // The movers first: the fixed world can only end a continuation
      // sooner, which takes its contact earlier and leaves its room as it was
      // up to there, so a continuation the movers alone do not let win is
      // not looked at against the fixed world.
      for (int k = 1; k < n_steps_ && !(done[0] && done[1]); ++k) {
        const auto j = static_cast<std::size_t>(k);
        twist.v = ramp(twist.v, v_target, limits_.acc_v, limits_.braking_v(), params_.dt);
        twist.omega = omegas[j];
        pose.theta = thetas[j];
        pose.x = pose.x + twist.v * cosines[j] * params_.dt;
        pose.y = pose.y + twist.v * sines[j] * params_.dt;
        const double t = (k + 1) * params_.dt;
        if (passes > 1) world.moving_clearances(footprint_, pose, t, step_clearance[0][j], step_clearance[1][j]);
        else step_clearance[0][j] = world.moving_clearance_below(footprint_, pose, t, kInf);
        step_pose[j] = pose;
        step_moved[j] = (std::abs(twist.v) + reach * std::abs(twist.omega)) * params_.dt;
        const double contact_within = half_step_motion(twist, mover_speed_);
        for (int p = 0; p < passes; ++p) {
          if (done[p]) continue;
          const double c = step_clearance[p][j];
          room[p] = std::min(room[p], c);
          if (c - moving_margin <= contact_within) contact[p] = t, walls_to[p] = k - 1, done[p] = true;
          else if (room[p] <= beaten_at[p]) done[p] = true;
        }
      }
      // The fixed world along the steps, as far as a ranking needs it (looked
      // at once for both). The most any footprint point has moved since the
      // last pose whose clearance from it is known (poses[0] first), and how
      // much room that one had beyond the margin: until the motion uses it
      // up, the fixed world cannot come within the margin (no look-up, the
      // same answer).
      double moved = 0.0, anchor_room = room_at_first;
      int checked = 0, fixed_hit = n_steps_;  // the steps looked at; the first in contact
      const auto fixed_contact_by = [&](int k_last) {
        while (checked < k_last && fixed_hit == n_steps_) {
          const auto j = static_cast<std::size_t>(++checked);
          moved += step_moved[j];
          if (moved < anchor_room) continue;
          // Only whether the margin is reached matters: a source may settle
          // that from its bounds (exact below the cutoff), and what it
          // answers above it is still room the next steps may use.
          const double fixed_room =
              fixed.clearance_below(footprint_, step_pose[j], (checked + 1) * params_.dt, margin_ + 1e-9) - margin_;
          if (fixed_room <= 0.0) fixed_hit = checked;
          moved = 0.0;
          anchor_room = fixed_room - 1e-9;
        }
        return fixed_hit <= k_last ? fixed_hit : n_steps_;
      };
      for (int p = 0; p < passes; ++p) {
        const bool beaten = done[p] && std::isinf(contact[p]);
        if (beaten || !beats(out[p], contact[p], room[p])) continue;
        const int hit = fixed_contact_by(walls_to[p]);
        if (hit < n_steps_) {
          contact[p] = (hit + 1) * params_.dt;
          room[p] = kInf;
          for (int k = 1; k <= hit; ++k) room[p] = std::min(room[p], step_clearance[p][static_cast<std::size_t>(k)]);
        }
        if (beats(out[p], contact[p], room[p])) out[p] = Escape{contact[p], room[p]};
      }
      // A way out of the grown discs leaves the likely ones nothing to decide.
      if (std::isinf(out[0].contact)) passes = 1;
    }
  }
}

int LocalPlanner::best_evasion(const ClearanceSource& world) const {
  // Two rankings of the same candidates in one sweep: against the movers'
  // grown discs, and against where they most likely go. When the grown discs
  // leave no way out within the horizon, their growth, more than the robot's
  // motion, decides when each way meets them: the latest contact then goes to
  // standing still (the rest meet them a step sooner) while a slow disc walks
  // into the robot. The likely discs tell the ways apart then.
  int passes = world.movers_grow() ? 2 : 1;
  std::array<int, 2> best{-1, -1};
  std::array<std::tuple<double, double, double>, 2> best_key;
  const auto escapes = [&] { return best[0] >= 0 && std::isinf(std::get<0>(best_key[0])); };
  // Samples come v-major: a column of the window shares its turn (escape_after).
  const std::size_t columns = std::max<std::size_t>(headings_.size(), 1);
  std::vector<EscapeTurns> turns(columns);
  // A way out that only braking keeps off the fixed world is taken only when
  // no other is: braking is what an evasion has no time for.
  bool some_clear = false;
  if (params_.prefer_clear)
    for (std::size_t i = 0; i < result_.samples.size(); ++i)
      some_clear = some_clear || (result_.reasons[i] == RejectReason::Moving && keeps_clear(i));
  Escapes rivals, e;
  for (std::size_t i = 0; i < result_.samples.size(); ++i) {
    if (result_.reasons[i] != RejectReason::Moving) continue;
    if (some_clear && !keeps_clear(i)) continue;
    for (int p = 0; p < 2; ++p)
      rivals[p] = best[p] < 0 ? Escape{} : Escape{std::get<0>(best_key[p]), std::get<1>(best_key[p])};
    escape_after(i, world, passes, rivals, turns[i % columns], e);
    for (int p = 0; p < passes; ++p) {
      const auto key = std::make_tuple(e[p].contact, e[p].room, escape_[i]);
      if (best[p] < 0 || key > best_key[p]) {  // strict: ties keep the first sample
        best[p] = static_cast<int>(i);
        best_key[p] = key;
      }
    }
    // A way out of the grown discs leaves the likely ones nothing to decide.
    if (escapes()) passes = 1;
  }
  return best[0] < 0 || escapes() || !world.movers_grow() ? best[0] : best[1];
}

void LocalPlanner::score_and_choose(const CriticContext& context) {
  const std::size_t n = result_.samples.size();
  const std::size_t m = critics_.size();
  for (auto& critic : critics_) {
    if (critic->needs_path() && !context.path)
      throw Error("critic '" + critic->name() + "' needs a global path: call set_global_path first");
    critic->prepare(context);
  }
  result_.raw.setZero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  result_.normalized.setZero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
  result_.total.setConstant(static_cast<Eigen::Index>(n), -std::numeric_limits<double>::infinity());

  result_.vetoed_by.assign(n, -1);
  result_.critic_vetoes.assign(m, 0);
  result_.signed_weights.assign(m, 0.0);  // until the weights are set below: nothing was scored
  admissible_.clear();
  admissible_index_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (result_.reasons[i] != RejectReason::None) continue;
    admissible_.push_back(Rollout{result_.samples[i], &rollouts_[i], result_.min_clearance[i], result_.free_distance[i]});
    admissible_index_.push_back(i);
  }
  if (admissible_.empty()) return;
  scores_.resize(admissible_.size());
  for (std::size_t j = 0; j < m; ++j) {
    critics_[j]->score_all(admissible_, scores_.data());
    for (std::size_t a = 0; a < admissible_.size(); ++a) {
      const std::size_t i = admissible_index_[a];
      if (Critic::is_veto(scores_[a])) {
        // The first critic to veto a sample is the one it is counted against.
        if (result_.vetoed_by[i] < 0) {
          result_.vetoed_by[i] = static_cast<int>(j);
          ++result_.critic_vetoes[j];
        }
        continue;
      }
      if (!std::isfinite(scores_[a]))
        throw Error(detail::describe("critic '" + critics_[j]->name() + "' score", scores_[a],
                                     "must be finite (Critic::veto() rejects a sample)"));
      result_.raw(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = scores_[a];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (result_.vetoed_by[i] < 0) continue;
    --result_.reject_counts[static_cast<std::size_t>(RejectReason::None)];
    ++result_.reject_counts[static_cast<std::size_t>(RejectReason::Critic)];
    result_.reasons[i] = RejectReason::Critic;
    result_.raw.row(static_cast<Eigen::Index>(i)).setZero();
  }

  // The vetoed leave the admissible; the loops below visit the rest alone, in order.
  admissible_index_.erase(std::remove_if(admissible_index_.begin(), admissible_index_.end(),
                                         [&](std::size_t i) { return result_.reasons[i] != RejectReason::None; }),
                          admissible_index_.end());
  for (std::size_t j = 0; j < m; ++j) {
    const auto raw = result_.raw.col(static_cast<Eigen::Index>(j));
    auto normalized = result_.normalized.col(static_cast<Eigen::Index>(j));
    double magnitude = 0.0, lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const std::size_t i : admissible_index_) {
      magnitude += std::abs(raw(i));
      lo = std::min(lo, raw(i));
      hi = std::max(hi, raw(i));
    }
    // Rejected samples keep the zero they were given above.
    switch (params_.normalization) {
      // Dividing by a positive number keeps every term's order, whatever its sign.
      case Normalization::Sum:
        if (magnitude > 0.0)
          for (const std::size_t i : admissible_index_) normalized(i) = raw(i) / magnitude;
        break;
      case Normalization::MinMax:
        if (hi > lo)
          for (const std::size_t i : admissible_index_) normalized(i) = (raw(i) - lo) / (hi - lo);
        break;
      case Normalization::None:
        for (const std::size_t i : admissible_index_) normalized(i) = raw(i);
        break;
    }
  }
  // This cycle's weights: the velocity critic's scaled while a mover is near;
  // a cost's negated (exactly: -(w x) is (-w) x).
  cycle_weights_ = result_.weights;
  if (speed_critic_ < m &&
      context.world->moving_clearance(footprint_, context.state.pose, 0.0) <= params_.mover_caution_radius)
    cycle_weights_[speed_critic_] *= params_.mover_speed_weight;
  std::vector<double>& signed_weights = result_.signed_weights;
  signed_weights.resize(m);
  for (std::size_t j = 0; j < m; ++j)
    signed_weights[j] = result_.senses[j] == CriticSense::Cost ? -cycle_weights_[j] : cycle_weights_[j];
  double best = -std::numeric_limits<double>::infinity();
  // Movers apart: their predicted contacts have rules of their own (moving_horizon).
  bool some_clear = false;
  if (params_.prefer_clear)
    for (const std::size_t i : admissible_index_) some_clear = some_clear || stays_off(i);
  for (const std::size_t i : admissible_index_) {
    double total = 0.0;
    for (std::size_t j = 0; j < m; ++j) total += signed_weights[j] * result_.normalized(i, j);
    if (!std::isfinite(total)) {
      // Finite scores whose weighted sum is not: a choice made on inf is no choice.
      std::size_t worst = 0;
      for (std::size_t j = 1; j < m; ++j)
        if (!(std::abs(result_.normalized(i, j)) <= std::abs(result_.normalized(i, worst)))) worst = j;
      throw Error("critic '" + result_.critic_names[worst] + "': its score " +
                  detail::format_number(result_.raw(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(worst))) +
                  " (weighted " + detail::format_number(signed_weights[worst]) +
                  ") makes a sample's total overflow: scale the scores down or normalise them");
    }
    result_.total(static_cast<Eigen::Index>(i)) = total;
    if (some_clear && !stays_off(i)) continue;  // scored, but not chosen
    if (total > best) {  // strict: ties keep the first sample, deterministically
      best = total;
      result_.best_index = static_cast<int>(i);
    }
  }
}

}  // namespace fgdwa
