#include "fgdwa/weights.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "validation.hpp"

namespace fgdwa {

FixedWeights::FixedWeights(CriticWeights weights) : weights_(std::move(weights)) {
  for (const auto& [critic, weight] : weights_) {
    if (critic.empty()) throw Error("fixed weights: a critic name is empty");
    detail::require_non_negative("weight of critic '" + critic + "'", weight);
  }
}

namespace {
CriticWeights paper_pair(double beta, double delta) {
  detail::require_non_negative("beta", beta);
  detail::require_non_negative("delta", delta);
  return {{"clearance", beta}, {"similarity", delta}};
}
}  // namespace

FixedWeights::FixedWeights(double beta, double delta) : FixedWeights(paper_pair(beta, delta)) {}

namespace {
void require_contact_time(double t) {
  if (std::isnan(t) || t < 0.0)
    throw Error(detail::describe("contact time T", t, "must be >= 0 (s; +inf without a mover on its way)"));
}
}  // namespace

CriticWeights WeightPolicy::weights(double density, double deviation, double contact_time) const {
  require_contact_time(contact_time);
  return weights(density, deviation);
}

FuzzyWeights::FuzzyWeights() : FuzzyWeights(paper_fuzzy_controller()) {}

FuzzyWeights::FuzzyWeights(MamdaniEngine engine, std::map<std::string, std::string> output_critics)
    : engine_(std::move(engine)), output_critics_(std::move(output_critics)) {
  const std::size_t n = engine_.n_inputs();
  if (n < 2 || n > 3) throw Error("fuzzy weights: the engine needs the inputs I and D, and optionally T");
  in_density_ = engine_.input_index("I");
  in_deviation_ = engine_.input_index("D");
  if (n == 3) in_contact_time_ = engine_.input_index("T");  // throws naming the inputs when the third is another
  if (output_critics_.size() != engine_.n_outputs())
    throw Error("fuzzy weights: the engine has " + std::to_string(engine_.n_outputs()) + " outputs, but " +
                std::to_string(output_critics_.size()) + " are mapped to critics");
  for (const auto& [output, critic] : output_critics_) {
    if (critic.empty()) throw Error("fuzzy weights: output '" + output + "' is mapped to an empty critic name");
    outputs_.emplace_back(engine_.output_index(output), critic);  // throws on an output the engine lacks
  }
}

CriticWeights FuzzyWeights::weights(double density, double deviation) const {
  return weights(density, deviation, std::numeric_limits<double>::infinity());
}

CriticWeights FuzzyWeights::weights(double density, double deviation, double contact_time) const {
  require_contact_time(contact_time);
  double in[3];
  in[in_density_] = density;
  in[in_deviation_] = deviation;
  if (engine_.n_inputs() == 3) in[in_contact_time_] = contact_time;
  std::vector<double> out(engine_.n_outputs());
  engine_.evaluate(in, engine_.n_inputs(), out.data(), out.size());
  CriticWeights weights;
  for (const auto& [index, critic] : outputs_) weights[critic] = out[index];
  return weights;
}

}  // namespace fgdwa
