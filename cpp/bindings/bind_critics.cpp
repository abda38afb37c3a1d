#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/critics.hpp"

namespace py = pybind11;
using namespace fgdwa;
using fgdwa::py_convert::critic_config;

namespace fgdwa::py_convert {
CriticConfig critic_config(std::string name, double weight, const py::dict& params) {
  CriticConfig c(std::move(name), weight);
  for (auto kv : params) {
    const auto key = py::str(kv.first).cast<std::string>();
    if (py::isinstance<py::str>(kv.second))
      c.options[key] = kv.second.cast<std::string>();
    else if (py::isinstance<py::float_>(kv.second) || py::isinstance<py::int_>(kv.second))
      c.params[key] = kv.second.cast<double>();
    else
      throw Error("critic " + c.name + "." + key + ": expected a number or a word, got " +
                  std::string(py::str(py::type::of(kv.second))));
  }
  return c;
}
}  // namespace fgdwa::py_convert

void init_critics(py::module_& m) {
  py::class_<CriticConfig>(m, "CriticConfig",
                           "A critic by registered name, its weight, and its own parameters "
                           "(e.g. CriticConfig('clearance', 0.15, {'cap': 2.0})).")
      .def(py::init([](std::string name, double weight, py::dict params) {
             CriticConfig c = critic_config(std::move(name), weight, params);
             make_critic(c);  // validates name, weight and parameters now
             return c;
           }),
           py::arg("name"), py::arg("weight") = 1.0, py::arg("params") = py::dict(),
           "params: numbers (e.g. {'cap': 2.0}) and words (e.g. {'sampling': 'segment'}).")
      .def_readwrite("name", &CriticConfig::name)
      .def_readwrite("weight", &CriticConfig::weight)
      .def_property_readonly("params", [](const CriticConfig& c) {
        py::dict out;
        for (const auto& [k, v] : c.params) out[py::str(k)] = v;
        for (const auto& [k, v] : c.options) out[py::str(k)] = v;
        return out;
      })
      .def("__repr__", [](const CriticConfig& c) {
        std::ostringstream s;
        s << "CriticConfig('" << c.name << "', " << c.weight;
        if (!c.params.empty() || !c.options.empty()) {
          s << ", {";
          bool first = true;
          for (const auto& [k, v] : c.params) {
            s << (first ? "" : ", ") << "'" << k << "': " << v;
            first = false;
          }
          for (const auto& [k, v] : c.options) {
            s << (first ? "" : ", ") << "'" << k << "': '" << v << "'";
            first = false;
          }
          s << "}";
        }
        s << ")";
        return s.str();
      });
  m.def("critic_names", &critic_names, "Names of the critics that can be configured.");
}
