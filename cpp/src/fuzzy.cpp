#include "fgdwa/fuzzy.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <sstream>

#include "validation.hpp"

namespace fgdwa {

namespace {

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

std::string term_names(const FuzzyVariable& v) {
  std::vector<std::string> names;
  for (const auto& t : v.terms) names.push_back(t.name);
  return join(names);
}

std::string variable_names(const std::vector<FuzzyVariable>& vars) {
  std::vector<std::string> names;
  for (const auto& v : vars) names.push_back(v.name);
  return join(names);
}

// Names appear in rule text and as Python keyword arguments.
void require_name(const std::string& field, const std::string& name) {
  const auto ok_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  const bool ok = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                  std::all_of(name.begin(), name.end(), ok_char);
  if (!ok)
    throw Error(field + " = '" + name + "': must be letters, digits and '_', not starting with a digit");
}

// Storage for per-call scratch that stays on the stack for ordinary engines.
template <typename T>
class Scratch {
 public:
  explicit Scratch(std::size_t n) {
    if (n > kInline) heap_.resize(n);
    data_ = n > kInline ? heap_.data() : inline_.data();
  }
  T* data() { return data_; }

 private:
  static constexpr std::size_t kInline = 128;
  std::array<T, kInline> inline_;
  std::vector<T> heap_;
  T* data_;
};

struct Sums {
  double y = 0.0;   // sum of the aggregated membership over the grid points
  double ky = 0.0;  // the same weighted by the grid index
};

// Sums of the aggregate max_a min(level_a, samples_a[k]) over k in [k0, k1).
// N > 0 fixes the number of active terms at compile time so the loops unroll;
// N = 0 takes it from `n`. Four partial sums keep the additions independent.
template <int N>
Sums accumulate(const double* const* samples, const double* level, int k0, int k1, std::size_t n = N) {
  const std::size_t count = N > 0 ? static_cast<std::size_t>(N) : n;
  double sy[4] = {0, 0, 0, 0}, sky[4] = {0, 0, 0, 0};
  const auto at = [&](int k) {
    double y = std::min(level[0], samples[0][k]);
    for (std::size_t a = 1; a < count; ++a) y = std::max(y, std::min(level[a], samples[a][k]));
    return y;
  };
  int k = k0;
  for (; k + 4 <= k1; k += 4)
    for (int l = 0; l < 4; ++l) {
      const double y = at(k + l);
      sy[l] += y;
      sky[l] += static_cast<double>(k + l) * y;
    }
  for (; k < k1; ++k) {
    const double y = at(k);
    sy[0] += y;
    sky[0] += static_cast<double>(k) * y;
  }
  return {(sy[0] + sy[1]) + (sy[2] + sy[3]), (sky[0] + sky[1]) + (sky[2] + sky[3])};
}

}  // namespace

// ---------------------------------------------------------------- membership

MembershipFunction MembershipFunction::triangle(double a, double b, double c) {
  MembershipFunction mf{Shape::Triangle, {a, b, c, 0.0}};
  mf.validate();
  return mf;
}

MembershipFunction MembershipFunction::trapezoid(double a, double b, double c, double d) {
  MembershipFunction mf{Shape::Trapezoid, {a, b, c, d}};
  mf.validate();
  return mf;
}

MembershipFunction MembershipFunction::gaussian(double mean, double sigma) {
  MembershipFunction mf{Shape::Gaussian, {mean, sigma, 0.0, 0.0}};
  mf.validate();
  return mf;
}

double MembershipFunction::operator()(double x) const {
  if (std::isnan(x)) return x;
  const auto& p = params;
  switch (shape) {
    case Shape::Triangle:
      if (x < p[0] || x > p[2]) return 0.0;
      if (x < p[1]) return (x - p[0]) / (p[1] - p[0]);
      if (x > p[1]) return (p[2] - x) / (p[2] - p[1]);
      return 1.0;
    case Shape::Trapezoid:
      if (x < p[0] || x > p[3]) return 0.0;
      if (x < p[1]) return (x - p[0]) / (p[1] - p[0]);
      if (x > p[2]) return (p[3] - x) / (p[3] - p[2]);
      return 1.0;
    case Shape::Gaussian: {
      const double z = (x - p[0]) / p[1];
      return std::exp(-0.5 * z * z);
    }
  }
  return 0.0;
}

std::size_t MembershipFunction::n_params() const {
  switch (shape) {
    case Shape::Triangle: return 3;
    case Shape::Trapezoid: return 4;
    case Shape::Gaussian: return 2;
  }
  return 0;
}

std::string MembershipFunction::shape_name() const {
  switch (shape) {
    case Shape::Triangle: return "triangle";
    case Shape::Trapezoid: return "trapezoid";
    case Shape::Gaussian: return "gaussian";
  }
  return "unknown";
}

std::string MembershipFunction::to_string() const {
  std::ostringstream out;
  out << shape_name() << "(";
  for (std::size_t i = 0; i < n_params(); ++i) out << (i ? ", " : "") << params[i];
  out << ")";
  return out.str();
}

void MembershipFunction::validate(const std::string& field) const {
  const std::string where = field + " = " + to_string();
  for (std::size_t i = 0; i < n_params(); ++i)
    if (!std::isfinite(params[i])) throw Error(where + ": parameters must be finite");
  const auto& p = params;
  switch (shape) {
    case Shape::Triangle:
      if (!(p[0] <= p[1] && p[1] <= p[2])) throw Error(where + ": needs a <= b <= c");
      if (!(p[0] < p[2])) throw Error(where + ": needs a < c (an empty support)");
      break;
    case Shape::Trapezoid:
      if (!(p[0] <= p[1] && p[1] <= p[2] && p[2] <= p[3])) throw Error(where + ": needs a <= b <= c <= d");
      if (!(p[0] < p[3])) throw Error(where + ": needs a < d (an empty support)");
      break;
    case Shape::Gaussian:
      if (!(p[1] > 0.0)) throw Error(where + ": sigma must be > 0");
      break;
  }
}

// ------------------------------------------------------------------ variables

int FuzzyVariable::term_index(const std::string& term) const {
  for (std::size_t i = 0; i < terms.size(); ++i)
    if (terms[i].name == term) return static_cast<int>(i);
  return -1;
}

double FuzzyVariable::membership(const std::string& term, double x) const {
  if (std::isnan(x)) throw Error("variable " + name + " x = nan: must be a number");
  const int i = term_index(term);
  if (i < 0) throw Error("variable " + name + " has no term '" + term + "' (terms: " + term_names(*this) + ")");
  return terms[static_cast<std::size_t>(i)].membership(x);
}

void FuzzyVariable::validate() const {
  require_name("variable name", name);
  detail::require_finite("variable " + name + " lo", lo);
  detail::require_finite("variable " + name + " hi", hi);
  if (!(lo < hi)) {
    std::ostringstream out;
    out << "variable " << name << " domain = [" << lo << ", " << hi << "]: needs lo < hi";
    throw Error(out.str());
  }
  if (terms.empty()) throw Error("variable " + name + ": needs at least one term");
  std::set<std::string> seen;
  for (const auto& t : terms) {
    require_name("variable " + name + " term name", t.name);
    if (!seen.insert(t.name).second) throw Error("variable " + name + " term '" + t.name + "' is defined twice");
    const std::string field = "variable " + name + " term " + t.name;
    t.membership.validate(field);
    // The point of the domain nearest the term's peak or plateau.
    const bool gaussian = t.membership.shape == MembershipFunction::Shape::Gaussian;
    const double peak = std::clamp(t.membership.params[gaussian ? 0 : 1], lo, hi);
    if (!(t.membership(peak) > 0.0)) {
      std::ostringstream out;
      out << field << " = " << t.membership.to_string() << ": is zero everywhere in the domain [" << lo << ", " << hi
          << "]";
      throw Error(out.str());
    }
  }
}

FuzzyVariable uniform_partition(const std::string& name, double lo, double hi, const std::vector<std::string>& terms) {
  if (terms.size() < 2) throw Error("variable " + name + ": a uniform partition needs at least 2 terms");
  FuzzyVariable v{name, lo, hi, {}};
  const std::size_t n = terms.size();
  std::vector<double> peaks(n);
  for (std::size_t i = 0; i < n; ++i) peaks[i] = lo + (hi - lo) * static_cast<double>(i) / static_cast<double>(n - 1);
  peaks[n - 1] = hi;  // exact, whatever the rounding above
  for (std::size_t i = 0; i < n; ++i) {
    const double a = peaks[i == 0 ? 0 : i - 1], c = peaks[i + 1 == n ? i : i + 1];
    v.terms.push_back({terms[i], {MembershipFunction::Shape::Triangle, {a, peaks[i], c, 0.0}}});
  }
  v.validate();
  return v;
}

// ---------------------------------------------------------------------- rules

FuzzyRule FuzzyRule::parse(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  const auto keyword = [](const std::string& token, const char* word) {
    std::string lower = token;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
    return lower == word;
  };
  const auto fail = [&](const std::string& what) -> Error {
    return Error("rule '" + text + "': " + what + " (expected 'IF v is t AND ... THEN v is t AND ...')");
  };
  std::size_t i = 0;
  const auto clauses = [&](std::vector<FuzzyClause>& out, const char* stop) {
    while (true) {
      if (i + 3 > tokens.size()) throw fail("a clause 'variable is term' is cut short");
      if (!keyword(tokens[i + 1], "is"))
        throw fail("expected 'is' after '" + tokens[i] + "', got '" + tokens[i + 1] + "'");
      out.push_back({tokens[i], tokens[i + 2]});
      i += 3;
      if (i == tokens.size()) return;
      if (stop != nullptr && keyword(tokens[i], stop)) return;
      if (!keyword(tokens[i], "and")) throw fail("expected 'AND'" + std::string(stop ? " or 'THEN'" : "") +
                                                 ", got '" + tokens[i] + "'");
      ++i;
    }
  };
  if (tokens.empty() || !keyword(tokens[0], "if")) throw fail("must start with 'IF'");
  i = 1;
  FuzzyRule rule;
  clauses(rule.antecedents, "then");
  if (i == tokens.size()) throw fail("no THEN part");
  ++i;
  clauses(rule.consequents, nullptr);
  return rule;
}

std::string FuzzyRule::to_string() const {
  std::string out = "IF";
  for (std::size_t i = 0; i < antecedents.size(); ++i)
    out += (i ? " AND " : " ") + antecedents[i].variable + " is " + antecedents[i].term;
  out += " THEN";
  for (std::size_t i = 0; i < consequents.size(); ++i)
    out += (i ? " AND " : " ") + consequents[i].variable + " is " + consequents[i].term;
  return out;
}

// --------------------------------------------------------------------- engine

MamdaniEngine::MamdaniEngine(std::vector<FuzzyVariable> inputs, std::vector<FuzzyVariable> outputs,
                             std::vector<FuzzyRule> rules, int resolution)
    : inputs_(std::move(inputs)), outputs_(std::move(outputs)), rules_(std::move(rules)), resolution_(resolution) {
  detail::require_count("resolution", resolution_, kMinResolution, kMaxResolution);
  if (inputs_.empty()) throw Error("inputs: the engine needs at least one input variable");
  if (outputs_.empty()) throw Error("outputs: the engine needs at least one output variable");
  if (rules_.empty()) throw Error("rules: the engine needs at least one rule");
  std::set<std::string> names;
  for (const auto* group : {&inputs_, &outputs_})
    for (const auto& v : *group) {
      v.validate();
      if (!names.insert(v.name).second) throw Error("variable name '" + v.name + "' is used twice");
    }

  input_term_begin_.push_back(0);
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    for (const auto& t : inputs_[i].terms) {
      input_of_term_.push_back(i);
      input_mf_.push_back(t.membership);
    }
    input_term_begin_.push_back(input_mf_.size());
  }
  output_term_begin_.push_back(0);
  for (const auto& v : outputs_) output_term_begin_.push_back(output_term_begin_.back() + v.terms.size());

