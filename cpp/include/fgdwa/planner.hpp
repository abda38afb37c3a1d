#pragma once
// The local planner: one control cycle in, one command and its diagnostics out.
//
// Data flows one way per cycle: window -> samples -> rollouts -> clearance and
// admissibility -> critics -> normalise -> best command. The planner owns its
// buffers, so a cycle allocates nothing once the first one has run.
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "fgdwa/clearance.hpp"
#include "fgdwa/critics.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/robot.hpp"
#include "fgdwa/window.hpp"

namespace fgdwa {

enum class Status : std::uint8_t {
  Ok,                    // a command was chosen among admissible samples
  NoAdmissibleVelocity,  // every sample was rejected: the command brakes
  GoalReached,           // within goal_tolerance of the goal: the command brakes
  Evading,               // every sample meets a moving obstacle soon, standing still too: the command is the
                         // one (among those the static obstacles admit) after which the robot can get
                         // away best: its best continuation meets a mover or a wall latest
};

enum class RejectReason : std::uint8_t {
  None,       // admissible
  Collision,  // the rollout touches an obstacle before the robot could stop
  Terrain,    // the footprint enters grade-4 terrain before the robot could stop
  Critic,     // a critic vetoed it (PlanResult::vetoed_by names which)
  Moving,     // a moving obstacle is predicted to meet it within moving_horizon (braking cannot help)
};
constexpr std::size_t kRejectReasonCount = 5;

// How slope grades 0-4 limit the robot: each grade's passing factor
// scales v_max on its cells; grade 4 cannot be entered at all.
using PassingFactors = std::array<double, TerrainGrid::kMaxGrade + 1>;
constexpr PassingFactors kDefaultPassingFactors = {1.0, 0.8, 0.6, 0.4, 0.0};
// Throws fgdwa::Error unless every factor lies in [0, 1].
void validate_passing_factors(const PassingFactors& factors);

enum class Normalization : std::uint8_t {
  // Each term divided by the sum of its magnitudes over the admissible samples
  // (classic DWA's sum for the usual non-negative terms).
  Sum,
  MinMax,  // each term mapped to [0, 1] over the admissible samples
  // Raw terms as they are, total = sum of weight * raw: how Nav2's DWB adds its
  // critics (scale * cost), which only works with terms on agreed scales.
  None,
};

// What the heading critic aims at (docs/algorithms.md, "Global guidance").
enum class HeadingTarget : std::uint8_t {
  Goal,      // the goal itself: plain DWA
  KeyNodes,  // the first key node of the global path not yet reached: GDWA
};

// How the wheels take a new command, in the rollouts' first steps.
enum class WheelModel : std::uint8_t {
  Ramp,     // from the measured twist toward the command at the acceleration limits, as a robot's wheels do
  Instant,  // the command from the period's start, as an ideal simulated body does
};

const char* to_string(Status status);
const char* to_string(HeadingTarget target);
const char* to_string(WheelModel wheels);
constexpr std::array<WheelModel, 2> enum_values(WheelModel) { return {WheelModel::Ramp, WheelModel::Instant}; }
const char* to_string(RejectReason reason);
const char* to_string(Normalization normalization);
constexpr std::array<Normalization, 3> enum_values(Normalization) {
  return {Normalization::Sum, Normalization::MinMax, Normalization::None};
}
constexpr std::array<HeadingTarget, 2> enum_values(HeadingTarget) { return {HeadingTarget::Goal, HeadingTarget::KeyNodes}; }

struct PlannerParams {
  double dt = 0.15;
  double sim_time = 3.0;
  WindowParams window;
  Normalization normalization = Normalization::Sum;
  BrakingModel braking = BrakingModel::Discrete;
  WheelModel wheels = WheelModel::Instant;
  double response_time = 0.0;
  double goal_tolerance = 0.3;
  double safety_margin = 0.02;
  // A robot that brakes is still hit by what moves into it, so standing
  // still is judged against moving obstacles too.
  double moving_horizon = 1.0;
  // A constant-velocity prediction is trusted over so many metres of the
  // fastest mover's travel: among fast movers the rejection looks less far
  // ahead, and the clearance critic weighs what lies beyond.
  double moving_reach = 2.0;
  // A mover may turn or reverse; a slower robot keeps the time to answer it.
  double mover_caution_radius = 2.0;
  double mover_speed_weight = 0.5;
  // The braking rule (Eq. 3) admits a rollout that meets a wall after the
  // robot could have stopped; noise in the wheels or a map a few centimetres
  // off spends that room, so a rollout that stays clear is taken first.
  bool prefer_clear = true;
  HeadingTarget heading_target = HeadingTarget::Goal;
  KeyNodeParams key_nodes;
  std::vector<CriticConfig> critics = {
      {"heading", 0.5}, {"clearance", 0.15}, {"velocity", 1.0}};  // Table 5

