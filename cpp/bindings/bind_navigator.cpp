#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

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

  py::class_<NavigatorParams>(m, "NavigatorParams", "Replanning and recovery settings of a Navigator (SPEC 13).")
      .def(py::init([](FloatArg path_margin, FloatArg replan_period, FloatArg stall_time, FloatArg stall_distance,
                       FloatArg give_up_length, FloatArg keep_clear, FloatArg sensed_close_radius,
                       FloatArg backup_distance, FloatArg backup_speed, FloatArg rotate_limit_deg, FloatArg wait_time,
                       FloatArg wait_radius, IntArg max_recoveries, FloatArg progress_reset, IntArg record_top_k,
                       const OccupancyParams& occupancy, FloatArg unknown_cost, bool track_moving,
                       const SegmentParams& segment, const TrackerParams& tracker, bool learn_obstacles,
                       FloatArg mover_margin, bool route_around_movers, FloatArg mover_route_horizon,
                       FloatArg mover_route_lookahead) {
             NavigatorParams p;
             p.path_margin = to_float(path_margin, "path_margin");
             p.replan_period = to_float(replan_period, "replan_period");
             p.stall_time = to_float(stall_time, "stall_time");
             p.stall_distance = to_float(stall_distance, "stall_distance");
             p.give_up_length = to_float(give_up_length, "give_up_length");
             p.keep_clear = to_float(keep_clear, "keep_clear");
             p.sensed_close_radius = to_float(sensed_close_radius, "sensed_close_radius");
             p.backup_distance = to_float(backup_distance, "backup_distance");
             p.backup_speed = to_float(backup_speed, "backup_speed");
             p.rotate_limit =
                 radians_from_degrees("rotate_limit_deg", to_float(rotate_limit_deg, "rotate_limit_deg"), 0.0, 36000.0);
             p.wait_time = to_float(wait_time, "wait_time");
             p.wait_radius = to_float(wait_radius, "wait_radius");
             p.max_recoveries =
                 to_int<int>(max_recoveries, "max_recoveries", 0, static_cast<int>(limits::kMaxEventCount));
             p.progress_reset = to_float(progress_reset, "progress_reset");
             p.record_top_k =
                 to_int<int>(record_top_k, "record_top_k", 0, static_cast<int>(limits::kMaxWindowSamples));
             p.occupancy = occupancy;
             p.unknown_cost = to_float(unknown_cost, "unknown_cost");
             p.track_moving = track_moving;
             p.segment = segment;
             p.tracker = tracker;
             p.learn_obstacles = learn_obstacles;
             p.mover_margin = to_float(mover_margin, "mover_margin");
             p.route_around_movers = route_around_movers;
             p.mover_route_horizon = to_float(mover_route_horizon, "mover_route_horizon");
             p.mover_route_lookahead = to_float(mover_route_lookahead, "mover_route_lookahead");
             p.validate();
             return p;
           }),
           py::arg("path_margin") = 0.3, py::arg("replan_period") = 0.5, py::arg("stall_time") = 3.0,
           py::arg("stall_distance") = 0.1, py::arg("give_up_length") = 0.6, py::arg("keep_clear") = 0.3,
           py::arg("sensed_close_radius") = 2.0, py::arg("backup_distance") = 0.3, py::arg("backup_speed") = 0.2,
           py::arg("rotate_limit_deg") = 360.0,
           py::arg("wait_time") = 2.0, py::arg("wait_radius") = 1.5, py::arg("max_recoveries") = 6,
           py::arg("progress_reset") = 1.0, py::arg("record_top_k") = 5,
           py::arg("occupancy") = OccupancyParams(), py::arg("unknown_cost") = 0.0, py::arg("track_moving") = true,
           py::arg("segment") = SegmentParams(), py::arg("tracker") = TrackerParams(), py::arg("learn_obstacles") = true,
           py::arg("mover_margin") = 0.0, py::arg("route_around_movers") = true, py::arg("mover_route_horizon") = 1.0,
           py::arg("mover_route_lookahead") = 3.0,
           "path_margin: m kept beyond the footprint's radius by the global path where the map allows; "
           "replan_period: s between replans for a blocked path; stall_time: s over which less than stall_distance "
           "(m) of progress is a stall (0: never); give_up_length: m of path ahead closed to the global planner after "
           "a stall, except within keep_clear (m) of the robot and the goal; sensed_close_radius (m): at a stall, the "
           "scan's hits the map lacks this near are closed to the global planner too; backup_distance (m) at backup_speed "
           "(m/s); rotate_limit_deg: the most a rotation recovery turns; wait_time (s) for a known moving obstacle "
           "within wait_radius (m); max_recoveries in a row without progress_reset (m) of progress before Failed; "
           "record_top_k: best rollouts kept in each CycleRecord; occupancy: the map built from scans (its range_std "
           "is at least the lidar's noise_std); unknown_cost: extra cost per metre of the global path through cells the "
           "scans have not observed (0: unknown is free); track_moving: segment and track moving obstacles in the scans, "
           "predict them in the planner and keep their hits out of the map (False: every hit is static where it is, "
           "the ablation); segment, tracker: their settings; learn_obstacles: with a known map, obstacles the scans find "
           "that it lacks join it (False: they reach only the local planner, and the global one at a stall); mover_margin "
           "(m): added to a tracked mover's radius; route_around_movers: the global path keeps off the floor each "
           "moving obstacle sweeps over the next mover_route_horizon (s) at its predicted velocity, and a sweep within "
           "the footprint's inscribed radius of the path's next mover_route_lookahead (m) asks for a new path (False: "
           "movers reach only the local planner).")
      .def_readonly("path_margin", &NavigatorParams::path_margin)
      .def_readonly("replan_period", &NavigatorParams::replan_period)
      .def_readonly("stall_time", &NavigatorParams::stall_time)
      .def_readonly("stall_distance", &NavigatorParams::stall_distance)
      .def_readonly("give_up_length", &NavigatorParams::give_up_length)
      .def_readonly("keep_clear", &NavigatorParams::keep_clear)
      .def_readonly("sensed_close_radius", &NavigatorParams::sensed_close_radius)
      .def_readonly("backup_distance", &NavigatorParams::backup_distance)
      .def_readonly("backup_speed", &NavigatorParams::backup_speed)
      .def_property_readonly("rotate_limit_deg", [](const NavigatorParams& p) { return p.rotate_limit * 180.0 / M_PI; })
      .def_readonly("wait_time", &NavigatorParams::wait_time)
      .def_readonly("wait_radius", &NavigatorParams::wait_radius)
      .def_readonly("max_recoveries", &NavigatorParams::max_recoveries)
      .def_readonly("progress_reset", &NavigatorParams::progress_reset)
      .def_readonly("record_top_k", &NavigatorParams::record_top_k)
      .def_readonly("occupancy", &NavigatorParams::occupancy)
      .def_readonly("unknown_cost", &NavigatorParams::unknown_cost)
      .def_readonly("track_moving", &NavigatorParams::track_moving)
      .def_readonly("segment", &NavigatorParams::segment)
      .def_readonly("tracker", &NavigatorParams::tracker)
      .def_readonly("learn_obstacles", &NavigatorParams::learn_obstacles)
      .def_readonly("mover_margin", &NavigatorParams::mover_margin)
      .def_readonly("route_around_movers", &NavigatorParams::route_around_movers)
      .def_readonly("mover_route_horizon", &NavigatorParams::mover_route_horizon)
      .def_readonly("mover_route_lookahead", &NavigatorParams::mover_route_lookahead)
      .def("__repr__", [](const NavigatorParams& p) {
        std::ostringstream s;
        s << "NavigatorParams(stall_time=" << p.stall_time << ", backup_distance=" << p.backup_distance
          << ", max_recoveries=" << p.max_recoveries << ", replan_period=" << p.replan_period << ")";
        return s.str();
      });

  py::class_<ScoredRollout>(m, "ScoredRollout", "A rollout the planner scored: its sample, command, total, poses.")
      .def_readonly("sample", &ScoredRollout::sample)
      .def_readonly("command", &ScoredRollout::command)
      .def_readonly("total", &ScoredRollout::total)
      .def_property_readonly("poses", [](const ScoredRollout& r) { return poses_to_array(r.poses); });

  py::class_<CycleRecord>(m, "CycleRecord", "Everything one Navigator cycle decided.")
      .def_readonly("time", &CycleRecord::time)
      .def_readonly("state", &CycleRecord::state)
      .def_readonly("command", &CycleRecord::command)
      .def_readonly("mode", &CycleRecord::mode)
      .def_readonly("failure", &CycleRecord::failure)
      .def_readonly("status", &CycleRecord::status)
      .def_readonly("planned", &CycleRecord::planned, "Whether the local planner ran this cycle.")
      .def_property_readonly("target", [](const CycleRecord& r) { return std::make_pair(r.target.x(), r.target.y()); })
      .def_readonly("key_node", &CycleRecord::key_node)
      .def_readonly("density", &CycleRecord::density)
      .def_readonly("deviation", &CycleRecord::deviation)
      .def_readonly("beta", &CycleRecord::beta)
      .def_readonly("delta", &CycleRecord::delta)
      .def_readonly("chosen", &CycleRecord::chosen)
      .def_property_readonly("chosen_rollout", [](const CycleRecord& r) { return poses_to_array(r.chosen_rollout); })
      .def_readonly("best", &CycleRecord::best)
      .def_property_readonly("path_points", [](const CycleRecord& r) -> py::object {
        if (!r.path) return py::none();
        return points_array(r.path->points());
      }, "(n, 2) points of the global path followed, None without one.")
      .def_readonly("path_version", &CycleRecord::path_version)
      .def_property_readonly("reject_counts", [](const CycleRecord& r) {
        py::dict out;
        for (std::size_t i = 0; i < kRejectReasonCount; ++i) out[to_string(static_cast<RejectReason>(i))] = r.reject_counts[i];
        return out;
      })
      .def_readonly("critic_vetoes", &CycleRecord::critic_vetoes,
                    "Per critic of the planner (in PlannerParams.critics order): samples it vetoed this cycle.")
      .def_readonly("new_cells", &CycleRecord::new_cells)
      .def_readonly("tracked", &CycleRecord::tracked, "The moving tracks the planner predicted (Discs now, with velocity).")
      .def_readonly("recoveries", &CycleRecord::recoveries)
      .def_property_readonly("times", [](const CycleRecord& r) {
        py::dict out;
        out["tracking"] = r.times.tracking;
        out["map"] = r.times.map;
        out["global"] = r.times.global;
        out["perception"] = r.times.perception;
        out["plan"] = r.times.plan;
        return out;
      }, "Wall-clock seconds per stage: map, global, perception, plan.")
      .def("__repr__", [](const CycleRecord& r) {
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