  const auto find = [](const std::vector<FuzzyVariable>& vars, const std::string& name) -> int {
    for (std::size_t i = 0; i < vars.size(); ++i)
      if (vars[i].name == name) return static_cast<int>(i);
    return -1;
  };
  rule_ante_begin_.push_back(0);
  rule_cons_begin_.push_back(0);
  for (std::size_t r = 0; r < rules_.size(); ++r) {
    const FuzzyRule& rule = rules_[r];
    const std::string where = "rule " + std::to_string(r) + " '" + rule.to_string() + "'";
    if (rule.antecedents.empty()) throw Error(where + ": needs at least one clause after IF");
    if (rule.consequents.empty()) throw Error(where + ": needs at least one clause after THEN");
    const auto resolve = [&](const FuzzyClause& clause, bool is_input) {
      const auto& vars = is_input ? inputs_ : outputs_;
      const int v = find(vars, clause.variable);
      if (v < 0) {
        if (find(is_input ? outputs_ : inputs_, clause.variable) >= 0)
          throw Error(where + ": " + clause.variable + " is an " + (is_input ? "output" : "input") + "; only " +
                      (is_input ? "inputs may follow IF" : "outputs may follow THEN"));
        throw Error(where + ": unknown " + (is_input ? "input" : "output") + " variable '" + clause.variable + "' (" +
                    (is_input ? "inputs: " : "outputs: ") + variable_names(vars) + ")");
      }
      const auto& var = vars[static_cast<std::size_t>(v)];
      const int t = var.term_index(clause.term);
      if (t < 0)
        throw Error(where + ": variable " + var.name + " has no term '" + clause.term + "' (terms: " +
                    term_names(var) + ")");
      const auto& begin = is_input ? input_term_begin_ : output_term_begin_;
      return begin[static_cast<std::size_t>(v)] + static_cast<std::size_t>(t);
    };
    for (const auto& c : rule.antecedents) rule_ante_.push_back(resolve(c, true));
    for (const auto& c : rule.consequents) rule_cons_.push_back(resolve(c, false));
    rule_ante_begin_.push_back(rule_ante_.size());
    rule_cons_begin_.push_back(rule_cons_.size());
  }

