#pragma once
// Cost terms of the evaluation function (Eqs. 4 and 12), one class each.
//
// Lifecycle: the planner builds its critics once from configuration by name
// (`make_critic`, from the factories given to `register_critic`), calls
// `prepare(context)` once per control cycle, then `score_all` over the
// admissible samples. A score is the raw term in the critic's declared sense:
// larger is better for a Reward, smaller for a Cost. The planner normalises
// each term (Normalization: divided by the sum of the terms' magnitudes, mapped
// to [0, 1] between their extremes, or raw) and adds weight x term for a reward
// and subtracts it for a cost, so no normalisation reverses a critic's
// preference. A critic vetoes a sample by scoring it `Critic::veto()`: the
// sample is rejected (RejectReason::Critic) and counted against that critic.
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "fgdwa/dtw.hpp"
#include "fgdwa/geometry.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/path.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {

class ClearanceSource;

// What every critic may read about the current cycle.
struct CriticContext {
  RobotState state;
  Vec2 goal = Vec2::Zero();
  Vec2 target = Vec2::Zero();  // what the heading aims at: the goal, or a key node
  double dt = 0.0;             // s, rollout step
  int n_steps = 0;
  const GlobalPath* path = nullptr;  // the global path, when the planner has one
  double v_max = 0.0;                // m/s, the robot's speed limit
  // What the planner measures clearance against, for critics that need the
  // clearance of single poses (a Rollout carries only its minimum).
  const ClearanceSource* world = nullptr;
  const Footprint* footprint = nullptr;
};

// One sampled command with what the planner measured about it.
struct Rollout {
  Twist command;
  const Trajectory* poses = nullptr;  // n_steps poses after each dt
  double min_clearance = 0.0;         // m, smallest footprint clearance over the poses
  double free_distance = 0.0;         // m, arc length before first contact, +inf if none
};

// Whether a critic's larger raw scores are better (Reward) or worse (Cost).
enum class CriticSense : std::uint8_t { Reward, Cost };
const char* to_string(CriticSense sense);

// Threads: a critic belongs to one planner; prepare() and score() write its
// scratch buffers.
class Critic {
 public:
  virtual ~Critic() = default;
  virtual std::string name() const = 0;
  virtual CriticSense sense() const { return CriticSense::Reward; }
  // The score that vetoes a sample (NaN); every other score must be finite.
  static double veto() { return std::numeric_limits<double>::quiet_NaN(); }
  static bool is_veto(double score) { return std::isnan(score); }
  virtual void prepare(const CriticContext& context) { (void)context; }
  // Whether the critic reads the global path (the planner refuses to run it without one).
  virtual bool needs_path() const { return false; }
  virtual double score(const Rollout& rollout) const = 0;
  // score() of each rollout into out[i]; critics that gain from seeing many
  // rollouts at once override it, with the same results.
  virtual void score_all(const std::vector<Rollout>& rollouts, double* out) const {
    for (std::size_t i = 0; i < rollouts.size(); ++i) out[i] = score(rollouts[i]);
  }
};

// How a critic is named in configuration: its registered name, the weight the
// planner gives it, and its own numeric parameters and word options (unknown
// keys are an error).
struct CriticConfig {
  CriticConfig() = default;
  CriticConfig(std::string name_, double weight_ = 1.0, std::map<std::string, double> params_ = {},
               std::map<std::string, std::string> options_ = {})
      : name(std::move(name_)), weight(weight_), params(std::move(params_)), options(std::move(options_)) {}

  std::string name;
  double weight = 1.0;
  std::map<std::string, double> params;
  std::map<std::string, std::string> options;
};

// pi - |angle between the final heading and the direction from the final position to the target|.
class HeadingCritic : public Critic {
 public:
  std::string name() const override { return "heading"; }
  void prepare(const CriticContext& context) override { target_ = context.target; }
  double score(const Rollout& rollout) const override;

 private:
  Vec2 target_ = Vec2::Zero();
};

struct ClearanceParams {
  double cap = 2.0;

  static constexpr const char* kName = "clearance";
  template <class V>
  static void fields(V& v) {
    v.real("cap", &ClearanceParams::cap, "m", Bounds::positive(), "clearance beyond which a rollout scores no higher (the detect window's radius)");
  }
  void validate() const { validate_params(*this); }
};

// The rollout's smallest clearance, clipped to [0, cap].
class ClearanceCritic : public Critic {
 public:
  explicit ClearanceCritic(const ClearanceParams& params = {});
  std::string name() const override { return "clearance"; }
  double score(const Rollout& rollout) const override;
  double cap() const { return cap_; }

 private:
  double cap_;
};

// The commanded forward speed.
class VelocityCritic : public Critic {
 public:
  std::string name() const override { return "velocity"; }
  double score(const Rollout& rollout) const override { return rollout.command.v; }
};

