#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bind_report.hpp"
#include "convert.hpp"
#include "fgdwa/controller.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

void init_controller(py::module_& m) {
  py::class_<ScoredRollout>(m, "ScoredRollout", "A rollout the planner scored: its sample, command, total, poses.")
      .def_readonly("sample", &ScoredRollout::sample)
      .def_readonly("command", &ScoredRollout::command)
      .def_readonly("total", &ScoredRollout::total)
      .def_property_readonly("poses", [](const ScoredRollout& r) { return poses_to_array(r.poses); })
      .def_readonly("raw", &ScoredRollout::raw, "Per critic (the report's critic_names): its raw score.")
      .def_readonly("terms", &ScoredRollout::terms,
                    "Per critic: signed weight x normalised score, its part of the total (costs negative); "
                    "they sum to total.");

  py::class_<CriticStats>(m, "CriticStats",
                          "One critic's weighted term over a cycle's admissible samples (zeros when none).")
      .def_readonly("min", &CriticStats::min)
      .def_readonly("mean", &CriticStats::mean)
      .def_readonly("max", &CriticStats::max)
      .def("__repr__", [](const CriticStats& c) {
        std::ostringstream s;
        s << "CriticStats(min=" << c.min << ", mean=" << c.mean << ", max=" << c.max << ")";
        return s.str();
      });
  py::class_<CycleReport> report(m, "CycleReport", "What a control cycle sensed, how it weighed it and what it chose.");
  report.def_readonly("command", &CycleReport::command);
  bind_report_fields(report, [](const CycleReport& r) -> const CycleReport& { return r; });
  report.def("__repr__", [](const CycleReport& r) {
    std::ostringstream s;
    s << "CycleReport(density=" << r.density << ", deviation=" << r.deviation << ", beta=" << r.beta
      << ", delta=" << r.delta << ", sensed_points=" << r.sensed_points << ", chosen=" << r.choice.sample << ")";
    return s.str();
  });

  py::class_<Controller>(m, "Controller",
                         "One control cycle as a robot runs it: scan -> obstacles the map lacks and density I; "
                         "global path -> deviation D; weight policy -> beta, delta; planner -> command.")
      .def(py::init<const RobotLimits&, const Footprint&, const PlannerParams&, std::shared_ptr<const DistanceField>,
                    std::shared_ptr<const WeightPolicy>, const DetectWindowParams&>(),
           py::arg("limits"), py::arg("footprint"), py::arg("params") = PlannerParams{}, py::arg("map") = nullptr,
           py::arg("policy") = nullptr, py::arg("window") = DetectWindowParams{})
      .def(
          "set_global_path",
          [](Controller& c, py::handle path) {
            if (py::isinstance<GlobalPath>(path))
              c.set_global_path(path.cast<const GlobalPath&>());
            else
              c.set_global_path(GlobalPath(to_points(path, "path")));
          },
          py::arg("path"))
      .def(
          "step",
          [](Controller& c, const RobotState& state, py::handle goal, const Scan* scan,
             const std::vector<Disc>& discs) -> PlanResult {
            c.step(state, to_vec2(goal, "goal"), scan, discs);
            return c.plan_result();
          },
          py::arg("state"), py::arg("goal"), py::arg("scan") = nullptr, py::arg("discs") = std::vector<Disc>{},
           "One cycle toward goal with this cycle's scan (or None) and the known moving discs placed now.")
      .def("set_map", &Controller::set_map, py::arg("map"),
           "Replaces the map's distance field (None for none), e.g. with ScanMap.field() after new cells.")
      .def_property_readonly("map", &Controller::map)
      .def_property_readonly("world", &Controller::world, py::return_value_policy::reference_internal,
                             "What the planner saw last cycle: the map's field, the sensed points and the discs.")
      .def_property_readonly("report", &Controller::report, py::return_value_policy::copy)
      .def_property_readonly("planner", &Controller::planner, py::return_value_policy::reference_internal)
      .def("__repr__", [](const Controller&) { return std::string("Controller()"); });
}
