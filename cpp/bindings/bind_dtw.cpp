#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "convert.hpp"
#include "fgdwa/dtw.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_dtw(py::module_& m) {
  m.attr("NO_BAND") = kNoBand;
  m.def(
      "dtw",
      [](py::handle a, py::handle b, IntArg band_arg) {
        const int band = to_int<int>(band_arg, "band", kNoBand);
        if (band < kNoBand) throw Error("band = " + std::to_string(band) + ": must be >= 0, or -1 for no band");
        return dtw(to_points(a, "a"), to_points(b, "b"), band);
      },
      py::arg("a"), py::arg("b"), py::arg("band") = kNoBand,
      "Dynamic time warping between (n, 2) and (m, 2) point sequences: the sum of Euclidean point distances "
      "along the optimal warping path (steps (i-1, j), (i, j-1), (i-1, j-1)). band >= 0: Sakoe-Chiba band "
      "around the diagonal, in samples (widened where too narrow to connect the ends); -1: none.");
}
