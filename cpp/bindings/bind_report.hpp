#pragma once
// The fields of a CycleReport, bound on any class that holds one: the
// controller's report itself and the navigator's record read the same.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "convert.hpp"
#include "fgdwa/controller.hpp"

namespace fgdwa::py_convert {

template <class Class, class Get>
void bind_report_fields(Class& cls, Get report) {
  namespace py = pybind11;
  using T = typename Class::type;
  cls.def_property_readonly("status", [report](const T& t) { return report(t).status; })
      .def_property_readonly("target", [report](const T& t) {
        const Vec2& target = report(t).target;
        return std::make_pair(target.x(), target.y());
      }, "What the heading critic aimed at.")
      .def_property_readonly("key_node", [report](const T& t) { return report(t).key_node; })
      .def_property_readonly("density", [report](const T& t) { return report(t).density; }, "I; NaN without a scan.")
      .def_property_readonly("deviation", [report](const T& t) { return report(t).deviation; },
                             "D (m); NaN without a global path.")
      .def_property_readonly("beta", [report](const T& t) { return report(t).beta; },
                             "Clearance weight used; NaN without that critic.")
      .def_property_readonly("delta", [report](const T& t) { return report(t).delta; },
                             "Similarity weight used; NaN without that critic.")
      .def_property_readonly("contact_time", [report](const T& t) { return report(t).contact_time; },
                             "T (s): when the nearest moving disc would first touch the robot's circle, both keeping "
                             "their velocities; inf without one on its way.")
      .def_property_readonly("sensed_points", [report](const T& t) { return report(t).sensed_points; },
                             "Lidar hits that neither the map nor the known discs explain.")
      .def_property_readonly("live_points", [report](const T& t) { return report(t).live_points; },
                             "Lidar hits near the map's obstacles but off them along their beam by more "
                             "than the range noise explains: points the planner keeps clear of this cycle.")
      .def_property_readonly("choice", [report](const T& t) { return report(t).choice; },
                             "The chosen sample as a ScoredRollout (sample -1 when none), its per-critic scores included.")
      .def_property_readonly("chosen", [report](const T& t) { return report(t).choice.sample; },
                             "The chosen sample, -1 when none.")
      .def_property_readonly("chosen_rollout", [report](const T& t) { return poses_to_array(report(t).choice.poses); })
      .def_property_readonly("critic_names", [report](const T& t) { return report(t).critic_names; },
                             "The planner's critics: the order of raw, terms and critic_vetoes.")
      .def_property_readonly("best", [report](const T& t) { return report(t).best; },
                             "The best admissible rollouts (ScoredRollout), best first.")
      .def_property_readonly("reject_counts", [report](const T& t) {
        py::dict out;
        for (std::size_t i = 0; i < kRejectReasonCount; ++i)
          out[to_string(static_cast<RejectReason>(i))] = report(t).reject_counts[i];
        return out;
      })
      .def_property_readonly("critic_vetoes", [report](const T& t) { return report(t).critic_vetoes; },
                             "Per critic of the planner (in PlannerParams.critics order): samples it vetoed this cycle.")
      .def_property_readonly("critic_stats", [report](const T& t) { return report(t).critic_stats; },
                             "Per critic (CriticStats): min, mean and max of its term over the admissible samples.");
}

}  // namespace fgdwa::py_convert
