#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "convert.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/global_planner.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

namespace {
TerrainCost terrain_cost(double w_risk, py::handle risk) {
  TerrainCost cost;
  cost.w_risk = w_risk;
  auto r = float_array(risk, "risk", 1, 4);
  for (std::size_t g = 0; g < 4; ++g) cost.risk[g] = r.data()[g];
  cost.validate();
  return cost;
}

}  // namespace

void init_global_planner(py::module_& m) {
  py::enum_<GlobalStatus> global_status_enum(m, "GlobalStatus", "Outcome of a global planning query.");
  global_status_enum
      .value("Found", GlobalStatus::Found)
      .value("NoPath", GlobalStatus::NoPath)
      .value("Timeout", GlobalStatus::Timeout);
  refuse_unnamed_values(global_status_enum);

  py::class_<GlobalPlan>(m, "GlobalPlan", "A global planner's result: status, (n, 2) path, cost, planning time (s).")
      .def_readonly("status", &GlobalPlan::status)
      .def_property_readonly("path", [](const GlobalPlan& p) { return points_array(p.path); })
      .def_readonly("cost", &GlobalPlan::cost)
      .def_readonly("planning_time", &GlobalPlan::planning_time)
      .def_property_readonly("found", [](const GlobalPlan& p) { return p.status == GlobalStatus::Found; })
      .def("__repr__", [](const GlobalPlan& p) {
        std::ostringstream s;
        s << "GlobalPlan(status=" << to_string(p.status) << ", points=" << p.path.size() << ", cost=" << p.cost
          << ", planning_time=" << p.planning_time << ")";
        return s.str();
      });

  m.def(
      "inflate",
      [](const OccupancyGrid& grid, FloatArg inflation_radius, const TerrainGrid* terrain) {
        auto blocked = inflate(grid, to_float(inflation_radius, "inflation_radius"), terrain);
        py::array_t<std::uint8_t> out({grid.rows(), grid.cols()});
        std::copy(blocked.begin(), blocked.end(), out.mutable_data());
        return out;
      },
      py::arg("grid"), py::arg("inflation_radius"), py::arg("terrain") = nullptr,
      "(rows, cols) uint8, 1 where a robot of that radius cannot centre: obstacles, cells nearer than the "
      "radius to one, and grade-4 terrain.");

  py::class_<AStarPlanner>(m, "AStarPlanner",
                           "8-connected grid A* (octile heuristic, no corner cutting, inflated obstacles, optional "
                           "terrain cost = step length x (1 + w_risk x risk[grade])).")
      .def(py::init([](const OccupancyGrid& grid, FloatArg inflation_radius, bool simplify, const TerrainGrid* terrain,
                       FloatArg w_risk, py::handle risk, FloatArg unknown_cost) {
             AStarParams params;
             params.inflation_radius = to_float(inflation_radius, "inflation_radius");
             params.simplify = simplify;
             params.terrain = terrain_cost(to_float(w_risk, "w_risk"), risk);
             params.unknown_cost = to_float(unknown_cost, "unknown_cost");
             std::optional<TerrainGrid> t;
             if (terrain) t = *terrain;
             return AStarPlanner(grid, params, t);
           }),
           py::arg("grid"), py::arg("inflation_radius") = 0.25, py::arg("simplify") = true,
           py::arg("terrain") = nullptr, py::arg("w_risk") = 1.0,
           py::arg("risk") = py::make_tuple(0.0, 0.5, 1.0, 2.0), py::arg("unknown_cost") = 0.0,
           "unknown_cost: extra cost per metre through the cells set_unknown() marks (a step costs 1 + unknown_cost "
           "times more).")
      .def(
          "set_unknown",
          [](AStarPlanner& p, py::object unknown) {
            if (unknown.is_none()) return p.set_unknown({});
            const auto a = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(unknown);
            if (!a || a.ndim() != 2 || a.shape(0) != p.grid().rows() || a.shape(1) != p.grid().cols())
              throw Error("unknown: expected a (rows, cols) array of the grid's shape");
            p.set_unknown(std::vector<std::uint8_t>(a.data(), a.data() + a.size()));
          },
          py::arg("unknown"), "Which cells are unknown ((rows, cols), nonzero = unknown; None for none).")
      .def(
          "plan",
          [](const AStarPlanner& p, py::handle start, py::handle goal) {
            return p.plan(to_vec2(start, "start"), to_vec2(goal, "goal"));
          },
          py::arg("start"), py::arg("goal"))
      .def_property_readonly("blocked", [](const AStarPlanner& p) {
        py::array_t<std::uint8_t> out({p.grid().rows(), p.grid().cols()});
        std::copy(p.blocked().begin(), p.blocked().end(), out.mutable_data());
        return out;
      })
      .def("__repr__", [](const AStarPlanner& p) {
        std::ostringstream s;
        s << "AStarPlanner(" << p.grid().rows() << "x" << p.grid().cols()
          << ", inflation_radius=" << p.params().inflation_radius << ")";
        return s.str();
      });

  py::class_<OmplPlanner>(m, "OmplPlanner",
                          "OMPL's sampling-based planners over the same map, with a weighted cost of path length, "
                          "clearance and terrain risk; seeded and time-bounded.")
      .def(py::init([](const OccupancyGrid& grid, const Footprint& footprint, const std::string& planner,
                       FloatArg time_limit, FloatArg range, IntArg max_iterations, IntArg seed,
                       py::object inflation_radius, FloatArg w_length, FloatArg w_clearance,
                       FloatArg clearance_reference, const TerrainGrid* terrain, FloatArg w_risk, py::handle risk,
                       bool simplify, FloatArg interpolation, bool verbose) {
             OmplParams params;
             params.planner = planner;
             params.time_limit = to_float(time_limit, "time_limit");
             params.range = to_float(range, "range");
             params.max_iterations = to_int<std::uint32_t>(max_iterations, "max_iterations");
             params.seed = to_int<std::uint32_t>(seed, "seed");
             params.inflation_radius = inflation_radius.is_none() ? footprint.radius() : to_number(inflation_radius, "inflation_radius");
             params.w_length = to_float(w_length, "w_length");
             params.w_clearance = to_float(w_clearance, "w_clearance");
             params.clearance_reference = to_float(clearance_reference, "clearance_reference");
             params.terrain = terrain_cost(to_float(w_risk, "w_risk"), risk);
             params.simplify = simplify;
             params.interpolation = to_float(interpolation, "interpolation");
             params.verbose = verbose;
             std::optional<TerrainGrid> t;
             if (terrain) t = *terrain;
             return std::make_unique<OmplPlanner>(grid, footprint, params, t);
           }),
           py::arg("grid"), py::arg("footprint"), py::arg("planner") = "RRTstar", py::arg("time_limit") = 1.0,
           py::arg("range") = 1.0, py::arg("max_iterations") = 0, py::arg("seed") = 0, py::arg("inflation_radius") = py::none(), py::arg("w_length") = 1.0,
           py::arg("w_clearance") = 0.5, py::arg("clearance_reference") = 1.0, py::arg("terrain") = nullptr,
           py::arg("w_risk") = 1.0, py::arg("risk") = py::make_tuple(0.0, 0.5, 1.0, 2.0), py::arg("simplify") = true,
           py::arg("interpolation") = 0.1, py::arg("verbose") = false)
      .def(
          "plan",
          [](const OmplPlanner& p, py::handle start, py::handle goal) {
            const Vec2 s = to_vec2(start, "start"), g = to_vec2(goal, "goal");
            py::gil_scoped_release release;
            return p.plan(s, g);
          },
          py::arg("start"), py::arg("goal"))
      .def_static("planner_names", &OmplPlanner::planner_names);
}
