#include "fgdwa/critics.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "validation.hpp"

namespace fgdwa {

double HeadingCritic::score(const Rollout& rollout) const {
  const Pose2& last = rollout.poses->back();
  const Vec2 to_target = target_ - last.position();
  if (to_target.squaredNorm() == 0.0) return M_PI;
  const double bearing = std::atan2(to_target.y(), to_target.x());
  return M_PI - std::abs(angle_difference(bearing, last.theta));
}

ClearanceCritic::ClearanceCritic(double cap) : cap_(cap) { detail::require_positive("clearance cap", cap); }

double ClearanceCritic::score(const Rollout& rollout) const {
  return std::clamp(rollout.min_clearance, 0.0, cap_);
}

namespace {
using Params = std::map<std::string, double>;

double take(Params& params, const std::string& key, double fallback) {
  auto it = params.find(key);
  if (it == params.end()) return fallback;
  const double value = it->second;
  params.erase(it);
  return value;
}

using Factory = std::function<std::unique_ptr<Critic>(Params&)>;

const std::map<std::string, Factory>& registry() {
  static const std::map<std::string, Factory> factories = {
      {"heading", [](Params&) { return std::make_unique<HeadingCritic>(); }},
      {"clearance", [](Params& p) { return std::make_unique<ClearanceCritic>(take(p, "cap", 2.0)); }},
      {"velocity", [](Params&) { return std::make_unique<VelocityCritic>(); }},
  };
  return factories;
}
}  // namespace

std::unique_ptr<Critic> make_critic(const CriticConfig& config) {
  detail::require_finite("weight of critic '" + config.name + "'", config.weight);
  const auto& factories = registry();
  auto it = factories.find(config.name);
  if (it == factories.end()) {
    std::string known;
    for (const auto& [name, factory] : factories) known += (known.empty() ? "" : ", ") + name;
    throw Error("unknown critic '" + config.name + "' (known: " + known + ")");
  }
  Params params = config.params;
  for (const auto& [key, value] : params) detail::require_finite("critic " + config.name + "." + key, value);
  auto critic = it->second(params);
  if (!params.empty())
    throw Error("critic '" + config.name + "' has no parameter '" + params.begin()->first + "'");
  return critic;
}

std::vector<std::string> critic_names() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : registry()) names.push_back(name);
  return names;
}

}  // namespace fgdwa
