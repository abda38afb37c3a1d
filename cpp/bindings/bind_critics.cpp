#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bind_params.hpp"
#include "convert.hpp"
#include "fgdwa/critics.hpp"
#include "fgdwa/dwb_critics.hpp"

namespace py = pybind11;
using namespace fgdwa;
using fgdwa::py_convert::critic_config;
using fgdwa::py_convert::FloatArg;
using fgdwa::py_convert::float_fields;
using fgdwa::py_convert::refuse_unnamed_values;
using fgdwa::py_convert::to_float;

namespace fgdwa::py_convert {
CriticConfig critic_config(std::string name, double weight, const py::dict& params) {
  CriticConfig c(std::move(name), weight);
  for (auto kv : params) {
    const auto key = py::str(kv.first).cast<std::string>();
    if (py::isinstance<py::str>(kv.second))
      c.options[key] = kv.second.cast<std::string>();
    else if (py::isinstance<py::bool_>(kv.second) || !py::hasattr(kv.second, "__float__"))
      throw Error("critic " + c.name + "." + key + ": expected a number or a word, got " +
                  std::string(py::str(py::type::of(kv.second))));
    else
      c.params[key] = to_number(kv.second, "critic " + c.name + "." + key);
  }
  return c;
}
}  // namespace fgdwa::py_convert

namespace {

// A critic written in Python: an instance of a registered class, scoring a
// batch of rollouts as numpy arrays (see fgdwa.register_critic).
class PythonCritic : public Critic {
 public:
  PythonCritic(std::string name, py::object instance) : name_(std::move(name)), instance_(std::move(instance)) {
    const std::string sense = py::str(py::getattr(instance_, "sense", py::str("reward")));
    if (sense != "reward" && sense != "cost")
      throw Error("critic '" + name_ + "': sense = '" + sense + "': expected 'reward' or 'cost'");
    sense_ = sense == "cost" ? CriticSense::Cost : CriticSense::Reward;
    needs_path_ = py::bool_(py::getattr(instance_, "needs_path", py::bool_(false)));
  }
  std::string name() const override { return name_; }
  CriticSense sense() const override { return sense_; }
  bool needs_path() const override { return needs_path_; }
  void prepare(const CriticContext& c) override {
    if (!py::hasattr(instance_, "prepare")) return;
    py::dict context;
    context["pose"] = py::make_tuple(c.state.pose.x, c.state.pose.y, c.state.pose.theta);
    context["velocity"] = py::make_tuple(c.state.twist.v, c.state.twist.omega);
    context["goal"] = py::make_tuple(c.goal.x(), c.goal.y());
    context["target"] = py::make_tuple(c.target.x(), c.target.y());
    context["dt"] = c.dt;
    context["path"] = c.path ? py::object(py_convert::points_array(c.path->points())) : py::object(py::none());
    instance_.attr("prepare")(context);
  }
  double score(const Rollout& rollout) const override {
    double out = 0.0;
    score_all({rollout}, &out);
    return out;
  }
  void score_all(const std::vector<Rollout>& rollouts, double* out) const override {
    const auto n = static_cast<py::ssize_t>(rollouts.size());
    const auto steps = n ? static_cast<py::ssize_t>(rollouts[0].poses->size()) : 0;
    py::array_t<double> poses({n, steps, py::ssize_t(3)}), commands({n, py::ssize_t(2)}), clearance(n);
    auto p = poses.mutable_unchecked<3>();
    auto c = commands.mutable_unchecked<2>();
    auto d = clearance.mutable_unchecked<1>();
    for (py::ssize_t i = 0; i < n; ++i) {
      const Rollout& r = rollouts[static_cast<std::size_t>(i)];
      for (py::ssize_t k = 0; k < steps; ++k) {
        const Pose2& q = (*r.poses)[static_cast<std::size_t>(k)];
        p(i, k, 0) = q.x, p(i, k, 1) = q.y, p(i, k, 2) = q.theta;
      }
      c(i, 0) = r.command.v, c(i, 1) = r.command.omega;
      d(i) = r.min_clearance;
    }
    const py::object scores = instance_.attr("score_batch")(poses, commands, clearance);
    // NaN is a veto, so the scores are not checked for finiteness here (the planner does).
    // Real numbers only: a cast would drop an imaginary part or turn objects into noise.
    const py::array given = py::array::ensure(scores);
    if (given && std::string("biuf").find(given.dtype().kind()) == std::string::npos)
      throw Error("critic '" + name_ + "': score_batch returned scores of dtype " +
                  std::string(py::str(given.dtype())) + ": expected real numbers");
    const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(scores);
    if (!values || values.ndim() != 1)
      throw Error("critic '" + name_ + "': score_batch must return a 1-d array of numbers");
    if (values.size() != n)
      throw Error("critic '" + name_ + "': score_batch returned " + std::to_string(values.size()) + " scores for " +
                  std::to_string(n) + " rollouts");
    for (py::ssize_t i = 0; i < n; ++i) out[i] = values.at(i);
  }

