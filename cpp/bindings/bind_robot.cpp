#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "bind_params.hpp"
#include "convert.hpp"
#include "fgdwa/robot.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_robot(py::module_& m) {
  bind_params<RobotLimits>(m, "RobotLimits", "Velocity and acceleration limits of a differential-drive robot.")
      .def("braking_v", &RobotLimits::braking_v)
      .def("braking_omega", &RobotLimits::braking_omega);

  py::class_<RobotState>(m, "RobotState", "Pose and velocity of the robot.")
      .def(py::init([](py::handle pose, py::handle twist) {
             return RobotState{to_pose(pose, "pose"), to_twist(twist, "twist")};
           }),
           py::arg("pose") = Pose2{}, py::arg("twist") = Twist{})
      .def_readwrite("pose", &RobotState::pose)
      .def_readwrite("twist", &RobotState::twist)
      .def("__repr__", [](const RobotState& s) {
        std::ostringstream o;
        o << "RobotState(pose=(" << s.pose.x << ", " << s.pose.y << ", " << s.pose.theta << "), twist=(" << s.twist.v
          << ", " << s.twist.omega << "))";
        return o.str();
      });

  py::class_<Footprint>(m, "Footprint", "The robot's outline: a circle, or a convex polygon in the robot frame.")
      .def_static(
          "circle", [](FloatArg radius) { return Footprint::circle(to_float(radius, "radius")); }, py::arg("radius"),
          "A circle of `radius` metres about the robot origin.")
      .def_static(
          "polygon", [](py::handle vertices) { return Footprint::polygon(to_points(vertices, "vertices")); },
          py::arg("vertices"), "A convex polygon, (n, 2) vertices in metres, robot frame (x forward, y left).")
      .def(
          "padded", [](const Footprint& f, FloatArg margin) { return f.padded(to_float(margin, "margin")); },
          py::arg("margin"),
          "The footprint grown by `margin` metres on every side (a polygon's corners kept sharp).")
      .def_property_readonly("is_circle", &Footprint::is_circle)
      .def_property_readonly("radius", &Footprint::radius, "Circle radius or circumscribed radius, m.")
      .def_property_readonly("inscribed_radius", &Footprint::inscribed_radius,
                             "Largest circle about the robot origin inside the footprint, m.")
      .def_property_readonly("half_width", &Footprint::half_width,
                             "Half the footprint's least width (the radius for a circle): no point inside lies "
                             "farther than this from the outline, m.")
      .def_property_readonly("vertices",
                             [](const Footprint& f) {
                               py::array_t<double> out({static_cast<py::ssize_t>(f.vertices().size()), py::ssize_t{2}});
                               auto a = out.mutable_unchecked<2>();
                               for (std::size_t i = 0; i < f.vertices().size(); ++i) {
                                 a(i, 0) = f.vertices()[i].x();
                                 a(i, 1) = f.vertices()[i].y();
                               }
                               return out;
                             })
      .def(
          "signed_distance",
          [](const Footprint& f, py::handle pose, py::handle point) {
            return f.signed_distance(to_pose(pose, "pose"), to_vec2(point, "point"));
          },
          py::arg("pose"), py::arg("point"))
      .def("__repr__", [](const Footprint& f) {
        std::ostringstream s;
        if (f.is_circle())
          s << "Footprint.circle(radius=" << f.radius() << ")";
        else
          s << "Footprint.polygon(" << f.vertices().size() << " vertices, radius=" << f.radius() << ")";
        return s.str();
      });

  m.def(
      "unicycle_step",
      [](py::handle pose, py::handle twist, FloatArg dt_arg) {
        const double dt = to_float(dt_arg, "dt");
        if (!(dt > 0.0) || !std::isfinite(dt)) throw Error("dt = " + number_text(dt) + ": must be > 0");
        return unicycle_step(to_pose(pose, "pose"), to_twist(twist, "twist"), dt);
      },
      py::arg("pose"), py::arg("twist"), py::arg("dt"),
      "One unicycle step: theta += omega dt, then x += v cos(theta) dt, y += v sin(theta) dt.");
  m.def(
      "rollout",
      [](py::handle pose, py::handle twist, FloatArg dt_arg, IntArg n_steps_arg) {
        const double dt = to_float(dt_arg, "dt");
        const int n_steps = to_int<int>(n_steps_arg, "n_steps", 1, static_cast<int>(limits::kMaxRolloutSteps));
        if (!(dt > 0.0)) throw Error("dt = " + number_text(dt) + ": must be > 0");
        if (n_steps < 1) throw Error("n_steps = " + std::to_string(n_steps) + ": must be >= 1");
        return poses_to_array(rollout(to_pose(pose, "pose"), to_twist(twist, "twist"), dt, n_steps));
      },
      py::arg("pose"), py::arg("twist"), py::arg("dt"), py::arg("n_steps"),
      "(n_steps, 3) poses of a constant command, each after one more step (the start is not included).");
}
