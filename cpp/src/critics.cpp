#include "fgdwa/critics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <mutex>

#include "fgdwa/dwb_critics.hpp"
#include "validation.hpp"

namespace fgdwa {

double HeadingCritic::score(const Rollout& rollout) const {
  const Pose2& last = rollout.poses->back();
  const Vec2 to_target = target_ - last.position();
  if (to_target.squaredNorm() == 0.0) return M_PI;
  const double bearing = std::atan2(to_target.y(), to_target.x());
  return M_PI - std::abs(angle_difference(bearing, last.theta));
}

ClearanceCritic::ClearanceCritic(const ClearanceParams& params) : cap_(params.cap) { params.validate(); }

double ClearanceCritic::score(const Rollout& rollout) const {
  return std::clamp(rollout.min_clearance, 0.0, cap_);
}

const char* to_string(ReferenceSpeed speed) {
  switch (speed) {
    case ReferenceSpeed::Current: return "current";
    case ReferenceSpeed::Limit: return "limit";
  }
  return "?";
}

const char* to_string(DtwPrecision precision) {
  switch (precision) {
    case DtwPrecision::Single: return "single";
    case DtwPrecision::Double: return "double";
  }
  return "?";
}

SimilarityCritic::SimilarityCritic(const SimilarityParams& params) : params_(params) { params_.validate(); }

void SimilarityCritic::prepare(const CriticContext& context) {
  if (!context.path) throw Error("critic 'similarity' needs a global path");
  const double v_ref = params_.reference_speed == ReferenceSpeed::Limit ? std::max(context.v_max, params_.v_ref_min)
                                                             : std::max(context.state.twist.v, params_.v_ref_min);
  reference_samples(*context.path, context.state.pose.position(), v_ref, context.dt, context.n_steps,
                    params_.sampling, reference_);
  origin_ = context.state.pose.position();
  reference_x_.resize(reference_.size());
  reference_y_.resize(reference_.size());
  for (std::size_t j = 0; j < reference_.size(); ++j) {
    reference_x_[j] = static_cast<float>(reference_[j].x() - origin_.x());
    reference_y_[j] = static_cast<float>(reference_[j].y() - origin_.y());
  }
}

void SimilarityCritic::score_f32(const Rollout* rollouts, std::size_t count, double* out) const {
  const std::size_t n = rollouts[0].poses->size();
  batch_x_f32_.resize(n * count);
  batch_y_f32_.resize(n * count);
  for (std::size_t k = 0; k < count; ++k) {
    const Trajectory& poses = *rollouts[k].poses;
    for (std::size_t i = 0; i < n; ++i) {
      batch_x_f32_[i * count + k] = static_cast<float>(poses[i].x - origin_.x());
      batch_y_f32_[i * count + k] = static_cast<float>(poses[i].y - origin_.y());
    }
  }
  dtw_f32_.resize(count);
  workspace_.distance_batch_f32_unchecked(batch_x_f32_.data(), batch_y_f32_.data(), n, count, reference_x_.data(),
                                reference_y_.data(), reference_x_.size(), dtw_f32_.data());
  for (std::size_t k = 0; k < count; ++k) out[k] = 1.0 / (static_cast<double>(dtw_f32_[k]) + 1.0);
}

double SimilarityCritic::score(const Rollout& rollout) const {
  if (single_precision() && !rollout.poses->empty()) {
    double out;
    score_f32(&rollout, 1, &out);
    return out;
  }
  const Trajectory& poses = *rollout.poses;
  positions_.resize(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) positions_[i] = poses[i].position();
  return 1.0 / (workspace_.distance(positions_, reference_, params_.band) + 1.0);
}

void SimilarityCritic::score_all(const std::vector<Rollout>& rollouts, double* out) const {
  if (params_.band != kNoBand) {
    Critic::score_all(rollouts, out);
    return;
  }
  // Batches of rollouts side by side: the DTW recurrence of one rollout is a
  // chain of dependent steps, several rollouts in step keep the processor busy
  // (128 floats: 8 to 32 vectors, whatever the instruction set; with the
  // two rows of the programme, about 40 kB for 20 poses and 20 samples).
  constexpr std::size_t kBatch = 128;
  for (std::size_t first = 0; first < rollouts.size(); first += kBatch) {
    const std::size_t count = std::min(kBatch, rollouts.size() - first);
    const std::size_t n = rollouts[first].poses->size();
    bool same_length = true;
    for (std::size_t k = 1; k < count; ++k) same_length = same_length && rollouts[first + k].poses->size() == n;
    if (!same_length || n == 0) {
      for (std::size_t k = 0; k < count; ++k) out[first + k] = score(rollouts[first + k]);
      continue;
    }
    if (single_precision()) {
      score_f32(&rollouts[first], count, out + first);
      continue;
    }
    batch_x_.resize(n * count);
    batch_y_.resize(n * count);
    for (std::size_t k = 0; k < count; ++k) {
      const Trajectory& poses = *rollouts[first + k].poses;
      for (std::size_t i = 0; i < n; ++i) {
        batch_x_[i * count + k] = poses[i].x;
        batch_y_[i * count + k] = poses[i].y;
      }
    }
    workspace_.distance_batch(batch_x_.data(), batch_y_.data(), n, count, reference_.data(), reference_.size(),
                              out + first);
    for (std::size_t k = 0; k < count; ++k) out[first + k] = 1.0 / (out[first + k] + 1.0);
  }
}

namespace {
using Params = std::map<std::string, double>;
using Options = std::map<std::string, std::string>;

// A critic's parameters from its configuration's numbers and words, by its
// schema: what is read is taken out, so what is left over was misspelt.
template <class P>
struct ConfigReader {
  const std::string& critic;
  Params& numbers;
  Options& words;
  P& out;

