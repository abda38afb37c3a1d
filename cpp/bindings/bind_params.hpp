#pragma once
// A parameter struct as a Python class, derived from its field list
// (fgdwa/params.hpp): one keyword constructor (defaults only in C++),
// read-write attributes with the C++ names, schema(), to_dict(), pickling.
// Every value is converted and checked against its field's bounds when it is
// set; the rules between fields when the struct is built and when it is used.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "convert.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/params.hpp"

namespace fgdwa::py_convert {

namespace py = pybind11;

// A CriticConfig from a CriticConfig, a dict {name, weight, params} or a
// (name, weight[, params]) tuple; `where` names it in errors.
CriticConfig critic_from_python(py::handle item, const std::string& where);
// Critics as a list of dicts {name, weight, params}.
py::list critics_to_python(const std::vector<CriticConfig>& critics);
double param_real(py::handle value, const std::string& path, const Bounds& bounds, const char* unit);
long long param_integer(py::handle value, const std::string& path, const Bounds& bounds);
bool param_flag(py::handle value, const std::string& path);
std::string param_text(py::handle value, const std::string& path);
// The unknown-name error: the names P has, the nearest first.
[[noreturn]] void fail_unknown_param(const std::string& path, const std::string& name,
                                     const std::vector<ParamInfo>& schema);
py::dict schema_entry(const ParamInfo& info);

template <class P>
void set_param(P& params, const std::string& name, py::handle value, const std::string& path);
template <class P>
py::dict params_to_dict(const P& params);

namespace detail {

// Sets the field `name` (its first part, when dotted) of `p` from `value`.
template <class P>
struct FieldSetter {
  P& p;
  std::string head, rest;  // "window.n_v": head "window", rest "n_v"
  py::handle value;
  std::string path;  // where `p` lives, for errors
  bool found = false;

  bool match(const char* name) {
    if (found || head != name) return false;
    found = true;
    if (!rest.empty()) throw Error(param_path(path, name) + " has no field '" + rest + "'");
    return true;
  }
  void real(const char* name, double P::*member, const char* unit, Bounds bounds, const char*) {
    if (match(name)) p.*member = param_real(value, param_path(path, name), bounds, unit);
  }
  template <class I>
  void integer(const char* name, I P::*member, const char*, Bounds bounds, const char*) {
    if (match(name)) p.*member = static_cast<I>(param_integer(value, param_path(path, name), bounds));
  }
  void flag(const char* name, bool P::*member, const char*) {
    if (match(name)) p.*member = param_flag(value, param_path(path, name));
  }
  template <class E>
  void choice(const char* name, E P::*member, const char*) {
    if (!match(name)) return;
    const std::string where = param_path(path, name);
    const std::string word = param_text(value, where);
    std::string known;
    for (E option : enum_values(E{})) {
      if (word == to_string(option)) {
        p.*member = option;
        return;
      }
      known += (known.empty() ? "'" : ", '") + std::string(to_string(option)) + "'";
    }
    fail_param(where, "'" + word + "'", "expected one of " + known);
  }
  void text(const char* name, std::string P::*member, const char*) {
    if (match(name)) p.*member = param_text(value, param_path(path, name));
  }
  template <std::size_t N>
  void reals(const char* name, std::array<double, N> P::*member, const char* unit, Bounds bounds, const char*) {
    if (!match(name)) return;
    const std::string where = param_path(path, name);
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value) || py::len(value) != N)
      throw Error(where + ": expected a list of " + std::to_string(N) + " numbers");
    const auto items = py::reinterpret_borrow<py::sequence>(value);
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i)
      out[i] = param_real(items[i], where + "[" + std::to_string(i) + "]", bounds, unit);
    p.*member = out;
  }
  template <class L>
  void critics(const char* name, L P::*member, const char*) {
    if (!match(name)) return;
    const std::string where = param_path(path, name);
    if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
      throw Error(where + ": expected a list of critics");
    L out;
    std::size_t i = 0;
    for (auto item : py::reinterpret_borrow<py::sequence>(value))
      out.push_back(critic_from_python(item, where + "[" + std::to_string(i++) + "]"));
    p.*member = std::move(out);
  }
  template <class G>
  void group(const char* name, G P::*member, const char*) {
    if (found || head != name) return;
    found = true;
    const std::string where = param_path(path, name);
    if (!rest.empty()) {
      set_param(p.*member, rest, value, where);
    } else if (py::isinstance<G>(value)) {
      p.*member = value.cast<const G&>();
    } else if (py::isinstance<py::dict>(value)) {
      // Fields not given keep their current values.
      for (auto [key, item] : py::reinterpret_borrow<py::dict>(value))
        set_param(p.*member, param_text(key, where + ": a key"), item, where);
    } else {
      throw Error(where + ": expected a " + std::string(G::kName) + " parameter set or a dict, got " +
                  std::string(py::str(py::type::of(value).attr("__name__"))));
    }
  }
};

// The value of field `name` of `p` as a Python object; a nested set by
// reference into `owner`, or as a dict without one.
template <class P>
struct FieldGetter {
  const P& p;
  const std::string& name;
  py::handle owner;
  py::object out;

