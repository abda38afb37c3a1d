#pragma once
// The exact world on FCL: the static grid as merged boxes, moving discs, and the
// footprint's exact distance and collision against them. It is the simulator's
// ground truth and the reference the fast FieldClearance is checked against.
#include <memory>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {

// An axis-aligned rectangle of occupied cells, rows [row, row + rows), cols [col, col + cols).
struct CellRect {
  int row = 0;
  int col = 0;
  int rows = 0;
  int cols = 0;
};

// Covers the occupied cells exactly with disjoint rectangles: runs of a row are
// merged, then identical runs of consecutive rows are stacked.
std::vector<CellRect> merge_occupied_cells(const OccupancyGrid& grid);

// Threads: as ClearanceSource.
class CollisionWorld : public ClearanceSource {
 public:
  CollisionWorld();
  explicit CollisionWorld(const OccupancyGrid& grid, std::vector<Disc> discs = {});
  ~CollisionWorld() override;
  CollisionWorld(CollisionWorld&&) noexcept;
  CollisionWorld& operator=(CollisionWorld&&) noexcept;

  void set_discs(std::vector<Disc> discs);
  const std::vector<Disc>& discs() const;
  const std::vector<CellRect>& boxes() const;

  // Exact distance from the footprint at `pose` to the nearest obstacle, with the
  // discs moved `t` seconds ahead; 0 on contact, +inf in an empty world.
  double clearance(const Footprint& footprint, const Pose2& pose, double t) const override;
  double distance(const Footprint& footprint, const Pose2& pose, double t = 0.0) const {
    return clearance(footprint, pose, t);
  }
  bool in_collision(const Footprint& footprint, const Pose2& pose, double t = 0.0) const;
  double obstacle_speed() const override;
  double moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fgdwa
