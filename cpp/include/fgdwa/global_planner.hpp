#pragma once
// Global planners (docs/algorithms.md, "Global guidance"): grid A* and OMPL's
// sampling-based planners, with one result type. No path is a status; a start
// or goal inside an obstacle is misuse and throws.
#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fgdwa/grid.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {

enum class GlobalStatus : std::uint8_t { Found, NoPath, Timeout };
const char* to_string(GlobalStatus status);

struct GlobalPlan {
  GlobalStatus status = GlobalStatus::NoPath;
  std::vector<Vec2> path;      // m, start to goal; empty unless Found
  double cost = 0.0;           // the planner's own cost of the path
  double planning_time = 0.0;  // s, wall clock
};

// Terrain risk in the cost: step length x (1 + w_risk x risk[grade]); grade 4 is impassable.
struct TerrainCost {
  double w_risk = 1.0;
  std::array<double, 4> risk = {0.0, 0.5, 1.0, 2.0};

  static constexpr const char* kName = "terrain_cost";
  template <class V>
  static void fields(V& v) {
    v.real("w_risk", &TerrainCost::w_risk, "", Bounds::at_least(0, 1e6), "weight of the terrain risk in the cost");
    v.reals("risk", &TerrainCost::risk, "", Bounds::at_least(0, 1e6), "risk of grades 0-3 (grade 4 is impassable)");
  }
  void validate() const { validate_params(*this); }
  double multiplier(int grade) const { return 1.0 + w_risk * risk[static_cast<std::size_t>(grade)]; }
};

// Cells a robot of `inflation_radius` cannot centre on: occupied and grade-4
// cells, and cells whose centre is nearer than the radius to the square of
// either (the local planner keeps the footprint off both). Row-major, 1 = blocked.
std::vector<std::uint8_t> inflate(const OccupancyGrid& grid, double inflation_radius,
                                  const TerrainGrid* terrain = nullptr);

// Whether the segment a-b crosses only cells (of `layout`'s cell layout) for
// which `free(row, col)` holds: an exact grid traversal, and where the segment
// passes exactly through a cell corner both cells beside it must be free.
// Cells outside the grid are not free.
bool segment_free(const OccupancyGrid& layout, const Vec2& a, const Vec2& b,
                  const std::function<bool(int, int)>& free);

struct AStarParams {
  double inflation_radius = 0.25;
  bool simplify = true;
  TerrainCost terrain_cost;
  double unknown_cost = 0.0;

  static constexpr const char* kName = "astar";
  template <class V>
  static void fields(V& v) {
    using P = AStarParams;
    v.real("inflation_radius", &P::inflation_radius, "m", Bounds::at_least(0), "cells nearer an obstacle than this are closed (usually the footprint's radius)");
    v.flag("simplify", &P::simplify, "shortcut the cell path by line of sight");
    v.group("terrain_cost", &P::terrain_cost, "step cost through terrain: length x (1 + w_risk x risk[grade])");
    v.real("unknown_cost", &P::unknown_cost, "", Bounds::at_least(0, 1e6), "extra cost per metre through cells the map has not observed (set_unknown; 0: unknown is free)");
  }
  void validate() const { validate_params(*this); }
};

// 8-connected A* over cell centres with the octile heuristic. A diagonal step
// needs both cells beside it free (no corner cutting). Ties are broken by the
// smaller heuristic, then the smaller cell index, so results are reproducible.
// The start and goal cells may lie in the inflated band (a robot parked near a
// wall) but not in an obstacle; from a start in the band, the band's cells
// within the inflation radius of the start are passable, so the path can leave it.
// Threads: plan() is const and keeps its search state on the stack, so
// threads may share a planner; set_unknown() may not run concurrently.
class AStarPlanner {
 public:
  AStarPlanner(const OccupancyGrid& grid, const AStarParams& params = {},
               std::optional<TerrainGrid> terrain = std::nullopt);

  GlobalPlan plan(const Vec2& start, const Vec2& goal) const;
  // Which cells are unknown (row-major, 1 = unknown; empty for none), priced
  // by AStarParams::unknown_cost. Throws fgdwa::Error on a size other than the grid's.
  void set_unknown(std::vector<std::uint8_t> unknown);

