#include "fgdwa/weights.hpp"

#include <cmath>

#include "validation.hpp"

namespace fgdwa {

FixedWeights::FixedWeights(double beta, double delta) : weights_{beta, delta} {
  detail::require_non_negative("beta", beta);
  detail::require_non_negative("delta", delta);
}

FuzzyWeights::FuzzyWeights() : FuzzyWeights(paper_fuzzy_controller()) {}

FuzzyWeights::FuzzyWeights(MamdaniEngine engine) : engine_(std::move(engine)) {
  if (engine_.n_inputs() != 2 || engine_.n_outputs() != 2)
    throw Error("fuzzy weights: the engine needs exactly the inputs I, D and the outputs beta, delta");
  in_density_ = engine_.input_index("I");
  in_deviation_ = engine_.input_index("D");
  out_beta_ = engine_.output_index("beta");
  out_delta_ = engine_.output_index("delta");
}

WeightPair FuzzyWeights::weights(double density, double deviation) const {
  double in[2], out[2];
  in[in_density_] = density;
  in[in_deviation_] = deviation;
  engine_.evaluate(in, 2, out, 2);
  return {out[out_beta_], out[out_delta_]};
}

}  // namespace fgdwa