  static constexpr const char* kName = "planner";
  template <class V>
  static void fields(V& v) {
    using P = PlannerParams;
    v.real("dt", &P::dt, "s", Bounds::closed(limits::kMinTimeStep, limits::kMaxTimeStep), "control period and rollout step");
    v.real("sim_time", &P::sim_time, "s", Bounds::positive(limits::kMaxHorizon), "rollout horizon (the paper's perDT)");
    v.group("window", &P::window, "samples of the dynamic window");
    v.choice("normalization", &P::normalization, "how each critic's terms are scaled before weighting: sum (classic DWA), minmax, or none (raw, as Nav2's DWB adds them)");
    v.choice("braking", &P::braking, "admissibility's braking rule (Eq. 3): discrete (one period of latency, stepped deceleration) or continuous (the paper's literal form)");
    v.choice("wheels", &P::wheels, "how a rollout's first steps reach the sampled velocity: ramp (from the measured twist at the acceleration limits, as a robot's wheels do) or instant (at once, as an ideal simulated body does)");
    v.real("response_time", &P::response_time, "s", Bounds::closed(0, 1), "with wheels ramp: time constant of the first-order lag with which the wheels follow a command on top of the ramp, as the robot's identified response (0: the ramp alone)");
    v.real("goal_tolerance", &P::goal_tolerance, "m", Bounds::at_least(0), "GoalReached within this distance of the goal");
    v.real("safety_margin", &P::safety_margin, "m", Bounds::at_least(0), "clearance below which a rollout counts as in contact (never more than the robot's own)");
    v.real("moving_horizon", &P::moving_horizon, "s", Bounds::at_least(0, limits::kMaxHorizon), "a rollout predicted to meet a moving obstacle this soon is rejected, standing still included (0: only the braking rule counts movers)");
    v.real("moving_reach", &P::moving_reach, "m", Bounds::at_least(0, limits::kMaxHorizon), "the rejection's horizon is at most the time the fastest mover (speed plus growth) takes to travel this far (0: moving_horizon alone)");
    v.real("mover_caution_radius", &P::mover_caution_radius, "m", Bounds::at_least(0), "while a moving obstacle is this near the footprint, the velocity critic's weight is scaled by mover_speed_weight");
    v.real("mover_speed_weight", &P::mover_speed_weight, "", Bounds::closed(0, 1), "the velocity critic's weight factor beside a mover (1: no change)");
    v.flag("prefer_clear", &P::prefer_clear, "choose among the admissible samples whose rollouts stay off the fixed world (to where they first come within the contact margin) when there are any, the others (admitted by the braking rule) only when there are none; an evasion among the samples whose rollouts keep the margin to their end when there are any (false: among all, as the paper)");
    v.choice("heading_target", &P::heading_target, "what the heading critic aims at: goal (DWA) or key_nodes (GDWA: the first key node of the global path not yet reached)");
    v.group("key_nodes", &P::key_nodes, "key nodes of the global path, for heading_target key_nodes");
    v.critics("critics", &P::critics, "the critics scored, each {name, weight, params} (default heading 0.5, clearance 0.15, velocity 1.0)");
  }
  // sim_time covers 1 to limits::kMaxRolloutSteps steps of dt; at least one critic, none twice.
  void check_relations(const ParamPath& path) const;

