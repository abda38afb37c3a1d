#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/window.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_window(py::module_& m) {
  py::class_<VelocityWindow>(m, "VelocityWindow", "Vm ∩ Vd: the commands reachable in one control period.")
      .def_readonly("v_lo", &VelocityWindow::v_lo)
      .def_readonly("v_hi", &VelocityWindow::v_hi)
      .def_readonly("omega_lo", &VelocityWindow::omega_lo)
      .def_readonly("omega_hi", &VelocityWindow::omega_hi)
      .def(
          "contains", [](const VelocityWindow& w, py::handle t) { return w.contains(to_twist(t, "twist")); },
          py::arg("twist"))
      .def("__repr__", [](const VelocityWindow& w) {
        std::ostringstream s;
        s << "VelocityWindow(v=[" << w.v_lo << ", " << w.v_hi << "], omega=[" << w.omega_lo << ", " << w.omega_hi
          << "])";
        return s.str();
      });

  m.def(
      "dynamic_window",
      [](const RobotLimits& limits, py::handle current, FloatArg dt_arg) {
        const double dt = to_float(dt_arg, "dt");
        limits.validate();
        if (!(dt > 0.0) || !std::isfinite(dt)) throw Error("dt = " + number_text(dt) + ": must be > 0");
        return dynamic_window(limits, to_twist(current, "current"), dt);
      },
      py::arg("limits"), py::arg("current"), py::arg("dt"), "Vm ∩ Vd for the current (v, omega).");
  m.def(
      "sample_window",
      [](const VelocityWindow& w, py::handle current, IntArg n_v, IntArg n_omega) {
        const int most = static_cast<int>(limits::kMaxWindowSamplesPerAxis);
        WindowParams params{to_int<int>(n_v, "n_v", 1, most), to_int<int>(n_omega, "n_omega", 1, most)};
        params.validate();
        std::vector<Twist> samples;
        sample_window(w, to_twist(current, "current"), params, samples);
        return twists_array(samples);
      },
      py::arg("window"), py::arg("current"), py::arg("n_v") = 21, py::arg("n_omega") = 21,
      "(n_v * n_omega, 2) sampled commands (v, omega), v-major.");
}