  // Sample every output term once, so a call only clips, takes maxima and sums.
  const std::size_t n = static_cast<std::size_t>(resolution_);
  samples_.resize(output_term_begin_.back() * n);
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    const auto& v = outputs_[o];
    const double h = (v.hi - v.lo) / static_cast<double>(n - 1);
    for (std::size_t t = 0; t < v.terms.size(); ++t) {
      const std::size_t j = output_term_begin_[o] + t;
      double* s = samples_.data() + j * n;
      int first = -1, last = -1;
      for (std::size_t k = 0; k < n; ++k) {
        const double x = k + 1 == n ? v.hi : v.lo + h * static_cast<double>(k);
        s[k] = v.terms[t].membership(x);
        if (s[k] > 0.0) {
          if (first < 0) first = static_cast<int>(k);
          last = static_cast<int>(k) + 1;
        }
      }
      if (first < 0)
        throw Error("output " + v.name + " term " + v.terms[t].name + " = " + v.terms[t].membership.to_string() +
                    ": zero at every one of the " + std::to_string(resolution_) +
                    " grid points; raise resolution or widen the term");
      sample_first_.push_back(first);
      sample_last_.push_back(last);
    }
  }
}

std::size_t MamdaniEngine::input_index(const std::string& name) const {
  for (std::size_t i = 0; i < inputs_.size(); ++i)
    if (inputs_[i].name == name) return i;
  throw Error("unknown input '" + name + "' (inputs: " + variable_names(inputs_) + ")");
}

