#pragma once
// Parameters declared once.
//
// Each parameter struct names itself and lists its fields in one place:
//
//   struct NavigatorParams {
//     double path_margin = 0.3;
//     OccupancyParams occupancy;
//     static constexpr const char* kName = "navigator";
//     template <class V> static void fields(V& v) {
//       v.real("path_margin", &NavigatorParams::path_margin, "m", Bounds::at_least(0), "kept beyond ...");
//       v.group("occupancy", &NavigatorParams::occupancy, "the map built from scans");
//     }
//     void validate() const { validate_params(*this); }
//   };
//
// A visitor walks that list: validate_params() checks every field against its
// bounds and names it by its full path ("navigator.occupancy.hit = -1: must be
// > 0"); param_schema() lists the fields (name, type, SI unit, bounds, doc,
// choices) for the Python classes, the ROS node, scenario files and the
// parameter reference page. Rules that tie fields together go in the struct's
// `void check_relations(const ParamPath& path) const`, called after its fields.
// A check that passes builds no text: validate() runs in control cycles.
// Adding a parameter is its member and its line in fields().
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "fgdwa/limits.hpp"

namespace fgdwa {

// A closed or half-open interval a number must lie in; `infinite_ok` lets +inf
// through as "no limit" (an upper bound of +inf with infinite_ok).
struct Bounds {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;
  bool hi_open = false;
  bool infinite_ok = false;

  // [lo, hi]
  static constexpr Bounds closed(double lo, double hi) { return {lo, hi, false, false, false}; }
  // (lo, hi]
  static constexpr Bounds above(double lo, double hi) { return {lo, hi, true, false, false}; }
  // [lo, hi)
  static constexpr Bounds below(double lo, double hi) { return {lo, hi, false, true, false}; }
  // [lo, kMaxLength]: lengths and most non-negative quantities.
  static constexpr Bounds at_least(double lo, double hi = limits::kMaxLength) { return closed(lo, hi); }
  // (0, hi]
  static constexpr Bounds positive(double hi = limits::kMaxLength) { return above(0.0, hi); }
  constexpr Bounds or_infinite() const { return {lo, hi, lo_open, hi_open, true}; }

  bool contains(double value) const {
    if (std::isnan(value)) return false;
    if (std::isinf(value)) return infinite_ok && value > 0.0;
    return (lo_open ? value > lo : value >= lo) && (hi_open ? value < hi : value <= hi);
  }
  // "must be >= 0", "must lie in (0, 1]", ... for the side `value` breaks.
  std::string rule(double value) const;
};

enum class ParamType : std::uint8_t {
  Real,     // double
  Integer,  // int or unsigned
  Flag,     // bool
  Choice,   // an enum, by the word to_string() writes for it
  Text,     // a string (its struct checks it)
  Reals,    // a fixed-size array of doubles, each within the bounds
  Critics,  // PlannerParams::critics, a list of {name, weight, params}
  Group,    // a nested parameter struct
};
const char* to_string(ParamType type);

// One field as the schema lists it.
struct ParamInfo {
  std::string name;  // path from the struct listed, '.'-joined ("occupancy.hit")
  ParamType type = ParamType::Real;
  std::string unit;  // SI: "m", "s", "rad", "m/s", ...; "" for a count or a pure number
  Bounds bounds;     // Real, Integer, Reals
  std::string doc;
  std::vector<std::string> choices;  // Choice: the words it takes
  std::string group;                 // Group: the nested struct's kName
  std::size_t size = 0;              // Reals: how many
};

// Where a parameter struct sits: its name and the struct it is nested in
// ("navigator" -> "occupancy"). Its text is built only for an error.
struct ParamPath {
  const char* name;
  const ParamPath* parent = nullptr;
  std::string str() const;                    // "navigator.occupancy"
  std::string field(const char* field) const;  // "navigator.occupancy.hit"
};

// Joins a path and a field name with '.'.
std::string param_path(const std::string& path, const char* name);
// Throws fgdwa::Error "path = value: rule (unit)".
[[noreturn]] void fail_param(const std::string& path, double value, const Bounds& bounds, const char* unit);
[[noreturn]] void fail_param(const std::string& path, const std::string& value, const std::string& rule);

// The names among `known` closest to `name` (edit distance), best first: the
// "did you mean" of every lookup by name.
std::vector<std::string> nearest_names(const std::string& name, const std::vector<std::string>& known,
                                       std::size_t count = 3);

namespace detail {

template <class P, class = void>
struct HasRelations : std::false_type {};
template <class P>
struct HasRelations<P, std::void_t<decltype(std::declval<const P&>().check_relations(std::declval<const ParamPath&>()))>>
    : std::true_type {};

template <class P>
void validate_params_at(const P& params, const ParamPath& path);

template <class P>
struct ParamValidator {
  const P& p;
  const ParamPath& path;

