#pragma once
// The robot side of one control cycle (docs/algorithms.md, "Navigator"): the
// map, the global path kept on it, the controller, and the recovery behaviours,
// in one object a robot program steps every control period.
//
// Per step the data flows one way through its parts: the scan, taken apart
// once (ScanFrame) -> the localiser (the scan matched to the map; the
// odometry's pose corrected onto it) -> the world model (hits on the known map set aside, the
// rest segmented and tracked, the map updated) -> recovery (stalls, backing
// up, turning, waiting for movers) -> the route keeper ((re)plan the global
// path when needed over a ladder of inflation radii) -> the controller
// (density I, deviation D, weights, local planner) -> command. The
// CycleRecord holds each stage's output.
//
// Lifecycle: construct once per robot; set_goal(); step() every control
// period with the robot's state and its scan; a new set_goal() starts over
// (the map built so far is kept).
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "fgdwa/controller.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/localiser.hpp"
#include "fgdwa/navigator_params.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/recovery.hpp"
#include "fgdwa/route_keeper.hpp"
#include "fgdwa/scan_frame.hpp"
#include "fgdwa/weights.hpp"
#include "fgdwa/world_model.hpp"

namespace fgdwa {

// Wall-clock time of each stage of the cycle, s.
struct StageTimes {
  double localise = 0.0;    // the scan matched to the map
  double tracking = 0.0;    // segmenting the scan, updating the tracks
  double map = 0.0;         // scan into the map, distance field update
  double global = 0.0;      // path-blocked checks and global planning
  double perception = 0.0;  // sensed points, density I, deviation D, weights
  double plan = 0.0;        // the local planner
  double total() const { return localise + tracking + map + global + perception + plan; }
};

struct CycleRecord {
  double time = 0.0;  // s, as given to step()
  RobotState state;    // the state planned from: its pose on the map (map_to_odom composed with the odometry's)
  Pose2 odometry;      // the pose given to step(), as the odometry has it
  Pose2 map_to_odom;   // the odometry's frame on the map after this cycle's scan (the identity until a match moves it)
  ScanMatch match;     // this cycle's scan matched to the map: accepted or why not, the scores
  Twist command;
  NavigatorMode mode = NavigatorMode::Following;
  FailureReason failure = FailureReason::None;
  RecoveryTrigger trigger = RecoveryTrigger::None;  // what started the recovery under way (or the one that failed)
  int recoveries = 0;   // recoveries in a row without progress, this one included
  bool planned = false; // whether the local planner ran this cycle
  // The controller's report when it ran; otherwise the target is the goal,
  // the deviation from the path kept, and nothing was sensed or chosen.
  CycleReport control;
  std::shared_ptr<const GlobalPath> path;  // the global path followed (null without one)
  int path_version = 0;                    // bumped on every new global path
  std::size_t new_cells = 0;  // map cells this scan turned occupied or free
  std::vector<Disc> tracked;  // the moving tracks the planner predicted this cycle (discs now, with velocity)
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

  // One control cycle at `time` (s) from `state` (its pose the odometry's,
  // in the frame of the scan's pose) with this cycle's scan (null when the
  // sensor gave none); `discs` the moving obstacles the robot knows,
  // placed now. Throws fgdwa::Error on misuse: no goal, a state or scan that is
  // not finite, a scan of another size than the lidar's.
  const CycleRecord& step(const RobotState& state, const Scan* scan, double time,
                          const std::vector<Disc>& discs = {});

  const CycleRecord& record() const { return record_; }
  const PlanResult& plan_result() const { return controller_.plan_result(); }
  const LocalPlanner& planner() const { return controller_.planner(); }
  const Controller& controller() const { return controller_; }
  const Tracker& tracker() const { return world_.tracker(); }
  const OccupancyGrid& map() const { return world_.map(); }
  const WorldModel& world_model() const { return world_; }
  const Localiser& localiser() const { return localiser_; }
  MapMode map_mode() const { return world_.mode(); }
  const NavigatorParams& params() const { return params_; }
  const std::shared_ptr<const GlobalPath>& path() const { return route_.path(); }
  int path_version() const { return route_.version(); }
  // Cycles spent in each mode so far.
  const std::array<int, kNavigatorModeCount>& mode_counts() const { return recovery_.mode_counts(); }
  bool has_goal() const { return has_goal_; }
  const Vec2& goal() const { return goal_; }

 private:
  // The controller's report for a cycle it did not run.
  void idle_report(const Vec2& position);

  RobotLimits limits_;
  Footprint footprint_;
  NavigatorParams params_;
  LidarParams lidar_;
  double dt_;
  Controller controller_;
  Localiser localiser_;
  WorldModel world_;
  RouteKeeper route_;
  Recovery recovery_;
  bool has_goal_ = false;
  double last_time_ = -std::numeric_limits<double>::infinity();  // s, the last step's: time runs forward
  bool scanned_ = false;  // a scan has come: the start's watch is set
  Vec2 goal_ = Vec2::Zero();
  int controller_path_version_ = 0;  // the route's path version the controller follows
  ScanFrame frame_;
  CycleRecord record_;
};

}  // namespace fgdwa
