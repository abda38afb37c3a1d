#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "fgdwa/critics.hpp"

namespace py = pybind11;
using namespace fgdwa;

void init_critics(py::module_& m) {
  py::class_<CriticConfig>(m, "CriticConfig",
                           "A critic by registered name, its weight, and its own parameters "
                           "(e.g. CriticConfig('clearance', 0.15, {'cap': 2.0})).")
      .def(py::init([](std::string name, double weight, std::map<std::string, double> params) {
             CriticConfig c{std::move(name), weight, std::move(params)};
             make_critic(c);  // validates name, weight and parameters now
             return c;
           }),
           py::arg("name"), py::arg("weight") = 1.0, py::arg("params") = std::map<std::string, double>{})
      .def_readwrite("name", &CriticConfig::name)
      .def_readwrite("weight", &CriticConfig::weight)
      .def_readwrite("params", &CriticConfig::params)
      .def("__repr__", [](const CriticConfig& c) {
        std::ostringstream s;
        s << "CriticConfig('" << c.name << "', " << c.weight;
        if (!c.params.empty()) {
          s << ", {";
          bool first = true;
          for (const auto& [k, v] : c.params) {
            s << (first ? "" : ", ") << "'" << k << "': " << v;
            first = false;
          }
          s << "}";
        }
        s << ")";
        return s.str();
      });
  m.def("critic_names", &critic_names, "Names of the critics that can be configured.");
}
