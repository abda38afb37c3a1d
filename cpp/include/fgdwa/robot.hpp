#pragma once
// The robot: velocity and acceleration limits, its footprint, and the unicycle
// motion model used both to predict rollouts and to move the simulated robot.
#include <vector>

#include "fgdwa/geometry.hpp"
#include "fgdwa/params.hpp"

namespace fgdwa {

struct RobotLimits {
  double v_min = 0.0;
  double v_max = 1.2;
  double omega_max = 1.0;
  double acc_v = 1.0;
  double acc_omega = 2.0;
  double brake_v = 0.0;
  double brake_omega = 0.0;

  static constexpr const char* kName = "limits";
  template <class V>
  static void fields(V& v) {
    using limits::kMaxAcceleration;
    using limits::kMaxSpeed;
    using limits::kMinAcceleration;
    v.real("v_min", &RobotLimits::v_min, "m/s", Bounds::at_least(0, kMaxSpeed), "slowest forward speed (0: forward only, down to standing)");
    v.real("v_max", &RobotLimits::v_max, "m/s", Bounds::positive(kMaxSpeed), "fastest forward speed");
    v.real("omega_max", &RobotLimits::omega_max, "rad/s", Bounds::positive(kMaxSpeed), "symmetric turn-rate limit");
    v.real("acc_v", &RobotLimits::acc_v, "m/s^2", Bounds::closed(kMinAcceleration, kMaxAcceleration), "linear acceleration");
    v.real("acc_omega", &RobotLimits::acc_omega, "rad/s^2", Bounds::closed(kMinAcceleration, kMaxAcceleration), "angular acceleration");
    v.real("brake_v", &RobotLimits::brake_v, "m/s^2", Bounds::at_least(0, kMaxAcceleration), "linear braking deceleration; 0: the same as acc_v");
    v.real("brake_omega", &RobotLimits::brake_omega, "rad/s^2", Bounds::at_least(0, kMaxAcceleration), "angular braking deceleration; 0: the same as acc_omega");
  }
  // v_min <= v_max; a braking deceleration other than 0 at least kMinAcceleration.
  void check_relations(const ParamPath& path) const;

  double braking_v() const { return brake_v > 0.0 ? brake_v : acc_v; }
  double braking_omega() const { return brake_omega > 0.0 ? brake_omega : acc_omega; }
  // Throws fgdwa::Error naming the first bad field.
  void validate() const { validate_params(*this); }
};

struct RobotState {
  Pose2 pose;
  Twist twist;
};

// A circle centred on the robot, or a convex polygon in the robot frame
// (x forward, y left), vertices in any winding order.
// Threads: immutable once built; share it freely.
class Footprint {
 public:
  static Footprint circle(double radius);
  static Footprint polygon(std::vector<Vec2> vertices);

  // The footprint grown by `margin` (m, >= 0) on every side: a circle's radius,
  // a polygon's edges moved outward, its corners kept sharp (mitred) so
  // that the grown polygon covers every point within `margin` of the outline.
  Footprint padded(double margin) const;

  bool is_circle() const { return vertices_.empty(); }
  // Circle radius, or the polygon's circumscribed radius about the robot origin.
  double radius() const { return radius_; }
  // Largest circle about the robot origin inside the footprint.
  double inscribed_radius() const { return inscribed_radius_; }
  // Half the footprint's least width (the radius for a circle): no point
  // inside lies farther than this from the outline.
  double half_width() const { return half_width_; }
  // The smallest axis-aligned box holding the footprint, in the robot frame
  // (its lower and upper corners): a point's distance from it is a lower
  // bound of its distance from the footprint.
  const Vec2& box_min() const { return box_min_; }
  const Vec2& box_max() const { return box_max_; }
  // Counter-clockwise vertices in the robot frame; empty for a circle.
  const std::vector<Vec2>& vertices() const { return vertices_; }

  // The footprint's shortest chord along the heading (the robot's x axis) over
  // the heights it spans: a polygon's edge length at its lowest and highest y
  // (0 where a vertex sits alone there), 0 for a circle. A straight drive no
  // longer than it sweeps nothing outside the start and end placements.
  double heading_chord() const { return heading_chord_; }

