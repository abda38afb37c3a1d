#pragma once
// Where a rollout's clearance comes from. The planner asks one ClearanceSource
// per pose of every rollout; `FieldClearance` (distance field plus analytic
// discs) is the fast path, `CollisionWorld` (FCL, collision.hpp) the exact one.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "fgdwa/grid.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {

// A disc obstacle moving at constant velocity; radius 0 is a point (a lidar hit).
// A predicted obstacle (a track) is less certain the farther ahead it is
// placed: its radius grows by `growth` every second. A hypothesis that the
// mover turns, slows or reverses adds a constant `acceleration` for the first
// `accel_time` seconds, after which the velocity it reached holds.
struct Disc {
  Vec2 center = Vec2::Zero();    // m, position now
  double radius = 0.0;           // m
  Vec2 velocity = Vec2::Zero();  // m/s
  double growth = 0.0;           // m/s, radius added per second ahead
  Vec2 acceleration = Vec2::Zero();  // m/s^2
  double accel_time = 0.0;           // s, how long the acceleration lasts
  Vec2 center_at(double t) const {
    // The acceleration's part: t^2 / 2 up to accel_time, then growing linearly (none for a time past).
    const double s = std::clamp(t, 0.0, accel_time);
    return center + t * velocity + (s * (t - 0.5 * s)) * acceleration;
  }
  // Whether it moves or grows: otherwise it is a static obstacle.
  bool moves() const { return growth > 0.0 || !velocity.isZero() || (accel_time > 0.0 && !acceleration.isZero()); }
  // Never below 0, for a time past as well.
  double radius_at(double t) const { return std::max(radius + growth * t, 0.0); }
  // m/s, the fastest its centre ever moves: the velocity changes linearly
  // while the acceleration lasts, so its norm is largest at an end (a disc
  // that brakes is fastest now, not twice as fast).
  double top_speed() const { return std::max(velocity.norm(), (velocity + accel_time * acceleration).norm()); }
  // s, the first time ahead (0 if now) at which the disc, grown by `reach`
  // (m, >= 0), covers `point`; +inf if it never does. Closed form while the
  // disc does not accelerate; through the acceleration, by steps that pass
  // over no contact lasting accel_time / 1e5 or longer, then bisection.
  double time_to_reach(const Vec2& point, double reach) const;
  void validate() const;
};

// Threads: const queries of every source may run concurrently on one object
// (planners on several threads sharing one world); the setters may not run
// while anything else uses it.
class ClearanceSource {
 public:
  virtual ~ClearanceSource() = default;
  // Distance from the footprint placed at `pose` to the nearest obstacle, with
  // moving obstacles predicted `t` seconds ahead; <= 0 means contact.
  virtual double clearance(const Footprint& footprint, const Pose2& pose, double t) const = 0;
  // For every pose of a rollout (pose k predicted (k + 1) dt ahead), a cheap
  // value never above clearance(); the planner asks for the exact one only
  // where the bound cannot settle what it needs. -inf: no bound. Checks the
  // poses and dt, then asks lower_bounds().
  void clearance_lower_bounds(const Footprint& footprint, const Trajectory& poses, double dt, double* out) const;

  // Whether clearance_lower_bounds gives the clearance itself for this
  // footprint, bit for bit: the planner then asks for no exact value.
  virtual bool lower_bounds_exact(const Footprint& footprint) const {
    (void)footprint;
    return false;
  }
  // The fastest any obstacle moves or grows, m/s: how fast clearance can fall
  // with the robot standing. 0 in a static world.
  virtual double obstacle_speed() const { return 0.0; }
  // Distance from the footprint at `pose` to the moving obstacles alone (those
  // with a velocity or a growth), placed `t` seconds ahead; +inf without any.
  virtual double moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const {
    (void)footprint, (void)pose, (void)t;
    return std::numeric_limits<double>::infinity();
  }
  // The same world without its moving obstacles, which the planner checks on
  // their own (moving_clearance); the source itself when it cannot split them.
  virtual const ClearanceSource& static_part() const { return *this; }

 protected:
  // clearance_lower_bounds() without the checks. The planner calls it
  // directly: its rollouts come from a checked state, and checking every pose
  // of every rollout would cost it as much as a bound.
  friend class LocalPlanner;
  virtual void lower_bounds(const Footprint& footprint, const Trajectory& poses, double dt, double* out) const {
    (void)footprint, (void)dt;
    std::fill(out, out + poses.size(), -std::numeric_limits<double>::infinity());
  }
  // lower_bounds() for `count` rollouts of `steps` poses each (pose k of a
  // rollout predicted (k + 1) dt ahead), rollout i's into out[i * steps, ...).
  // The planner asks for all of a cycle's at once, so that a source may
  // look them up in vectors across rollouts; by default one rollout at a time.
  virtual void rollouts_lower_bounds(const Footprint& footprint, const Trajectory* rollouts, std::size_t count,
                                     std::size_t steps, double dt, double* out) const {
    for (std::size_t i = 0; i < count; ++i) lower_bounds(footprint, rollouts[i], dt, out + i * steps);
  }
  // moving_clearance() without the checks, bit for bit where it is below
  // `cutoff`; elsewhere any value from cutoff up to it. The planner needs the
  // movers' clearance only where it could decide contact or lower a
  // rollout's least clearance.
  virtual double moving_clearance_below(const Footprint& footprint, const Pose2& pose, double t, double cutoff) const {
    (void)cutoff;
    return moving_clearance(footprint, pose, t);
  }
  // moving_clearance() without the checks, each mover where it is most
  // likely: its disc without the growth its prediction's uncertainty adds
  // ahead. The evasion falls back on it when the grown discs leave no way
  // out. The same as moving_clearance() while no mover grows.
  virtual double likely_moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const {
    return moving_clearance(footprint, pose, t);
  }
  // Whether some moving obstacle grows ahead (likely_moving_clearance() may differ).
  virtual bool movers_grow() const { return false; }
  // Both at once, bit for bit: grown as moving_clearance() without the checks,
  // likely as likely_moving_clearance(). A source may measure each mover once
  // for both (the two differ by the growth alone).
  virtual void moving_clearances(const Footprint& footprint, const Pose2& pose, double t, double& grown,
                                 double& likely) const {
    grown = moving_clearance(footprint, pose, t);
    likely = likely_moving_clearance(footprint, pose, t);
  }
  // clearance() without the checks, bit for bit where it is below `cutoff`;
  // elsewhere any value from cutoff up to the clearance. The planner often
  // needs to know only that a pose is at least so clear, which a source may
  // settle from cheap bounds without the exact value.
  virtual double clearance_below(const Footprint& footprint, const Pose2& pose, double t, double cutoff) const {
    (void)cutoff;
    return clearance(footprint, pose, t);
  }
};

