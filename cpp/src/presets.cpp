#include "fgdwa/presets.hpp"

#include <functional>
#include <map>

#include "fgdwa/error.hpp"

namespace fgdwa {

namespace {
// Table 5 / 14: alpha 0.5, beta 0.15, gamma 1; dt 0.15 s, perDT 3 s.
PlannerParams guided(double beta, double delta, bool similarity) {
  PlannerParams p;
  p.dt = 0.15;
  p.sim_time = 3.0;
  p.heading_target = HeadingTarget::KeyNodes;
  p.critics = {{"heading", 0.5}, {"clearance", beta}, {"velocity", 1.0}};
  if (similarity) p.critics.push_back({"similarity", delta});
  return p;
}

// Nav2's DWB with the scales of nav2_bringup's nav2_params.yaml: BaseObstacle
// 0.02, PathAlign 32, GoalAlign 24, PathDist 32, GoalDist 24. DWB multiplies a
// map-grid critic's scale by half the costmap resolution (MapGridCritic::getScale),
// so the weight of a cost in cells is scale * 0.05 / 2; BaseObstacle's scale is
// its weight. Key nodes only so that a global path is planned: no critic here
// reads the heading target.
PlannerParams dwb() {
  constexpr double kCostmapResolution = 0.05;  // m, the dwb_* critics' default cell
  constexpr double grid_scale = 0.5 * kCostmapResolution;
  PlannerParams p;
  p.dt = 0.15;
  p.sim_time = 3.0;
  p.heading_target = HeadingTarget::KeyNodes;
  p.normalization = Normalization::None;
  p.critics = {{"dwb_obstacle", 0.02},
               {"dwb_path_align", 32.0 * grid_scale},
               {"dwb_goal_align", 24.0 * grid_scale},
               {"dwb_path_dist", 32.0 * grid_scale},
               {"dwb_goal_dist", 24.0 * grid_scale}};
  return p;
}

const std::map<std::string, std::function<PlannerPreset()>>& presets() {
  static const std::map<std::string, std::function<PlannerPreset()>> table = {
      {"dwa",
       [] {
         PlannerParams p = guided(0.15, 0.0, false);
         p.heading_target = HeadingTarget::Goal;
         return PlannerPreset{"dwa", "classic DWA heading for the goal (Table 5 weights)", p, false};
       }},
      {"gdwa",
       [] {
         return PlannerPreset{"gdwa", "guided DWA: heading for the key nodes of the global path (Tables 5, 14)",
                              guided(0.15, 0.0, false), false};
       }},
      {"sgdwa",
       [] {
         return PlannerPreset{"sgdwa", "guided DWA with the trajectory-similarity cost (Table 6)",
                              guided(0.15, 0.5, true), false};
       }},
      {"fgdwa",
       [] {
         // Table 13: alpha 0.5 and gamma 1 fixed; beta and delta start at Table 6's
         // values and are set by the fuzzy controller from the first cycle on.
         return PlannerPreset{"fgdwa", "guided DWA with similarity, beta and delta from the fuzzy controller (Table 13)",
                              guided(0.15, 0.5, true), true};
       }},
      {"gdwa_high_safety",
       [] {
         // The top of the fuzzy controller's beta domain, held fixed.
         return PlannerPreset{"gdwa_high_safety", "guided DWA with similarity, fixed high safety weight beta = 1",
                              guided(1.0, 0.5, true), false};
       }},
      {"gdwa_high_similarity",
       [] {
         // The top of the fuzzy controller's delta domain, held fixed.
         return PlannerPreset{"gdwa_high_similarity",
                              "guided DWA with similarity, fixed high similarity weight delta = 5",
                              guided(0.15, 5.0, true), false};
       }},
      {"dwb",
       [] {
         return PlannerPreset{"dwb", "Nav2's DWB critics and scales (nav2_params.yaml), costs added unnormalised",
                              dwb(), false};
       }},
  };
  return table;
}
}  // namespace

std::shared_ptr<WeightPolicy> PlannerPreset::weight_policy() const {
  if (fuzzy) return std::make_shared<FuzzyWeights>();
  return nullptr;
}

PlannerPreset planner_preset(const std::string& name) {
  const auto& table = presets();
  auto it = table.find(name);
  if (it == table.end()) {
    std::string known;
    for (const auto& [n, f] : table) known += (known.empty() ? "" : ", ") + n;
    throw Error("unknown planner preset '" + name + "' (known: " + known + ")");
  }
  return it->second();
}

RobotPreset robot_preset(const std::string& name) {
  if (name == "default")
    return RobotPreset{"default", "fgdwa's default robot: 1.2 m/s, 1 rad/s, circle of 0.25 m", RobotLimits{},
                       Footprint::circle(0.25), Footprint::circle(0.25)};
  if (name == "jackal") {
    // Clearpath's jackal_control/config/control.yaml: linear x max_velocity 2.0 m/s,
    // max_acceleration 20 m/s^2; angular z max_velocity 4.0 rad/s, max_acceleration 25 rad/s^2.
    RobotLimits limits;
    limits.v_min = 0.0;
    limits.v_max = 2.0;
    limits.omega_max = 4.0;
    limits.acc_v = 20.0;
    limits.acc_omega = 25.0;
    // The outline: Clearpath's outer dimensions, 508 mm x 430 mm with the wheels, about base_link.
    return RobotPreset{"jackal", "Clearpath Jackal: planned as BARN's 0.42 m x 0.33 m box, body 0.508 m x 0.430 m, "
                                 "2 m/s, 4 rad/s, 20 m/s^2, 25 rad/s^2", limits,
                       Footprint::polygon({{0.21, 0.165}, {-0.21, 0.165}, {-0.21, -0.165}, {0.21, -0.165}}),
                       Footprint::polygon({{0.254, 0.215}, {-0.254, 0.215}, {-0.254, -0.215}, {0.254, -0.215}})};
  }
  throw Error("unknown robot preset '" + name + "' (known: default, jackal)");
}

std::vector<std::string> robot_names() { return {"default", "jackal"}; }

std::vector<std::string> preset_names() {
  return {"dwa", "gdwa", "sgdwa", "fgdwa", "gdwa_high_safety", "gdwa_high_similarity", "dwb"};
}

}  // namespace fgdwa
