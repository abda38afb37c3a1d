#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>
#include <sstream>

#include "convert.hpp"
#include "fgdwa/grid.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

namespace {
OccupancyGrid grid_from_array(py::handle cells, double resolution, py::handle origin, const std::string& name = "cells",
                              bool allow_bool = true) {
  py::array array;
  try {
    array = py::array::ensure(cells);
  } catch (const py::error_already_set&) {
  }
  if (!array) throw Error(name + ": expected a 2-D numpy array");
  const char kind = array.dtype().kind();
  if (!((allow_bool && kind == 'b') || (kind == 'u' && array.itemsize() == 1)))
    throw Error(name + ": expected dtype uint8" + (allow_bool ? std::string(" or bool (1 = obstacle)") : "") + ", got " +
                std::string(py::str(array.dtype())));
  if (array.ndim() != 2) throw Error(name + ": expected a 2-D array, got " + std::to_string(array.ndim()) + " dimensions");
  if (array.shape(0) == 0 || array.shape(1) == 0) throw Error(name + ": the grid is empty");
  auto c = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(array);
  std::vector<std::uint8_t> data(c.data(), c.data() + c.size());
  return OccupancyGrid(static_cast<int>(c.shape(0)), static_cast<int>(c.shape(1)), resolution,
                       to_vec2(origin, "origin"), std::move(data));
}

py::array_t<std::uint8_t> cells_array(const OccupancyGrid& g) {
  py::array_t<std::uint8_t> out({g.rows(), g.cols()});
  std::copy(g.cells().begin(), g.cells().end(), out.mutable_data());
  return out;
}
}  // namespace

