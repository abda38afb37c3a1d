#pragma once
// The robot side of one control cycle (docs/algorithms.md, "Navigator"): the
// map, the global path kept on it, the controller, and the recovery behaviours,
// in one object a robot program steps every control period.
//
// Per step the data flows one way: scan -> moving obstacles (segmented,
// tracked, predicted) -> map (built from scans, the movers' hits left out, or
// the known one) -> (re)plan the global path when needed (no path yet, a new goal, the
// path ahead blocked, after a recovery) over a ladder of inflation radii ->
// density I and deviation D -> weights -> local planner (terrain inside) ->
// recovery -> command. Everything the cycle decided is in its CycleRecord.
//
// Lifecycle: construct once per robot; set_goal(); step() every control
// period with the robot's state and its scan; a new set_goal() starts over
// (the map built so far is kept).
#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fgdwa/controller.hpp"
#include "fgdwa/global_planner.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/mapping.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/planner.hpp"
#include "fgdwa/tracking.hpp"
#include "fgdwa/weights.hpp"

namespace fgdwa {

enum class NavigatorMode : std::uint8_t {
  Following,   // the local planner drives along the global path (or to the goal)
  Replanning,  // a new global path was planned this cycle; the planner drives on it
  BackingUp,   // straight back after a stall, while the robot's map shows the rear clear
  Rotating,    // in place toward the most open direction after a stall with the rear blocked
  Waiting,     // standing while a known moving obstacle near the robot passes
  GoalReached,
  Failed,      // see CycleRecord::failure
};
constexpr std::size_t kNavigatorModeCount = 7;

enum class FailureReason : std::uint8_t {
  None,
  NoGlobalPath,         // no path to the goal on the map, at any inflation radius
  RecoveriesExhausted,  // max_recoveries recoveries in a row without progress
};

const char* to_string(NavigatorMode mode);
const char* to_string(FailureReason reason);

// Where the navigator's map comes from.
enum class MapMode : std::uint8_t {
  Known,  // the grid given is the map; obstacles it lacks are learnt from the scans (learn_obstacles)
  Scan,   // the grid gives only the layout; the map is built from the scans' hits
};
const char* to_string(MapMode mode);

struct NavigatorParams {
  double path_margin = 0.3;
  double replan_period = 0.5;
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
  int record_top_k = 5;
  OccupancyParams occupancy;
  // Moving obstacles from the scans: hits the map does not hold as static are
  // segmented and tracked; the moving tracks are predicted by the planner
  // (space-time clearance), count in the detect window's density, can make a
  // stalled robot wait, and their hits stay out of the map built from scans.
  bool track_moving = true;
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
    v.real("path_margin", &P::path_margin, "m", distance, "kept beyond the footprint's circumscribed radius by the global path where the map allows");
    v.real("replan_period", &P::replan_period, "s", Bounds::positive(limits::kMaxHorizon), "shortest time between two replans for a blocked path");
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
    v.integer("record_top_k", &P::record_top_k, "", Bounds::closed(0, limits::kMaxWindowSamples), "best-scored rollouts kept in each CycleRecord");
    v.group("occupancy", &P::occupancy, "the map built from scans (its range_std is at least the lidar's noise_std)");
    v.flag("track_moving", &P::track_moving, "segment and track moving obstacles in the scans (false: every hit is static where it is, the ablation)");
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

// One rollout the planner scored, as recorded.
struct ScoredRollout {
  int sample = -1;  // index into the cycle's samples
  Twist command;
  double total = 0.0;  // the planner's total score
  Trajectory poses;
};

// Wall-clock time of each stage of the cycle, s.
struct StageTimes {
  double tracking = 0.0;    // segmenting the scan, updating the tracks
  double map = 0.0;         // scan into the map, distance field update
  double global = 0.0;      // path-blocked checks and global planning
  double perception = 0.0;  // sensed points, density I, deviation D, weights
  double plan = 0.0;        // the local planner
  double total() const { return tracking + map + global + perception + plan; }
};

struct CycleRecord {
  double time = 0.0;  // s, as given to step()
  RobotState state;
  Twist command;
  NavigatorMode mode = NavigatorMode::Following;
  FailureReason failure = FailureReason::None;
  Status status = Status::Ok;  // the local planner's, when it ran this cycle
  bool planned = false;        // whether the local planner ran this cycle
  Vec2 target = Vec2::Zero();  // what the heading critic aimed at
  int key_node = -1;
  double density = std::numeric_limits<double>::quiet_NaN();    // I; NaN without a scan
  double deviation = std::numeric_limits<double>::quiet_NaN();  // m, D; NaN without a global path
  double beta = std::numeric_limits<double>::quiet_NaN();       // clearance weight; NaN without that critic
  double delta = std::numeric_limits<double>::quiet_NaN();      // similarity weight; NaN without that critic
  int chosen = -1;                 // the chosen sample, -1 when none
  Trajectory chosen_rollout;       // its rollout (empty when none)
  std::vector<ScoredRollout> best; // the record_top_k best admissible rollouts, best first
  std::shared_ptr<const GlobalPath> path;  // the global path followed (null without one)
  int path_version = 0;            // bumped on every new global path
  std::array<int, kRejectReasonCount> reject_counts{};  // samples per reject reason
  std::vector<int> critic_vetoes;  // per critic of the planner (PlanResult::critic_names): samples it vetoed
  std::size_t new_cells = 0;       // map cells this scan turned occupied or free
  std::vector<Disc> tracked;       // the moving tracks the planner predicted this cycle (discs now, with velocity)
  int recoveries = 0;              // recoveries in a row without progress, this one included
  StageTimes times;
};

// Threads: one per robot and thread; nothing it owns is shared, and it
// shares nothing it may update.
class Navigator {
 public:
  // `map`: the known map (MapMode::Known) or the layout of the one to build
  // (MapMode::Scan); `terrain` (optional) on the same layout, its grades
  // scaling v_max by `passing_factors` (each in [0, 1], checked with or
  // without terrain). `lidar`: the robot's scanner, against which every scan
  // is checked. `policy` null keeps the params' weights.
  Navigator(const RobotLimits& limits, const Footprint& footprint, const PlannerParams& planner,
            const OccupancyGrid& map, MapMode mode, const LidarParams& lidar,
            std::shared_ptr<const WeightPolicy> policy = nullptr, const NavigatorParams& params = {},
            std::optional<TerrainGrid> terrain = std::nullopt,
            const PassingFactors& passing_factors = kDefaultPassingFactors, const DetectWindowParams& window = {});

