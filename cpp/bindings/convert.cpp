#include "convert.hpp"

#include <cmath>
#include <sstream>

namespace fgdwa::py_convert {

py::array_t<double, py::array::c_style> float_array(py::handle obj, const std::string& name, int ndim, long width,
                                                    bool allow_infinite) {
  py::array array;
  try {
    array = py::array::ensure(obj);
  } catch (const py::error_already_set&) {
  }
  if (!array) throw Error(name + ": expected an array of numbers, got " + std::string(py::str(py::type::of(obj))));
  if (array.dtype().kind() != 'f' && array.dtype().kind() != 'i' && array.dtype().kind() != 'u')
    throw Error(name + ": expected numbers, got dtype " + std::string(py::str(array.dtype())));
  auto out = py::array_t<double, py::array::c_style>::ensure(array);
  std::ostringstream want;
  want << (ndim == 1 ? "(" : "(n, ") << (width > 0 ? std::to_string(width) : "n") << ")";
  const bool shape_ok = out.ndim() == ndim && (width <= 0 || out.shape(ndim - 1) == width);
  if (!shape_ok) {
    std::ostringstream got;
    got << "(";
    for (py::ssize_t i = 0; i < out.ndim(); ++i) got << (i ? ", " : "") << out.shape(i);
    got << ")";
    throw Error(name + ": expected shape " + want.str() + ", got " + got.str());
  }
  const double* data = out.data();
  for (py::ssize_t i = 0; i < out.size(); ++i) {
    if (allow_infinite && std::isnan(data[i])) throw Error(name + "[" + std::to_string(i) + "] is NaN");
    if (!allow_infinite && !std::isfinite(data[i]))
      throw Error(name + ": element " + std::to_string(i) + " is not finite");
  }
  return out;
}

namespace {
template <std::size_t N>
std::array<double, N> fixed(py::handle obj, const std::string& name) {
  auto a = float_array(obj, name, 1, static_cast<long>(N));
  std::array<double, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = a.data()[i];
  return out;
}

std::string type_name(py::handle obj) { return py::str(py::type::of(obj).attr("__name__")); }
}  // namespace

double to_number(py::handle obj, const std::string& name) {
  // A bool is an int to Python, but never the number a user meant.
  if (py::isinstance<py::bool_>(obj) ||
      !(py::isinstance<py::float_>(obj) || py::isinstance<py::int_>(obj) || py::hasattr(obj, "__float__")))
    throw Error(name + ": expected a number, got " + type_name(obj));
  const double value = PyFloat_AsDouble(obj.ptr());
  if (value == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    if (py::isinstance<py::int_>(obj)) throw Error(name + " = " + int_text(obj) + ": too large for a float");
    throw Error(name + ": expected a number, got " + type_name(obj) + " whose __float__ failed");
  }
  return value;
}

std::string int_text(py::handle value) {
  constexpr std::size_t kShown = 10, kLongest = 24;
  PyObject* text = PyObject_Str(value.ptr());
  if (!text) {  // beyond Python's own limit on the digits of int to str
    PyErr_Clear();
    const auto bits = py::reinterpret_steal<py::object>(PyObject_CallMethod(value.ptr(), "bit_length", nullptr));
    if (!bits) {
      PyErr_Clear();
      return "an int";
    }
    return "an int of " + std::string(py::str(bits)) + " bits";
  }
  std::string s = py::reinterpret_steal<py::str>(text);
  const std::size_t sign = !s.empty() && s[0] == '-';
  if (s.size() <= kLongest) return s;
  return s.substr(0, sign + kShown) + "... (" + std::to_string(s.size() - sign) + " digits)";
}

bool int_fits(const py::int_& value, long long& out) {
  int overflow = 0;
  out = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (out == -1 && PyErr_Occurred()) {
    PyErr_Clear();
    return false;
  }
  return overflow == 0;
}

bool int_fits(const py::int_& value, unsigned long long& out) {
  out = PyLong_AsUnsignedLongLong(value.ptr());
  if (out == static_cast<unsigned long long>(-1) && PyErr_Occurred()) {
    PyErr_Clear();
    return false;
  }
  return true;
}

void fail_int(const IntArg& arg, const std::string& name, const std::string& lo, const std::string& hi) {
  throw Error(name + " = " + int_text(arg.value) + ": must lie in [" + lo + ", " + hi + "]");
}

double to_float(const FloatArg& arg, const std::string& name) {
  return arg.too_large ? to_number(arg.too_large, name) : arg.value;
}

std::string number_text(double value) { return std::string(py::repr(py::float_(value))); }

double to_time(double t, const std::string& name) {
  if (!(std::abs(t) <= limits::kMaxHorizon)) {
    std::ostringstream s;
    s << name << " = " << number_text(t) << ": must lie in [-" << limits::kMaxHorizon << ", " << limits::kMaxHorizon << "] s";
    throw Error(s.str());
  }
  return t;
}

std::string to_word(py::handle obj, const std::string& name) {
  if (!py::isinstance<py::str>(obj)) throw Error(name + ": expected a str, got " + type_name(obj));
  return obj.cast<std::string>();
}

py::dict to_dict(py::handle obj, const std::string& name) {
  if (!py::isinstance<py::dict>(obj)) throw Error(name + ": expected a dict, got " + type_name(obj));
  return obj.cast<py::dict>();
}

Vec2 to_vec2(py::handle obj, const std::string& name) {
  if (py::isinstance<Pose2>(obj)) return obj.cast<Pose2>().position();
  const auto a = fixed<2>(obj, name);
  return {a[0], a[1]};
}

Pose2 to_pose(py::handle obj, const std::string& name) {
  if (py::isinstance<Pose2>(obj)) return obj.cast<Pose2>();
  const auto a = fixed<3>(obj, name);
  return {a[0], a[1], a[2]};
}

Twist to_twist(py::handle obj, const std::string& name) {
  if (py::isinstance<Twist>(obj)) return obj.cast<Twist>();
  const auto a = fixed<2>(obj, name);
  return {a[0], a[1]};
}

std::vector<Vec2> to_points(py::handle obj, const std::string& name) {
  auto a = float_array(obj, name, 2, 2);
  std::vector<Vec2> out(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec2(a.at(i, 0), a.at(i, 1));
  return out;
}

py::array_t<double> poses_to_array(const Trajectory& poses) {
  py::array_t<double> out({static_cast<py::ssize_t>(poses.size()), py::ssize_t{3}});
  auto m = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    m(i, 0) = poses[i].x;
    m(i, 1) = poses[i].y;
    m(i, 2) = poses[i].theta;
  }
  return out;
}

py::array_t<double> points_array(const std::vector<Vec2>& points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    a(i, 0) = points[i].x();
    a(i, 1) = points[i].y();
  }
  return out;
}