  const OccupancyGrid& grid() const { return grid_; }
  const std::vector<std::uint8_t>& blocked() const { return blocked_; }
  const AStarParams& params() const { return params_; }
  // Whether the straight segment a-b crosses only free cells whose grade is at
  // most `max_grade`.
  bool line_of_sight(const Vec2& a, const Vec2& b, int max_grade) const;

 private:
  int grade(std::size_t cell) const;
  // The cost per metre of a step into the cell, relative to flat known ground.
  double multiplier(std::size_t cell) const;
  // Whether the segment a-b crosses only free cells no dearer than `dearest`.
  bool shortcut_clear(const Vec2& a, const Vec2& b, double dearest) const;
  OccupancyGrid grid_;
  std::vector<std::uint8_t> unknown_;
  AStarParams params_;
  std::optional<TerrainGrid> terrain_;
  std::vector<std::uint8_t> blocked_;
};

struct OmplParams {
  std::string planner = "RRTstar";
  double time_limit = 1.0;
  double range = 1.0;
  std::uint32_t max_iterations = 0;
  std::uint32_t seed = 0;
  double inflation_radius = 0.25;
  double w_length = 1.0;
  double w_clearance = 0.5;
  double clearance_reference = 1.0;
  TerrainCost terrain_cost;
  bool simplify = true;
  double interpolation = 0.1;
  bool verbose = false;

  static constexpr const char* kName = "ompl";
  template <class V>
  static void fields(V& v) {
    using P = OmplParams;
    const Bounds count = Bounds::closed(0, 4294967295.0);
    const Bounds weight = Bounds::at_least(0, 1e6);
    v.text("planner", &P::planner, "RRTstar, InformedRRTstar, PRMstar, BITstar or RRTConnect");
    v.real("time_limit", &P::time_limit, "s", Bounds::positive(limits::kMaxHorizon), "planning time budget");
    v.real("range", &P::range, "m", Bounds::at_least(0), "longest tree edge of the planners that have one (0: OMPL's default)");
    v.integer("max_iterations", &P::max_iterations, "", count, "stop after this many planner iterations too (0: time only)");
    v.integer("seed", &P::seed, "", count, "with max_iterations binding, the same seed gives the same path (a time budget alone lets the machine's speed decide)");
    v.real("inflation_radius", &P::inflation_radius, "m", Bounds::at_least(0), "for a circle footprint: cells nearer an obstacle than this are closed");
    v.real("w_length", &P::w_length, "", weight, "weight of path length in the cost");
    v.real("w_clearance", &P::w_clearance, "", weight, "weight of the clearance cost");
    v.real("clearance_reference", &P::clearance_reference, "m", Bounds::positive(), "clearance beyond which a state costs nothing");
    v.group("terrain_cost", &P::terrain_cost, "terrain risk in the cost (its weight: terrain_cost.w_risk)");
    v.flag("simplify", &P::simplify, "OMPL's path simplifier");
    v.real("interpolation", &P::interpolation, "m", Bounds::closed(limits::kMinResolution, limits::kMaxLength), "spacing of the interpolated output path");
    v.flag("verbose", &P::verbose, "OMPL's console output");
  }
  // planner is one OMPL knows; some weight of the cost is positive.
  void check_relations(const ParamPath& path) const;
  void validate() const { validate_params(*this); }
};

// OMPL over the same inflated grid (and, for a polygon footprint, the exact
// footprint against the map with FCL, planning over SE(2)). The cost is a
// weighted sum of OMPL objectives: path length, a clearance integral and a
// terrain-risk integral.
// Threads: plan() may be called from several threads; OMPL's global state
// is guarded by a lock, so such calls run one at a time.
class OmplPlanner {
 public:
  OmplPlanner(const OccupancyGrid& grid, const Footprint& footprint, const OmplParams& params = {},
              std::optional<TerrainGrid> terrain = std::nullopt);
  ~OmplPlanner();
  OmplPlanner(OmplPlanner&&) noexcept;
  OmplPlanner& operator=(OmplPlanner&&) noexcept;

  GlobalPlan plan(const Vec2& start, const Vec2& goal) const;
  static std::vector<std::string> planner_names();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgdwa
