#pragma once
// Conversions at the Python edge: every failure raises fgdwa::Error (FgdwaError
// in Python) naming the argument and what was wrong with it.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <initializer_list>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
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
// An int as Python writes it; one of many digits shortened to its first ones
// and its length, so that a message stays readable.
std::string int_text(py::handle value);
std::string to_word(py::handle obj, const std::string& name);
py::dict to_dict(py::handle obj, const std::string& name);

// The argument types of integer and float parameters. pybind11 refuses a
// Python int that does not fit the C++ type with a TypeError naming no
// parameter ("incompatible function arguments"); these take any int, and
// to_int / to_float refuse the ones that do not fit with fgdwa::Error naming
// the parameter and the value. They take what pybind11 takes for int and
// double otherwise (bool and objects with __index__ for an int, never a float),
// and the type stubs name them as pybind11 names int and float.
struct IntArg {
  py::int_ value;
};

struct FloatArg {
  double value = 0.0;
  py::object too_large;  // an int beyond a double, as given
};

// Whether `value` fits a long long / an unsigned long long; if so, it is in `out`.
bool int_fits(const py::int_& value, long long& out);
bool int_fits(const py::int_& value, unsigned long long& out);
[[noreturn]] void fail_int(const IntArg& arg, const std::string& name, const std::string& lo, const std::string& hi);

// `arg` as a T. A value T cannot hold is refused as "name = value: must lie in
// [lo, hi]", lo and hi being the bounds the library checks the parameter
// against (by default T's own); a value T holds is returned as it is, for the
// library's own checks to refuse in their words.
template <typename T>
T to_int(const IntArg& arg, const std::string& name, T lo = std::numeric_limits<T>::min(),
         T hi = std::numeric_limits<T>::max()) {
  static_assert(std::is_integral_v<T> && !std::is_same_v<T, bool>);
  if constexpr (std::is_signed_v<T>) {
    long long value;
    if (int_fits(arg.value, value) && value >= std::numeric_limits<T>::min() && value <= std::numeric_limits<T>::max())
      return static_cast<T>(value);
  } else {
    unsigned long long value;
    if (int_fits(arg.value, value) && value <= std::numeric_limits<T>::max()) return static_cast<T>(value);
  }
  fail_int(arg, name, std::to_string(lo), std::to_string(hi));
}

// `arg` as a double; an int too large for one is refused naming `name`.
double to_float(const FloatArg& arg, const std::string& name);

// Float fields of C as read-write properties whose setter takes a FloatArg
// (def_readwrite's takes a double, so pybind11 refuses a huge int with a TypeError).
template <typename C>
void float_fields(py::class_<C>& cls, std::initializer_list<std::pair<const char*, double C::*>> fields) {
  for (const auto& [name, field] : fields)
    cls.def_property(
        name, [field = field](const C& object) { return object.*field; },
        [field = field, name = name](C& object, FloatArg value) { object.*field = to_float(value, name); });
}

// Makes `E(value)` from Python refuse an int that names none of the enum's
// members: pybind11's own constructor, replaced here, takes any value of the
// underlying type and gives a member named "???". Call it after the last .value().
template <typename E>
void refuse_unnamed_values(py::enum_<E>& cls) {
  std::vector<std::pair<long long, std::string>> members;
  for (const auto& [name, member] : py::cast<py::dict>(cls.attr("__members__")))
    members.emplace_back(static_cast<long long>(py::cast<E>(member)), py::str(name));
  const std::string type = py::str(cls.attr("__name__"));
  py::delattr(cls, "__init__");
  cls.def(py::init([members, type](IntArg value) {
            const long long v = to_int<long long>(value, type + " value");
            std::string names;
            for (const auto& [number, name] : members) {
              if (number == v) return static_cast<E>(v);
              names += (names.empty() ? "" : ", ") + std::to_string(number) + " (" + name + ")";
            }
            throw Error(type + " value = " + std::to_string(v) + ": must be one of " + names);
          }),
          py::arg("value"));
}


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

namespace pybind11::detail {

#if PYBIND11_VERSION_MAJOR >= 3
#define FGDWA_NUMBER_NAME(in, out) io_name(in, out)
#else
#define FGDWA_NUMBER_NAME(in, out) const_name(out)
#endif

template <>
struct type_caster<fgdwa::py_convert::IntArg> {
  PYBIND11_TYPE_CASTER(fgdwa::py_convert::IntArg,
                       FGDWA_NUMBER_NAME("typing.SupportsInt | typing.SupportsIndex", "int"));
  bool load(handle src, bool convert);
  static handle cast(const fgdwa::py_convert::IntArg& arg, return_value_policy, handle) {
    return arg.value.inc_ref();
  }
};

template <>
struct type_caster<fgdwa::py_convert::FloatArg> {
  PYBIND11_TYPE_CASTER(fgdwa::py_convert::FloatArg,
                       FGDWA_NUMBER_NAME("typing.SupportsFloat | typing.SupportsIndex", "float"));
  bool load(handle src, bool convert);
  static handle cast(const fgdwa::py_convert::FloatArg& arg, return_value_policy, handle) {
    return arg.too_large ? arg.too_large.inc_ref() : PyFloat_FromDouble(arg.value);
  }
};

#undef FGDWA_NUMBER_NAME

}  // namespace pybind11::detail