std::size_t MamdaniEngine::output_index(const std::string& name) const {
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    if (outputs_[i].name == name) return i;
  throw Error("unknown output '" + name + "' (outputs: " + variable_names(outputs_) + ")");
}

void MamdaniEngine::check_inputs(const double* inputs, std::size_t n_inputs) const {
  if (n_inputs != inputs_.size())
    throw Error("inputs: expected " + std::to_string(inputs_.size()) + " values (" + variable_names(inputs_) +
                "), got " + std::to_string(n_inputs));
  for (std::size_t i = 0; i < n_inputs; ++i)
    if (std::isnan(inputs[i])) throw Error("input " + inputs_[i].name + " = nan: must be a number");
}

void MamdaniEngine::fire(const double* inputs, double* degrees, double* firing) const {
  for (std::size_t j = 0; j < input_mf_.size(); ++j) {
    const FuzzyVariable& v = inputs_[input_of_term_[j]];
    degrees[j] = input_mf_[j](std::clamp(inputs[input_of_term_[j]], v.lo, v.hi));
  }
  for (std::size_t r = 0; r + 1 < rule_ante_begin_.size(); ++r) {
    double w = 1.0;
    for (std::size_t a = rule_ante_begin_[r]; a < rule_ante_begin_[r + 1]; ++a) w = std::min(w, degrees[rule_ante_[a]]);
    firing[r] = w;
  }
}

