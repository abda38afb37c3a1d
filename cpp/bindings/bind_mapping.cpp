#include <pybind11/pybind11.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <limits>
#include <sstream>

#include "convert.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/mapping.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_mapping(py::module_& m) {
  py::class_<OccupancyParams>(m, "OccupancyParams",
                              "The log-odds update of a ScanMap's cells (defaults: OctoMap's probabilities).")
      .def(py::init([](FloatArg hit, FloatArg miss, FloatArg clamp_min, FloatArg clamp_max, FloatArg occupied,
                       FloatArg free, FloatArg range_std, FloatArg clear_range, FloatArg hit_share, bool clear, FloatArg edge_margin) {
             OccupancyParams p;
             p.hit = to_float(hit, "hit");
             p.miss = to_float(miss, "miss");
             p.clamp_min = to_float(clamp_min, "clamp_min");
             p.clamp_max = to_float(clamp_max, "clamp_max");
             p.occupied = to_float(occupied, "occupied");
             p.free = to_float(free, "free");
             p.range_std = to_float(range_std, "range_std");
             p.clear_range = to_float(clear_range, "clear_range");
             p.hit_share = to_float(hit_share, "hit_share");
             p.clear = clear;
             p.edge_margin = to_float(edge_margin, "edge_margin");
             p.validate();
             return p;
           }),
           py::arg("hit") = 0.85, py::arg("miss") = -0.4, py::arg("clamp_min") = -2.0, py::arg("clamp_max") = 3.5,
           py::arg("occupied") = 0.5, py::arg("free") = -0.5, py::arg("range_std") = 0.0,
           py::arg("clear_range") = std::numeric_limits<double>::infinity(), py::arg("hit_share") = 0.2,
           py::arg("clear") = true, py::arg("edge_margin") = DistanceField::kDefaultEdgeMargin,
           "hit / miss: log-odds added to a hit's cell / to each cell a beam passes; clamp_min, clamp_max: the "
           "range a cell's log-odds stays in; a cell turns occupied at `occupied` and free again at `free`; "
           "range_std (m): the lidar's range noise (hits placed 2 std beyond the reading, clearing stops 3 std "
           "short); clear_range (m): the farthest a beam clears; hit_share: a cell some beams of a scan end in and "
           "others pass is hit when at least this share end in it; clear=False: hits only, nothing clears; "
           "edge_margin (m): the free margin the map's field keeps past the grid's edge (DistanceField).")
      .def_readonly("hit", &OccupancyParams::hit)
      .def_readonly("miss", &OccupancyParams::miss)
      .def_readonly("clamp_min", &OccupancyParams::clamp_min)
      .def_readonly("clamp_max", &OccupancyParams::clamp_max)
      .def_readonly("occupied", &OccupancyParams::occupied)
      .def_readonly("free", &OccupancyParams::free)
      .def_readonly("range_std", &OccupancyParams::range_std)
      .def_readonly("clear_range", &OccupancyParams::clear_range)
      .def_readonly("hit_share", &OccupancyParams::hit_share)
      .def_readonly("clear", &OccupancyParams::clear)
      .def_readonly("edge_margin", &OccupancyParams::edge_margin)
      .def("__repr__", [](const OccupancyParams& p) {
        std::ostringstream s;
        s << "OccupancyParams(hit=" << p.hit << ", miss=" << p.miss << ", clamp=[" << p.clamp_min << ", "
          << p.clamp_max << "], occupied=" << p.occupied << ", free=" << p.free << ", range_std=" << p.range_std
          << ", clear=" << (p.clear ? "True" : "False") << ", edge_margin=" << p.edge_margin << ")";
        return s.str();
      });

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
          [](ScanMap& map, const Scan& scan, py::object keep_hit) {
            if (keep_hit.is_none()) return map.integrate(scan);
            const auto keep = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(keep_hit);
            if (!keep || keep.ndim() != 1)
              throw Error("keep_hit: expected a 1-d array of one flag per beam");
            const std::vector<std::uint8_t> flags(keep.data(), keep.data() + keep.size());
            return map.integrate(scan, &flags);
          },
          py::arg("scan"), py::arg("keep_hit") = py::none(),
          "One scan's evidence (each cell updated once, by the vote of the beams ending and passing in it); keep_hit (one flag per "
          "beam) says which hits to mark. Returns how many cells turned occupied or stopped being occupied.")
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