  std::string where(const char* name) const { return "critic " + critic + ": " + name; }
  void real(const char* name, double P::*member, const char*, Bounds, const char*) {
    const auto it = numbers.find(name);
    if (it == numbers.end()) return;
    out.*member = it->second;
    numbers.erase(it);
  }
  template <class I>
  void integer(const char* name, I P::*member, const char*, Bounds bounds, const char*) {
    const auto it = numbers.find(name);
    if (it == numbers.end()) return;
    const double x = it->second;
    numbers.erase(it);
    if (x != std::floor(x)) throw Error(detail::describe(where(name), x, "must be a whole number"));
    if (!bounds.contains(x)) fail_param(where(name), x, bounds, "");
    out.*member = static_cast<I>(x);
  }
  template <class E>
  void choice(const char* name, E P::*member, const char*) {
    const auto it = words.find(name);
    if (it == words.end()) return;
    const std::string word = it->second;
    words.erase(it);
    std::string known;
    for (const E value : enum_values(E{})) {
      if (word == to_string(value)) {
        out.*member = value;
        return;
      }
      known += (known.empty() ? "'" : ", '") + std::string(to_string(value)) + "'";
    }
    throw Error(where(name) + " = '" + word + "': expected one of " + known);
  }
};

template <class P>
P critic_params(const std::string& critic, Params& numbers, Options& words) {
  P params;
  ConfigReader<P> reader{critic, numbers, words, params};
  P::fields(reader);
  params.validate();
  return params;
}

using Factory = CriticFactory;

std::mutex& registry_mutex() {
  static std::mutex mutex;
  return mutex;
}

// A critic of type T built from its parameters P.
template <class T, class P>
Factory made_from(const std::string& critic) {
  return [critic](Params& p, Options& o) -> std::unique_ptr<Critic> {
    return std::make_unique<T>(critic_params<P>(critic, p, o));
  };
}

// The map-grid critics; only the align ones look ahead of the last pose.
template <class T>
Factory dwb_grid(const std::string& critic, bool forward_point) {
  return [critic, forward_point](Params& p, Options& o) -> std::unique_ptr<Critic> {
    if (!forward_point && p.count("forward_point_distance"))
      throw Error("critic '" + critic + "' has no parameter 'forward_point_distance'");
    return std::make_unique<T>(critic_params<DwbGridParams>(critic, p, o));
  };
}

std::map<std::string, Factory>& registry() {
  static std::map<std::string, Factory> factories = {
      {"heading", [](Params&, Options&) { return std::make_unique<HeadingCritic>(); }},
      {"clearance", made_from<ClearanceCritic, ClearanceParams>("clearance")},
      {"velocity", [](Params&, Options&) { return std::make_unique<VelocityCritic>(); }},
      {"similarity", made_from<SimilarityCritic, SimilarityParams>("similarity")},
      {"dwb_obstacle", made_from<DwbObstacleCritic, DwbObstacleParams>("dwb_obstacle")},
      {"dwb_path_dist", dwb_grid<DwbPathDistCritic>("dwb_path_dist", false)},
      {"dwb_goal_dist", dwb_grid<DwbGoalDistCritic>("dwb_goal_dist", false)},
      {"dwb_path_align", dwb_grid<DwbPathAlignCritic>("dwb_path_align", true)},
      {"dwb_goal_align", dwb_grid<DwbGoalAlignCritic>("dwb_goal_align", true)},
  };
  return factories;
}
}  // namespace

const char* to_string(CriticSense sense) {
  switch (sense) {
    case CriticSense::Reward: return "reward";
    case CriticSense::Cost: return "cost";
  }
  return "?";
}

void register_critic(const std::string& name, CriticFactory factory) {
  if (name.empty()) throw Error("register_critic: the name is empty");
  if (!factory) throw Error("register_critic: critic '" + name + "' has no factory");
  std::lock_guard<std::mutex> lock(registry_mutex());
  if (!registry().emplace(name, std::move(factory)).second)
    throw Error("register_critic: a critic named '" + name + "' is already registered");
}

std::unique_ptr<Critic> make_critic(const CriticConfig& config) {
  detail::require_finite("weight of critic '" + config.name + "'", config.weight);
  Factory factory;
  {
    std::lock_guard<std::mutex> lock(registry_mutex());
    const auto& factories = registry();
    auto it = factories.find(config.name);
    if (it != factories.end()) factory = it->second;
  }
  if (!factory) {
    std::lock_guard<std::mutex> lock(registry_mutex());
    const auto& factories = registry();
    std::string known;
    for (const auto& entry : factories) known += (known.empty() ? "" : ", ") + entry.first;
    throw Error("unknown critic '" + config.name + "' (known: " + known + ")");
  }
  Params params = config.params;
  for (const auto& [key, value] : params) detail::require_finite("critic " + config.name + "." + key, value);
  Options options = config.options;
  auto critic = factory(params, options);
  if (!critic) throw Error("critic '" + config.name + "': its factory returned no critic");
  if (!params.empty())
    throw Error("critic '" + config.name + "' has no parameter '" + params.begin()->first + "'");
  if (!options.empty())
    throw Error("critic '" + config.name + "' has no option '" + options.begin()->first + "'");
  return critic;
}

std::vector<std::string> critic_names() {
  std::lock_guard<std::mutex> lock(registry_mutex());
  std::vector<std::string> names;
  for (const auto& [name, factory] : registry()) names.push_back(name);
  return names;
}

}  // namespace fgdwa
