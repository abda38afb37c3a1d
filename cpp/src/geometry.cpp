#include "fgdwa/geometry.hpp"

#include <algorithm>
#include <cmath>

#include "validation.hpp"

namespace fgdwa {

double wrap_angle(double angle) {
  // Most angles are already wrapped, and remainder() returns them unchanged; it
  // is slow enough to show in the planner's profile, so it is skipped for them.
  if (angle > -M_PI && angle <= M_PI) return angle;
  // One turn off (a difference of two wrapped angles): remainder() would take
  // exactly one 2 pi away, and so does the subtraction, exact for operands
  // within a factor of two of each other. Negated on the negative side, so
  // that -2 pi wraps to -0 as remainder() gives it.
  if (angle > M_PI && angle < 7.0) return angle - 2.0 * M_PI;
  if (angle <= -M_PI && angle > -7.0) return -(-angle - 2.0 * M_PI);
  detail::require_finite("angle", angle);
  double wrapped = std::remainder(angle, 2.0 * M_PI);  // [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

double angle_difference(double a, double b) { return wrap_angle(a - b); }

Pose2 compose(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, wrap_angle(a.theta + b.theta)};
}

Pose2 inverse(const Pose2& p) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  return {-c * p.x - s * p.y, s * p.x - c * p.y, wrap_angle(-p.theta)};
}

}  // namespace fgdwa
