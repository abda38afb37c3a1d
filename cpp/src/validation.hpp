#pragma once
// Checks shared by every validate(): each message names the field and its value.
#include <cmath>
#include <sstream>
#include <string>

#include "fgdwa/error.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa::detail {

template <typename T>
std::string describe(const std::string& field, const T& value, const std::string& rule) {
  std::ostringstream out;
  out << field << " = " << value << ": " << rule;
  return out.str();
}

inline void require_finite(const std::string& field, double value) {
  if (!std::isfinite(value)) throw Error(describe(field, value, "must be finite"));
}

inline void require_positive(const std::string& field, double value) {
  require_finite(field, value);
  if (!(value > 0.0)) throw Error(describe(field, value, "must be > 0"));
}

inline void require_non_negative(const std::string& field, double value) {
  require_finite(field, value);
  if (value < 0.0) throw Error(describe(field, value, "must be >= 0"));
}

inline void require_at_least(const std::string& field, long value, long minimum) {
  if (value < minimum)
    throw Error(describe(field, value, "must be >= " + std::to_string(minimum)));
}

inline void require_finite_state(const RobotState& s) {
  require_finite("state x", s.pose.x);
  require_finite("state y", s.pose.y);
  require_finite("state theta", s.pose.theta);
  require_finite("state v", s.twist.v);
  require_finite("state omega", s.twist.omega);
}

}  // namespace fgdwa::detail
