#pragma once
// Checks shared by every validate() and public entry: each message names the
// field and its value as given, and the bound it breaks (fgdwa/limits.hpp).
#include <charconv>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>

#include <Eigen/Core>

#include "fgdwa/error.hpp"
#include "fgdwa/geometry.hpp"
#include "fgdwa/limits.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa::detail {

// The shortest text that reads back as the same double.
inline std::string format_number(double value) {
  char text[32];
  const auto end = std::to_chars(text, text + sizeof text, value).ptr;
  return std::string(text, end);
}

template <typename T>
std::string describe(std::string_view field, const T& value, std::string_view rule) {
  std::ostringstream out;
  if constexpr (std::is_floating_point_v<T>)
    out << field << " = " << format_number(static_cast<double>(value)) << ": " << rule;
  else
    out << field << " = " << value << ": " << rule;
  return out.str();
}

// Every check passes on its first comparison and builds text only to fail:
// some run once per clearance query.
[[noreturn, gnu::cold, gnu::noinline]] inline void fail_range(std::string_view field, double value, double lo, double hi) {
  if (!std::isfinite(value)) throw Error(describe(field, value, "must be finite"));
  throw Error(describe(field, value, "must lie in [" + format_number(lo) + ", " + format_number(hi) + "]"));
}

inline void require_finite(std::string_view field, double value) {
  if (!std::isfinite(value)) throw Error(describe(field, value, "must be finite"));
}

inline void require_positive(std::string_view field, double value) {
  require_finite(field, value);
  if (!(value > 0.0)) throw Error(describe(field, value, "must be > 0"));
}

inline void require_non_negative(std::string_view field, double value) {
  require_finite(field, value);
  if (value < 0.0) throw Error(describe(field, value, "must be >= 0"));
}

inline void require_at_least(std::string_view field, long value, long minimum) {
  if (value < minimum) throw Error(describe(field, value, "must be >= " + std::to_string(minimum)));
}

inline void require_at_most(std::string_view field, double value, double maximum) {
  require_finite(field, value);
  if (value > maximum) throw Error(describe(field, value, "must be <= " + format_number(maximum)));
}

// lo <= value <= hi, finite.
inline void require_in_range(std::string_view field, double value, double lo, double hi) {
  if (value >= lo && value <= hi && std::isfinite(value)) return;
  fail_range(field, value, lo, hi);
}

