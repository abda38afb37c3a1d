#include <pybind11/pybind11.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/geometry.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_geometry(py::module_& m) {
  py::class_<Pose2> pose_class(m, "Pose2", "A planar pose: x, y in metres and theta in radians.");
  float_fields(pose_class, {{"x", &Pose2::x}, {"y", &Pose2::y}, {"theta", &Pose2::theta}});
  pose_class
      .def(py::init([](FloatArg x, FloatArg y, FloatArg theta) {
             return Pose2{to_float(x, "x"), to_float(y, "y"), to_float(theta, "theta")};
           }),
           py::arg("x") = 0.0, py::arg("y") = 0.0, py::arg("theta") = 0.0)
      .def("__iter__", [](const Pose2& p) { return py::iter(py::make_tuple(p.x, p.y, p.theta)); })
      .def("__repr__", [](const Pose2& p) {
        std::ostringstream s;
        s << "Pose2(x=" << p.x << ", y=" << p.y << ", theta=" << p.theta << ")";
        return s.str();
      });

  py::class_<Twist> twist_class(m, "Twist", "A velocity command: v in m/s forward, omega in rad/s counter-clockwise.");
  float_fields(twist_class, {{"v", &Twist::v}, {"omega", &Twist::omega}});
  twist_class
      .def(py::init([](FloatArg v, FloatArg omega) { return Twist{to_float(v, "v"), to_float(omega, "omega")}; }),
           py::arg("v") = 0.0, py::arg("omega") = 0.0)
      .def("__iter__", [](const Twist& t) { return py::iter(py::make_tuple(t.v, t.omega)); })
      .def("__repr__", [](const Twist& t) {
        std::ostringstream s;
        s << "Twist(v=" << t.v << ", omega=" << t.omega << ")";
        return s.str();
      });

  m.def(
      "wrap_angle", [](FloatArg angle) { return wrap_angle(to_float(angle, "angle")); }, py::arg("angle"),
      "The angle in (-pi, pi].");
  m.def(
      "angle_difference", [](FloatArg a, FloatArg b) { return angle_difference(to_float(a, "a"), to_float(b, "b")); },
      py::arg("a"), py::arg("b"), "The signed difference a - b in (-pi, pi].");
}
