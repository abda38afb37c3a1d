#include "fgdwa/recovery.hpp"

#include <algorithm>
#include <cmath>

#include "fgdwa/planner.hpp"
#include "fgdwa/window.hpp"
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

const char* to_string(RecoveryTrigger trigger) {
  switch (trigger) {
    case RecoveryTrigger::None: return "None";
    case RecoveryTrigger::NoProgress: return "NoProgress";
    case RecoveryTrigger::AllRejected: return "AllRejected";
    case RecoveryTrigger::Start: return "Start";
    case RecoveryTrigger::Wandering: return "Wandering";
  }
  return "?";
}

namespace {

int cycles_of(double seconds, double dt) { return static_cast<int>(std::lround(seconds / dt)); }

// Moves `current` toward `target` by at most `step`.
double approach(double current, double target, double step) {
  return current + std::clamp(target - current, -step, step);
}

}  // namespace

Recovery::Recovery(const RobotLimits& limits, const Footprint& footprint, const NavigatorParams& params, double dt,
                   double safety_margin, double goal_tolerance)
    : limits_(limits),
      footprint_(footprint),
      params_(params),
      dt_(dt),
      safety_margin_(safety_margin),
      goal_tolerance_(goal_tolerance),
      stall_cycles_(cycles_of(params.stall_time, dt)),
      wander_cycles_(cycles_of(params.wander_time, dt)) {}

void Recovery::reset() {
  recent_.clear();
  wander_origin_.reset();
  mode_ = NavigatorMode::Following;
  failure_ = FailureReason::None;
  trigger_ = RecoveryTrigger::None;
  recoveries_ = 0;
  rejected_cycles_ = 0;
}

void Recovery::watch(double duration) {
  detail::require_in_range("watch duration", duration, 0.0, limits::kMaxHorizon);
  const int cycles = cycles_of(duration, dt_);
  if (cycles < 1 || mode_ != NavigatorMode::Following) return;
  mode_ = NavigatorMode::Waiting;
  trigger_ = RecoveryTrigger::Start;
  wait_cycles_left_ = cycles;
}

void Recovery::fail(FailureReason reason) {
  mode_ = NavigatorMode::Failed;
  failure_ = reason;
}

void Recovery::replanned() {
  if (mode_ == NavigatorMode::Following) mode_ = NavigatorMode::Replanning;
}

void Recovery::end_cycle() {
  ++mode_counts_[static_cast<std::size_t>(mode_)];
  if (mode_ == NavigatorMode::Replanning) mode_ = NavigatorMode::Following;
}

RecoveryStep Recovery::step(const RobotState& state, const Vec2& goal, const FieldClearance& seen,
                            const std::vector<Disc>& movers, bool rejected_all) {
  RecoveryStep out;
  const Vec2 position = state.pose.position();
  if (recoveries_ > 0 && (position - origin_).norm() >= params_.progress_reset) recoveries_ = 0;
  if (mode_ != NavigatorMode::Failed && (goal - position).norm() <= goal_tolerance_) mode_ = NavigatorMode::GoalReached;
  // A trigger lasts while its recovery does (and stays with the failure it ended in).
  if (mode_ == NavigatorMode::Following || mode_ == NavigatorMode::Replanning || mode_ == NavigatorMode::GoalReached)
    trigger_ = RecoveryTrigger::None;

  switch (mode_) {
    case NavigatorMode::GoalReached:
    case NavigatorMode::Failed:
      out.command = braking_command(limits_, state.twist, dt_);
      break;
    case NavigatorMode::Following:
    case NavigatorMode::Replanning:
      if (stalled(state, rejected_all)) {
        start(state, seen, movers, out);
        if (mode_ == NavigatorMode::Failed) {
          out.command = braking_command(limits_, state.twist, dt_);
          break;
        }
        if (mode_ != NavigatorMode::Following && mode_ != NavigatorMode::Replanning) break;
      }
      mode_ = NavigatorMode::Following;
      out.drive = true;
      break;
    default:
      remember_position(position);
      break;
  }
  // A recovery in progress gives this cycle's command, or ends and hands over
  // to the planner on a new path.
  const auto hand_over = [&] {
    mode_ = NavigatorMode::Following;
    trigger_ = RecoveryTrigger::None;
    out.replan = true;
    out.drive = true;
  };
  // A mover that would reach the robot before the recovery is over ends it:
  // standing, backing up or turning blind to it, the robot would wait to be
  // hit; the planner gets it out of the way. Cut short, a backing up or a
  // turn is no attempt that failed (a wait never counts as one).
  const auto mover_coming = [&](double time_left) {
    return !movers.empty() && !standing_clear_of(movers, state, std::max(time_left, dt_));
  };
  const auto cut_short = [&] {
    --recoveries_;
    hand_over();
  };
  if (mode_ == NavigatorMode::BackingUp) {
    out.command = backup_command(state);
    if (mover_coming((params_.backup_distance - backed_up_) / reverse_limit()))
      cut_short();
    else if (out.command.v < 0.0 && step_clear(seen, state.pose, out.command))
      backed_up_ += -out.command.v * dt_;
    else
      hand_over();  // done, or the rear closed
  } else if (mode_ == NavigatorMode::Rotating) {
    out.command = rotate_command(state);
    const double angle = std::abs(wrap_angle(rotate_goal_ - state.pose.theta));
    const bool done = angle < 0.05 && std::abs(out.command.omega) < 1e-3;
    if (mover_coming(std::min(angle, params_.rotate_limit - rotated_) / limits_.omega_max))
      cut_short();
    else if (done || rotated_ >= params_.rotate_limit || !step_clear(seen, state.pose, out.command))
      hand_over();
    else
      rotated_ += std::abs(out.command.omega) * dt_;
  } else if (mode_ == NavigatorMode::Waiting) {
    if (wait_cycles_left_ > 0 && !mover_coming(wait_cycles_left_-- * dt_))
      out.command = braking_command(limits_, state.twist, dt_);
    else
      hand_over();
  }
  return out;
}