  // A new goal: throws fgdwa::Error if it is not finite or lies off the map.
  // The next step() plans a path to it.
  void set_goal(const Vec2& goal);
  // Follow this path (e.g. planned by OMPL) instead of planning one; replans
  // (blocked path, stalls) still use A* on the navigator's map. After set_goal().
  void set_global_path(const GlobalPath& path);

  // One control cycle at `time` (s) from `state` with this cycle's scan (null
  // when the sensor gave none); `discs` the moving obstacles the robot knows,
  // placed now. Throws fgdwa::Error on misuse: no goal, a state or scan that is
  // not finite, a scan of another size than the lidar's.
  const CycleRecord& step(const RobotState& state, const Scan* scan, double time,
                          const std::vector<Disc>& discs = {});

  const CycleRecord& record() const { return record_; }
  const PlanResult& plan_result() const { return controller_.planner().last_result(); }
  const LocalPlanner& planner() const { return controller_.planner(); }
  const Controller& controller() const { return controller_; }
  const Tracker& tracker() const { return tracker_; }
  const OccupancyGrid& map() const;
  MapMode map_mode() const { return mode_; }
  const NavigatorParams& params() const { return params_; }
  const std::shared_ptr<const GlobalPath>& path() const { return path_; }
  int path_version() const { return path_version_; }
  // Cycles spent in each mode so far.
  const std::array<int, kNavigatorModeCount>& mode_counts() const { return mode_counts_; }
  bool has_goal() const { return has_goal_; }
  const Vec2& goal() const { return goal_; }

