#include "fgdwa/geometry.hpp"

#include <cmath>

namespace fgdwa {

double wrap_angle(double angle) {
  double wrapped = std::remainder(angle, 2.0 * M_PI);  // [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

double angle_difference(double a, double b) { return wrap_angle(a - b); }

}  // namespace fgdwa
