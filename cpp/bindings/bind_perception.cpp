#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "bind_params.hpp"
#include "convert.hpp"
#include "fgdwa/perception.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_perception(py::module_& m) {
  bind_params<LidarParams>(m, "LidarParams", "A planar lidar.")
      .def_property_readonly("angles", [](const LidarParams& p) {
        py::array_t<double> out(p.beams);
        for (int i = 0; i < p.beams; ++i) out.mutable_data()[i] = p.angle(i);
        return out;
      }, "Beam angles relative to the heading, rad.");

  py::class_<Scan>(m, "Scan", "One lidar scan: ranges (m, +inf for no hit) of beams from angle_min by angle_increment.")
      // Scans measured elsewhere (a real lidar, another simulator) enter here;
      // LaserScanner makes fgdwa's own.
      .def(py::init([](py::handle ranges, FloatArg angle_min_arg, FloatArg angle_increment_arg, FloatArg max_range_arg,
                       py::handle pose) {
             const double angle_min = to_float(angle_min_arg, "angle_min");
             const double angle_increment = to_float(angle_increment_arg, "angle_increment");
             const double max_range = to_float(max_range_arg, "max_range");
             Scan s;
             s.pose = to_pose(pose, "pose");
             if (!std::isfinite(angle_min)) throw Error("angle_min: must be finite, got " + std::to_string(angle_min));
             if (!std::isfinite(angle_increment) || angle_increment < 0.0)
               throw Error("angle_increment: must be finite and >= 0, got " + std::to_string(angle_increment));
             if (!(max_range > 0.0) || !std::isfinite(max_range))
               throw Error("max_range: must be finite and > 0, got " + std::to_string(max_range));
             s.angle_min = angle_min;
             s.angle_increment = angle_increment;
             s.max_range = max_range;
             const auto values = float_array(ranges, "ranges", 1, 0, /*allow_infinite=*/true);
             s.ranges.assign(values.data(), values.data() + values.size());
             s.validate();  // the library's bounds: pose, angles, max_range, every range
             return s;
           }),
           py::arg("ranges"), py::arg("angle_min"), py::arg("angle_increment"), py::arg("max_range"),
           py::arg("pose") = py::make_tuple(0.0, 0.0, 0.0),
           "A scan measured elsewhere: ranges (m, +inf for no hit) of beams from angle_min (rad, relative to the "
           "sensor's heading) by angle_increment (rad), max_range (m), taken at pose (x, y, theta) of the sensor.")
      .def_property(
          "pose", [](const Scan& s) { return s.pose; },
          [](Scan& s, py::handle pose) {
            const Pose2 before = s.pose;
            s.pose = to_pose(pose, "pose");
            try {
              s.validate();
            } catch (...) {
              s.pose = before;
              throw;
            }
          },
          "Where the scan was taken, as the robot believes: hit_points and the map place the ranges from it.")
      .def_readonly("angle_min", &Scan::angle_min)
      .def_readonly("angle_increment", &Scan::angle_increment)
      .def_readonly("max_range", &Scan::max_range)
      .def_property_readonly("ranges", [](const Scan& s) { return py::array_t<double>(s.ranges.size(), s.ranges.data()); })
      .def_property_readonly("angles", [](const Scan& s) {
        py::array_t<double> out(s.ranges.size());
        for (std::size_t i = 0; i < s.ranges.size(); ++i) out.mutable_data()[i] = s.angle_min + i * s.angle_increment;
        return out;
      }, "Beam angles relative to the heading, rad.")
      .def_property_readonly("hit_points", [](const Scan& s) { return points_array(s.hit_points()); })
      .def("__repr__", [](const Scan& s) {
        std::size_t hits = 0;
        for (double r : s.ranges) hits += std::isfinite(r);
        return "Scan(" + std::to_string(s.ranges.size()) + " beams, " + std::to_string(hits) + " hits)";
      });

  py::class_<LaserScanner>(m, "LaserScanner",
                           "Ray casting against the true world's distance field and moving discs, with seeded noise.")
      .def(py::init<const LidarParams&, std::shared_ptr<const DistanceField>>(), py::arg("params"), py::arg("world"))
      .def_property_readonly("params", &LaserScanner::params)
      .def(
          "scan",
          [](const LaserScanner& s, py::handle pose, std::vector<Disc> discs, FloatArg t, IntArg seed) {
            std::mt19937_64 rng(to_int<std::uint64_t>(seed, "seed"));
            Scan out;
            s.scan(to_pose(pose, "pose"), discs, to_float(t, "t"), rng, out);
            return out;
          },
          py::arg("pose"), py::arg("discs") = std::vector<Disc>{}, py::arg("t") = 0.0, py::arg("seed") = 0,
          "One scan at pose; discs placed t seconds ahead; noise and dropped beams drawn from a generator "
          "seeded with seed.");

  bind_params<DetectWindowParams>(m, "DetectWindowParams", "The detect window ahead of the robot, over which the density I is measured.");

  py::class_<DensityReading>(m, "DensityReading", "Obstacle density I of the detect window and its parts.")
      .def_readonly("density", &DensityReading::density)
      .def_readonly("area_ratio", &DensityReading::area_ratio)
      .def_readonly("max_gap", &DensityReading::max_gap)
      .def_readonly("beams", &DensityReading::beams)
      .def("__repr__", [](const DensityReading& r) {
        std::ostringstream s;
        s << "DensityReading(density=" << r.density << ", area_ratio=" << r.area_ratio << ", max_gap=" << r.max_gap
          << ", beams=" << r.beams << ")";
        return s.str();
      });

  m.def("obstacle_density", &obstacle_density, py::arg("scan"), py::arg("window") = DetectWindowParams{},
        "Eq. 13: I = S_d / S_w + c^max_gap over the detect window, clamped to [0, 2].");
  m.def(
      "points_field",
      [](py::handle points, FloatArg resolution) {
        return points_field(to_points(points, "points"), to_float(resolution, "resolution"));
      },
      py::arg("points"), py::arg("resolution"),
      "A DistanceField of scattered obstacle points on a grid just covering them (None for no point).");
}