  void real(const char* n, double P::*member, const char*, Bounds, const char*) {
    if (name == n) out = py::float_(p.*member);
  }
  template <class I>
  void integer(const char* n, I P::*member, const char*, Bounds, const char*) {
    if (name == n) out = py::int_(p.*member);
  }
  void flag(const char* n, bool P::*member, const char*) {
    if (name == n) out = py::bool_(p.*member);
  }
  template <class E>
  void choice(const char* n, E P::*member, const char*) {
    if (name == n) out = py::str(to_string(p.*member));
  }
  void text(const char* n, std::string P::*member, const char*) {
    if (name == n) out = py::str(p.*member);
  }
  template <std::size_t N>
  void reals(const char* n, std::array<double, N> P::*member, const char*, Bounds, const char*) {
    if (name != n) return;
    py::list items;
    for (double x : p.*member) items.append(x);
    out = items;
  }
  template <class L>
  void critics(const char* n, L P::*member, const char*) {
    if (name == n) out = critics_to_python(p.*member);
  }
  template <class G>
  void group(const char* n, G P::*member, const char*) {
    if (name != n) return;
    out = owner ? py::cast(&(p.*member), py::return_value_policy::reference_internal, owner)
                : py::object(params_to_dict(p.*member));
  }
};

template <class P>
const std::vector<std::string>& field_names() {
  // The top-level fields: the schema's names without a dot.
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const ParamInfo& info : param_schema<P>())
      if (info.name.find('.') == std::string::npos) out.push_back(info.name);
    return out;
  }();
  return names;
}

template <class P>
py::object get_field(const P& params, const std::string& name, py::handle owner) {
  FieldGetter<P> getter{params, name, owner, py::object()};
  P::fields(getter);
  return getter.out;
}

}  // namespace detail

// Sets `name` ("hit", or dotted into nested sets: "occupancy.hit") of
// `params` from a Python value, checked against the field's bounds.
template <class P>
void set_param(P& params, const std::string& name, py::handle value, const std::string& path) {
  const auto dot = name.find('.');
  detail::FieldSetter<P> setter{params,
                                dot == std::string::npos ? name : name.substr(0, dot),
                                dot == std::string::npos ? std::string() : name.substr(dot + 1),
                                value,
                                path};
  P::fields(setter);
  if (!setter.found) fail_unknown_param(path, name, param_schema<P>());
}

// The fields as a dict, nested sets as nested dicts.
template <class P>
py::dict params_to_dict(const P& params) {
  py::dict out;
  for (const std::string& name : detail::field_names<P>())
    out[py::str(name)] = detail::get_field(params, name, py::handle());
  return out;
}

template <class P>
py::class_<P> bind_params(py::module_& m, const char* py_name, const char* doc) {
  std::ostringstream text;
  text << doc << "\n\nKeyword arguments, attributes (SI units, radians):\n";
  for (const ParamInfo& info : param_schema<P>())
    if (info.name.find('.') == std::string::npos)
      text << "  " << info.name << (info.unit.empty() ? "" : " (" + info.unit + ")") << ": " << info.doc << "\n";
  py::class_<P> cls(m, py_name, text.str().c_str());
  cls.def(py::init([](py::kwargs kwargs) {
            P params;
            for (auto [key, value] : kwargs) set_param(params, py::str(key), value, P::kName);
            params.validate();
            return params;
          }),
          "Every field a keyword (defaults: the C++ struct's); a nested set takes its own class or a dict.");
  for (const std::string& name : detail::field_names<P>()) {
    cls.def_property(
        name.c_str(), [name](py::object self) { return detail::get_field(self.cast<const P&>(), name, self); },
        [name](P& params, py::handle value) { set_param(params, name, value, P::kName); });
  }
  cls.def_static(
      "schema",
      [] {
        py::list out;
        const py::object defaults = py::cast(P{});
        for (const ParamInfo& info : param_schema<P>()) {
          py::dict entry = schema_entry(info);
          // The default as the attribute reads it.
          if (info.type != ParamType::Group) entry["default"] = defaults.attr("get")(info.name);
          out.append(entry);
        }
        return out;
      },
      "Every field, nested ones by their dotted names: name, type, unit, bounds, doc, choices, default.");
  cls.def_property_readonly_static("name", [](py::object) { return std::string(P::kName); },
                                   "The set's name: the first part of every field's path.");
  cls.def("to_dict", &params_to_dict<P>, "The fields as a dict, nested sets as dicts.");
  cls.def(
      "set", [](P& params, const std::string& name, py::handle value) { set_param(params, name, value, P::kName); },
      py::arg("name"), py::arg("value"), "Sets one field, nested ones by dotted name (\"window.n_v\").");
  cls.def(
      "get",
      [](py::object self, const std::string& name) {
        const auto dot = name.find('.');
        const std::string head = name.substr(0, dot);
        const auto& names = detail::field_names<P>();
        if (std::find(names.begin(), names.end(), head) == names.end())
          fail_unknown_param(P::kName, name, param_schema<P>());
        py::object value = detail::get_field(self.cast<const P&>(), head, self);
        return dot == std::string::npos ? value : value.attr("get")(name.substr(dot + 1));
      },
      py::arg("name"), "One field's value, nested ones by dotted name.");
  cls.def("validate", &P::validate, "Checks every field and the rules between them; raises FgdwaError naming the first bad one.");
  cls.def("__repr__", [py_name](const P& params) {
    std::string out = std::string(py_name) + "(";
    bool first = true;
    for (auto [key, value] : params_to_dict(params)) {
      out += std::string(first ? "" : ", ") + std::string(py::str(key)) + "=" + std::string(py::repr(value));
      first = false;
    }
    return out + ")";
  });
  cls.def("__eq__", [](const P& a, py::handle b) {
    return py::isinstance<P>(b) && params_to_dict(a).equal(params_to_dict(b.cast<const P&>()));
  });
  cls.def("__copy__", [](const P& params) { return P(params); });
  cls.def("__deepcopy__", [](const P& params, py::handle) { return P(params); });
  cls.def(py::pickle([](const P& params) { return params_to_dict(params); },
                     [](const py::dict& fields) {
                       P params;
                       for (auto [key, value] : fields) set_param(params, py::str(key), value, P::kName);
                       params.validate();
                       return params;
                     }));
  return cls;
}

}  // namespace fgdwa::py_convert