// The footprint's distance to those of `discs` that move or grow, placed `t` seconds ahead.
double moving_disc_clearance(const std::vector<Disc>& discs, const Footprint& footprint, const Pose2& pose, double t);

// Threads: as ClearanceSource. The fields it holds may be shared with other
// sources; none of them may be updated while it is queried.
class FieldClearance : public ClearanceSource {
 public:
  // `field` may be null (no static map).
  explicit FieldClearance(std::shared_ptr<const DistanceField> field = nullptr, std::vector<Disc> discs = {});

  void set_discs(std::vector<Disc> discs);
  // Replaces the static map's field (null for none), e.g. with a map built from scans.
  void set_field(std::shared_ptr<const DistanceField> field);
  const std::vector<Disc>& discs() const { return discs_; }
  const std::shared_ptr<const DistanceField>& field() const { return field_; }
  // Obstacles seen by the lidar but missing from the map (perception.hpp's
  // points_field); null for none.
  void set_sensed(std::shared_ptr<const DistanceField> sensed);
  const std::shared_ptr<const DistanceField>& sensed() const { return sensed_; }

  double clearance(const Footprint& footprint, const Pose2& pose, double t) const override;
  // True for a circle among discs alone (point obstacles): no grid field.
  bool lower_bounds_exact(const Footprint& footprint) const override;
  double obstacle_speed() const override { return obstacle_speed_; }
  double moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const override;
  const ClearanceSource& static_part() const override { return fixed_ ? *fixed_ : *this; }

 protected:
  void lower_bounds(const Footprint& footprint, const Trajectory& poses, double dt, double* out) const override;
  void rollouts_lower_bounds(const Footprint& footprint, const Trajectory* rollouts, std::size_t count,
                             std::size_t steps, double dt, double* out) const override;
  double clearance_below(const Footprint& footprint, const Pose2& pose, double t, double cutoff) const override;
  double moving_clearance_below(const Footprint& footprint, const Pose2& pose, double t, double cutoff) const override;
  double likely_moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const override;
  bool movers_grow() const override { return !likely_moving_.empty(); }
  void moving_clearances(const Footprint& footprint, const Pose2& pose, double t, double& grown,
                         double& likely) const override;

 private:
  std::shared_ptr<const DistanceField> field_;
  double obstacle_speed_ = 0.0;
  // The fields and the discs that do not move; null when no disc moves.
  std::shared_ptr<FieldClearance> fixed_;
  void split_moving();
  std::shared_ptr<const DistanceField> sensed_;
  std::vector<Disc> discs_;
  // The discs that neither move nor grow, column by column, so that the
  // distance to all of them is one loop the compiler vectorises: point
  // obstacles (zero-radius discs) cost about what a grid does. The others stay
  // in moving_.
  struct StaticDiscs {
    // Sorted bucket by bucket (row-major), so that the discs of a row of
    // buckets lie side by side; the order changes no minimum.
    std::vector<double> x, y, radius;
    // Square buckets of side `side` from (x0, y0): bucket b = row * cols + col
    // holds the discs [start[b], start[b + 1]). No buckets for a few discs.
    double x0 = 0.0, y0 = 0.0, side = 0.0, largest_radius = 0.0;
    int cols = 0, rows = 0;
    std::vector<std::uint32_t> start;
    void assign(const std::vector<Disc>& still);
    // Calls run(first, count) for runs of discs holding every disc whose
    // centre lies within `reach` of (px, py) (and maybe others); all of them
    // at once without buckets or with a reach that is not finite.
    template <class Run>
    void near(double px, double py, double reach, Run run) const;
    // min over the discs of (|p - centre| - inflate) - radius (a circle's
    // clearance when inflate is its radius), bit for bit below `cutoff`;
    // otherwise `cutoff`. Looks only at the discs near enough to come below it.
    double distance_below(double px, double py, double inflate, double cutoff) const;
    // The least signed distance minus radius from a polygon footprint at
    // pose (px, py) with heading cos c and sin s: exact below `cutoff`,
    // otherwise a value from cutoff up to it.
    double polygon_distance(const Footprint& footprint, double px, double py, double c, double s, double cutoff) const;
  };
  StaticDiscs static_discs_;
  std::vector<Disc> moving_;
  // moving_ without growth, when some disc there grows (else empty).
  std::vector<Disc> likely_moving_;
};

}  // namespace fgdwa