bool Recovery::stalled(const RobotState& state, bool rejected_all) {
  if (stall_cycles_ < 1) return false;
  // Every sample rejected cycle after cycle is a stall too, wherever the robot drifts.
  rejected_cycles_ = rejected_all ? rejected_cycles_ + 1 : 0;
  // A stall starts its checks over.
  const auto stall = [&](RecoveryTrigger trigger) {
    recent_.clear();
    wander_origin_.reset();
    trigger_ = trigger;
    return true;
  };
  if (rejected_cycles_ >= stall_cycles_) {
    rejected_cycles_ = 0;
    return stall(RecoveryTrigger::AllRejected);
  }
  const Vec2 position = state.pose.position();
  remember_position(position);
  if (wander_cycles_ > 0) {
    if (!wander_origin_ || (position - *wander_origin_).norm() > params_.wander_radius) {
      wander_origin_ = position;
      wandered_ = 0;
    } else if (++wandered_ >= wander_cycles_) {
      return stall(RecoveryTrigger::Wandering);
    }
  }
  if (static_cast<int>(recent_.size()) < stall_cycles_ + 1) return false;
  if ((position - recent_.front()).norm() >= params_.stall_distance) return false;
  return stall(RecoveryTrigger::NoProgress);
}

void Recovery::remember_position(const Vec2& position) {
  if (stall_cycles_ < 1) return;
  recent_.push_back(position);
  if (static_cast<int>(recent_.size()) > stall_cycles_ + 1) recent_.pop_front();
}

void Recovery::start(const RobotState& state, const FieldClearance& seen, const std::vector<Disc>& movers,
                     RecoveryStep& out) {
  const Vec2 position = state.pose.position();
  ++recoveries_;
  origin_ = position;
  if (recoveries_ > params_.max_recoveries) {
    fail(FailureReason::RecoveriesExhausted);
    return;
  }
  const bool mover_near = std::any_of(movers.begin(), movers.end(), [&](const Disc& d) {
    return d.velocity.norm() > 0.05 && (d.center - position).norm() - d.radius <= params_.wait_radius;
  });
  if (mover_near && params_.wait_time > 0.0) {
    // Letting a mover pass is not an attempt that failed.
    --recoveries_;
    mode_ = NavigatorMode::Waiting;
    wait_cycles_left_ = std::max(1, cycles_of(params_.wait_time, dt_));
    return;
  }
  out.give_up_ahead = true;
  backed_up_ = 0.0;
  backup_braking_ = false;
  rotated_ = 0.0;
  const Twist first_back = backup_command(state);
  if (params_.backup_distance > 0.0 && first_back.v < 0.0 && step_clear(seen, state.pose, first_back)) {
    mode_ = NavigatorMode::BackingUp;
  } else if (params_.rotate_limit > 0.0) {
    mode_ = NavigatorMode::Rotating;
    rotate_goal_ = open_heading(seen, state.pose);
  } else {
    out.replan = true;
  }
}