inline void require_count(std::string_view field, long value, long lo, long hi) {
  if (value < lo || value > hi)
    throw Error(describe(field, value, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]"));
}

// |value| <= bound (NaN fails).
inline void require_magnitude(std::string_view field, double value, double bound) {
  if (std::abs(value) <= bound) return;
  fail_range(field, value, -bound, bound);
}

// A positive length no longer than limits::kMaxLength.
inline void require_length(std::string_view field, double value) {
  require_positive(field, value);
  require_at_most(field, value, limits::kMaxLength);
}

// A non-negative length no longer than limits::kMaxLength.
inline void require_distance(std::string_view field, double value) {
  require_non_negative(field, value);
  require_at_most(field, value, limits::kMaxLength);
}

// A control period: at least kMinTimeStep, so counts of periods stay small.
inline void require_time_step(std::string_view field, double dt) {
  require_in_range(field, dt, limits::kMinTimeStep, limits::kMaxTimeStep);
}

// A step of integration (a simulator's, odometry's): any length up to
// kMaxTimeStep, 0 included.
inline void require_step_length(std::string_view field, double dt) {
  require_in_range(field, dt, 0.0, limits::kMaxTimeStep);
}

inline void require_resolution(std::string_view field, double resolution) {
  require_in_range(field, resolution, limits::kMinResolution, limits::kMaxResolution);
}

// The text of a failure is built out of line, so the passing checks inline.
[[gnu::cold, gnu::noinline]] inline void fail_xy(std::string_view field, double x, double y, double bound) {
  require_magnitude(std::string(field) + " x", x, bound);
  require_magnitude(std::string(field) + " y", y, bound);
}

inline void require_xy(std::string_view field, double x, double y, double bound) {
  if (std::abs(x) <= bound && std::abs(y) <= bound) return;
  fail_xy(field, x, y, bound);
}

// A point the user places in the world.
inline void require_point(std::string_view field, const Vec2& p) {
  require_xy(field, p.x(), p.y(), limits::kMaxCoordinate);
}

// A point of a geometric query (looser: rollouts from valid poses pass).
inline void require_query_point(std::string_view field, const Vec2& p) {
  require_xy(field, p.x(), p.y(), limits::kMaxQueryCoordinate);
}

// A point a distance field is asked about: any point of a footprint placed at
// a query pose, or a lidar hit from one.
inline constexpr double kMaxFieldCoordinate = limits::kMaxQueryCoordinate + limits::kMaxLength;
inline bool is_field_point(const Vec2& p) {
  return std::abs(p.x()) <= kMaxFieldCoordinate && std::abs(p.y()) <= kMaxFieldCoordinate;
}
inline void require_field_point(std::string_view field, const Vec2& p) {
  require_xy(field, p.x(), p.y(), kMaxFieldCoordinate);
}

[[gnu::cold, gnu::noinline]] inline void fail_pose(std::string_view field, const Pose2& pose, double bound) {
  require_xy(field, pose.x, pose.y, bound);
  require_magnitude(std::string(field) + " theta", pose.theta, limits::kMaxAngle);
}

// A pose whose position lies within `bound` (m) and whose heading is finite and bounded.
inline void require_pose_within(std::string_view field, const Pose2& pose, double bound) {
  if (std::abs(pose.x) <= bound && std::abs(pose.y) <= bound && std::abs(pose.theta) <= limits::kMaxAngle) return;
  fail_pose(field, pose, bound);
}

inline void require_pose(std::string_view field, const Pose2& pose) {
  require_pose_within(field, pose, limits::kMaxCoordinate);
}

inline void require_query_pose(std::string_view field, const Pose2& pose) {
  require_pose_within(field, pose, limits::kMaxQueryCoordinate);
}

// Every point of an array, in one branch-free pass for the common case; the
// first bad one is named field[i].
inline void require_points(std::string_view field, const Vec2* points, std::size_t n, double bound) {
  bool bad = false;
  for (std::size_t i = 0; i < n; ++i)
    bad |= !(std::abs(points[i].x()) <= bound) | !(std::abs(points[i].y()) <= bound);
  if (!bad) return;
  for (std::size_t i = 0; i < n; ++i)
    require_xy(std::string(field) + "[" + std::to_string(i) + "]", points[i].x(), points[i].y(), bound);
}

// Every pose of a trajectory, in one branch-free pass for the common case.
// The poses are read as one flat array of doubles, which vectorises: every
// field of a pose has the same bound.
static_assert(limits::kMaxAngle == limits::kMaxQueryCoordinate && sizeof(Pose2) == 3 * sizeof(double));
inline void require_query_poses(std::string_view field, const Trajectory& poses) {
  if (poses.empty()) return;
  const Eigen::Map<const Eigen::ArrayXd> values(&poses.front().x, static_cast<Eigen::Index>(3 * poses.size()));
  if ((values.abs() <= limits::kMaxQueryCoordinate).all()) return;  // NaN fails
  for (std::size_t k = 0; k < poses.size(); ++k)
    require_query_pose(std::string(field) + "[" + std::to_string(k) + "]", poses[k]);
}

[[gnu::cold, gnu::noinline]] inline void fail_twist(std::string_view field, const Twist& twist) {
  require_magnitude(std::string(field) + " v", twist.v, limits::kMaxSpeed);
  require_magnitude(std::string(field) + " omega", twist.omega, limits::kMaxSpeed);
}

inline void require_twist(std::string_view field, const Twist& twist) {
  if (std::abs(twist.v) <= limits::kMaxSpeed && std::abs(twist.omega) <= limits::kMaxSpeed) return;
  fail_twist(field, twist);
}

// rows x cols cells within limits::kMaxGridCells, checked before any cell is made.
inline void require_grid_size(int rows, int cols) {
  require_count("grid rows", rows, 1, limits::kMaxGridCells);
  require_count("grid cols", cols, 1, limits::kMaxGridCells);
  if (static_cast<long>(rows) * cols > limits::kMaxGridCells)
    throw Error(describe("grid size", std::to_string(rows) + " x " + std::to_string(cols),
                         "at most " + std::to_string(limits::kMaxGridCells) + " cells"));
}

inline void require_finite_state(const RobotState& s) {
  require_pose("state", s.pose);
  require_twist("state", s.twist);
}

}  // namespace fgdwa::detail