  void real(const char* name, double P::*member, const char* unit, Bounds bounds, const char*) const {
    const double value = p.*member;
    if (!bounds.contains(value)) fail_param(path.field(name), value, bounds, unit);
  }
  template <class I>
  void integer(const char* name, I P::*member, const char* unit, Bounds bounds, const char*) const {
    const double value = static_cast<double>(p.*member);
    if (!bounds.contains(value)) fail_param(path.field(name), value, bounds, unit);
  }
  void flag(const char*, bool P::*, const char*) const {}
  template <class E>
  void choice(const char* name, E P::*member, const char*) const {
    for (E value : enum_values(E{}))
      if (p.*member == value) return;
    fail_param(path.field(name), std::to_string(static_cast<int>(p.*member)), "not one of its values");
  }
  void text(const char*, std::string P::*, const char*) const {}
  template <std::size_t N>
  void reals(const char* name, std::array<double, N> P::*member, const char* unit, Bounds bounds, const char*) const {
    for (std::size_t i = 0; i < N; ++i)
      if (!bounds.contains((p.*member)[i]))
        fail_param(path.field(name) + "[" + std::to_string(i) + "]", (p.*member)[i], bounds, unit);
  }
  template <class L>
  void critics(const char*, L P::*, const char*) const {}  // checked by check_relations
  template <class G>
  void group(const char* name, G P::*member, const char*) const {
    validate_params_at(p.*member, ParamPath{name, &path});
  }
};

template <class P>
void validate_params_at(const P& params, const ParamPath& path) {
  ParamValidator<P> visitor{params, path};
  P::fields(visitor);
  if constexpr (HasRelations<P>::value) params.check_relations(path);
}

template <class P>
struct SchemaCollector {
  std::vector<ParamInfo>& out;
  std::string prefix;

  void add(const char* name, ParamType type, const char* unit, Bounds bounds, const char* doc) {
    ParamInfo info;
    info.name = prefix.empty() ? name : prefix + "." + name;
    info.type = type;
    info.unit = unit;
    info.bounds = bounds;
    info.doc = doc;
    out.push_back(std::move(info));
  }
  void real(const char* name, double P::*, const char* unit, Bounds bounds, const char* doc) {
    add(name, ParamType::Real, unit, bounds, doc);
  }
  template <class I>
  void integer(const char* name, I P::*, const char* unit, Bounds bounds, const char* doc) {
    add(name, ParamType::Integer, unit, bounds, doc);
  }
  void flag(const char* name, bool P::*, const char* doc) { add(name, ParamType::Flag, "", {}, doc); }
  template <class E>
  void choice(const char* name, E P::*, const char* doc) {
    add(name, ParamType::Choice, "", {}, doc);
    for (E value : enum_values(E{})) out.back().choices.emplace_back(to_string(value));
  }
  void text(const char* name, std::string P::*, const char* doc) { add(name, ParamType::Text, "", {}, doc); }
  template <std::size_t N>
  void reals(const char* name, std::array<double, N> P::*, const char* unit, Bounds bounds, const char* doc) {
    add(name, ParamType::Reals, unit, bounds, doc);
    out.back().size = N;
  }
  template <class L>
  void critics(const char* name, L P::*, const char* doc) {
    add(name, ParamType::Critics, "", {}, doc);
  }
  template <class G>
  void group(const char* name, G P::*, const char* doc) {
    add(name, ParamType::Group, "", {}, doc);
    out.back().group = G::kName;
    SchemaCollector<G> nested{out, out.back().name};
    G::fields(nested);
  }
};

}  // namespace detail

// Checks every field of `params` (nested structs included) and then the rules
// between them; throws fgdwa::Error naming the first bad field by its path from
// P::kName.
template <class P>
void validate_params(const P& params) {
  detail::validate_params_at(params, ParamPath{P::kName});
}

// Every field of P, nested structs' fields after their group's entry, in
// declaration order.
template <class P>
std::vector<ParamInfo> param_schema() {
  std::vector<ParamInfo> out;
  detail::SchemaCollector<P> collector{out, ""};
  P::fields(collector);
  return out;
}

}  // namespace fgdwa
