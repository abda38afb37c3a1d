#pragma once
// A map the robot builds as it goes: it starts empty and every lidar hit marks
// its cell occupied. This is how a robot without a prior map (BARN's setting)
// gives its global planner and its local planner the obstacles it has seen so
// far, including those now behind it or hidden by nearer ones.
//
// Lifecycle: construct with the layout of the map to build; integrate() every
// scan; field() when the planners need distances (updated around new cells only).
// Cells are never cleared: the map suits static worlds.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "fgdwa/geometry.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/perception.hpp"

namespace fgdwa {

class ScanMap {
 public:
  ScanMap(int rows, int cols, double resolution, Vec2 origin);
  // An empty map with the layout of `like`.
  explicit ScanMap(const OccupancyGrid& like);

  // Marks the cells of the scan's hits (hits outside the layout are dropped);
  // returns how many cells became occupied.
  std::size_t integrate(const Scan& scan);
  // Marks the cells holding these points; returns how many became occupied.
  std::size_t mark(const std::vector<Vec2>& points);

  // The map so far.
  const OccupancyGrid& grid() const { return grid_; }
  // Its distance field, brought up to date on the first call after new cells
  // (only the cells near them are recomputed).
  std::shared_ptr<const DistanceField> field();
  // Cells marked since construction.
  std::size_t occupied_count() const { return occupied_; }

 private:
  bool mark_point(const Vec2& p);
  // Publishes the marked cells in grid(); returns `added`.
  std::size_t commit(std::size_t added);

  OccupancyGrid grid_;
  std::vector<std::uint8_t> cells_;
  std::size_t occupied_ = 0;
  bool stale_ = true;
  std::shared_ptr<const DistanceField> field_;
};

// Whether the path ahead of `position` passes closer than `clearance` to an
// obstacle of `field`: the path from its point nearest `position` onward,
// checked every half cell. The part behind the robot does not count.
bool path_blocked(const GlobalPath& path, const Vec2& position, const DistanceField& field, double clearance);

}  // namespace fgdwa
