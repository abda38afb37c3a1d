#pragma once
// Helpers shared by several binding files.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "convert.hpp"
#include "fgdwa/clearance.hpp"

namespace fgdwa::py_convert {

// Clearance of one pose (a float) or of (n, 3) poses (an array).
inline py::object clearances(const ClearanceSource& source, const Footprint& fp, py::handle poses, double t) {
  py_convert::to_time(t, "t");
  if (py::isinstance<Pose2>(poses)) return py::float_(source.clearance(fp, poses.cast<Pose2>(), t));
  const py::array probe = py::array::ensure(poses);
  auto a = float_array(poses, "poses", probe && probe.ndim() == 1 ? 1 : 2, 3);
  if (a.ndim() == 1) return py::float_(source.clearance(fp, Pose2{a.at(0), a.at(1), a.at(2)}, t));
  py::array_t<double> out(a.shape(0));
  for (py::ssize_t i = 0; i < a.shape(0); ++i)
    out.mutable_data()[i] = source.clearance(fp, Pose2{a.at(i, 0), a.at(i, 1), a.at(i, 2)}, t);
  return std::move(out);
}

}  // namespace fgdwa::py_convert