  // Poses per rollout: sim_time / dt, rounded.
  int n_steps() const;
  void validate() const { validate_params(*this); }
};

// m: how much closer a robot already within a millimetre of an obstacle (or
// overlapping one) may come in one control cycle.
inline constexpr double kContactSlack = 1e-6;

// The clearance (m) below which a motion of a robot with clearance `clearance`
// counts as contact: the safety margin, never more than the room the robot has
// less a millimetre; within a millimetre, the clearance less kContactSlack, and
// the same when overlapping by a measured depth (a negative clearance, as a
// circle's distance field gives): it may then turn and move away, but not close
// in. At a clearance of exactly zero (where a polygon's or FCL's clearance stops)
// the margin is zero: only leaving contact at once is allowed.
double contact_margin(double clearance, double safety_margin);

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

struct PlanResult {
  Status status = Status::Ok;
  Twist command;
  int best_index = -1;         // index into samples, -1 when no sample was chosen
  Vec2 target = Vec2::Zero();  // what the heading critic aimed at
  int key_node = -1;           // index of the target in the key nodes, -1 when aiming at the goal
  std::vector<std::string> critic_names;
  std::vector<double> weights;                  // per critic, this cycle
  std::vector<Twist> samples;                   // n_v x n_omega, v-major
  std::vector<RejectReason> reasons;            // per sample
  std::vector<double> min_clearance;            // m, per sample, until the rollout reaches the goal
  std::vector<double> free_distance;            // m, per sample (+inf: never touches)
  std::vector<double> moving_contact;           // s, per sample: first predicted contact with a moving obstacle
                                                // within moving_horizon (+inf: none)
  std::vector<int> vetoed_by;                   // per sample: the critic that vetoed it, -1 for none
  std::vector<int> critic_vetoes;               // per critic: samples it vetoed this cycle
  std::vector<CriticSense> senses;              // per critic
  Matrix raw;                                   // samples x critics, 0 for rejected samples
  Matrix normalized;                            // samples x critics, 0 for rejected samples (raw with Normalization::None)
  std::vector<double> signed_weights;           // per critic: the factor of its normalised score in the total
                                                // (negative for a cost; the velocity critic's eased near movers)
  Eigen::VectorXd total;                        // sum over critics of signed_weights x normalized; -inf if rejected
  std::array<int, kRejectReasonCount> reject_counts{};  // samples per reason
  int admissible_count() const { return reject_counts[0]; }
};

// Threads: one planner per thread. plan() writes its buffers and result, so
// a planner is never shared while planning; the world it is given may be
// shared (ClearanceSource).
class LocalPlanner {
 public:
  LocalPlanner(const RobotLimits& limits, const Footprint& footprint, const PlannerParams& params = {});

  // One control cycle from `state` toward `goal`, the heading aiming at the goal
  // or at the current key node per `heading_target`. The reference stays valid
  // until the next call.
  const PlanResult& plan(const RobotState& state, const Vec2& goal, const ClearanceSource& world);
  // The same with the heading's target given by the caller.
  const PlanResult& plan(const RobotState& state, const Vec2& goal, const Vec2& target, const ClearanceSource& world);

  // The global path to follow; resets the key-node tracking. HeadingTarget::KeyNodes
  // needs one; the path-aware critics read it.
  void set_global_path(const GlobalPath& path);
  void clear_global_path();

  // Slope terrain on the map's layout (null for none): a rollout whose footprint
  // enters a grade-4 cell before it could stop is rejected (RejectReason::Terrain),
  // and the window's top speed is the passing factor of the cell under the robot
  // times v_max, so the command is one the robot can make there.
  void set_terrain(std::shared_ptr<const TerrainGrid> terrain, const PassingFactors& factors = kDefaultPassingFactors);
  const std::shared_ptr<const TerrainGrid>& terrain() const { return terrain_; }
  const GlobalPath* global_path() const { return path_.get(); }
  // Whether a cycle needs a global path: the key-node heading or a critic reads it.
  bool needs_path() const;
  const std::vector<std::size_t>& key_nodes() const;

