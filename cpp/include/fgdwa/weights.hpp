#pragma once
// How critics' weights are set each control cycle from the obstacle density I,
// the path deviation D and the time T to the nearest predicted contact with a
// mover (docs/algorithms.md, "Fuzzy weights"): held fixed,
// or read from a fuzzy controller. A policy returns weights by critic name; the
// controller applies those the planner has (the paper's fuzzy policy also names
// the similarity critic, which GDWA lacks).
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "fgdwa/fuzzy.hpp"

namespace fgdwa {

// Weight per critic name.
using CriticWeights = std::map<std::string, double>;

// Threads: weights() is const; the shipped policies may be shared.
class WeightPolicy {
 public:
  virtual ~WeightPolicy() = default;
  virtual std::string name() const = 0;
  // Weights for this cycle's density I (0-2) and deviation D (m).
  virtual CriticWeights weights(double density, double deviation) const = 0;
  // The same with T (s, >= 0; +inf without a mover on its way): what the
  // controller calls. A policy that does not read T leaves it to the above.
  virtual CriticWeights weights(double density, double deviation, double contact_time) const;
};

class FixedWeights : public WeightPolicy {
 public:
  // Throws fgdwa::Error on an empty critic name or a negative or non-finite weight.
  explicit FixedWeights(CriticWeights weights);
  // The paper's pair: beta for the clearance critic, delta for the similarity critic.
  FixedWeights(double beta, double delta);
  std::string name() const override { return "fixed"; }
  CriticWeights weights(double, double) const override { return weights_; }
  using WeightPolicy::weights;

 private:
  CriticWeights weights_;
};

// Critic weights from a Mamdani engine with inputs I and D, and optionally T:
// each output sets the critic it is mapped to (default: the paper's
// controller, beta -> clearance and delta -> similarity).
class FuzzyWeights : public WeightPolicy {
 public:
  FuzzyWeights();
  explicit FuzzyWeights(MamdaniEngine engine,
                        std::map<std::string, std::string> output_critics = {{"beta", "clearance"},
                                                                             {"delta", "similarity"}});
  std::string name() const override { return "fuzzy"; }
  // Without a mover on its way (T = +inf).
  CriticWeights weights(double density, double deviation) const override;
  CriticWeights weights(double density, double deviation, double contact_time) const override;
  const MamdaniEngine& engine() const { return engine_; }
  // Output name -> critic name.
  const std::map<std::string, std::string>& output_critics() const { return output_critics_; }

 private:
  MamdaniEngine engine_;
  std::map<std::string, std::string> output_critics_;
  std::vector<std::pair<std::size_t, std::string>> outputs_;  // engine output index -> critic
  std::size_t in_density_, in_deviation_;
  std::size_t in_contact_time_ = 0;  // read when the engine has a third input
};

}  // namespace fgdwa
