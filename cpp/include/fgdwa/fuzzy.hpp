#pragma once
// A compact Mamdani fuzzy inference engine, and the paper's weight controller
// (Section 2.2.2, Tables 3 and 4) as a ready preset.
//
// Lifecycle: describe the variables and rules once (in code, or from
// configuration through Python), build a MamdaniEngine from them (everything is
// validated and the output terms are sampled then), and call evaluate() every
// control cycle. Evaluation does not mutate the engine, so one engine may be
// shared between threads, and does not allocate unless the engine has more than
// 128 terms in all.
//
// Inference: AND = min, implication = min (clip), aggregation = max, centroid
// defuzzification. Inputs outside a variable's domain are clamped into it. The
// centroid is that of the piecewise-linear curve through the aggregated
// membership sampled on a uniform grid of the output domain (`resolution`
// points, ends included). When no rule fires for an output (every firing
// strength of its rules is 0), that output is the midpoint of its domain.
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace fgdwa {

// A membership function: degrees in [0, 1] over the real line.
struct MembershipFunction {
  enum class Shape { Triangle, Trapezoid, Gaussian };

  Shape shape = Shape::Triangle;
  // Triangle: a, b (peak), c. Trapezoid: a, b, c, d (plateau [b, c]).
  // Gaussian: mean, sigma. Unused entries are 0.
  std::array<double, 4> params{0.0, 0.5, 1.0, 0.0};

  // Each factory validates: finite, ordered, a non-empty support, sigma > 0.
  // a == b or b == c (c == d for a trapezoid) gives a shoulder.
  static MembershipFunction triangle(double a, double b, double c);
  static MembershipFunction trapezoid(double a, double b, double c, double d);
  static MembershipFunction gaussian(double mean, double sigma);

  // NaN in, NaN out: the engine and FuzzyVariable::membership refuse NaN before it gets here.
  double operator()(double x) const;
  // How many entries of `params` the shape uses (3, 4 or 2).
  std::size_t n_params() const;
  // "triangle", "trapezoid" or "gaussian".
  std::string shape_name() const;
  // e.g. "triangle(0, 0, 1)".
  std::string to_string() const;
  // Throws fgdwa::Error whose message starts with `field`.
  void validate(const std::string& field = "membership function") const;
};

struct FuzzyTerm {
  std::string name;
  MembershipFunction membership;
};

// A linguistic variable: a name, a domain [lo, hi] and its named terms.
struct FuzzyVariable {
  std::string name;
  double lo = 0.0;  // the domain, in the variable's own unit
  double hi = 1.0;
  std::vector<FuzzyTerm> terms;

  // Index of the term called `term`, or -1.
  int term_index(const std::string& term) const;
  // Degree of `x` (not clamped) in the term called `term`; throws on an unknown term or a NaN x.
  double membership(const std::string& term, double x) const;
  // Names: letters, digits and '_', not starting with a digit. Every term must be
  // valid, uniquely named, and reach a positive degree inside [lo, hi].
  void validate() const;
};

// The uniform triangular partition of [lo, hi] into terms with evenly spaced
// peaks and shoulders at both ends; for S, M, L with mid m:
// S = tri(lo, lo, m), M = tri(lo, m, hi), L = tri(m, hi, hi).
FuzzyVariable uniform_partition(const std::string& name, double lo, double hi,
                                const std::vector<std::string>& terms = {"S", "M", "L"});

// "variable is term".
struct FuzzyClause {
  std::string variable;
  std::string term;
};

// IF every antecedent holds (AND) THEN every consequent.
struct FuzzyRule {
  std::vector<FuzzyClause> antecedents;
  std::vector<FuzzyClause> consequents;

  // Reads "IF I is S AND D is M THEN beta is S AND delta is M" (keywords in any case).
  static FuzzyRule parse(const std::string& text);
  // The same form parse() reads.
  std::string to_string() const;
};

// Threads: evaluate() and fire() are const and write only their outputs;
// share an engine freely once built.
class MamdaniEngine {
 public:
  static constexpr int kDefaultResolution = 1001;
  // Points of each output's defuzzification grid: a million is far finer than
  // any term needs, and bounds the engine's memory.
  static constexpr int kMinResolution = 3;
  static constexpr int kMaxResolution = 1000000;

  // Throws fgdwa::Error on: no inputs, outputs or rules; a bad variable; a name
  // used twice; a rule naming an unknown variable or term, or an output in its
  // IF part or an input in its THEN part; resolution outside [kMinResolution,
  // kMaxResolution]; an output term that is zero at every grid point (narrower
  // than the grid spacing).
  MamdaniEngine(std::vector<FuzzyVariable> inputs, std::vector<FuzzyVariable> outputs, std::vector<FuzzyRule> rules,
                int resolution = kDefaultResolution);

  // Outputs in the order of outputs(), from inputs in the order of inputs().
  std::vector<double> evaluate(const std::vector<double>& inputs) const;
  // The same without allocating: `outputs` must hold n_outputs() values.
  // Throws on a count mismatch or a NaN input; +-inf clamps like any value.
  void evaluate(const double* inputs, std::size_t n_inputs, double* outputs, std::size_t n_outputs) const;
  // By name: every input must be given, and nothing else.
  std::map<std::string, double> evaluate(const std::map<std::string, double>& inputs) const;

  // Firing strength of each rule for these inputs (diagnostics, tests).
  std::vector<double> firing_strengths(const std::vector<double>& inputs) const;

  const std::vector<FuzzyVariable>& inputs() const { return inputs_; }
  const std::vector<FuzzyVariable>& outputs() const { return outputs_; }
  const std::vector<FuzzyRule>& rules() const { return rules_; }
  int resolution() const { return resolution_; }
  std::size_t n_inputs() const { return inputs_.size(); }
  std::size_t n_outputs() const { return outputs_.size(); }
  // Position of a variable in inputs() / outputs(); throws on an unknown name.
  std::size_t input_index(const std::string& name) const;
  std::size_t output_index(const std::string& name) const;

 private:
  void check_inputs(const double* inputs, std::size_t n_inputs) const;
  // Rule firing strengths into `firing` (n rules); `degrees` is scratch for every input term.
  void fire(const double* inputs, double* degrees, double* firing) const;

  std::vector<FuzzyVariable> inputs_, outputs_;
  std::vector<FuzzyRule> rules_;
  int resolution_;

  // Input terms flattened: term j belongs to input input_of_term_[j].
  std::vector<std::size_t> input_term_begin_;  // per input, plus one past the end
  std::vector<std::size_t> input_of_term_;
  std::vector<MembershipFunction> input_mf_;
  // Rules compiled to flat indices: antecedents into the input terms,
  // consequents into the output terms.
  std::vector<std::size_t> rule_ante_begin_, rule_ante_;
  std::vector<std::size_t> rule_cons_begin_, rule_cons_;
  // Output terms flattened, each sampled on its output's grid, with the index
  // range [first, last) where the sample is positive.
  std::vector<std::size_t> output_term_begin_;
  std::vector<double> samples_;  // n_output_terms x resolution
  std::vector<int> sample_first_, sample_last_;
};

// The paper's controller: inputs I (obstacle density, [0, 2]) and D (path
// deviation, [0, 5] m); outputs beta ([0, 1], weight of the clearance term dist) and
// delta ([0, 5], weight of the similarity term); S, M, L uniform partitions;
// the rules of Tables 3 and 4, one per (D, I) pair concluding on both outputs.
MamdaniEngine paper_fuzzy_controller(int resolution = MamdaniEngine::kDefaultResolution);

// The paper's controller with a third input, T in [0, kContactTimeRange] s:
// the time to the nearest predicted contact with a mover (docs/algorithms.md,
// "Fuzzy weights"). The paper's rules stand; as T falls below the range, rules
// that add the delta term one and then two lower than the paper's fire.
// Beta is the paper's whatever T.
inline constexpr double kContactTimeRange = 3.0;  // s
MamdaniEngine mover_fuzzy_controller(int resolution = MamdaniEngine::kDefaultResolution);

}  // namespace fgdwa