void MamdaniEngine::evaluate(const double* inputs, std::size_t n_inputs, double* outputs, std::size_t n_outputs) const {
  check_inputs(inputs, n_inputs);
  if (n_outputs != outputs_.size())
    throw Error("outputs: expected room for " + std::to_string(outputs_.size()) + " values (" +
                variable_names(outputs_) + "), got " + std::to_string(n_outputs));
  const std::size_t n_in_terms = input_mf_.size(), n_out_terms = output_term_begin_.back();
  Scratch<double> scratch(n_in_terms + rules_.size() + 2 * n_out_terms);
  double* degrees = scratch.data();
  double* firing = degrees + n_in_terms;
  double* levels = firing + rules_.size();
  double* active_level = levels + n_out_terms;
  Scratch<const double*> active_samples(n_out_terms);
  const double** active = active_samples.data();

  fire(inputs, degrees, firing);
  // Rules concluding on the same term clip it once, at their strongest firing
  // (max_r min(w_r, mu) = min(max_r w_r, mu)).
  std::fill(levels, levels + n_out_terms, 0.0);
  for (std::size_t r = 0; r < rules_.size(); ++r)
    for (std::size_t c = rule_cons_begin_[r]; c < rule_cons_begin_[r + 1]; ++c)
      levels[rule_cons_[c]] = std::max(levels[rule_cons_[c]], firing[r]);

  const int n = resolution_;
  for (std::size_t o = 0; o < outputs_.size(); ++o) {
    const FuzzyVariable& v = outputs_[o];
    std::size_t n_active = 0;
    int k0 = n, k1 = 0;
    for (std::size_t j = output_term_begin_[o]; j < output_term_begin_[o + 1]; ++j) {
      if (!(levels[j] > 0.0)) continue;
      active[n_active] = samples_.data() + j * static_cast<std::size_t>(n);
      active_level[n_active] = levels[j];
      ++n_active;
      k0 = std::min(k0, sample_first_[j]);
      k1 = std::max(k1, sample_last_[j]);
    }
    if (n_active == 0) {
      outputs[o] = 0.5 * (v.lo + v.hi);
      continue;
    }
    const auto aggregate = [&](int k) {
      double y = 0.0;
      for (std::size_t a = 0; a < n_active; ++a) y = std::max(y, std::min(active_level[a], active[a][k]));
      return y;
    };
    Sums sums;
    switch (n_active) {
      case 1: sums = accumulate<1>(active, active_level, k0, k1); break;
      case 2: sums = accumulate<2>(active, active_level, k0, k1); break;
      case 3: sums = accumulate<3>(active, active_level, k0, k1); break;
      default: sums = accumulate<0>(active, active_level, k0, k1, n_active); break;
    }
    // Trapezoid weights at the domain's ends, plus the exact correction for the
    // product of two linear pieces: the centroid of the piecewise-linear curve.
    const double y_first = k0 == 0 ? aggregate(0) : 0.0;
    const double y_last = k1 == n ? aggregate(n - 1) : 0.0;
    const double area = sums.y - 0.5 * (y_first + y_last);
    const double moment = sums.ky - 0.5 * (n - 1) * y_last + (y_first - y_last) / 6.0;
    const double h = (v.hi - v.lo) / (n - 1);
    outputs[o] = std::clamp(v.lo + h * moment / area, v.lo, v.hi);
  }
}

std::vector<double> MamdaniEngine::evaluate(const std::vector<double>& inputs) const {
  std::vector<double> out(outputs_.size());
  evaluate(inputs.data(), inputs.size(), out.data(), out.size());
  return out;
}

