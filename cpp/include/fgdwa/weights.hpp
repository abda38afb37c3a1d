#pragma once
// How the weights of the clearance (beta) and similarity (delta) critics are
// set each control cycle from the obstacle density I and the path deviation D
// (SPEC 6): held fixed, or read from a fuzzy controller.
#include <memory>
#include <string>

#include "fgdwa/fuzzy.hpp"

namespace fgdwa {

struct WeightPair {
  double beta = 0.0;   // weight of the clearance critic
  double delta = 0.0;  // weight of the similarity critic
};

class WeightPolicy {
 public:
  virtual ~WeightPolicy() = default;
  virtual std::string name() const = 0;
  // Weights for this cycle's density I (0-2) and deviation D (m).
  virtual WeightPair weights(double density, double deviation) const = 0;
};

class FixedWeights : public WeightPolicy {
 public:
  FixedWeights(double beta, double delta);
  std::string name() const override { return "fixed"; }
  WeightPair weights(double, double) const override { return weights_; }

 private:
  WeightPair weights_;
};

// beta and delta from a Mamdani engine with inputs I and D and outputs beta
// and delta (by those names); the paper's controller by default.
class FuzzyWeights : public WeightPolicy {
 public:
  FuzzyWeights();
  explicit FuzzyWeights(MamdaniEngine engine);
  std::string name() const override { return "fuzzy"; }
  WeightPair weights(double density, double deviation) const override;
  const MamdaniEngine& engine() const { return engine_; }

 private:
  MamdaniEngine engine_;
  std::size_t in_density_, in_deviation_, out_beta_, out_delta_;
};

}  // namespace fgdwa
