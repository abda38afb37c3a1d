#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/mapping.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_mapping(py::module_& m) {
  py::class_<ScanMap>(m, "ScanMap",
                      "A map built from lidar hits: starts empty, each hit marks its cell occupied; "
                      "cells are never cleared (static worlds).")
      .def(py::init<const OccupancyGrid&>(), py::arg("like"), "An empty map with the layout of `like`.")
      .def(py::init([](int rows, int cols, double resolution, py::handle origin) {
             return ScanMap(rows, cols, resolution, to_vec2(origin, "origin"));
           }),
           py::arg("rows"), py::arg("cols"), py::arg("resolution"), py::arg("origin"))
      .def("integrate", &ScanMap::integrate, py::arg("scan"),
           "Marks the cells of the scan's hits; returns how many cells became occupied.")
      .def(
          "mark", [](ScanMap& map, py::handle points) { return map.mark(to_points(points, "points")); },
          py::arg("points"), "Marks the cells holding (n, 2) points; returns how many became occupied.")
      .def_property_readonly("grid", &ScanMap::grid, py::return_value_policy::copy, "The map so far (a copy).")
      .def("field", &ScanMap::field,
           "Its distance field, brought up to date (around the new cells only) on the first call after new cells.")
      .def_property_readonly("occupied_count", &ScanMap::occupied_count)
      .def("__repr__", [](const ScanMap& map) {
        std::ostringstream s;
        s << "ScanMap(" << map.grid().rows() << "x" << map.grid().cols() << ", " << map.occupied_count()
          << " occupied)";
        return s.str();
      });

  m.def(
      "path_blocked",
      [](const GlobalPath& path, py::handle position, const DistanceField& field, double clearance) {
        return path_blocked(path, to_vec2(position, "position"), field, clearance);
      },
      py::arg("path"), py::arg("position"), py::arg("field"), py::arg("clearance"),
      "Whether the path ahead of `position` (from its nearest point on) passes closer than `clearance` (m) "
      "to an obstacle of `field`.");
}
