#include <pybind11/pybind11.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/geometry.hpp"

namespace py = pybind11;
using namespace fgdwa;

void init_geometry(py::module_& m) {
  py::class_<Pose2>(m, "Pose2", "A planar pose: x, y in metres and theta in radians.")
      .def(py::init([](double x, double y, double theta) { return Pose2{x, y, theta}; }), py::arg("x") = 0.0,
           py::arg("y") = 0.0, py::arg("theta") = 0.0)
      .def_readwrite("x", &Pose2::x)
      .def_readwrite("y", &Pose2::y)
      .def_readwrite("theta", &Pose2::theta)
      .def("__iter__", [](const Pose2& p) { return py::iter(py::make_tuple(p.x, p.y, p.theta)); })
      .def("__repr__", [](const Pose2& p) {
        std::ostringstream s;
        s << "Pose2(x=" << p.x << ", y=" << p.y << ", theta=" << p.theta << ")";
        return s.str();
      });

  py::class_<Twist>(m, "Twist", "A velocity command: v in m/s forward, omega in rad/s counter-clockwise.")
      .def(py::init([](double v, double omega) { return Twist{v, omega}; }), py::arg("v") = 0.0,
           py::arg("omega") = 0.0)
      .def_readwrite("v", &Twist::v)
      .def_readwrite("omega", &Twist::omega)
      .def("__iter__", [](const Twist& t) { return py::iter(py::make_tuple(t.v, t.omega)); })
      .def("__repr__", [](const Twist& t) {
        std::ostringstream s;
        s << "Twist(v=" << t.v << ", omega=" << t.omega << ")";
        return s.str();
      });

  m.def("wrap_angle", &wrap_angle, py::arg("angle"), "The angle in (-pi, pi].");
  m.def("angle_difference", &angle_difference, py::arg("a"), py::arg("b"), "The signed difference a - b in (-pi, pi].");
}