void init_grid(py::module_& m) {
  py::class_<OccupancyGrid>(m, "OccupancyGrid",
                            "An occupancy grid: cells[row, col], row 0 at the bottom (lowest y), 1 = obstacle. "
                            "Cell (row, col) covers x in origin.x + [col, col + 1) * resolution and "
                            "y in origin.y + [row, row + 1) * resolution. Outside the grid is free.")
      .def(py::init([](py::handle cells, FloatArg resolution, py::handle origin) {
             return grid_from_array(cells, to_float(resolution, "resolution"), origin);
           }),
           py::arg("cells"), py::arg("resolution"),
           py::arg("origin") = py::make_tuple(0.0, 0.0))
      .def_property_readonly("rows", &OccupancyGrid::rows)
      .def_property_readonly("cols", &OccupancyGrid::cols)
      .def_property_readonly("shape", [](const OccupancyGrid& g) { return py::make_tuple(g.rows(), g.cols()); })
      .def_property_readonly("resolution", &OccupancyGrid::resolution)
      .def_property_readonly("origin",
                             [](const OccupancyGrid& g) { return py::make_tuple(g.origin().x(), g.origin().y()); })
      .def_property_readonly("cells", &cells_array, "A copy of the cells, (rows, cols) uint8.")
      .def_property_readonly("extent",
                             [](const OccupancyGrid& g) {
                               const double x0 = g.origin().x(), y0 = g.origin().y();
                               return py::make_tuple(x0, x0 + g.cols() * g.resolution(), y0,
                                                     y0 + g.rows() * g.resolution());
                             },
                             "(x_min, x_max, y_min, y_max) in metres, as matplotlib's imshow takes it.")
      .def(
          "occupied_at",
          [](const OccupancyGrid& g, py::handle points) {
            auto pts = to_points(points, "points");
            py::array_t<bool> out(static_cast<py::ssize_t>(pts.size()));
            for (std::size_t i = 0; i < pts.size(); ++i) out.mutable_data()[i] = g.occupied_at(pts[i]);
            return out;
          },
          py::arg("points"), "Whether each of (n, 2) points lies in an occupied cell.")
      .def("cell_center", [](const OccupancyGrid& g, IntArg row_arg, IntArg col_arg) {
        const int row = to_int<int>(row_arg, "row", 0, g.rows() - 1);
        const int col = to_int<int>(col_arg, "col", 0, g.cols() - 1);
        if (!g.in_bounds(row, col)) throw Error("cell (" + std::to_string(row) + ", " + std::to_string(col) + ") is outside the grid");
        const Vec2 c = g.cell_center(row, col);
        return py::make_tuple(c.x(), c.y());
      }, py::arg("row"), py::arg("col"))
      .def("__repr__", [](const OccupancyGrid& g) {
        std::ostringstream s;
        s << "OccupancyGrid(" << g.rows() << "x" << g.cols() << ", resolution=" << g.resolution() << ", origin=("
          << g.origin().x() << ", " << g.origin().y() << "), occupied=" << g.occupied_count() << ")";
        return s.str();
      });

  py::class_<TerrainGrid>(m, "TerrainGrid",
                          "Slope grades 0-4 per cell, laid out like an OccupancyGrid (grades[row, col]); grade 4 "
                          "cannot be entered.")
      .def(py::init([](py::handle grades, FloatArg resolution_arg, py::handle origin) {
             const double resolution = to_float(resolution_arg, "resolution");
             const OccupancyGrid layout = grid_from_array(grades, resolution, origin, "grades", false);
             return TerrainGrid(layout.rows(), layout.cols(), resolution, layout.origin(), layout.cells());
           }),
           py::arg("grades"), py::arg("resolution"), py::arg("origin") = py::make_tuple(0.0, 0.0))
      .def_property_readonly("grades", [](const TerrainGrid& t) {
        py::array_t<std::uint8_t> out({t.rows(), t.cols()});
        std::copy(t.grades().begin(), t.grades().end(), out.mutable_data());
        return out;
      })
      .def_property_readonly("shape", [](const TerrainGrid& t) { return py::make_tuple(t.rows(), t.cols()); })
      .def_property_readonly("resolution", &TerrainGrid::resolution)
      .def_property_readonly("origin", [](const TerrainGrid& t) { return py::make_tuple(t.origin().x(), t.origin().y()); })
      .def_property_readonly("extent",
                             [](const TerrainGrid& t) {
                               const double x0 = t.origin().x(), y0 = t.origin().y();
                               return py::make_tuple(x0, x0 + t.cols() * t.resolution(), y0, y0 + t.rows() * t.resolution());
                             })
      .def("grade_at", [](const TerrainGrid& t, py::handle p) { return t.grade_at(to_vec2(p, "point")); }, py::arg("point"))
      .def("__repr__", [](const TerrainGrid& t) {
        std::ostringstream s;
        s << "TerrainGrid(" << t.rows() << "x" << t.cols() << ", resolution=" << t.resolution() << ")";
        return s.str();
      });

  py::class_<DistanceField, std::shared_ptr<DistanceField>>(
      m, "DistanceField",
      "Exact Euclidean distance transform of a grid. `cells` holds centre-to-centre distances in metres "
      "(scipy's distance_transform_edt(cells == 0) * resolution); `distance(points)` is the exact distance "
      "to the nearest obstacle cell's edge. Given `previous`, the field of an earlier grid with the same "
      "layout, only the cells near changed obstacles are recomputed (same result, faster).")
      .def(py::init([](const OccupancyGrid& grid, std::shared_ptr<const DistanceField> previous,
                       const py::object& edge_margin) {
             if (previous && !edge_margin.is_none())
               throw Error("DistanceField: edge_margin comes from `previous` when it is given; pass one or the other");
             if (previous) return std::make_shared<DistanceField>(grid, *previous);
             return std::make_shared<DistanceField>(
                 grid, edge_margin.is_none() ? DistanceField::kDefaultEdgeMargin : to_number(edge_margin, "edge_margin"));
           }),
           py::arg("grid"), py::arg("previous") = nullptr, py::kw_only(), py::arg("edge_margin") = py::none(),
           "edge_margin: free space in metres the field adds around the grid (default 3), so that points "
           "past the edge cost no more than inside; held to 64 cells and, on large grids, a sixteenth more cells.")
      .def_property_readonly("edge_margin", &DistanceField::edge_margin,
                             "the free margin kept around the grid, in metres: edge_margin rounded up to whole cells, less where the budget holds it")
      .def_property_readonly("grid", &DistanceField::grid)
      .def_property_readonly("cells",
                             [](const DistanceField& f) {
                               py::array_t<double> out({f.grid().rows(), f.grid().cols()});
                               const std::vector<double> distances = f.cell_distances();
                               std::copy(distances.begin(), distances.end(), out.mutable_data());
                               return out;
                             })
      .def(
          "distance",
          [](const DistanceField& f, py::handle points) {
            auto pts = to_points(points, "points");
            py::array_t<double> out(static_cast<py::ssize_t>(pts.size()));
            for (std::size_t i = 0; i < pts.size(); ++i) out.mutable_data()[i] = f.distance(pts[i]);
            return out;
          },
          py::arg("points"), "Distance in metres from each of (n, 2) points to the nearest obstacle edge.")
      .def("__repr__", [](const DistanceField& f) {
        std::ostringstream s;
        s << "DistanceField(" << f.grid().rows() << "x" << f.grid().cols() << ", resolution=" << f.grid().resolution()
          << ")";
        return s.str();
      });
}