  bool has_critic(const std::string& critic) const;
  // Weight of a critic by name, e.g. set each cycle by a weight policy.
  void set_weight(const std::string& critic, double weight);
  double weight(const std::string& critic) const;

  const RobotLimits& limits() const { return limits_; }
  const Footprint& footprint() const { return footprint_; }
  const PlannerParams& params() const { return params_; }
  const PlanResult& last_result() const { return result_; }
  // Every sample's rollout of the last cycle.
  const std::vector<Trajectory>& rollouts() const { return rollouts_; }

 private:
  std::size_t critic_index(const std::string& name) const;
  void evaluate_rollouts(const RobotState& state, const Vec2& goal, const ClearanceSource& world);
  void score_and_choose(const CriticContext& context);
  const PlanResult& run_cycle(const RobotState& state, const Vec2& goal, const Vec2& target, int key_node,
                              const ClearanceSource& world);

  RobotLimits limits_;
  Footprint footprint_;
  PlannerParams params_;
  int n_steps_;
  std::vector<std::unique_ptr<Critic>> critics_;
  std::vector<Trajectory> rollouts_;
  std::vector<double> bounds_, exact_;
  std::vector<double> at_least_;  // per pose: a clearance it is known to reach without its exact value
  std::vector<RolloutHeadings> headings_;  // per omega of the window
  // rollouts_[first], rollouts_[first + stride], ...: the samples turning as
  // the first does, from headings_[first].
  void rollouts_sharing(const Pose2& start, std::size_t first, std::size_t stride);
  // Each row of the window (one v, `row` samples) ramps from `v_now` toward
  // its v the same way: the signed length of every step, the distance
  // travelled after k steps and what its first period does.
  struct SpeedProfile {
    double reached = 0.0;  // m/s, v at the end of the first period
    double first = 0.0;    // m, the first period's travel
    double longest = 0.0;  // m, the longest step
  };
  void speed_profiles(double v_now, std::size_t row, bool instant);
  std::vector<double> lengths_;  // rows x steps
  std::vector<double> travel_;   // rows x (steps + 1), from 0
  std::vector<SpeedProfile> profiles_;
  std::vector<double> fixed_clearance_;  // per sample: its rollout's least clearance from the fixed world (movers apart)
  // Whether sample i's rollout stays off the fixed world up to its first pose
  // within the contact margin (or its end, or the goal): the admissible choice.
  bool stays_off(std::size_t i) const { return fixed_clearance_[i] > 0.0; }
  // Whether it keeps the contact margin to its end (or the goal), no braking
  // needed: the evasion's choice.
  bool keeps_clear(std::size_t i) const { return fixed_clearance_[i] > margin_; }
  std::vector<double> escape_;  // per sample: clearance to the movers at the end of the horizon
  std::vector<double> shallowest_;  // per sample: its least clearance to the movers within the horizon
  double moving_horizon_ = 0.0;  // s, this cycle's: moving_horizon, shortened by moving_reach
  double mover_speed_ = 0.0;     // m/s, this cycle's world's fastest obstacle (speed plus growth)
  // The velocity critic's index (none: past the end), and the weights this
  // cycle scores with (its weight scaled while a mover is near).
  std::size_t speed_critic_ = std::numeric_limits<std::size_t>::max();
  std::vector<double> cycle_weights_;
  std::vector<Rollout> admissible_;  // this cycle's admissible rollouts, for the critics
  std::vector<std::size_t> admissible_index_;
  std::vector<double> scores_;
  // The first pose at which the footprint enters grade-4 terrain, n_steps_ if
  // none; `centre_only` holds only the centre to it (a footprint already over it).
  int first_terrain_contact(const Trajectory& poses, bool centre_only) const;
  // The smallest of `below` and the footprint's clearance to grade-4 terrain over poses 0..last.
  double impassable_clearance(const Trajectory& poses, int last, double below) const;
  // Time (s) at which the rollout first comes into contact with a moving
  // obstacle of `world`, within moving_horizon; +inf if it does not.
  // `at_start`: the start's clearance to them. `closest`: its smallest
  // clearance to them over the start and poses 0..last; `escape`: its
  // clearance to them at the last pose within moving_horizon. Both are exact
  // below `fixed_clearance` (the rollout's least clearance to the fixed
  // world, which the caller takes the least of with each) and elsewhere at
  // least that. `shallowest`: its least clearance to them over the start and
  // the poses up to the last within moving_horizon, exact when it meets them.
  double first_moving_contact(const Twist& cmd, const Trajectory& poses, const ClearanceSource& world,
                              double margin, int last, double at_start, double fixed_clearance, double& closest,
                              double& escape, double& shallowest) const;
  // A contact between two poses a period apart leaves one of them within half
  // the relative motion of the step: the robot's drive and turn at `twist` and
  // the obstacles' travel at `obstacle_speed` (m/s).
  double half_step_motion(const Twist& twist, double obstacle_speed) const;
  // How well a robot can get away after one period of a sample: the latest
  // first contact (s, +inf: none within the rollout) with a mover or a wall
  // over continuations that head for kEscapeTargets^2 commands spread over the
  // whole velocity range at the acceleration limits, then the most room (m) to
  // the movers along it. A sample that meets a mover within its first period
  // has no continuation that helps: its room is its own least clearance to
  // the movers within the horizon (the shallowest way in wins).
  struct Escape {
    double contact = -std::numeric_limits<double>::infinity();
    double room = -std::numeric_limits<double>::infinity();
  };
  static constexpr int kEscapeTargets = 5;
  // The continuations' turns after one period of a sample, per turn target:
  // each step's turn rate and heading with its cos and sin. They depend on
  // the sample's turn alone (its heading after the period and the rate its
  // wheels reach), so one set serves a whole column of the window's samples;
  // worked out again for another heading or rate.
  struct EscapeTurns {
    double theta0 = std::numeric_limits<double>::quiet_NaN(), omega0 = std::numeric_limits<double>::quiet_NaN();
    std::vector<double> omega, theta, cos, sin;  // [target * n_steps + step]
  };
  // One Escape per ranking: [0] against the movers' grown discs, [1] against
  // where they most likely go (likely_moving_clearance).
  using Escapes = std::array<Escape, 2>;
  // The first `passes` rankings of sample i (1: the grown discs alone).
  // Continuations that cannot beat a ranking's rival (the best of the samples
  // before, contact -inf for none) are left unfinished there: the result then
  // falls short of the rival's, as the finished one would.
  void escape_after(std::size_t i, const ClearanceSource& world, int passes, const Escapes& rivals,
                    EscapeTurns& turns, Escapes& out) const;
  // Among the samples rejected only for a moving obstacle, the one whose best
  // continuation meets a mover or a wall latest (then keeps the most room, then
  // is farthest from the movers at the horizon); -1 if there is none. Judged
  // against the movers' grown discs, or, when no way escapes those within the
  // horizon, against where they most likely go.
  int best_evasion(const ClearanceSource& world) const;
  double margin_ = 0.0;  // this cycle's contact margin (m)
  Twist start_twist_;    // this cycle's measured twist, where every rollout starts
  double response_ = 0.0;  // s, the wheels' lag the rollouts model (0 with instant wheels)

  std::shared_ptr<const TerrainGrid> terrain_;
  PassingFactors passing_factors_ = kDefaultPassingFactors;
  std::unique_ptr<FieldClearance> impassable_;  // grade-4 cells as obstacles
  std::unique_ptr<GlobalPath> path_;
  std::unique_ptr<KeyNodeTracker> tracker_;
  PlanResult result_;
};

}  // namespace fgdwa
