#pragma once
// The navigator's modes and how it gets out of a stall: a robot that has not
// made progress for stall_time waits for a mover beside it to pass, or backs
// up while its rear is clear, or turns toward the most open direction; then
// the local planner takes over on a new path (at once if a mover comes at
// the robot). Too many recoveries in a row without progress and it gives up.
//
// Lifecycle: reset() with every new goal; step() every cycle, before the local
// planner; end_cycle() after it.
#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/navigator_params.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {

enum class NavigatorMode : std::uint8_t {
  Following,   // the local planner drives along the global path (or to the goal)
  Replanning,  // a new global path was planned this cycle; the planner drives on it
  BackingUp,   // straight back after a stall, while the robot's map shows the rear clear
  Rotating,    // in place toward the most open direction after a stall with the rear blocked
  Waiting,     // standing while a known moving obstacle near the robot passes
  GoalReached,
  Failed,      // see CycleRecord::failure
};
constexpr std::size_t kNavigatorModeCount = 7;

enum class FailureReason : std::uint8_t {
  None,
  NoGlobalPath,         // no path to the goal on the map, at any inflation radius
  RecoveriesExhausted,  // max_recoveries recoveries in a row without progress
};

// What started the recovery under way.
enum class RecoveryTrigger : std::uint8_t {
  None,         // no recovery under way
  NoProgress,   // less than stall_distance of progress in stall_time
  AllRejected,  // the planner rejected every sample for stall_time
  Start,        // the first scans: the robot watches what moves before it drives (start_watch_time)
  Wandering,    // moving, but within wander_radius of one point for wander_time
};

const char* to_string(NavigatorMode mode);
const char* to_string(FailureReason reason);
const char* to_string(RecoveryTrigger trigger);

// What the recovery stage decided for this cycle.
struct RecoveryStep {
  bool drive = false;          // the local planner drives this cycle; otherwise `command`
  Twist command;
  bool replan = false;         // a new global path before the planner drives again
  bool give_up_ahead = false;  // a recovery began: the path ahead and the obstacles sensed near are closed to the global planner
};

// Threads: one per robot.
class Recovery {
 public:
  // `safety_margin` (m): the planner's; `goal_tolerance` (m): where the goal counts as reached.
  Recovery(const RobotLimits& limits, const Footprint& footprint, const NavigatorParams& params, double dt,
           double safety_margin, double goal_tolerance);

  // A new goal: following, no recoveries, no progress history.
  void reset();
  // This cycle from `state`: `seen` the robot's view of the world, `movers`
  // this cycle's moving obstacles, `rejected_all` whether the last cycle's
  // planner rejected every sample.
  RecoveryStep step(const RobotState& state, const Vec2& goal, const FieldClearance& seen,
                    const std::vector<Disc>& movers, bool rejected_all);
  // The robot stands for `duration` (s, in [0, 3600]) in Waiting, as it does for a
  // mover to pass: it hands over to the planner early if a mover comes at it.
  void watch(double duration);
  // No path to the goal: the robot stops for good.
  void fail(FailureReason reason);
  // A new global path was adopted while following.
  void replanned();
  // Counts the cycle's mode; a Replanning cycle goes back to Following.
  void end_cycle();

  NavigatorMode mode() const { return mode_; }
  FailureReason failure() const { return failure_; }
  // Why the recovery under way (or the one that gave up) began.
  RecoveryTrigger trigger() const { return trigger_; }
  // Recoveries in a row without progress, the current one included.
  int recoveries() const { return recoveries_; }
  // Cycles spent in each mode so far.
  const std::array<int, kNavigatorModeCount>& mode_counts() const { return mode_counts_; }

 private:
  bool stalled(const RobotState& state, bool rejected_all);
  // Keeps the last stall_cycles_ + 1 positions for the progress check.
  void remember_position(const Vec2& position);
  void start(const RobotState& state, const FieldClearance& seen, const std::vector<Disc>& movers, RecoveryStep& out);
  // Clearance below which the recoveries count the footprint in contact, for a robot at `pose`.
  double contact_margin(const FieldClearance& seen, const Pose2& pose) const;
  // Whether the footprint stays clear of the robot's view of the world moving from `pose` by `command`.
  bool step_clear(const FieldClearance& seen, const Pose2& pose, const Twist& command) const;
  // Whether the robot, braking to a stop from `state`, stays clear of the
  // movers for `duration` (s): waiting for a mover to pass is safe only where
  // it will not come.
  bool standing_clear_of(const std::vector<Disc>& movers, const RobotState& state, double duration) const;
  Twist backup_command(const RobotState& state);
  Twist rotate_command(const RobotState& state) const;
  // The fastest reverse a recovery asks for: backup_speed, never beyond v_max.
  double reverse_limit() const { return std::min(params_.backup_speed, limits_.v_max); }
  double open_heading(const FieldClearance& seen, const Pose2& pose) const;

  RobotLimits limits_;
  Footprint footprint_;
  NavigatorParams params_;
  double dt_, safety_margin_, goal_tolerance_;
  int stall_cycles_;
  NavigatorMode mode_ = NavigatorMode::Following;
  FailureReason failure_ = FailureReason::None;
  RecoveryTrigger trigger_ = RecoveryTrigger::None;
  int recoveries_ = 0;
  int rejected_cycles_ = 0;  // cycles in a row with every sample rejected
  std::deque<Vec2> recent_;  // positions of the last stall_cycles_ + 1 cycles
  int wander_cycles_ = 0;        // wander_time in cycles
  std::optional<Vec2> wander_origin_;  // where the robot last got wander_radius away from
  int wandered_ = 0;             // cycles following since then
  Vec2 origin_ = Vec2::Zero();   // where the last recovery began
  double backed_up_ = 0.0;       // m driven back in this recovery
  bool backup_braking_ = false;  // the back-up is stopping
  double rotated_ = 0.0;         // rad turned in this recovery
  double rotate_goal_ = 0.0;     // rad, the heading the rotation aims at
  int wait_cycles_left_ = 0;
  std::array<int, kNavigatorModeCount> mode_counts_{};
};

}  // namespace fgdwa
