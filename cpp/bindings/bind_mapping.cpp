#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <optional>
#include <sstream>

#include "bind_params.hpp"
#include "convert.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/mapping.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_mapping(py::module_& m) {
  bind_params<OccupancyParams>(m, "OccupancyParams",
                               "The log-odds update of a ScanMap's cells (defaults: OctoMap's probabilities).");

  py::class_<ScanMap>(m, "ScanMap",
                      "A map built from lidar scans: log-odds per cell, beams ray-traced (the cells they pass are "
                      "evidence of free space, the hit's cell of an obstacle), so spurious hits and moved objects fade.")
      .def(py::init<const OccupancyGrid&, const OccupancyParams&>(), py::arg("like"),
           py::arg("params") = OccupancyParams(), "An empty map with the layout of `like`.")
      .def(py::init([](IntArg rows, IntArg cols, FloatArg resolution, py::handle origin, const OccupancyParams& params) {
             const int most = static_cast<int>(limits::kMaxGridCells);
             return ScanMap(to_int<int>(rows, "grid rows", 1, most), to_int<int>(cols, "grid cols", 1, most),
                            to_float(resolution, "resolution"), to_vec2(origin, "origin"), params);
           }),
           py::arg("rows"), py::arg("cols"), py::arg("resolution"), py::arg("origin"),
           py::arg("params") = OccupancyParams())
      .def(
          "integrate",
          [](ScanMap& map, const Scan& scan, py::object keep_hit, std::optional<FloatArg> time) {
            const double at = time ? to_float(*time, "time") : std::numeric_limits<double>::quiet_NaN();
            if (keep_hit.is_none()) return map.integrate(scan, nullptr, at);
            const auto keep = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(keep_hit);
            if (!keep || keep.ndim() != 1)
              throw Error("keep_hit: expected a 1-d array of one flag per beam");
            const std::vector<std::uint8_t> flags(keep.data(), keep.data() + keep.size());
            return map.integrate(scan, &flags, at);
          },
          py::arg("scan"), py::arg("keep_hit") = py::none(), py::arg("time") = py::none(),
          "One scan's evidence (each cell updated once, by the vote of the beams ending and passing in it); keep_hit (one flag per "
          "beam) says which hits to mark; time (s, or None) lets the occupied cells no beam reached fade (fade_time). Returns how many cells turned occupied or stopped being occupied.")
      .def(
          "mark", [](ScanMap& map, py::handle points) { return map.mark(to_points(points, "points")); },
          py::arg("points"), "One hit on each cell holding (n, 2) points; returns how many turned occupied.")
      .def_property_readonly("grid", &ScanMap::grid, py::return_value_policy::copy,
                             "The map so far (a copy): occupied cells are obstacles.")
      .def("field", &ScanMap::field,
           "Its distance field, brought up to date (incrementally) on the first call after changes.")
      .def_property_readonly("occupied_count", &ScanMap::occupied_count)
      .def_property_readonly("known_count", &ScanMap::known_count, "Cells observed at least once.")
      .def_property_readonly("params", &ScanMap::params)
      .def_property_readonly(
          "states",
          [](const ScanMap& map) {
            py::array_t<std::uint8_t> out({map.grid().rows(), map.grid().cols()});
            std::copy(map.states().begin(), map.states().end(), out.mutable_data());
            return out;
          },
          "(rows, cols) uint8: 0 unknown, 1 free, 2 occupied.")
      .def_property_readonly(
          "log_odds",
          [](const ScanMap& map) {
            py::array_t<float> out({map.grid().rows(), map.grid().cols()});
            std::copy(map.log_odds().begin(), map.log_odds().end(), out.mutable_data());
            return out;
          },
          "(rows, cols) float32 log-odds of each cell.")
      .def("__repr__", [](const ScanMap& map) {
        std::ostringstream s;
        s << "ScanMap(" << map.grid().rows() << "x" << map.grid().cols() << ", " << map.occupied_count()
          << " occupied, " << map.known_count() << " known)";
        return s.str();
      });

  m.def(
      "path_blocked",
      [](const GlobalPath& path, py::handle position, const DistanceField& field, FloatArg clearance) {
        return path_blocked(path, to_vec2(position, "position"), field, to_float(clearance, "clearance"));
      },
      py::arg("path"), py::arg("position"), py::arg("field"), py::arg("clearance"),
      "Whether the path ahead of `position` (from its nearest point on) passes closer than `clearance` (m) "
      "to an obstacle of `field`.");
}
