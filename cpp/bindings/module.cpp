#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fgdwa/error.hpp"
#include "fgdwa/params.hpp"

namespace py = pybind11;

void init_geometry(py::module_& m);
void init_robot(py::module_& m);
void init_grid(py::module_& m);
void init_clearance(py::module_& m);
void init_collision(py::module_& m);
void init_window(py::module_& m);
void init_critics(py::module_& m);
void init_path(py::module_& m);
void init_dtw(py::module_& m);
void init_perception(py::module_& m);
void init_global_planner(py::module_& m);
void init_planner(py::module_& m);
void init_fuzzy(py::module_& m);
void init_weights(py::module_& m);
void init_controller(py::module_& m);
void init_mapping(py::module_& m);
void init_tracking(py::module_& m);
void init_scan_matcher(py::module_& m);
void init_navigator(py::module_& m);

PYBIND11_MODULE(_core, m) {
  m.doc() = "fgdwa's C++ core: robot model, grids, collision, dynamic window, critics and planner.";
  py::register_exception<fgdwa::Error>(m, "FgdwaError", PyExc_ValueError);
  init_geometry(m);
  init_robot(m);
  init_grid(m);
  init_clearance(m);
  init_collision(m);
  init_window(m);
  init_critics(m);
  init_path(m);
  init_dtw(m);
  init_perception(m);
  init_global_planner(m);
  init_planner(m);
  init_fuzzy(m);
  init_weights(m);
  init_controller(m);
  init_mapping(m);
  init_tracking(m);
  init_scan_matcher(m);
  init_navigator(m);
  m.def("nearest_names", &fgdwa::nearest_names, py::arg("name"), py::arg("known"), py::arg("count") = 3,
        "The names among `known` closest to `name` (edit distance, a dotted or '/'-joined name matched on its "
        "last part too), best first: the 'did you mean' of every lookup by name.");
}
