#include "bind_params.hpp"

#include <cmath>

#include "fgdwa/critics.hpp"

namespace fgdwa::py_convert {

namespace {
std::string type_of(py::handle obj) { return py::str(py::type::of(obj).attr("__name__")); }
}  // namespace

CriticConfig critic_from_python(py::handle item, const std::string& where) {
  CriticConfig c;
  if (py::isinstance<CriticConfig>(item)) {
    c = item.cast<CriticConfig>();
  } else if (py::isinstance<py::dict>(item)) {
    auto d = item.cast<py::dict>();
    for (auto kv : d) {
      const auto key = to_word(kv.first, where + ": a key");
      if (key != "name" && key != "weight" && key != "params")
        throw Error(where + ": unknown key '" + key + "' (expected name, weight, params)");
    }
    if (!d.contains("name")) throw Error(where + ": no 'name'");
    const std::string name = to_word(d["name"], where + ".name");
    c = critic_config(name, d.contains("weight") ? to_number(d["weight"], where + ".weight of '" + name + "'") : 1.0,
                      d.contains("params") ? to_dict(d["params"], where + ".params of '" + name + "'") : py::dict());
  } else if (py::isinstance<py::tuple>(item) || py::isinstance<py::list>(item)) {
    auto t = item.cast<py::sequence>();
    if (t.size() < 2 || t.size() > 3) throw Error(where + ": a tuple entry is (name, weight[, params])");
    const std::string name = to_word(t[0], where + ".name");
    c = critic_config(name, to_number(t[1], where + ".weight of '" + name + "'"),
                      t.size() == 3 ? to_dict(t[2], where + ".params of '" + name + "'") : py::dict());
  } else {
    throw Error(where + ": each critic is a CriticConfig, a dict or a (name, weight[, params]) tuple, got " +
                type_of(item));
  }
  make_critic(c);
  return c;
}

py::list critics_to_python(const std::vector<CriticConfig>& critics) {
  py::list out;
  for (const CriticConfig& c : critics) {
    py::dict params;
    for (const auto& [key, value] : c.params) params[py::str(key)] = value;
    for (const auto& [key, value] : c.options) params[py::str(key)] = value;
    py::dict entry;
    entry["name"] = c.name;
    entry["weight"] = c.weight;
    entry["params"] = params;
    out.append(entry);
  }
  return out;
}

double param_real(py::handle value, const std::string& path, const Bounds& bounds, const char* unit) {
  const double x = to_number(value, path);
  if (!bounds.contains(x)) fail_param(path, x, bounds, unit);
  return x;
}

long long param_integer(py::handle value, const std::string& path, const Bounds& bounds) {
  // A float, even a whole one, is refused: a count given as 1.5 or 2.0 is a slip.
  if (py::isinstance<py::bool_>(value) || PyFloat_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw Error(path + ": expected an integer, got " + type_of(value));
  IntArg arg{py::reinterpret_steal<py::int_>(PyNumber_Index(value.ptr()))};
  const auto lo = static_cast<long long>(bounds.lo), hi = static_cast<long long>(bounds.hi);
  const long long x = to_int<long long>(arg, path, lo, hi);
  if (!bounds.contains(static_cast<double>(x))) fail_param(path, static_cast<double>(x), bounds, "");
  return x;
}

bool param_flag(py::handle value, const std::string& path) {
  if (!py::isinstance<py::bool_>(value)) throw Error(path + ": expected True or False, got " + type_of(value));
  return value.cast<bool>();
}

std::string param_text(py::handle value, const std::string& path) {
  if (!py::isinstance<py::str>(value)) throw Error(path + ": expected a string, got " + type_of(value));
  return value.cast<std::string>();
}

void fail_unknown_param(const std::string& path, const std::string& name, const std::vector<ParamInfo>& schema) {
  std::vector<std::string> known;
  for (const ParamInfo& info : schema) known.push_back(info.name);
  const auto nearest = nearest_names(name, known);
  std::string message = path + ": unknown parameter '" + name + "'";
  if (!nearest.empty()) {
    message += "; did you mean ";
    for (std::size_t i = 0; i < nearest.size(); ++i)
      message += std::string(i == 0 ? "" : i + 1 == nearest.size() ? " or " : ", ") + "'" + nearest[i] + "'";
    message += "?";
  }
  throw Error(message);
}

py::dict schema_entry(const ParamInfo& info) {
  py::dict entry;
  entry["name"] = info.name;
  entry["type"] = to_string(info.type);
  entry["unit"] = info.unit;
  entry["doc"] = info.doc;
  if (info.type == ParamType::Real || info.type == ParamType::Integer || info.type == ParamType::Reals) {
    entry["min"] = info.bounds.lo;
    entry["max"] = info.bounds.hi;
    entry["min_open"] = info.bounds.lo_open;
    entry["max_open"] = info.bounds.hi_open;
    entry["infinite_ok"] = info.bounds.infinite_ok;
  }
  if (info.type == ParamType::Choice) entry["choices"] = info.choices;
  if (info.type == ParamType::Group) entry["group"] = info.group;
  if (info.type == ParamType::Reals) entry["size"] = info.size;
  return entry;
}

}  // namespace fgdwa::py_convert
