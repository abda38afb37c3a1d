#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include <cmath>

#include "convert.hpp"
#include "fgdwa/planner.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

namespace {
CriticConfig critic_from_python(py::handle item) {
  CriticConfig c;
  if (py::isinstance<CriticConfig>(item)) {
    c = item.cast<CriticConfig>();
  } else if (py::isinstance<py::dict>(item)) {
    auto d = item.cast<py::dict>();
    for (auto kv : d) {
      const auto key = to_word(kv.first, "critics: a key");
      if (key != "name" && key != "weight" && key != "params")
        throw Error("critics: unknown key '" + key + "' (expected name, weight, params)");
    }
    if (!d.contains("name")) throw Error("critics: an entry has no 'name'");
    const std::string name = to_word(d["name"], "critics: name");
    c = critic_config(name, d.contains("weight") ? to_number(d["weight"], "critics: weight of '" + name + "'") : 1.0,
                      d.contains("params") ? to_dict(d["params"], "critics: params of '" + name + "'") : py::dict());
  } else if (py::isinstance<py::tuple>(item) || py::isinstance<py::list>(item)) {
    auto t = item.cast<py::sequence>();
    if (t.size() < 2 || t.size() > 3) throw Error("critics: a tuple entry is (name, weight[, params])");
    const std::string name = to_word(t[0], "critics: name");
    c = critic_config(name, to_number(t[1], "critics: weight of '" + name + "'"),
                      t.size() == 3 ? to_dict(t[2], "critics: params of '" + name + "'") : py::dict());
  } else {
    throw Error("critics: each entry is a CriticConfig, a dict or a (name, weight[, params]) tuple, got " +
                std::string(py::str(py::type::of(item))));
  }
  make_critic(c);
  return c;
}

BrakingModel braking_from_string(const std::string& name) {
  return enum_from_string("braking", name, std::array{BrakingModel::Discrete, BrakingModel::Continuous});
}

HeadingTarget heading_target_from_string(const std::string& name) {
  return enum_from_string("heading_target", name, std::array{HeadingTarget::Goal, HeadingTarget::KeyNodes});
}

Normalization normalization_from_string(const std::string& name) {
  return enum_from_string("normalization", name,
                          std::array{Normalization::Sum, Normalization::MinMax, Normalization::None});
}

}  // namespace

