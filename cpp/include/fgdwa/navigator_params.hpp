#pragma once
// The navigator's parameters, and where its map comes from.
#include <cstdint>

#include "fgdwa/limits.hpp"
#include "fgdwa/mapping.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/scan_matcher.hpp"
#include "fgdwa/tracking.hpp"

namespace fgdwa {

// Where the navigator's map comes from.
enum class MapMode : std::uint8_t {
  Known,  // the grid given is the map; obstacles it lacks are learnt from the scans (learn_obstacles)
  Scan,   // the grid gives only the layout; the map is built from the scans' hits
};
const char* to_string(MapMode mode);

struct NavigatorParams {
  double footprint_padding = 0.0;
  double path_margin = 0.3;
  double replan_period = 0.5;
  double retry_period = 1.0;
  double stall_time = 3.0;
  double stall_distance = 0.1;
  double give_up_length = 0.6;
  double keep_clear = 0.3;
  double sensed_close_radius = 2.0;
  double backup_distance = 0.3;
  double backup_speed = 0.2;
  double rotate_limit = 6.283185307179586;  // one turn
  double wait_time = 2.0;
  double wait_radius = 1.5;
  int max_recoveries = 6;
  double progress_reset = 1.0;
  // A robot can keep moving and get nowhere (turning to and fro among posts):
  // as Nav2's progress checker, so much movement in so much time.
  double wander_time = 10.0;
  double wander_radius = 0.5;
  int record_top_k = 5;
  OccupancyParams occupancy;
  // Odometry drifts; each scan is aligned to the map before it goes in, and
  // the robot plans at the pose the alignment gives (Localiser).
  ScanMatchParams scan_match;
  // Moving obstacles from the scans: hits the map does not hold as static are
  // segmented and tracked; the moving tracks are predicted by the planner
  // (space-time clearance), count in the detect window's density, can make a
  // stalled robot wait, and their hits stay out of the map built from scans.
  bool track_moving = true;
  // A mover is labelled after a few scans of it: a robot that drove off at
  // its first scan would meet one near its start as a static obstacle.
  double start_watch_time = 0.3;
  double mover_margin = 0.0;
  // The local planner alone cannot lead the robot round a crossing mover: it
  // scores arcs of a second or two against a path that runs through the mover.
  bool route_around_movers = true;
  double mover_route_horizon = 1.0;
  double mover_route_lookahead = 3.0;
  SegmentParams segment;
  TrackerParams tracker;
  bool learn_obstacles = true;
  double unknown_cost = 0.0;

  static constexpr const char* kName = "navigator";
  template <class V>
  static void fields(V& v) {
    using P = NavigatorParams;
    const Bounds distance = Bounds::at_least(0);
    const Bounds time = Bounds::at_least(0, limits::kMaxHorizon);
    v.real("footprint_padding", &P::footprint_padding, "m", Bounds::at_least(0, limits::kMaxFootprintRadius), "the footprint grows by this on every side for everything the navigator plans and checks (room for a body larger than its configured footprint)");
    v.real("path_margin", &P::path_margin, "m", distance, "kept beyond the footprint's circumscribed radius by the global path where the map allows");
    v.real("replan_period", &P::replan_period, "s", Bounds::positive(limits::kMaxHorizon), "shortest time between two replans for a blocked path");
    v.real("retry_period", &P::retry_period, "s", Bounds::positive(limits::kMaxHorizon), "shortest time between two global plans for a goal that had no path (set_goal() with the same goal again does not plan sooner)");
    v.real("stall_time", &P::stall_time, "s", time, "time over which too little progress is a stall (0: never stalls)");
    v.real("stall_distance", &P::stall_distance, "m", distance, "progress in stall_time below which the robot has stalled");
    v.real("give_up_length", &P::give_up_length, "m", distance, "path ahead closed to the global planner after a stall");
    v.real("keep_clear", &P::keep_clear, "m", distance, "around the robot and the goal, never closed by a stall");
    v.real("sensed_close_radius", &P::sensed_close_radius, "m", distance, "at a stall, the scan's hits the map lacks this near are closed to the global planner");
    v.real("backup_distance", &P::backup_distance, "m", distance, "driven straight back after a stall");
    v.real("backup_speed", &P::backup_speed, "m/s", Bounds::positive(limits::kMaxSpeed), "reverse speed while backing up");
    v.real("rotate_limit", &P::rotate_limit, "rad", Bounds::at_least(0, limits::kMaxAngle), "the most a rotation recovery turns");
    v.real("wait_time", &P::wait_time, "s", time, "standing still for a moving obstacle to pass");
    v.real("wait_radius", &P::wait_radius, "m", distance, "a known moving obstacle this near at a stall makes the robot wait");
    v.integer("max_recoveries", &P::max_recoveries, "", Bounds::closed(0, limits::kMaxEventCount), "recoveries in a row without progress before Failed");
    v.real("progress_reset", &P::progress_reset, "m", distance, "distance from where the last recovery began that counts as progress");
    v.real("wander_time", &P::wander_time, "s", time, "a robot following the path that stays within wander_radius of one point this long has stalled too (0: never)");
    v.real("wander_radius", &P::wander_radius, "m", distance, "how far from where it was the robot must get within wander_time");
    v.integer("record_top_k", &P::record_top_k, "", Bounds::closed(0, limits::kMaxWindowSamples), "best-scored rollouts kept in each CycleRecord");
    v.group("occupancy", &P::occupancy, "the map built from scans (its range_std is at least the lidar's noise_std)");
    v.group("scan_match", &P::scan_match, "each scan aligned to the map: the correction from the odometry's frame to the map's");
    v.flag("track_moving", &P::track_moving, "segment and track moving obstacles in the scans (false: every hit is static where it is, the ablation)");
    v.real("start_watch_time", &P::start_watch_time, "s", time, "with track_moving, the robot stands this long from its first scan, while the tracker labels what moves, unless a labelled mover comes at it");
    v.real("mover_margin", &P::mover_margin, "m", distance, "added to a tracked mover's radius: room for a mover to change its mind");
    v.flag("route_around_movers", &P::route_around_movers, "the global path keeps off the floor each mover sweeps over mover_route_horizon (false: movers reach only the local planner)");
    v.real("mover_route_horizon", &P::mover_route_horizon, "s", time, "how far ahead a mover's sweep is closed to the global planner");
    v.real("mover_route_lookahead", &P::mover_route_lookahead, "m", distance, "a sweep within the inscribed radius of this much path ahead asks for a new path");
    v.group("segment", &P::segment, "scan segmentation into clusters");
    v.group("tracker", &P::tracker, "tracks of moving obstacles");
    v.flag("learn_obstacles", &P::learn_obstacles, "with a known map, obstacles the scans find that it lacks join it (false: they reach only the local planner)");
    v.real("unknown_cost", &P::unknown_cost, "", Bounds::at_least(0, 1e6), "extra cost per metre of global path through cells the scans have not observed (0: unknown is free)");
  }
  void validate() const { validate_params(*this); }
};

}  // namespace fgdwa