 private:
  bool needs_path() const;
  // A* on the map (given-up cells and the movers' sweeps closed) over the radius ladder; true if found.
  bool plan_path(const Vec2& from);
  void adopt_path(GlobalPath path);
  bool path_ahead_blocked(const Vec2& position);
  bool stalled(const RobotState& state);
  // Keeps the last stall_cycles_ + 1 positions for the progress check.
  void remember_position(const Vec2& position);
  void start_recovery(const RobotState& state, const std::vector<Disc>& discs);
  void give_up_path_ahead(const Vec2& position);
  // Closes to the global planner the cells of the scan's hits that the map lacks, near the robot.
  void close_sensed_obstacles(const Vec2& position);
  // Clearance below which the recoveries count the footprint in contact, for a robot at `pose`.
  double contact_margin(const Pose2& pose) const;
  // Whether the footprint stays clear of the robot's own view of the world moving from `pose` by `command`.
  bool step_clear(const Pose2& pose, const Twist& command) const;
  // Whether the robot, braking to a stop from `state`, stays clear of this
  // cycle's moving obstacles for `duration` (s): waiting for a mover to pass
  // is safe only where it will not come.
  bool standing_clear_of_movers(const RobotState& state, double duration) const;
  Twist backup_command(const RobotState& state);
  Twist rotate_command(const RobotState& state);
  double open_heading(const Pose2& pose) const;
  void finish_record(const RobotState& state);
  // Segments and tracks the scan's hits the map does not hold as static; sets
  // tracked_ and, per beam, whether its hit goes into the map (keep_hit_).
  void track(const Scan& scan, double time);
  // Each beam's hit point (hits_); a hit on the known map's obstacles is
  // neither segmented nor kept for the scan map (segment_mask_, keep_hit_).
  void locate_hits(const Scan& scan);
  // m: a hit this near an obstacle of the map is on it (half a cell and 3 std of range noise).
  double hit_tolerance() const;

  RobotLimits limits_;
  Footprint footprint_;
  NavigatorParams params_;
  LidarParams lidar_;
  MapMode mode_;
  double dt_;
  std::optional<TerrainGrid> terrain_;
  Controller controller_;
  Tracker tracker_;
  std::vector<Disc> discs_now_;                // the known discs and the tracked movers, this cycle
  std::vector<std::uint8_t> segment_mask_, keep_hit_;  // per beam
  std::vector<Vec2> hits_;                             // per beam, this cycle's (0 where no hit)
  std::unique_ptr<ScanMap> scan_map_;                    // MapMode::Scan
  std::unique_ptr<OccupancyGrid> known_map_;             // MapMode::Known
  std::unique_ptr<OccupancyGrid> planning_map_;          // MapMode::Known: the known map and the obstacles learnt
  std::shared_ptr<const DistanceField> known_field_;
  std::shared_ptr<DistanceField> planning_field_;         // MapMode::Known: planning_map_'s field, once it differs
  std::vector<std::uint8_t> closed_;                     // cells given up after stalls
  std::vector<double> radii_;                            // the inflation ladder, m
  bool has_goal_ = false;
  Vec2 goal_ = Vec2::Zero();
  std::shared_ptr<const GlobalPath> path_;
  int path_version_ = 0;
  int map_version_ = 0;  // bumped whenever scans change cells
  // The last blocked-path check that found the path clear: of which map and
  // path, and from which arc length (m) on.
  struct ClearCheck {
    int map_version = -1, path_version = -1;
    double from = 0.0;
  } clear_check_;
  bool replan_now_ = false;
  int replan_cycles_ = 0, stall_cycles_ = 0;
  int cycles_since_replan_ = 0;
  int rejected_cycles_ = 0;  // cycles in a row with every sample rejected
  std::deque<Vec2> recent_;  // positions of the last stall_cycles_ + 1 cycles
  NavigatorMode mode_now_ = NavigatorMode::Following;
  FailureReason failure_ = FailureReason::None;
  int recoveries_ = 0;
  Vec2 recovery_origin_ = Vec2::Zero();
  double backed_up_ = 0.0;       // m driven back in this recovery
  bool backup_braking_ = false;  // the back-up is stopping
  double rotated_ = 0.0;         // rad turned in this recovery
  double rotate_goal_ = 0.0;     // rad, the heading the rotation aims at
  int wait_cycles_left_ = 0;
  Pose2 last_pose_;
  std::array<int, kNavigatorModeCount> mode_counts_{};
  CycleRecord record_;
  std::vector<int> order_;
};

}  // namespace fgdwa
