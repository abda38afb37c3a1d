#include "fgdwa/geometry.hpp"

#include <algorithm>
#include <cmath>

namespace fgdwa {

double wrap_angle(double angle) {
  // Most angles are already wrapped, and remainder() returns them unchanged; it
  // is slow enough to show in the planner's profile, so it is skipped for them.
  if (angle > -M_PI && angle <= M_PI) return angle;
  double wrapped = std::remainder(angle, 2.0 * M_PI);  // [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

double angle_difference(double a, double b) { return wrap_angle(a - b); }

double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 ab = b - a;
  const double length2 = ab.squaredNorm();
  if (length2 == 0.0) return (p - a).norm();
  const double t = std::clamp((p - a).dot(ab) / length2, 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

}  // namespace fgdwa
