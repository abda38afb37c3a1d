#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "convert.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/presets.hpp"
#include "fgdwa/weights.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

namespace {
// Lets a Python class derive from WeightPolicy and define
// weights(density, deviation) -> {critic name: weight}.
class PyWeightPolicy : public WeightPolicy {
 public:
  std::string name() const override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const WeightPolicy*>(this), "name");
    return f ? f().cast<std::string>() : std::string("python");
  }
  CriticWeights weights(double density, double deviation) const override {
    py::gil_scoped_acquire gil;
    py::function f = py::get_override(static_cast<const WeightPolicy*>(this), "weights");
    if (!f) throw Error("a WeightPolicy subclass must define weights(density, deviation)");
    const py::object result = f(density, deviation);
    if (!py::isinstance<py::dict>(result))
      throw Error("WeightPolicy.weights must return a dict {critic name: weight}, got " +
                  std::string(py::str(py::type::of(result))));
    CriticWeights weights;
    for (auto item : result.cast<py::dict>()) {
      const std::string critic = py::str(item.first);
      double weight;
      try {
        weight = item.second.cast<double>();
      } catch (const py::cast_error&) {
        throw Error("WeightPolicy.weights: the weight of critic '" + critic + "' is not a number");
      }
      if (!std::isfinite(weight)) throw Error("WeightPolicy.weights: the weight of critic '" + critic + "' is not finite");
      weights[critic] = weight;
    }
    return weights;
  }
};
}  // namespace

void init_weights(py::module_& m) {
  py::class_<WeightPolicy, PyWeightPolicy, std::shared_ptr<WeightPolicy>>(
      m, "WeightPolicy",
      "Sets critics' weights from the obstacle density I and the path deviation D each cycle. Derive from it in "
      "Python (call super().__init__()) and define weights(density, deviation) -> {critic name: weight}; the "
      "controller applies the weights of the critics its planner has.")
      .def(py::init<>())
      .def_property_readonly("name", &WeightPolicy::name)
      .def(
          "weights",
          [](const WeightPolicy& p, FloatArg density_arg, FloatArg deviation_arg, FloatArg contact_arg) {
            const double density = to_float(density_arg, "density"), deviation = to_float(deviation_arg, "deviation");
            if (std::isnan(density)) throw Error("density I is NaN");
            if (std::isnan(deviation)) throw Error("deviation D is NaN");
            return p.weights(density, deviation, to_float(contact_arg, "contact_time"));
          },
          py::arg("density"), py::arg("deviation"), py::arg("contact_time") = std::numeric_limits<double>::infinity(),
          "{critic name: weight} for obstacle density I, path deviation D (m) and the time T (s) to the nearest "
          "predicted contact with a mover (inf, the default: none); a policy that does not read T gives its "
          "weights(I, D).");

  py::class_<FixedWeights, WeightPolicy, std::shared_ptr<FixedWeights>>(
      m, "FixedWeights", "Critics' weights held fixed: FixedWeights(beta, delta) for clearance and similarity, or "
                         "FixedWeights(weights={critic name: weight}).")
      .def(py::init([](FloatArg beta, FloatArg delta) {
             return std::make_shared<FixedWeights>(to_float(beta, "beta"), to_float(delta, "delta"));
           }),
           py::arg("beta"), py::arg("delta"))
      .def(py::init([](const std::map<std::string, FloatArg>& weights) {
             CriticWeights values;
             for (const auto& [critic, weight] : weights)
               values[critic] = to_float(weight, "weight of critic '" + critic + "'");
             return std::make_shared<FixedWeights>(std::move(values));
           }),
           py::arg("weights"))
      .def("__repr__", [](const FixedWeights& w) {
        std::ostringstream s;
        s << "FixedWeights({";
        bool first = true;
        for (const auto& [critic, weight] : w.weights(0.0, 0.0)) {
          s << (first ? "" : ", ") << "'" << critic << "': " << weight;
          first = false;
        }
        s << "})";
        return s.str();
      });

  py::class_<FuzzyWeights, WeightPolicy, std::shared_ptr<FuzzyWeights>>(
      m, "FuzzyWeights",
      "Critics' weights from a Mamdani engine with inputs I and D, and optionally T (the time to the nearest "
      "predicted contact with a mover), each output mapped to a critic.")
      .def(py::init([](const MamdaniEngine* engine, std::optional<std::map<std::string, std::string>> outputs) {
             if (!engine) {
               if (outputs) throw Error("FuzzyWeights: output_critics needs an engine");
               return std::make_shared<FuzzyWeights>();
             }
             return outputs ? std::make_shared<FuzzyWeights>(*engine, *outputs) : std::make_shared<FuzzyWeights>(*engine);
           }),
           py::arg("engine") = nullptr, py::arg("output_critics") = py::none(),
           "engine: a MamdaniEngine with inputs I and D, and optionally T (default: the paper's; "
           "mover_fuzzy_controller() reads T too); output_critics: {output: critic} "
           "(default: beta -> clearance, delta -> similarity).")
      .def_property_readonly("output_critics", &FuzzyWeights::output_critics)
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

  py::class_<RobotPreset>(m, "RobotPreset", "A robot by name: limits, the footprint it is planned with and its true outline.")
      .def_readonly("name", &RobotPreset::name)
      .def_readonly("description", &RobotPreset::description)
      .def_readonly("limits", &RobotPreset::limits)
      .def_readonly("footprint", &RobotPreset::footprint, "What the planner is configured with.")
      .def_readonly("outline", &RobotPreset::outline, "The body itself: what a referee judges contact with.")
      .def("__repr__", [](const RobotPreset& r) { return "RobotPreset('" + r.name + "')"; });
  m.def("robot_preset", &robot_preset, py::arg("name"), "A robot by name: default, jackal.");
  m.def("robot_names", &robot_names);
}