py::array_t<double> twists_array(const std::vector<Twist>& twists) {
  py::array_t<double> out({static_cast<py::ssize_t>(twists.size()), py::ssize_t{2}});
  auto a = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < twists.size(); ++i) {
    a(i, 0) = twists[i].v;
    a(i, 1) = twists[i].omega;
  }
  return out;
}

}  // namespace fgdwa::py_convert

namespace pybind11::detail {

bool type_caster<fgdwa::py_convert::IntArg>::load(handle src, bool convert) {
  if (!src || PyFloat_Check(src.ptr()) || !(convert || PyLong_Check(src.ptr()) || PyIndex_Check(src.ptr())))
    return false;
  // ints (bool included) and objects with __index__, as an exact int
  auto number = reinterpret_steal<object>(PyNumber_Index(src.ptr()));
  if (!number) {
    PyErr_Clear();
    // other numbers through __int__ (a numpy float32), as pybind11 converts them
    if (!convert || !PyNumber_Check(src.ptr())) return false;
    number = reinterpret_steal<object>(PyNumber_Long(src.ptr()));
    if (!number) {
      PyErr_Clear();
      return false;
    }
  }
  value.value = reinterpret_steal<int_>(number.release());
  return true;
}

bool type_caster<fgdwa::py_convert::FloatArg>::load(handle src, bool convert) {
  if (!src || !(convert || PyFloat_Check(src.ptr()) || PyLong_Check(src.ptr()))) return false;
  const double number = PyFloat_AsDouble(src.ptr());
  if (number == -1.0 && PyErr_Occurred()) {
    const bool overflow = PyErr_ExceptionMatches(PyExc_OverflowError);
    PyErr_Clear();
    if (overflow && PyLong_Check(src.ptr())) {
      value.too_large = reinterpret_borrow<object>(src);
      return true;
    }
    if (!convert || !PyNumber_Check(src.ptr())) return false;
    auto as_float = reinterpret_steal<object>(PyNumber_Float(src.ptr()));
    PyErr_Clear();
    return load(as_float, false);
  }
  value.value = number;
  value.too_large = object();
  return true;
}

}  // namespace pybind11::detail
