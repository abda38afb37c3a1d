#pragma once
// Conversions at the Python edge: every failure raises fgdwa::Error (FgdwaError
// in Python) naming the argument and what was wrong with it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <string>
#include <vector>

#include "fgdwa/critics.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/geometry.hpp"
#include "fgdwa/limits.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa::py_convert {

namespace py = pybind11;

// A float64 C-contiguous copy of `obj` with the given trailing width
// (`width` 0: one-dimensional), or an error naming `name`. Every element must be
// finite; with `allow_infinite`, +-inf pass (a lidar's no-hit) and only NaN is refused.
py::array_t<double, py::array::c_style> float_array(py::handle obj, const std::string& name, int ndim, long width,
                                                    bool allow_infinite = false);

// A Python number (int or float) as a double, a str, a dict; otherwise an
// error naming `name` and the type given.
double to_number(py::handle obj, const std::string& name);
// A time ahead (s): finite, |t| <= limits::kMaxHorizon.
double to_time(double t, const std::string& name);
// A number as Python writes it (the shortest text that reads back the same).
std::string number_text(double value);
std::string to_word(py::handle obj, const std::string& name);
py::dict to_dict(py::handle obj, const std::string& name);

// An angle given in degrees, checked in degrees (lo <= degrees <= hi; `hi_open`:
// degrees < hi), so a refusal names the value as the user gave it; in radians.
double radians_from_degrees(const std::string& name, double degrees, double lo, double hi, bool hi_open = false);

Vec2 to_vec2(py::handle obj, const std::string& name);
Pose2 to_pose(py::handle obj, const std::string& name);
Twist to_twist(py::handle obj, const std::string& name);
std::vector<Vec2> to_points(py::handle obj, const std::string& name);

py::array_t<double> poses_to_array(const Trajectory& poses);
py::array_t<double> points_array(const std::vector<Vec2>& points);
// (n, 2) commands (v, omega).
py::array_t<double> twists_array(const std::vector<Twist>& twists);
// The enum value whose to_string() is `name`, the names written once, in
// to_string; otherwise an error naming `field` and the values it takes.
template <typename Enum, std::size_t N>
Enum enum_from_string(const std::string& field, const std::string& name, const std::array<Enum, N>& values) {
  std::string known;
  for (Enum value : values) {
    if (name == to_string(value)) return value;
    known += std::string(known.empty() ? "" : ", ") + "'" + to_string(value) + "'";
  }
  throw Error(field + " = '" + name + "': expected one of " + known);
}

// A CriticConfig from Python: numeric params go to `params`, words to `options`.
CriticConfig critic_config(std::string name, double weight, const py::dict& params);

}  // namespace fgdwa::py_convert
