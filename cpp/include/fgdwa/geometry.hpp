#pragma once
// Plain value types of the plane: poses, velocity commands, trajectories.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <vector>

namespace fgdwa {

using Vec2 = Eigen::Vector2d;

struct Pose2 {
  double x = 0.0;      // m
  double y = 0.0;      // m
  double theta = 0.0;  // rad, counter-clockwise from +x
  Vec2 position() const { return {x, y}; }
};

struct Twist {
  double v = 0.0;      // m/s, forward speed
  double omega = 0.0;  // rad/s, counter-clockwise
};

// Poses after each time step of a rollout; the start pose is not included.
using Trajectory = std::vector<Pose2>;

// Angle in (-pi, pi].
double wrap_angle(double angle);

// Smallest signed difference a - b, in (-pi, pi].
double angle_difference(double a, double b);

// The pose `b`, given in the frame that `a` places, in a's own frame: a * b
// as rigid transforms.
Pose2 compose(const Pose2& a, const Pose2& b);
// The transform that undoes `p`: compose(inverse(p), p) is the identity.
Pose2 inverse(const Pose2& p);

// Inline: these run in the clearance queries' inner loops.
namespace detail {
// Squared distance from p to the segment a-b (to a when the segment is a
// point): the library's polygon takes one root of the least of its edges'.
inline double point_segment_distance2(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return (p - a).squaredNorm();
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return (p - (a + t * ab)).squaredNorm();
}
}  // namespace detail

// Distance from p to the segment a-b (to a when the segment is a point): the
// root of the square, as norm() takes it.
inline double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  return std::sqrt(detail::point_segment_distance2(p, a, b));
}

// The part [t0, t1] of the segment a + t (b - a), t in [0, 1], inside the box
// [lo, hi] (Liang-Barsky); false when it misses the box.
inline bool clip_segment_to_box(const Vec2& a, const Vec2& b, const Vec2& lo, const Vec2& hi, double& t0, double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const Vec2 d = b - a;
  for (int axis = 0; axis < 2; ++axis) {
    const double p[2] = {-d[axis], d[axis]};
    const double q[2] = {a[axis] - lo[axis], hi[axis] - a[axis]};
    for (int side = 0; side < 2; ++side) {
      if (p[side] == 0.0) {
        if (q[side] < 0.0) return false;  // parallel to this edge and outside it
        continue;
      }
      const double r = q[side] / p[side];
      if (p[side] < 0.0)
        t0 = std::max(t0, r);
      else
        t1 = std::min(t1, r);
    }
  }
  return t0 <= t1;
}


}  // namespace fgdwa
