#include "fgdwa/geometry.hpp"

#include <algorithm>
#include <cmath>

#include "validation.hpp"

namespace fgdwa {

double wrap_angle(double angle) {
  // Most angles are already wrapped, and remainder() returns them unchanged; it
  // is slow enough to show in the planner's profile, so it is skipped for them.
  if (angle > -M_PI && angle <= M_PI) return angle;
  detail::require_finite("angle", angle);
  double wrapped = std::remainder(angle, 2.0 * M_PI);  // [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

double angle_difference(double a, double b) { return wrap_angle(a - b); }

}  // namespace fgdwa