double Recovery::contact_margin(const FieldClearance& seen, const Pose2& pose) const {
  // As the planner does: the margin never asks for more room than the robot has.
  return fgdwa::contact_margin(seen.clearance(footprint_, pose, 0.0), safety_margin_);
}

bool Recovery::step_clear(const FieldClearance& seen, const Pose2& pose, const Twist& command) const {
  const double margin = contact_margin(seen, pose);
  // A turn in place sweeps the outline: check it every few degrees (no turn, no
  // check: the start itself, within the margin when in contact, is not the step's).
  const double turn = command.omega * dt_;
  const int turns = turn == 0.0 ? 0 : std::max(1, static_cast<int>(std::ceil(std::abs(turn) * footprint_.radius() / 0.02)));
  for (int i = 1; i <= turns; ++i) {
    const Pose2 turned{pose.x, pose.y, pose.theta + turn * i / turns};
    if (seen.clearance(footprint_, turned, 0.0) <= margin) return false;
  }
  const Pose2 after = unicycle_step(pose, command, dt_);
  const double length = std::hypot(after.x - pose.x, after.y - pose.y);
  const int pieces = std::max(1, static_cast<int>(std::ceil(length / 0.02)));
  for (int i = 1; i <= pieces; ++i) {
    const double f = double(i) / pieces;
    const Pose2 between{pose.x + f * (after.x - pose.x), pose.y + f * (after.y - pose.y), after.theta};
    if (seen.clearance(footprint_, between, 0.0) <= margin) return false;
  }
  return true;
}

double Recovery::open_heading(const FieldClearance& seen, const Pose2& pose) const {
  // The direction, of 16, in which the footprint can travel farthest (up to
  // 2 m) in the robot's view of the world; ties go to the smaller turn.
  const double margin = contact_margin(seen, pose);
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

Twist Recovery::backup_command(const RobotState& state) {
  // Reverse at up to backup_speed within the acceleration limits, braking in
  // time to stop after backup_distance.
  const double speed = std::max(0.0, -state.twist.v);
  const double brake = limits_.braking_v();
  const double remaining = params_.backup_distance - backed_up_;
  backup_braking_ = backup_braking_ || remaining <= speed * speed / (2.0 * brake) + speed * dt_;
  const double target = backup_braking_ ? 0.0 : reverse_limit();
  // A robot reversing faster than that is asked for no more: its wheels brake toward it.
  const double next = std::clamp(approach(speed, target, (target > speed ? limits_.acc_v : brake) * dt_), 0.0, reverse_limit());
  const double omega = approach(state.twist.omega, 0.0, limits_.braking_omega() * dt_);
  return Twist{-next, std::clamp(omega, -limits_.omega_max, limits_.omega_max)};
}

bool Recovery::standing_clear_of(const std::vector<Disc>& movers, const RobotState& state, double duration) const {
  Pose2 pose = state.pose;
  Twist twist = state.twist;
  for (int k = 0; k * dt_ <= duration + 1e-9; ++k) {
    if (moving_disc_clearance(movers, footprint_, pose, k * dt_) <= safety_margin_) return false;
    twist = braking_command(limits_, twist, dt_);
    pose = unicycle_step(pose, twist, dt_);
  }
  return true;
}

Twist Recovery::rotate_command(const RobotState& state) const {
  const double error = wrap_angle(rotate_goal_ - state.pose.theta);
  const double brake = limits_.braking_omega();
  // The fastest turn that still stops at the goal heading.
  const double reachable = std::sqrt(2.0 * brake * std::abs(error));
  const double target = std::copysign(std::min({limits_.omega_max, reachable, std::abs(error) / dt_}), error);
  const double omega = approach(state.twist.omega, target, limits_.acc_omega * dt_);
  const double v = state.twist.v >= 0.0 ? std::max(0.0, state.twist.v - limits_.braking_v() * dt_)
                                        : std::min(0.0, state.twist.v + limits_.braking_v() * dt_);
  // Whatever the state, the wheels are asked for nothing beyond the limits.
  return Twist{std::clamp(v, -reverse_limit(), limits_.v_max), std::clamp(omega, -limits_.omega_max, limits_.omega_max)};
}

}  // namespace fgdwa
