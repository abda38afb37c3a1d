#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>

#include "bind_params.hpp"
#include "convert.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/global_planner.hpp"

namespace py = pybind11;
using namespace fgdwa;
using namespace fgdwa::py_convert;

namespace {

// `params` (or the defaults) with the keyword arguments set on it by name, checked.
template <class P>
P params_with(std::optional<P> params, const py::kwargs& fields) {
  P out = params.value_or(P{});
  for (auto item : fields) set_param(out, py::str(item.first), item.second, P::kName);
  out.validate();
  return out;
}

std::optional<TerrainGrid> terrain_of(const TerrainGrid* terrain) {
  if (!terrain) return std::nullopt;
  return *terrain;
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

  bind_params<TerrainCost>(m, "TerrainCost", "Terrain risk in a global planner's cost: step length x (1 + w_risk x risk[grade]).");
  bind_params<AStarParams>(m, "AStarParams", "Grid A*: inflation, simplification, terrain and unknown-cell costs.");
  bind_params<OmplParams>(m, "OmplParams", "OMPL's planners: which, budget, seed, cost weights, output spacing.");

  py::class_<AStarPlanner>(m, "AStarPlanner",
                           "8-connected grid A* (octile heuristic, no corner cutting, inflated obstacles, optional "
                           "terrain cost = step length x (1 + w_risk x risk[grade])).")
      .def(py::init([](const OccupancyGrid& grid, std::optional<AStarParams> params, const TerrainGrid* terrain,
                       const py::kwargs& fields) {
             return AStarPlanner(grid, params_with(std::move(params), fields), terrain_of(terrain));
           }),
           py::arg("grid"), py::arg("params") = py::none(), py::arg("terrain") = nullptr,
           "params: AStarParams, or its fields as keywords (AStarPlanner(grid, inflation_radius=0.3, "
           "terrain_cost={'w_risk': 2.0})); terrain: a TerrainGrid on the grid's layout.")
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
      .def(py::init([](const OccupancyGrid& grid, const Footprint& footprint, std::optional<OmplParams> params,
                       const TerrainGrid* terrain, const py::kwargs& fields) {
             // Without a radius given, the footprint's own.
             if (!params && !fields.contains("inflation_radius")) {
               params = OmplParams{};
               params->inflation_radius = footprint.radius();
             }
             return std::make_unique<OmplPlanner>(grid, footprint, params_with(std::move(params), fields),
                                                  terrain_of(terrain));
           }),
           py::arg("grid"), py::arg("footprint"), py::arg("params") = py::none(), py::arg("terrain") = nullptr,
           "params: OmplParams, or its fields as keywords (OmplPlanner(grid, footprint, planner='PRMstar', "
           "time_limit=0.5)); without an inflation_radius, the footprint's radius; terrain: a TerrainGrid on the "
           "grid's layout.")
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
