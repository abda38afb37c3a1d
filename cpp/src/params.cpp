#include "fgdwa/params.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "fgdwa/error.hpp"
#include "validation.hpp"

namespace fgdwa {

std::string Bounds::rule(double value) const {
  using detail::format_number;
  if (std::isnan(value) || (std::isinf(value) && !infinite_ok)) return "must be finite";
  const bool low_side = lo_open ? !(value > lo) : !(value >= lo);
  // The side the value breaks; an interval whose other end is far (a sanity
  // bound such as limits::kMaxLength) is named by the end broken alone.
  if (low_side) return std::string(lo_open ? "must be > " : "must be >= ") + format_number(lo);
  return std::string(hi_open ? "must be < " : "must be <= ") + format_number(hi) + (infinite_ok ? " or inf" : "");
}

const char* to_string(ParamType type) {
  switch (type) {
    case ParamType::Real: return "real";
    case ParamType::Integer: return "integer";
    case ParamType::Flag: return "flag";
    case ParamType::Choice: return "choice";
    case ParamType::Text: return "text";
    case ParamType::Reals: return "reals";
    case ParamType::Critics: return "critics";
    case ParamType::Group: return "group";
  }
  return "?";
}

std::string ParamPath::str() const { return parent ? parent->field(name) : std::string(name); }

std::string ParamPath::field(const char* field) const { return str() + "." + field; }

std::string param_path(const std::string& path, const char* name) {
  return path.empty() ? std::string(name) : path + "." + name;
}

void fail_param(const std::string& path, double value, const Bounds& bounds, const char* unit) {
  std::string message = path + " = " + detail::format_number(value) + ": " + bounds.rule(value);
  if (unit && *unit) message += std::string(" (") + unit + ")";
  throw Error(message);
}

void fail_param(const std::string& path, const std::string& value, const std::string& rule) {
  throw Error(path + " = " + value + ": " + rule);
}

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

// The part after the last separator: "planner/window/n_v" -> "n_v".
std::string leaf(const std::string& name) {
  const auto at = name.find_last_of("./");
  return at == std::string::npos ? name : name.substr(at + 1);
}

}  // namespace

std::vector<std::string> nearest_names(const std::string& name, const std::vector<std::string>& known,
                                       std::size_t count) {
  // A name typed without its nesting ("n_v" for "planner.window.n_v") is
  // matched on its last part as well.
  std::vector<std::pair<std::size_t, std::string>> scored;
  const std::string name_leaf = leaf(name);
  for (const std::string& candidate : known) {
    const std::size_t whole = edit_distance(name, candidate);
    const std::size_t by_leaf = edit_distance(name_leaf, leaf(candidate));
    scored.emplace_back(std::min(whole, by_leaf), candidate);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  // Beyond half the name's length the candidates are guesses, not suggestions.
  const std::size_t cutoff = std::max<std::size_t>(2, name_leaf.size() / 2);
  for (const auto& [score, candidate] : scored) {
    if (out.size() == count || score > cutoff) break;
    out.push_back(candidate);
  }
  return out;
}

}  // namespace fgdwa
