#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "fgdwa/error.hpp"
#include "fgdwa/presets.hpp"
#include "fgdwa/weights.hpp"

namespace py = pybind11;
using namespace fgdwa;

namespace {
// Lets a Python class derive from WeightPolicy and define weights(density, deviation) -> (beta, delta).
class PyWeightPolicy : public WeightPolicy {
 public:
  std::string name() const override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const WeightPolicy*>(this), "name");
    return f ? f().cast<std::string>() : std::string("python");
  }
  WeightPair weights(double density, double deviation) const override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const WeightPolicy*>(this), "weights");
    if (!f) throw Error("a WeightPolicy subclass must define weights(density, deviation)");
    const py::object result = f(density, deviation);
    py::sequence pair;
    try {
      pair = result.cast<py::sequence>();
    } catch (const py::cast_error&) {
    }
    if (!pair || pair.size() != 2) throw Error("WeightPolicy.weights must return (beta, delta)");
    return {pair[0].cast<double>(), pair[1].cast<double>()};
  }
};
}  // namespace

void init_weights(py::module_& m) {
  py::class_<WeightPolicy, PyWeightPolicy, std::shared_ptr<WeightPolicy>>(
      m, "WeightPolicy",
      "Sets the clearance weight beta and the similarity weight delta from I and D each cycle. Derive from it in "
      "Python (call super().__init__()) and define weights(density, deviation) -> (beta, delta).")
      .def(py::init<>())
      .def_property_readonly("name", &WeightPolicy::name)
      .def(
          "weights",
          [](const WeightPolicy& p, double density, double deviation) {
            if (std::isnan(density)) throw Error("density I is NaN");
            if (std::isnan(deviation)) throw Error("deviation D is NaN");
            const WeightPair w = p.weights(density, deviation);
            return py::make_tuple(w.beta, w.delta);
          },
          py::arg("density"), py::arg("deviation"), "(beta, delta) for obstacle density I and path deviation D (m).");

  py::class_<FixedWeights, WeightPolicy, std::shared_ptr<FixedWeights>>(m, "FixedWeights",
                                                                         "beta and delta held fixed.")
      .def(py::init<double, double>(), py::arg("beta"), py::arg("delta"))
      .def("__repr__", [](const FixedWeights& w) {
        const WeightPair p = w.weights(0.0, 0.0);
        std::ostringstream s;
        s << "FixedWeights(beta=" << p.beta << ", delta=" << p.delta << ")";
        return s.str();
      });

  py::class_<FuzzyWeights, WeightPolicy, std::shared_ptr<FuzzyWeights>>(
      m, "FuzzyWeights",
      "beta and delta from a Mamdani engine with inputs I, D and outputs beta, delta (default: the paper's).")
      .def(py::init([](const MamdaniEngine* engine) {
             return engine ? std::make_shared<FuzzyWeights>(*engine) : std::make_shared<FuzzyWeights>();
           }),
           py::arg("engine") = nullptr)
      .def_property_readonly("engine", &FuzzyWeights::engine)
      .def("__repr__", [](const FuzzyWeights& w) {
        return "FuzzyWeights(" + std::to_string(w.engine().rules().size()) + " rules)";
      });

  py::class_<PlannerPreset>(m, "PlannerPreset", "A named planner of the paper's experiments: its parameters and weights.")
      .def_readonly("name", &PlannerPreset::name)
      .def_readonly("description", &PlannerPreset::description)
      .def_readonly("params", &PlannerPreset::params)
      .def_readonly("fuzzy", &PlannerPreset::fuzzy)
      .def("weight_policy", &PlannerPreset::weight_policy, "The policy to run it with; None for fixed weights.")
      .def("__repr__", [](const PlannerPreset& p) {
        return "PlannerPreset('" + p.name + "', fuzzy=" + (p.fuzzy ? "True" : "False") + ")";
      });
  m.def("planner_preset", &planner_preset, py::arg("name"),
        "A planner by name: dwa, gdwa, sgdwa, fgdwa, gdwa_high_safety, gdwa_high_similarity; dwb (Nav2's DWB critics).");
  m.def("preset_names", &preset_names);

  py::class_<RobotPreset>(m, "RobotPreset", "A robot by name: limits and footprint.")
      .def_readonly("name", &RobotPreset::name)
      .def_readonly("description", &RobotPreset::description)
      .def_readonly("limits", &RobotPreset::limits)
      .def_readonly("footprint", &RobotPreset::footprint)
      .def("__repr__", [](const RobotPreset& r) { return "RobotPreset('" + r.name + "')"; });
  m.def("robot_preset", &robot_preset, py::arg("name"), "A robot by name: default, jackal.");
  m.def("robot_names", &robot_names);
}
