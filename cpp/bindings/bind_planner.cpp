#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include <cmath>

#include "bind_params.hpp"
#include "convert.hpp"
#include "fgdwa/planner.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;


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

  bind_params<WindowParams>(m, "WindowParams", "Samples of the dynamic window.");
  bind_params<KeyNodeParams>(m, "KeyNodeParams", "Key nodes of the global path: the temporary targets of GDWA.");
  bind_params<PlannerParams>(m, "PlannerParams", "Parameters of the local planner.")
      .def_property_readonly("n_steps", &PlannerParams::n_steps, "Poses per rollout: sim_time / dt, rounded.");

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