void init_planner(py::module_& m) {
  py::enum_<Status> status_enum(m, "Status", "Outcome of one control cycle.");
  status_enum
      .value("Ok", Status::Ok)
      .value("NoAdmissibleVelocity", Status::NoAdmissibleVelocity)
      .value("GoalReached", Status::GoalReached)
      .value("Evading", Status::Evading);
  refuse_unnamed_values(status_enum);
  py::enum_<RejectReason> reject_reason_enum(m, "RejectReason", "Why a sampled command was rejected.");
  reject_reason_enum
      .value("None_", RejectReason::None)
      .value("Collision", RejectReason::Collision)
      .value("Terrain", RejectReason::Terrain)
      .value("Critic", RejectReason::Critic)
      .value("Moving", RejectReason::Moving);
  refuse_unnamed_values(reject_reason_enum);

  py::class_<PlannerParams>(m, "PlannerParams", "Parameters of the local planner (SI units).")
      .def(py::init([](FloatArg dt, FloatArg sim_time, IntArg n_v, IntArg n_omega, const std::string& normalization,
                       const std::string& braking, FloatArg goal_tolerance, py::object critics,
                       const std::string& heading_target, FloatArg key_node_angle_deg, FloatArg key_node_radius,
                       FloatArg safety_margin, bool key_node_sight, FloatArg moving_horizon,
                       FloatArg mover_caution_radius, FloatArg mover_speed_weight) {
             PlannerParams p;
             p.dt = to_float(dt, "dt");
             p.sim_time = to_float(sim_time, "sim_time");
             const int most = static_cast<int>(limits::kMaxWindowSamplesPerAxis);
             p.window.n_v = to_int<int>(n_v, "n_v", 1, most);
             p.window.n_omega = to_int<int>(n_omega, "n_omega", 1, most);
             p.normalization = normalization_from_string(normalization);
             p.braking = braking_from_string(braking);
             p.goal_tolerance = to_float(goal_tolerance, "goal_tolerance");
             p.heading_target = heading_target_from_string(heading_target);
             p.key_nodes.min_turn = radians_from_degrees(
                 "key_node_angle_deg", to_float(key_node_angle_deg, "key_node_angle_deg"), 0.0, 180.0, true);
             p.key_nodes.reach_radius = to_float(key_node_radius, "key_node_radius");
             p.key_nodes.require_sight = key_node_sight;
             p.safety_margin = to_float(safety_margin, "safety_margin");
             p.moving_horizon = to_float(moving_horizon, "moving_horizon");
             p.mover_caution_radius = to_float(mover_caution_radius, "mover_caution_radius");
             p.mover_speed_weight = to_float(mover_speed_weight, "mover_speed_weight");
             if (!critics.is_none()) {
               p.critics.clear();
               for (auto item : critics) p.critics.push_back(critic_from_python(item));
             }
             p.validate();
             return p;
           }),
           py::arg("dt") = 0.15, py::arg("sim_time") = 3.0, py::arg("n_v") = 21, py::arg("n_omega") = 21,
           py::arg("normalization") = "sum", py::arg("braking") = "discrete", py::arg("goal_tolerance") = 0.3, py::arg("critics") = py::none(),
           py::arg("heading_target") = "goal", py::arg("key_node_angle_deg") = 10.0, py::arg("key_node_radius") = 1.0,
           py::arg("safety_margin") = 0.02, py::arg("key_node_sight") = false, py::arg("moving_horizon") = 1.0,
           py::arg("mover_caution_radius") = 2.0, py::arg("mover_speed_weight") = 0.5,
           "dt: control period and rollout step (s); sim_time: rollout horizon (s); n_v, n_omega: sample "
           "counts; normalization: 'sum', 'minmax' or 'none' (raw terms, as Nav2's DWB adds them); braking: 'discrete' (stop within the free distance "
           "with one control period of latency and stepped deceleration) or 'continuous' (Eq. 3 as written); goal_tolerance (m); critics: list of CriticConfig, dicts "
           "or (name, weight[, params]) tuples (default: heading 0.5, clearance 0.15, velocity 1.0); "
           "heading_target: 'goal' (DWA) or 'key_nodes' (GDWA: the first key node of the global path not yet "
           "reached); key_node_angle_deg: turn that makes a vertex a key node; key_node_radius (m): a key node this "
           "near is reached; safety_margin (m): a rollout closer than this to an obstacle counts as in contact "
           "(never more than the robot's own clearance); key_node_sight: a key node within key_node_radius counts as "
           "reached only once the next one is in sight (default False: SPEC 5 as written); moving_horizon (s): a rollout "
           "predicted to meet a moving obstacle this soon is rejected, standing still included (0: moving obstacles "
           "count only as the braking rule counts them); while a moving obstacle is within mover_caution_radius (m) the "
           "velocity critic's weight is multiplied by mover_speed_weight (in [0, 1]; 1: no change).")
      .def_readonly("dt", &PlannerParams::dt)
      .def_readonly("sim_time", &PlannerParams::sim_time)
      .def_property_readonly("n_v", [](const PlannerParams& p) { return p.window.n_v; })
      .def_property_readonly("n_omega", [](const PlannerParams& p) { return p.window.n_omega; })
      .def_property_readonly("normalization", [](const PlannerParams& p) { return std::string(to_string(p.normalization)); })
      .def_property_readonly("braking", [](const PlannerParams& p) { return std::string(to_string(p.braking)); })
      .def_readonly("goal_tolerance", &PlannerParams::goal_tolerance)
      .def_property_readonly("heading_target", [](const PlannerParams& p) { return std::string(to_string(p.heading_target)); })
      .def_property_readonly("key_node_angle_deg", [](const PlannerParams& p) { return p.key_nodes.min_turn * 180.0 / M_PI; })
      .def_property_readonly("key_node_radius", [](const PlannerParams& p) { return p.key_nodes.reach_radius; })
      .def_readonly("safety_margin", &PlannerParams::safety_margin)
      .def_readonly("moving_horizon", &PlannerParams::moving_horizon)
      .def_readonly("mover_caution_radius", &PlannerParams::mover_caution_radius)
      .def_readonly("mover_speed_weight", &PlannerParams::mover_speed_weight)
      .def_property_readonly("key_node_sight", [](const PlannerParams& p) { return p.key_nodes.require_sight; })
      .def_readonly("critics", &PlannerParams::critics)
      .def_property_readonly("n_steps", &PlannerParams::n_steps)
      .def("__repr__", [](const PlannerParams& p) {
        std::ostringstream s;
        s << "PlannerParams(dt=" << p.dt << ", sim_time=" << p.sim_time << ", n_v=" << p.window.n_v
          << ", n_omega=" << p.window.n_omega << ", normalization='" << to_string(p.normalization)
          << "', braking='" << to_string(p.braking) << "', goal_tolerance=" << p.goal_tolerance << ", heading_target='" << to_string(p.heading_target) << "'" << ", critics=[";
        for (std::size_t i = 0; i < p.critics.size(); ++i)
          s << (i ? ", " : "") << "('" << p.critics[i].name << "', " << p.critics[i].weight << ")";
        s << "])";
        return s.str();
      });

  py::class_<PlanResult>(m, "PlanResult", "One control cycle's command, status and per-sample diagnostics.")
      .def_readonly("status", &PlanResult::status)
      .def_readonly("command", &PlanResult::command)
      .def_readonly("best_index", &PlanResult::best_index)
      .def_property_readonly("target", [](const PlanResult& r) { return py::make_tuple(r.target.x(), r.target.y()); })
      .def_readonly("key_node", &PlanResult::key_node, "Index of the target among the key nodes; -1 when aiming at the goal.")
      .def_readonly("critic_names", &PlanResult::critic_names)
      .def_readonly("weights", &PlanResult::weights)
      .def_property_readonly("samples", [](const PlanResult& r) { return twists_array(r.samples); },
                             "(n, 2) sampled commands (v, omega).")
      .def_property_readonly("admissible",
                             [](const PlanResult& r) {
                               py::array_t<bool> out(static_cast<py::ssize_t>(r.reasons.size()));
                               for (std::size_t i = 0; i < r.reasons.size(); ++i)
                                 out.mutable_data()[i] = r.reasons[i] == RejectReason::None;
                               return out;
                             })
      .def_property_readonly("reasons",
                             [](const PlanResult& r) {
                               py::list out;
                               for (RejectReason reason : r.reasons) out.append(to_string(reason));
                               return out;
                             },
                             "Per sample: 'None' (admissible) or the reject reason.")
      .def_property_readonly("reject_counts",
                             [](const PlanResult& r) {
                               py::dict out;
                               for (std::size_t i = 0; i < kRejectReasonCount; ++i)
                                 out[to_string(static_cast<RejectReason>(i))] = r.reject_counts[i];
                               return out;
                             })
      .def_property_readonly("min_clearance", [](const PlanResult& r) { return py::array_t<double>(r.min_clearance.size(), r.min_clearance.data()); })
      .def_property_readonly("free_distance", [](const PlanResult& r) { return py::array_t<double>(r.free_distance.size(), r.free_distance.data()); })
      .def_property_readonly("moving_contact", [](const PlanResult& r) { return py::array_t<double>(r.moving_contact.size(), r.moving_contact.data()); },
                             "s, per sample: first predicted contact with a moving obstacle within moving_horizon (inf: none).")
      .def_readonly("raw", &PlanResult::raw, "(n, critics) raw terms; 0 for rejected samples.")
      .def_readonly("normalized", &PlanResult::normalized, "(n, critics) normalised terms; 0 for rejected samples.")
      .def_readonly("total", &PlanResult::total, "(n,) weighted totals; -inf for rejected samples.")
      .def("__repr__", [](const PlanResult& r) {
        std::ostringstream s;
        s << "PlanResult(status=" << to_string(r.status) << ", command=(" << r.command.v << ", " << r.command.omega
          << "), admissible=" << r.admissible_count() << "/" << r.samples.size() << ")";
        return s.str();
      });

  py::class_<LocalPlanner>(m, "LocalPlanner",
                           "The dynamic window planner: one control cycle in, one command and its diagnostics out.")
      .def(py::init<const RobotLimits&, const Footprint&, const PlannerParams&>(), py::arg("limits"),
           py::arg("footprint"), py::arg("params") = PlannerParams{})
      .def(
          "plan",
          [](LocalPlanner& p, const RobotState& state, py::handle goal, const ClearanceSource& world, py::object target) {
            const Vec2 g = to_vec2(goal, "goal");
            if (target.is_none()) return p.plan(state, g, world);
            return p.plan(state, g, to_vec2(target, "target"), world);
          },
          py::arg("state"), py::arg("goal"), py::arg("world"), py::arg("target") = py::none(),
          "One control cycle toward `goal`. The heading aims at `target` when given, else at the goal or the "
          "current key node per the params' heading_target.")
      .def(
          "set_global_path",
          [](LocalPlanner& p, py::handle path) {
            if (py::isinstance<GlobalPath>(path))
              p.set_global_path(path.cast<const GlobalPath&>());
            else
              p.set_global_path(GlobalPath(to_points(path, "path")));
          },
          py::arg("path"), "The global path to follow (a GlobalPath or (n, 2) points); resets key-node tracking.")
      .def("clear_global_path", &LocalPlanner::clear_global_path)
      .def_property_readonly("global_path", [](const LocalPlanner& p) -> py::object {
        if (!p.global_path()) return py::none();
        return py::cast(*p.global_path());
      })
      .def_property_readonly("key_nodes", &LocalPlanner::key_nodes, "Indices of the key nodes in the global path's points.")
      .def_property_readonly("needs_path", &LocalPlanner::needs_path,
                             "Whether a cycle needs a global path: the key-node heading or a critic reads it.")
      .def(
          "set_weight",
          [](LocalPlanner& p, const std::string& critic, FloatArg weight) {
            p.set_weight(critic, to_float(weight, "weight"));
          },
          py::arg("critic"), py::arg("weight"))
      .def("weight", &LocalPlanner::weight, py::arg("critic"))
      .def_property_readonly("limits", &LocalPlanner::limits)
      .def_property_readonly("footprint", &LocalPlanner::footprint)
      .def_property_readonly("params", &LocalPlanner::params)
      .def(
          "rollouts",
          [](const LocalPlanner& p) {
            const auto& rs = p.rollouts();
            const py::ssize_t n = static_cast<py::ssize_t>(rs.size());
            const py::ssize_t k = rs.empty() ? 0 : static_cast<py::ssize_t>(rs.front().size());
            py::array_t<double> out({n, k, py::ssize_t{3}});
            auto a = out.mutable_unchecked<3>();
            for (py::ssize_t i = 0; i < n; ++i)
              for (py::ssize_t j = 0; j < k; ++j) {
                const Pose2& q = rs[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
                a(i, j, 0) = q.x;
                a(i, j, 1) = q.y;
                a(i, j, 2) = q.theta;
              }
            return out;
          },
          "(samples, n_steps, 3) rollouts of the last cycle.")
      .def("__repr__", [](const LocalPlanner& p) {
        std::ostringstream s;
        s << "LocalPlanner(" << p.params().critics.size() << " critics, " << p.params().window.n_v << "x"
          << p.params().window.n_omega << " samples, dt=" << p.params().dt << ")";
        return s.str();
      });
}