// Which speed spaces the reference samples E.
enum class ReferenceSpeed : std::uint8_t {
  // v_ref = max(v_current, v_ref_min): Eq. 9's v_r as written. A slow robot then
  // finds slow rollouts the most similar, and slows further: with a large delta
  // it crawls.
  Current,
  // v_ref = v_max: E is where a robot following the path at full speed would be,
  // so similarity rewards keeping to the path without rewarding slowness.
  Limit,
};
const char* to_string(ReferenceSpeed speed);
constexpr std::array<ReferenceSpeed, 2> enum_values(ReferenceSpeed) { return {ReferenceSpeed::Limit, ReferenceSpeed::Current}; }

// The arithmetic of the full DTW (no band; a banded one is double).
enum class DtwPrecision {
  // float, vectorised across rollouts with the widest instruction set the
  // processor has: 4-16 rollouts per instruction instead of 1-2. Positions are
  // taken relative to the robot, so a float's 7 digits hold millimetres.
  Single,
  // double, the reference the single-precision choice is tested against.
  Double,
};
const char* to_string(DtwPrecision precision);
constexpr std::array<DtwPrecision, 2> enum_values(DtwPrecision) { return {DtwPrecision::Single, DtwPrecision::Double}; }

// Eq. 11: 1 / (DTW(R, E) + 1) between the rollout's positions R and n reference
// samples E of the global path, spaced by v_ref dt.
struct SimilarityParams {
  ReferenceSampling sampling = ReferenceSampling::Polyline;
  ReferenceSpeed reference_speed = ReferenceSpeed::Limit;
  double v_ref_min = 0.1;
  int band = kNoBand;
  DtwPrecision precision = DtwPrecision::Single;

  static constexpr const char* kName = "similarity";
  template <class V>
  static void fields(V& v) {
    using P = SimilarityParams;
    v.choice("sampling", &P::sampling, "reference samples along the path's arc (polyline) or straight along its current segment (segment, Eq. 9 as written)");
    v.choice("reference_speed", &P::reference_speed, "the samples' spacing is v_ref dt with v_ref the speed limit (limit) or the current speed (current, Eq. 9 as written)");
    v.real("v_ref_min", &P::v_ref_min, "m/s", Bounds::positive(limits::kMaxSpeed), "least v_ref: keeps the samples from collapsing at standstill");
    v.integer("band", &P::band, "", Bounds::closed(kNoBand, limits::kMaxWindowSamples), "Sakoe-Chiba band of the DTW in samples (-1: the full DTW)");
    v.choice("precision", &P::precision, "arithmetic of the full DTW: single (vectorised float) or double (a banded one is double)");
  }
  void validate() const { validate_params(*this); }
};

class SimilarityCritic : public Critic {
 public:
  explicit SimilarityCritic(const SimilarityParams& params = {});
  std::string name() const override { return "similarity"; }
  bool needs_path() const override { return true; }
  void prepare(const CriticContext& context) override;
  double score(const Rollout& rollout) const override;
  void score_all(const std::vector<Rollout>& rollouts, double* out) const override;
  // The reference samples of the current cycle.
  const std::vector<Vec2>& reference() const { return reference_; }

 private:
  bool single_precision() const {
    return params_.precision == DtwPrecision::Single && params_.band == kNoBand;
  }
  // DTW of `count` rollouts, in float; out gets 1 / (DTW + 1).
  void score_f32(const Rollout* rollouts, std::size_t count, double* out) const;

  SimilarityParams params_;
  std::vector<Vec2> reference_;
  Vec2 origin_ = Vec2::Zero();  // m, the robot's position this cycle: float coordinates are taken from it
  std::vector<float> reference_x_, reference_y_;
  mutable std::vector<Vec2> positions_;
  mutable std::vector<double> batch_x_, batch_y_;
  mutable std::vector<float> batch_x_f32_, batch_y_f32_, dtw_f32_;
  mutable DtwWorkspace workspace_;
};

// Builds a critic from its configuration. A factory takes the numeric
// parameters and word options it understands out of the maps (anything left is
// an error) and throws fgdwa::Error on a bad value.
using CriticFactory = std::function<std::unique_ptr<Critic>(std::map<std::string, double>& params,
                                                            std::map<std::string, std::string>& options)>;
// Makes `name` buildable by make_critic (and so by PlannerParams::critics).
// The built-in critics are registered the same way. Throws fgdwa::Error on an
// empty name or one already registered.
void register_critic(const std::string& name, CriticFactory factory);

// Builds a critic by registered name (those above, the dwb_* ones of
// dwb_critics.hpp, and any registered since); throws fgdwa::Error on an
// unknown name, an unknown parameter or a bad value.
std::unique_ptr<Critic> make_critic(const CriticConfig& config);
// The names make_critic accepts.
std::vector<std::string> critic_names();

}  // namespace fgdwa
