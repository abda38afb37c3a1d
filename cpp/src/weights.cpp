#include "fgdwa/weights.hpp"

#include <cmath>
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

FuzzyWeights::FuzzyWeights() : FuzzyWeights(paper_fuzzy_controller()) {}

FuzzyWeights::FuzzyWeights(MamdaniEngine engine, std::map<std::string, std::string> output_critics)
    : engine_(std::move(engine)), output_critics_(std::move(output_critics)) {
  if (engine_.n_inputs() != 2) throw Error("fuzzy weights: the engine needs exactly the inputs I and D");
  in_density_ = engine_.input_index("I");
  in_deviation_ = engine_.input_index("D");
  if (output_critics_.size() != engine_.n_outputs())
    throw Error("fuzzy weights: the engine has " + std::to_string(engine_.n_outputs()) + " outputs, but " +
                std::to_string(output_critics_.size()) + " are mapped to critics");
  for (const auto& [output, critic] : output_critics_) {
    if (critic.empty()) throw Error("fuzzy weights: output '" + output + "' is mapped to an empty critic name");
    outputs_.emplace_back(engine_.output_index(output), critic);  // throws on an output the engine lacks
  }
}

CriticWeights FuzzyWeights::weights(double density, double deviation) const {
  double in[2];
  in[in_density_] = density;
  in[in_deviation_] = deviation;
  std::vector<double> out(engine_.n_outputs());
  engine_.evaluate(in, 2, out.data(), out.size());
  CriticWeights weights;
  for (const auto& [index, critic] : outputs_) weights[critic] = out[index];
  return weights;
}

}  // namespace fgdwa
