#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bind_params.hpp"
#include "bind_report.hpp"
#include "convert.hpp"
#include "fgdwa/navigator.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

namespace {

MapMode map_mode_from_string(const std::string& name) {
  return enum_from_string("mapping", name, std::array{MapMode::Known, MapMode::Scan});
}

PassingFactors passing_factors_from(py::handle obj) {
  const auto values = float_array(obj, "passing_factors", 1, static_cast<long>(PassingFactors{}.size()));
  PassingFactors factors{};
  std::copy(values.data(), values.data() + factors.size(), factors.begin());
  return factors;
}

}  // namespace

void init_navigator(py::module_& m) {
  py::enum_<NavigatorMode> navigator_mode_enum(m, "NavigatorMode", "What the navigator is doing this cycle.");
  navigator_mode_enum
      .value("Following", NavigatorMode::Following)
      .value("Replanning", NavigatorMode::Replanning)
      .value("BackingUp", NavigatorMode::BackingUp)
      .value("Rotating", NavigatorMode::Rotating)
      .value("Waiting", NavigatorMode::Waiting)
      .value("GoalReached", NavigatorMode::GoalReached)
      .value("Failed", NavigatorMode::Failed);
  refuse_unnamed_values(navigator_mode_enum);
  py::enum_<FailureReason> failure_reason_enum(m, "FailureReason", "Why the navigator gave up.");
  failure_reason_enum
      .value("None_", FailureReason::None)
      .value("NoGlobalPath", FailureReason::NoGlobalPath)
      .value("RecoveriesExhausted", FailureReason::RecoveriesExhausted);
  refuse_unnamed_values(failure_reason_enum);
  py::enum_<RecoveryTrigger> trigger_enum(m, "RecoveryTrigger", "What started a recovery.");
  trigger_enum
      .value("None_", RecoveryTrigger::None)
      .value("NoProgress", RecoveryTrigger::NoProgress)
      .value("AllRejected", RecoveryTrigger::AllRejected)
      .value("Start", RecoveryTrigger::Start)
      .value("Wandering", RecoveryTrigger::Wandering);
  refuse_unnamed_values(trigger_enum);

  bind_params<NavigatorParams>(m, "NavigatorParams",
                                "Replanning, recovery, the map from scans and moving obstacles of a Navigator.");

  py::class_<CycleRecord> record(m, "CycleRecord", "Everything one Navigator cycle decided.");
  record.def_readonly("time", &CycleRecord::time)
      .def_readonly("state", &CycleRecord::state, "The state planned from: its pose on the map (map_to_odom composed with the odometry's).")
      .def_readonly("odometry", &CycleRecord::odometry, "The pose given to step(), as the odometry has it.")
      .def_readonly("map_to_odom", &CycleRecord::map_to_odom,
                    "The odometry's frame on the map after this cycle's scan (Pose2; the identity until a match moves it).")
      .def_readonly("match", &CycleRecord::match, "This cycle's scan matched to the map (ScanMatch).")
      .def_readonly("command", &CycleRecord::command)
      .def_readonly("mode", &CycleRecord::mode)
      .def_readonly("failure", &CycleRecord::failure)
      .def_readonly("trigger", &CycleRecord::trigger, "What started the recovery under way (or the one that failed).")
      .def_readonly("recoveries", &CycleRecord::recoveries)
      .def_readonly("planned", &CycleRecord::planned, "Whether the local planner ran this cycle.")
      .def_readonly("control", &CycleRecord::control, "The controller's report (CycleReport).")
      .def_property_readonly("path_points", [](const CycleRecord& r) -> py::object {
        if (!r.path) return py::none();
        return points_array(r.path->points());
      }, "(n, 2) points of the global path followed, None without one.")
      .def_readonly("path_version", &CycleRecord::path_version)
      .def_readonly("new_cells", &CycleRecord::new_cells)
      .def_readonly("tracked", &CycleRecord::tracked, "The moving tracks the planner predicted (Discs now, with velocity).")
      .def_property_readonly("times", [](const CycleRecord& r) {
        py::dict out;
        out["localise"] = r.times.localise;
        out["tracking"] = r.times.tracking;
        out["map"] = r.times.map;
        out["global"] = r.times.global;
        out["perception"] = r.times.perception;
        out["plan"] = r.times.plan;
        return out;
      }, "Wall-clock seconds per stage: localise, tracking, map, global, perception, plan.");
  bind_report_fields(record, [](const CycleRecord& r) -> const CycleReport& { return r.control; });
  record.def("__repr__", [](const CycleRecord& r) {
    std::ostringstream s;
    s << "CycleRecord(time=" << r.time << ", mode=" << to_string(r.mode) << ", command=(" << r.command.v << ", "
      << r.command.omega << "), path_version=" << r.path_version << ")";
    return s.str();
  });

  py::class_<Navigator>(m, "Navigator",
                        "The robot side of the control cycle: map, global path, controller and recovery in one object.")
      .def(py::init([](const RobotLimits& limits, const Footprint& footprint, const PlannerParams& params,
                       const OccupancyGrid& map, const std::string& mapping, const LidarParams& lidar,
                       std::shared_ptr<const WeightPolicy> policy, const NavigatorParams& navigator,
                       std::optional<TerrainGrid> terrain, py::handle passing_factors, const DetectWindowParams& window) {
             return std::make_unique<Navigator>(limits, footprint, params, map, map_mode_from_string(mapping), lidar,
                                                std::move(policy), navigator, std::move(terrain),
                                                passing_factors_from(passing_factors), window);
           }),
           py::arg("limits"), py::arg("footprint"), py::arg("params"), py::arg("map"), py::arg("mapping") = "known",
           py::arg("lidar") = LidarParams{}, py::arg("policy") = nullptr, py::arg("navigator") = NavigatorParams{},
           py::arg("terrain") = py::none(),
           py::arg("passing_factors") = std::vector<double>(kDefaultPassingFactors.begin(), kDefaultPassingFactors.end()),
           py::arg("window") = DetectWindowParams{},
           "map: the known map (mapping='known') or the layout of the map to build from scans (mapping='scan'); "
           "lidar: the robot's scanner (scans are checked against it); policy: a WeightPolicy or None; terrain: "
           "a TerrainGrid on the map's layout; passing_factors: v_max scale of grades 0-4.")
      .def("set_goal", [](Navigator& n, py::handle goal) { n.set_goal(to_vec2(goal, "goal")); }, py::arg("goal"))
      .def(
          "set_global_path",
          [](Navigator& n, py::handle path) {
            if (py::isinstance<GlobalPath>(path))
              n.set_global_path(path.cast<const GlobalPath&>());
            else
              n.set_global_path(GlobalPath(to_points(path, "path")));
          },
          py::arg("path"), "Follow this path (GlobalPath or (n, 2) points) instead of planning one; after set_goal().")
      .def(
          "step",
          [](Navigator& n, const RobotState& state, const Scan* scan, FloatArg time,
             const std::vector<Disc>& discs) -> const CycleRecord& {
            return n.step(state, scan, to_float(time, "time"), discs);
          },
          py::arg("state"), py::arg("scan"), py::arg("time"), py::arg("discs") = std::vector<Disc>{},
          py::return_value_policy::reference_internal,
           "One cycle from `state` with this cycle's scan (or None) at `time` (s); `discs`: known moving obstacles "
           "placed now. The record stays valid until the next step().")
      .def_property_readonly("record", &Navigator::record, py::return_value_policy::reference_internal)
      .def_property_readonly("plan_result", &Navigator::plan_result, py::return_value_policy::reference_internal,
                             "The local planner's last result, every sample included.")
      .def_property_readonly("planner", &Navigator::planner, py::return_value_policy::reference_internal)
      .def_property_readonly("controller", &Navigator::controller, py::return_value_policy::reference_internal)
      .def_property_readonly("tracker", &Navigator::tracker, py::return_value_policy::reference_internal)
      .def_property_readonly("map", &Navigator::map, py::return_value_policy::copy, "The navigator's map now (a copy).")
      .def_property_readonly("mapping", [](const Navigator& n) { return std::string(to_string(n.map_mode())); })
      .def_property_readonly("params", &Navigator::params, py::return_value_policy::copy)
      .def_property_readonly("path", [](const Navigator& n) -> py::object {
        if (!n.path()) return py::none();
        return py::cast(GlobalPath(*n.path()));
      })
      .def_property_readonly("path_version", &Navigator::path_version)
      .def_property_readonly("mode_counts", [](const Navigator& n) {
        py::dict out;
        for (std::size_t i = 0; i < kNavigatorModeCount; ++i) out[to_string(static_cast<NavigatorMode>(i))] = n.mode_counts()[i];
        return out;
      }, "Cycles spent in each mode so far.")
      .def("__repr__", [](const Navigator& n) {
        std::ostringstream s;
        s << "Navigator(mapping='" << to_string(n.map_mode()) << "', mode=" << to_string(n.record().mode) << ")";
        return s.str();
      });
}
