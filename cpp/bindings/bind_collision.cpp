#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/collision.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_collision(py::module_& m) {
  py::class_<CollisionWorld, ClearanceSource, std::shared_ptr<CollisionWorld>>(
      m, "CollisionWorld",
      "The exact world on FCL: the grid's occupied cells merged into boxes, plus moving discs. "
      "The simulator's ground truth.")
      .def(py::init([](const OccupancyGrid* grid, std::vector<Disc> discs) {
             if (grid) return std::make_shared<CollisionWorld>(*grid, std::move(discs));
             auto world = std::make_shared<CollisionWorld>();
             world->set_discs(std::move(discs));
             return world;
           }),
           py::arg("grid") = nullptr, py::arg("discs") = std::vector<Disc>{})
      // A copy: a view into the vector would dangle once the discs are replaced.
      .def_property("discs", [](const CollisionWorld& w) { return w.discs(); }, &CollisionWorld::set_discs)
      .def_property_readonly(
          "boxes",
          [](const CollisionWorld& w) {
            py::array_t<int> out({static_cast<py::ssize_t>(w.boxes().size()), py::ssize_t{4}});
            auto a = out.mutable_unchecked<2>();
            for (std::size_t i = 0; i < w.boxes().size(); ++i) {
              const CellRect& r = w.boxes()[i];
              a(i, 0) = r.row;
              a(i, 1) = r.col;
              a(i, 2) = r.rows;
              a(i, 3) = r.cols;
            }
            return out;
          },
          "(k, 4) merged boxes as (row, col, rows, cols) of cells.")
      .def(
          "in_collision",
          [](const CollisionWorld& w, const Footprint& fp, py::handle pose, FloatArg t) {
            return w.in_collision(fp, to_pose(pose, "pose"), to_float(t, "t"));
          },
          py::arg("footprint"), py::arg("pose"), py::arg("t") = 0.0)
      .def("__repr__", [](const CollisionWorld& w) {
        std::ostringstream s;
        s << "CollisionWorld(boxes=" << w.boxes().size() << ", discs=" << w.discs().size() << ")";
        return s.str();
      });
}
