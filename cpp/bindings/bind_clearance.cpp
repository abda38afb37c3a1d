#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bind_common.hpp"
#include "convert.hpp"
#include "fgdwa/clearance.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_clearance(py::module_& m) {
  py::class_<Disc>(m, "Disc",
                   "A disc obstacle moving at constant velocity (after an optional constant acceleration); radius 0 is a point.")
      .def(py::init([](py::handle center, FloatArg radius, py::handle velocity, FloatArg growth, py::handle acceleration,
                       FloatArg accel_time) {
             Disc d{to_vec2(center, "center"), to_float(radius, "radius"), to_vec2(velocity, "velocity"),
                    to_float(growth, "growth"), to_vec2(acceleration, "acceleration"), to_float(accel_time, "accel_time")};
             d.validate();
             return d;
           }),
           py::arg("center"), py::arg("radius") = 0.0, py::arg("velocity") = py::make_tuple(0.0, 0.0),
           py::arg("growth") = 0.0, py::arg("acceleration") = py::make_tuple(0.0, 0.0), py::arg("accel_time") = 0.0,
           "growth (m/s): radius added per second ahead, for a predicted obstacle; acceleration (m/s^2) lasts the "
           "first accel_time (s), then the velocity reached holds (a mover predicted to turn, slow or reverse).")
      .def_property_readonly("center", [](const Disc& d) { return py::make_tuple(d.center.x(), d.center.y()); })
      .def_readonly("radius", &Disc::radius)
      .def_readonly("growth", &Disc::growth)
      .def_property_readonly("acceleration",
                             [](const Disc& d) { return py::make_tuple(d.acceleration.x(), d.acceleration.y()); })
      .def_readonly("accel_time", &Disc::accel_time)
      .def(
          "time_to_reach",
          [](const Disc& d, py::handle point, FloatArg reach) {
            return d.time_to_reach(to_vec2(point, "point"), to_float(reach, "reach"));
          },
          py::arg("point"), py::arg("reach") = 0.0,
          "s, the first time ahead at which the disc grown by reach (m) covers point; inf if never.")
      .def(
          "radius_at", [](const Disc& d, FloatArg t) { return d.radius_at(to_time(to_float(t, "t"), "t")); },
          py::arg("t"), "The radius t seconds ahead (for a t in the past, never below 0).")
      .def_property_readonly("velocity", [](const Disc& d) { return py::make_tuple(d.velocity.x(), d.velocity.y()); })
      .def("center_at", [](const Disc& d, FloatArg t) {
        const Vec2 c = d.center_at(to_time(to_float(t, "t"), "t"));
        return py::make_tuple(c.x(), c.y());
      }, py::arg("t"))
      .def("__repr__", [](const Disc& d) {
        std::ostringstream s;
        s << "Disc(center=(" << d.center.x() << ", " << d.center.y() << "), radius=" << d.radius << ", velocity=("
          << d.velocity.x() << ", " << d.velocity.y() << ")";
        if (d.growth > 0.0) s << ", growth=" << d.growth;
        if (d.accel_time > 0.0)
          s << ", acceleration=(" << d.acceleration.x() << ", " << d.acceleration.y() << "), accel_time=" << d.accel_time;
        s << ")";
        return s.str();
      });

  py::class_<ClearanceSource, std::shared_ptr<ClearanceSource>>(
      m, "ClearanceSource", "Where a rollout's clearance comes from (FieldClearance or CollisionWorld).")
      .def(
          "clearance",
          [](const ClearanceSource& s, const Footprint& fp, py::handle poses, FloatArg t) {
            return clearances(s, fp, poses, to_float(t, "t"));
          },
          py::arg("footprint"), py::arg("poses"), py::arg("t") = 0.0,
          "Clearance in metres of the footprint at each of (n, 3) poses (or one pose), moving obstacles "
          "predicted t seconds ahead; <= 0 means contact.");

  py::class_<FieldClearance, ClearanceSource, std::shared_ptr<FieldClearance>>(
      m, "FieldClearance", "The fast clearance: a distance field of the static map plus analytic discs.")
      .def(py::init([](std::shared_ptr<const DistanceField> field, std::vector<Disc> discs) {
             return std::make_shared<FieldClearance>(std::move(field), std::move(discs));
           }),
           py::arg("field") = nullptr, py::arg("discs") = std::vector<Disc>{})
      // A copy: a view into the vector would dangle once the discs are replaced.
      .def_property("discs", [](const FieldClearance& f) { return f.discs(); }, &FieldClearance::set_discs)
      .def_property_readonly("field", [](const FieldClearance& f) { return std::const_pointer_cast<DistanceField>(f.field()); })
      .def_property(
          "sensed", [](const FieldClearance& f) { return std::const_pointer_cast<DistanceField>(f.sensed()); },
          [](FieldClearance& f, std::shared_ptr<const DistanceField> sensed) { f.set_sensed(std::move(sensed)); },
          "Obstacles seen by the lidar but missing from the map, as a DistanceField (see points_field), or None.")
      .def("__repr__", [](const FieldClearance& f) {
        return "FieldClearance(field=" + std::string(f.field() ? "yes" : "None") +
               ", discs=" + std::to_string(f.discs().size()) + ")";
      });
}