std::map<std::string, double> MamdaniEngine::evaluate(const std::map<std::string, double>& inputs) const {
  for (const auto& [name, value] : inputs) input_index(name);
  std::vector<double> values(inputs_.size());
  for (std::size_t i = 0; i < inputs_.size(); ++i) {
    auto it = inputs.find(inputs_[i].name);
    if (it == inputs.end())
      throw Error("missing input '" + inputs_[i].name + "' (inputs: " + variable_names(inputs_) + ")");
    values[i] = it->second;
  }
  const std::vector<double> out = evaluate(values);
  std::map<std::string, double> named;
  for (std::size_t o = 0; o < outputs_.size(); ++o) named[outputs_[o].name] = out[o];
  return named;
}

std::vector<double> MamdaniEngine::firing_strengths(const std::vector<double>& inputs) const {
  check_inputs(inputs.data(), inputs.size());
  std::vector<double> degrees(input_mf_.size()), firing(rules_.size());
  fire(inputs.data(), degrees.data(), firing.data());
  return firing;
}

// --------------------------------------------------------------------- preset

MamdaniEngine paper_fuzzy_controller(int resolution) {
  const std::vector<std::string> sml = {"S", "M", "L"};
  // Tables 3 and 4: rows D, columns I.
  const char* beta[3][3] = {{"S", "M", "L"}, {"S", "M", "L"}, {"S", "M", "M"}};
  const char* delta[3][3] = {{"S", "S", "S"}, {"M", "M", "M"}, {"L", "L", "M"}};
  std::vector<FuzzyRule> rules;
  for (int d = 0; d < 3; ++d)
    for (int i = 0; i < 3; ++i)
      rules.push_back({{{"I", sml[i]}, {"D", sml[d]}}, {{"beta", beta[d][i]}, {"delta", delta[d][i]}}});
  return MamdaniEngine({uniform_partition("I", 0.0, 2.0), uniform_partition("D", 0.0, 5.0)},
                       {uniform_partition("beta", 0.0, 1.0), uniform_partition("delta", 0.0, 5.0)}, std::move(rules),
                       resolution);
}

MamdaniEngine mover_fuzzy_controller(int resolution) {
  const MamdaniEngine paper = paper_fuzzy_controller(resolution);
  const std::vector<std::string> sml = {"S", "M", "L"};
  const auto lower = [&](const std::string& term, int by) {
    const int i = static_cast<int>(std::find(sml.begin(), sml.end(), term) - sml.begin()) - by;
    return sml[static_cast<std::size_t>(std::max(i, 0))];
  };
  // T's terms: "near" rises from nothing at kContactTimeRange to full at half
  // of it and stays full; "imminent" rises from nothing there to full at 0.
  // Nested, not a partition, so that each only adds as a contact nears.
  const double half = 0.5 * kContactTimeRange;
  FuzzyVariable contact{"T", 0.0, kContactTimeRange,
                        {{"near", MembershipFunction::trapezoid(0.0, 0.0, half, kContactTimeRange)},
                         {"imminent", MembershipFunction::triangle(0.0, 0.0, half)}}};
  // A contact on its way frees the robot from the global path (delta down),
  // the more the sooner: the path may be where the mover is going, and the
  // way out is off it. The paper's rules stand whatever T (beta stays theirs
  // exactly: raising it as well left the robot fewer ways out); each delta
  // rule gains one adding the term one lower when T is near and one adding
  // the term two lower when T is imminent. Added, not swapped in: a Mamdani
  // output whose rules split one term between T's terms would be clipped
  // lower and drift with T.
  std::vector<FuzzyRule> rules;
  for (const FuzzyRule& rule : paper.rules()) {
    const FuzzyRule delta{rule.antecedents, {rule.consequents[1]}};
    rules.push_back(FuzzyRule{rule.antecedents, {rule.consequents[0]}});
    rules.push_back(delta);
    for (int by = 1; by <= 2; ++by) {
      const std::string term = lower(delta.consequents[0].term, by);
      if (term == delta.consequents[0].term) continue;
      FuzzyRule r = delta;
      r.antecedents.push_back({"T", by == 1 ? "near" : "imminent"});
      r.consequents[0].term = term;
      rules.push_back(std::move(r));
    }
  }
  return MamdaniEngine({paper.inputs()[0], paper.inputs()[1], std::move(contact)}, paper.outputs(), std::move(rules),
                       resolution);
}

}  // namespace fgdwa