 private:
  std::string name_;
  py::object instance_;
  CriticSense sense_ = CriticSense::Reward;
  bool needs_path_ = false;
};

}  // namespace

void init_critics(py::module_& m) {
  py::enum_<CriticSense> critic_sense_enum(m, "CriticSense", "Whether a critic's larger raw scores are better (reward) or worse (cost).");
  critic_sense_enum
      .value("Reward", CriticSense::Reward)
      .value("Cost", CriticSense::Cost);
  refuse_unnamed_values(critic_sense_enum);

  // The built-in critics' parameters, given in a CriticConfig's params by these names.
  bind_params<ClearanceParams>(m, "ClearanceParams", "The parameters of critic 'clearance'.");
  bind_params<SimilarityParams>(m, "SimilarityParams", "The parameters of critic 'similarity'.");
  bind_params<DwbObstacleParams>(m, "DwbObstacleParams", "The parameters of critic 'dwb_obstacle'.");
  bind_params<DwbGridParams>(m, "DwbGridParams",
                             "The parameters of the map-grid critics dwb_path_dist, dwb_goal_dist, dwb_path_align "
                             "and dwb_goal_align (forward_point_distance: the align ones only).");
  py::class_<CriticConfig> config_class(m, "CriticConfig",
                                        "A critic by registered name, its weight, and its own parameters "
                                        "(e.g. CriticConfig('clearance', 0.15, {'cap': 2.0})).");
  float_fields(config_class, {{"weight", &CriticConfig::weight}});
  config_class
      .def(py::init([](std::string name, FloatArg weight, py::dict params) {
             CriticConfig c = critic_config(std::move(name), to_float(weight, "weight"), params);
             make_critic(c);  // validates name, weight and parameters now
             return c;
           }),
           py::arg("name"), py::arg("weight") = 1.0, py::arg("params") = py::dict(),
           "params: numbers (e.g. {'cap': 2.0}) and words (e.g. {'sampling': 'segment'}).")
      .def_readwrite("name", &CriticConfig::name)
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
  m.def(
      "register_python_critic",
      [](const std::string& name, py::object cls) {
        if (!PyCallable_Check(cls.ptr())) throw Error("register_critic: critic '" + name + "' is not callable");
        if (!py::hasattr(cls, "score_batch") || !PyCallable_Check(py::getattr(cls, "score_batch").ptr()))
          throw Error("register_critic: critic '" + name + "' has no callable score_batch(poses, commands, min_clearance)");
        // Held for the life of the process: the registry outlives the interpreter's objects.
        PyObject* held = cls.inc_ref().ptr();
        register_critic(name, [name, held](std::map<std::string, double>& params,
                                           std::map<std::string, std::string>& options) -> std::unique_ptr<Critic> {
          py::gil_scoped_acquire gil;
          py::dict kwargs;
          for (const auto& [key, value] : params) kwargs[py::str(key)] = value;
          for (const auto& [key, value] : options) kwargs[py::str(key)] = value;
          params.clear();
          options.clear();
          py::object instance;
          try {
            instance = py::reinterpret_borrow<py::object>(held)(**kwargs);
          } catch (py::error_already_set& e) {
            throw Error("critic '" + name + "': " + std::string(e.what()));
          }
          return std::make_unique<PythonCritic>(name, instance);
        });
      },
      py::arg("name"), py::arg("cls"), "Registers a Python critic class under `name` (see fgdwa.register_critic).");
}
