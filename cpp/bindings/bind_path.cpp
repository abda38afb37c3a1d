#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "convert.hpp"
#include "fgdwa/path.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_path(py::module_& m) {
  m.def(
      "reference_samples",
      [](const GlobalPath& path, py::handle robot, FloatArg v_ref_arg, FloatArg dt_arg, IntArg n_arg,
         const std::string& sampling) {
        const double v_ref = to_float(v_ref_arg, "v_ref"), dt = to_float(dt_arg, "dt");
        const int n = to_int<int>(n_arg, "n", 1, static_cast<int>(limits::kMaxRolloutSteps));
        if (!(v_ref >= 0.0) || !std::isfinite(v_ref)) throw Error("v_ref = " + number_text(v_ref) + ": must be >= 0");
        if (!(dt > 0.0) || !std::isfinite(dt)) throw Error("dt = " + number_text(dt) + ": must be > 0");
        if (n < 1) throw Error("n = " + std::to_string(n) + ": must be >= 1");
        ReferenceSampling mode;
        if (sampling == "polyline")
          mode = ReferenceSampling::Polyline;
        else if (sampling == "segment")
          mode = ReferenceSampling::Segment;
        else
          throw Error("sampling = '" + sampling + "': expected 'polyline' or 'segment'");
        std::vector<Vec2> out;
        reference_samples(path, to_vec2(robot, "robot"), v_ref, dt, n, mode, out);
        return points_array(out);
      },
      py::arg("path"), py::arg("robot"), py::arg("v_ref"), py::arg("dt"), py::arg("n"), py::arg("sampling") = "polyline",
      "(n, 2) reference samples E of the similarity cost (Eq. 9): from the robot's projection onto the "
      "path, i * v_ref * dt further along the current segment ('segment') or along the path ('polyline').");

  py::class_<PathProjection>(m, "PathProjection", "The nearest point of a path to a query point.")
      .def_property_readonly("point", [](const PathProjection& p) { return py::make_tuple(p.point.x(), p.point.y()); })
      .def_readonly("segment", &PathProjection::segment)
      .def_readonly("arc_length", &PathProjection::arc_length)
      .def_readonly("distance", &PathProjection::distance)
      .def("__repr__", [](const PathProjection& p) {
        std::ostringstream s;
        s << "PathProjection(point=(" << p.point.x() << ", " << p.point.y() << "), segment=" << p.segment
          << ", arc_length=" << p.arc_length << ", distance=" << p.distance << ")";
        return s.str();
      });

  py::class_<GlobalPath>(m, "GlobalPath",
                         "A global path: a polyline of (n, 2) points in metres, with projection, deviation, "
                         "arc-length walking and key nodes.")
      .def(py::init([](py::handle points) { return GlobalPath(to_points(points, "points")); }), py::arg("points"))
      .def_property_readonly("points", [](const GlobalPath& p) { return points_array(p.points()); })
      .def_property_readonly("length", &GlobalPath::length)
      .def_property_readonly("segment_count", &GlobalPath::segment_count)
      .def("segment_direction", [](const GlobalPath& p, IntArg segment) {
        const std::size_t i = to_int<std::size_t>(segment, "segment", 0, p.segment_count() - 1);
        if (i >= p.segment_count()) throw Error("segment " + std::to_string(i) + " does not exist");
        return p.segment_direction(i);
      }, py::arg("segment"))
      .def("project", [](const GlobalPath& p, py::handle point) { return p.project(to_vec2(point, "point")); },
           py::arg("point"))
      .def("deviation", [](const GlobalPath& p, py::handle point) { return p.deviation(to_vec2(point, "point")); },
           py::arg("point"), "Distance in metres from the point to the path (D).")
      .def("point_at", [](const GlobalPath& p, FloatArg s_arg) {
        const double s = to_float(s_arg, "s");
        if (!std::isfinite(s)) throw Error("s: must be finite");
        const Vec2 q = p.point_at(s);
        return py::make_tuple(q.x(), q.y());
      }, py::arg("s"), "The point at arc length s metres (clamped to the path).")
      .def("key_nodes", [](const GlobalPath& p, FloatArg min_turn) { return p.key_nodes(to_float(min_turn, "min_turn")); },
           py::arg("min_turn") = KeyNodeParams{}.min_turn,
           "Indices of the vertices where the path turns by more than min_turn (rad), then the last vertex.")
      .def("__len__", [](const GlobalPath& p) { return p.points().size(); })
      .def("__repr__", [](const GlobalPath& p) {
        std::ostringstream s;
        s << "GlobalPath(" << p.points().size() << " points, length=" << p.length() << ")";
        return s.str();
      });
}
