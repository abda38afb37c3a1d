#pragma once
// What the robot knows of its surroundings, one scan at a time: the scan's
// hits on the known map's obstacles set aside, the rest segmented and tracked,
// the movers' hits kept out of the map, and the map itself (built from the
// scans, or the known one with the obstacles the scans found) with its
// distance field.
//
// Lifecycle: construct once per robot with the map; update() every cycle;
// field() when the planners need the map's distances.
#include <cstdint>
#include <memory>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/mapping.hpp"
#include "fgdwa/navigator_params.hpp"
#include "fgdwa/robot.hpp"
#include "fgdwa/scan_frame.hpp"
#include "fgdwa/tracking.hpp"

namespace fgdwa {

// What one scan changed in the robot's view of the world.
struct WorldUpdate {
  std::vector<Disc> tracked;  // the moving tracks (discs now, with velocity, mover_margin added)
  std::vector<Disc> movers;   // the known discs and the tracked: every mover the cycle plans around
  std::size_t new_cells = 0;  // map cells this scan turned occupied or free
  double tracking_time = 0.0;  // s, wall clock: segmenting and tracking
  double map_time = 0.0;       // s, wall clock: the scan into the map
};

// Threads: one per robot; the fields it hands out may be shared (an update
// goes to a copy while someone else holds one).
class WorldModel {
 public:
  // `edge_margin` (m): how far past the grid's edge the distance fields keep free space.
  WorldModel(const OccupancyGrid& map, MapMode mode, const NavigatorParams& params, const LidarParams& lidar,
             const Footprint& footprint, double edge_margin);

  // This cycle's scan (null without one) at `time` (s), and the moving
  // obstacles the robot is told of, placed now.
  const WorldUpdate& update(const ScanFrame* frame, double time, const std::vector<Disc>& discs);

  // The map the global planner plans on.
  const OccupancyGrid& map() const;
  // The map given with MapMode::Known, without what the scans added; null for a map built from scans.
  const OccupancyGrid* given_map() const { return known_map_.get(); }
  // Its distance field, brought up to date (null while a map built from scans
  // has seen nothing). Let go of the last one first and it is updated in place.
  std::shared_ptr<const DistanceField> field();
  // Bumped whenever a scan changes cells.
  int version() const { return version_; }
  // Per cell, 1 where no scan has looked yet; empty unless the map is built from scans.
  std::vector<std::uint8_t> unknown_cells() const;
  MapMode mode() const { return mode_; }
  // m: how far beyond its reading the map marks a hit (2 std of range noise).
  double hit_depth() const { return 2.0 * range_std_; }
  const Tracker& tracker() const { return tracker_; }
  const WorldUpdate& last() const { return update_; }

 private:
  // Each beam's hit on the known map's obstacles is neither segmented nor kept
  // for the scan map (segment_mask_, keep_hit_).
  void set_aside_known(const ScanFrame& frame);
  // Segments and tracks the hits left; a hit on a mover stays out of the map.
  void track(const ScanFrame& frame, double time);
  // m: a hit this near an obstacle of the map is on it (half a cell and 3 std of range noise).
  double hit_tolerance() const;

  NavigatorParams params_;
  double noise_std_;
  double range_std_;  // the map's: at least the lidar's noise
  Footprint footprint_;
  MapMode mode_;
  Tracker tracker_;
  std::unique_ptr<ScanMap> scan_map_;              // MapMode::Scan, or learning obstacles on a known map
  std::unique_ptr<OccupancyGrid> known_map_;       // MapMode::Known
  std::unique_ptr<OccupancyGrid> planning_map_;    // MapMode::Known: the known map and the obstacles learnt
  std::shared_ptr<const DistanceField> known_field_;
  std::shared_ptr<DistanceField> planning_field_;  // MapMode::Known: planning_map_'s field, once it differs
  bool has_field_ = false;
  bool field_stale_ = false;  // cells changed since field() last ran
  int version_ = 0;
  std::vector<std::uint8_t> segment_mask_, keep_hit_;  // per beam
  WorldUpdate update_;
};

}  // namespace fgdwa
