#pragma once
// The global path the robot follows and when to plan it anew: when there is
// none, after a recovery, and (every replan_period) when the map or a mover's
// sweep blocks the stretch ahead. Paths are planned by A* over a ladder of
// inflation radii, with the cells given up after stalls and the floor movers
// will sweep closed.
//
// Lifecycle: set_goal() with every new goal; update() every cycle.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "fgdwa/global_planner.hpp"
#include "fgdwa/navigator_params.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/robot.hpp"
#include "fgdwa/world_model.hpp"

namespace fgdwa {

// Threads: one per robot; the paths it hands out never change.
class RouteKeeper {
 public:
  // `map`: the layout of the robot's map; `terrain` (optional) on that layout.
  RouteKeeper(const OccupancyGrid& map, const Footprint& footprint, const NavigatorParams& params, double dt,
              std::optional<TerrainGrid> terrain);

  // A new goal: no path, nothing given up; the next update() plans (for the
  // goal the last plan found no path to, not before retry_period has passed).
  void set_goal(const Vec2& goal);
  // Follows `path` from now on.
  void adopt(GlobalPath path);
  // One cycle at `position`. With `follow` (the local planner drives on a
  // path this cycle), plans when there is no path, a replan was asked for, or
  // the path ahead is blocked. False when there is no path at all.
  bool update(const Vec2& position, bool follow, WorldModel& world, const std::vector<Disc>& movers);
  // Plans anew before the planner next drives.
  void request_replan() { replan_now_ = true; }
  // After a stall: the path ahead, and the scan's hits (`sensed`) the map
  // lacks near `position`, are closed to the global planner.
  void give_up_ahead(const Vec2& position, const std::vector<Vec2>& sensed, const OccupancyGrid& map);

  const std::shared_ptr<const GlobalPath>& path() const { return path_; }
  // Bumped on every new path.
  int version() const { return version_; }

 private:
  // A* on the map with the given-up cells and the movers' sweeps closed, over
  // the radius ladder; true if found. Off the map, from its nearest point.
  bool plan(const Vec2& position, WorldModel& world, const std::vector<Disc>& movers);
  bool ahead_blocked(const Vec2& position, WorldModel& world, const std::vector<Disc>& movers);

  Footprint footprint_;
  NavigatorParams params_;
  std::optional<TerrainGrid> terrain_;
  std::vector<double> radii_;           // the inflation ladder, m
  std::vector<std::uint8_t> closed_;    // cells given up after stalls
  int replan_cycles_;
  int cycles_since_replan_ = 0;
  // The goal the last plan found no path to, and the cycles since: the same
  // goal is planned for again only retry_cycles_ later, however often it is set.
  std::optional<Vec2> unreachable_;
  int retry_cycles_;
  int cycles_since_no_path_ = 0;
  bool replan_now_ = false;
  Vec2 goal_ = Vec2::Zero();
  std::shared_ptr<const GlobalPath> path_;
  int version_ = 0;
  // The last blocked-path check that found the path clear: of which map and
  // path, and from which arc length (m) on.
  struct ClearCheck {
    int map_version = -1, path_version = -1;
    double from = 0.0;
  } clear_check_;
};

}  // namespace fgdwa