  // Discs (robot frame: centre, radius) whose union covers the footprint: the
  // circle itself, or a polygon's bounding box cut into pieces of at most half
  // its short side. Distance bounds from them are tighter than from the
  // circumscribed circle for an elongated robot.
  struct CoverDisc {
    Vec2 centre;
    double radius;
  };
  const std::vector<CoverDisc>& cover() const { return cover_; }

  // Signed distance from the footprint placed at `pose` to the point `p`
  // (negative inside).
  double signed_distance(const Pose2& pose, const Vec2& p) const;
  // The same for a point `q` given in the robot frame: what a caller
  // measuring many points from one pose uses, turning each itself. Throws
  // fgdwa::Error for a point that is not finite or beyond the query bounds.
  double signed_distance_in_frame(const Vec2& q) const;
  // Whether the point `p` lies inside the footprint placed at `pose`.
  bool contains(const Pose2& pose, const Vec2& p) const;

 private:
  Footprint() = default;
  // Whether the polygon holds `q`, given in the robot's frame.
  bool polygon_contains(const Vec2& q) const;
  double radius_ = 0.0;
  double inscribed_radius_ = 0.0;
  double half_width_ = 0.0;
  double heading_chord_ = 0.0;
  Vec2 box_min_ = Vec2::Zero(), box_max_ = Vec2::Zero();
  std::vector<Vec2> vertices_;
  std::vector<CoverDisc> cover_;
};

// One unicycle step of length dt: theta first, then the position along the new
// heading (Figure 2 of the paper): theta += omega dt; x += v cos(theta) dt; y += v sin(theta) dt.
Pose2 unicycle_step(const Pose2& pose, const Twist& twist, double dt);

// `n_steps` poses of a constant command, each after one more step; written into
// `out` (resized) so a control loop can reuse the storage.
void rollout(const Pose2& start, const Twist& twist, double dt, int n_steps, Trajectory& out);
Trajectory rollout(const Pose2& start, const Twist& twist, double dt, int n_steps);

// How wheels follow a new command, the way Nav2 DWB's trajectory generator
// models it: a velocity moves toward its target at `rise` (per second) while
// its magnitude grows and at `fall` while it shrinks (through zero: shrinking,
// then growing), then holds it. One step of dt: `value` becomes the velocity at
// the step's end; returns its mean over the step, which a unicycle step uses.
double ramp_step(double& value, double target, double rise, double fall, double dt);
// The same for wheels that also follow the command through a first-order lag
// of time constant `response` (s): the velocity ramps toward where the lag has
// brought it by the step's end; ramp_step when `response` is 0.
double response_step(double& value, double target, double rise, double fall, double response, double dt);

// The rollout a planner predicts for `command` from a robot moving at
// `current`: each step moves with the mean twist of the ramp toward the
// command at the limits (acc_v, braking_v(); acc_omega, braking_omega()), then
// with the command itself.
void rollout(const Pose2& start, const Twist& current, const Twist& command, const RobotLimits& limits, double dt,
             int n_steps, Trajectory& out);
Trajectory rollout(const Pose2& start, const Twist& current, const Twist& command, const RobotLimits& limits,
                   double dt, int n_steps);

// The headings of a rollout, pose by pose, with their cosines and sines: they
// depend on the start heading and omega only, so every command of a window
// with the same omega shares them.
struct RolloutHeadings {
  // Computes them in place, reusing the storage.
  void assign(double start_theta, double cos_start, double sin_start, double omega, double dt, int n_steps);
  // The same for a turn rate that ramps from `omega_now` toward `omega`
  // (ramp_step, at `rise` and `fall`) before it holds: the first steps turn by
  // the ramp's mean, `max_turn` becomes the largest |turn| of a step (rad).
  // `response`: the wheels' first-order lag (response_step), 0 for none.
  void assign(double start_theta, double cos_start, double sin_start, double omega_now, double omega, double rise,
              double fall, double dt, int n_steps, double response = 0.0);
  std::vector<double> theta, cos, sin;  // per pose; theta wrapped to (-pi, pi]
  double max_turn = 0.0;
};

// The same rollout with the headings given and the step length v dt.
void rollout(const Pose2& start, double step_length, const RolloutHeadings& headings, Trajectory& out);

}  // namespace fgdwa
