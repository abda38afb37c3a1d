#include "node_params.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>

#include <ros/console.h>
#include <ros/param.h>
#include <xmlrpcpp/XmlRpcValue.h>

#include "fgdwa/error.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/presets.hpp"
#include "json.hpp"

namespace fgdwa_ros {

using fgdwa::Error;
using XmlRpc::XmlRpcValue;

namespace {

std::string shown(const XmlRpcValue& value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

[[noreturn]] void refuse(const std::string& name, const XmlRpcValue& value, const std::string& rule) {
  throw Error("parameter ~" + name + " = " + shown(value) + ": " + rule);
}

double as_number(const std::string& name, const XmlRpcValue& value) {
  if (value.getType() == XmlRpcValue::TypeDouble) return static_cast<double>(const_cast<XmlRpcValue&>(value));
  if (value.getType() == XmlRpcValue::TypeInt) return static_cast<int>(const_cast<XmlRpcValue&>(value));
  refuse(name, value, "must be a number");
}

std::string as_text(const std::string& name, const XmlRpcValue& value) {
  if (value.getType() != XmlRpcValue::TypeString) refuse(name, value, "must be a string");
  return static_cast<std::string>(const_cast<XmlRpcValue&>(value));
}

// One parameter: how to set it from the server's value and how to write it as JSON.
struct Entry {
  std::string name;
  std::function<void(const XmlRpcValue&)> set;
  std::function<std::string()> json;
};

Entry number(const std::string& name, double& field) {
  return {name, [name, &field](const XmlRpcValue& v) { field = as_number(name, v); },
          [&field] { return json_number(field); }};
}

Entry integer(const std::string& name, int& field) {
  return {name,
          [name, &field](const XmlRpcValue& v) {
            if (v.getType() != XmlRpcValue::TypeInt) refuse(name, v, "must be an integer");
            field = static_cast<int>(const_cast<XmlRpcValue&>(v));
          },
          [&field] { return std::to_string(field); }};
}

Entry flag(const std::string& name, bool& field) {
  return {name,
          [name, &field](const XmlRpcValue& v) {
            if (v.getType() != XmlRpcValue::TypeBoolean) refuse(name, v, "must be true or false");
            field = static_cast<bool>(const_cast<XmlRpcValue&>(v));
          },
          [&field] { return std::string(field ? "true" : "false"); }};
}

Entry text(const std::string& name, std::string& field) {
  return {name, [name, &field](const XmlRpcValue& v) { field = as_text(name, v); },
          [&field] { return json_text(field); }};
}

// An enum given by the word fgdwa::to_string() writes for it.
template <typename Enum>
Entry choice(const std::string& name, Enum& field, std::vector<Enum> values) {
  return {name,
          [name, &field, values](const XmlRpcValue& v) {
            const std::string word = as_text(name, v);
            std::string known;
            for (Enum value : values) {
              if (word == fgdwa::to_string(value)) {
                field = value;
                return;
              }
              known += std::string(known.empty() ? "" : ", ") + fgdwa::to_string(value);
            }
            refuse(name, v, "expected one of " + known);
          },
          [&field] { return json_text(fgdwa::to_string(field)); }};
}

// ~planner/critics: a list of {name: heading, weight: 0.5, params: {key: number or word}}.
Entry critics(const std::string& name, std::vector<fgdwa::CriticConfig>& field) {
  auto set = [name, &field](const XmlRpcValue& v) {
    if (v.getType() != XmlRpcValue::TypeArray || v.size() == 0)
      refuse(name, v, "must be a non-empty list of {name: ..., weight: ..., params: {...}}");
    std::vector<fgdwa::CriticConfig> out;
    for (int i = 0; i < v.size(); ++i) {
      XmlRpcValue item = v[i];
      const std::string where = name + "[" + std::to_string(i) + "]";
      if (item.getType() != XmlRpcValue::TypeStruct || !item.hasMember("name"))
        refuse(where, item, "must be a mapping with a name (and weight, params)");
      fgdwa::CriticConfig critic(as_text(where + "/name", item["name"]));
      for (auto& [key, value] : item) {
        if (key == "name") continue;
        if (key == "weight") {
          critic.weight = as_number(where + "/weight", value);
        } else if (key == "params") {
          if (value.getType() != XmlRpcValue::TypeStruct) refuse(where + "/params", value, "must be a mapping");
          for (auto& [pkey, pvalue] : value) {
            if (pvalue.getType() == XmlRpcValue::TypeString)
              critic.options[pkey] = static_cast<std::string>(pvalue);
            else
              critic.params[pkey] = as_number(where + "/params/" + pkey, pvalue);
          }
        } else {
          refuse(where + "/" + key, value, "unknown key (a critic has name, weight, params)");
        }
      }
      out.push_back(critic);
    }
    field = out;
  };
  auto json = [&field] {
    std::string out = "[";
    for (std::size_t i = 0; i < field.size(); ++i) {
      const auto& c = field[i];
      out += std::string(i ? ", " : "") + "{\"name\": " + json_text(c.name) + ", \"weight\": " + json_number(c.weight) +
             ", \"params\": {";
      bool first = true;
      for (const auto& [k, p] : c.params) {
        out += std::string(first ? "" : ", ") + json_text(k) + ": " + json_number(p);
        first = false;
      }
      for (const auto& [k, o] : c.options) {
        out += std::string(first ? "" : ", ") + json_text(k) + ": " + json_text(o);
        first = false;
      }
      out += "}}";
    }
    return out + "]";
  };
  return {name, set, json};
}

// ~footprint: [[x, y], ...] a convex polygon in the base frame, or ~footprint_radius: a circle.
Entry footprint(fgdwa::Footprint& field) {
  const std::string name = "footprint";
  auto set = [name, &field](const XmlRpcValue& v) {
    if (v.getType() != XmlRpcValue::TypeArray) refuse(name, v, "must be a list of [x, y] vertices (m)");
    std::vector<fgdwa::Vec2> vertices;
    for (int i = 0; i < v.size(); ++i) {
      XmlRpcValue point = v[i];
      if (point.getType() != XmlRpcValue::TypeArray || point.size() != 2)
        refuse(name + "[" + std::to_string(i) + "]", point, "must be [x, y]");
      vertices.emplace_back(as_number(name, point[0]), as_number(name, point[1]));
    }
    try {
      field = fgdwa::Footprint::polygon(vertices);
    } catch (const Error& e) {
      refuse(name, v, e.what());
    }
  };
  auto json = [&field] {
    if (field.is_circle()) return std::string("null");
    std::string out = "[";
    const auto& vs = field.vertices();
    for (std::size_t i = 0; i < vs.size(); ++i)
      out += std::string(i ? ", " : "") + "[" + json_number(vs[i].x()) + ", " + json_number(vs[i].y()) + "]";
    return out + "]";
  };
  return {name, set, json};
}

Entry footprint_radius(fgdwa::Footprint& field) {
  const std::string name = "footprint_radius";
  auto set = [name, &field](const XmlRpcValue& v) {
    try {
      field = fgdwa::Footprint::circle(as_number(name, v));
    } catch (const Error& e) {
      refuse(name, v, e.what());
    }
  };
  auto json = [&field] { return field.is_circle() ? json_number(field.radius()) : std::string("null"); };
  return {name, set, json};
}

// Entries for every field of a parameter struct, named "<prefix><field>" with
// nested sets '/'-joined, as its schema lists them (fgdwa/params.hpp).
template <class P>
struct EntryCollector {
  P& p;
  std::string prefix;
  std::vector<Entry>& out;

  void real(const char* name, double P::*member, const char*, fgdwa::Bounds, const char*) {
    out.push_back(number(prefix + name, p.*member));
  }
  void integer(const char* name, int P::*member, const char*, fgdwa::Bounds, const char*) {
    out.push_back(fgdwa_ros::integer(prefix + name, p.*member));
  }
  void flag(const char* name, bool P::*member, const char*) { out.push_back(fgdwa_ros::flag(prefix + name, p.*member)); }
  template <class E>
  void choice(const char* name, E P::*member, const char*) {
    const auto values = enum_values(E{});
    out.push_back(fgdwa_ros::choice(prefix + name, p.*member, std::vector<E>(values.begin(), values.end())));
  }
  void text(const char* name, std::string P::*member, const char*) {
    out.push_back(fgdwa_ros::text(prefix + name, p.*member));
  }
  template <class L>
  void critics(const char* name, L P::*member, const char*) {
    out.push_back(fgdwa_ros::critics(prefix + name, p.*member));
  }
  template <class G>
  void group(const char* name, G P::*member, const char*) {
    EntryCollector<G> nested{p.*member, prefix + name + "/", out};
    G::fields(nested);
  }
};

template <class P>
void add_entries(P& params, std::vector<Entry>& out) {
  EntryCollector<P> collector{params, std::string(P::kName) + "/", out};
  P::fields(collector);
}

std::vector<Entry> entries(NodeConfig& c) {
  NodeParams& n = c.node;
  std::vector<Entry> out = {
      text("preset", n.preset), text("robot", n.robot), text("scan_topic", n.scan_topic),
      text("odom_topic", n.odom_topic), text("cmd_vel_topic", n.cmd_vel_topic), text("map_topic", n.map_topic),
      text("global_frame", n.global_frame), text("base_frame", n.base_frame), text("map_frame", n.map_frame),
      flag("publish_map_odom_tf", n.publish_map_odom_tf), text("mapping", n.mapping),
      number("map_resolution", n.map_resolution), number("map_margin", n.map_margin),
      integer("occupied_threshold", n.occupied_threshold), number("scan_timeout", n.scan_timeout),
      number("odom_timeout", n.odom_timeout), number("transform_timeout", n.transform_timeout),
      number("patience", n.patience),
      text("rollout_colour_by", n.rollout_colour_by),
      footprint(c.footprint), footprint_radius(c.footprint), flag("fuzzy", c.fuzzy),
      number("lidar/noise_std", c.lidar_noise_std),
  };
  add_entries(c.limits, out);
  add_entries(c.planner, out);
  add_entries(c.navigator, out);
  add_entries(c.detect_window, out);
  return out;
}

// Runs a struct's validate(), its message prefixed with where its fields live.
template <typename Params>
void check(const std::string& where, const Params& params) {
  try {
    params.validate();
  } catch (const Error& e) {
    throw Error("parameters ~" + where + "/: " + e.what());
  }
}

}  // namespace

void NodeParams::validate() const {
  auto fail = [](const std::string& name, const std::string& value, const std::string& rule) {
    throw Error("parameter ~" + name + " = " + value + ": " + rule);
  };
  auto positive = [&](const std::string& name, double value) {
    if (!(std::isfinite(value) && value > 0.0)) fail(name, json_number(value), "must be a finite number > 0");
  };
  for (const auto& [name, value] : {std::pair{"scan_topic", scan_topic}, {"odom_topic", odom_topic},
                                    {"cmd_vel_topic", cmd_vel_topic}, {"map_topic", map_topic},
                                    {"global_frame", global_frame}, {"base_frame", base_frame},
                                    {"map_frame", map_frame}})
    if (value.empty()) fail(name, "''", "must not be empty");
  if (publish_map_odom_tf && map_frame == global_frame)
    fail("map_frame", json_text(map_frame), "must differ from global_frame while publish_map_odom_tf is on");
  if (mapping != "scan" && mapping != "known") fail("mapping", json_text(mapping), "expected scan or known");
  positive("map_resolution", map_resolution);
  if (!(std::isfinite(map_margin) && map_margin >= 0.0))
    fail("map_margin", json_number(map_margin), "must be a finite number >= 0");
  if (occupied_threshold < 1 || occupied_threshold > 100)
    fail("occupied_threshold", std::to_string(occupied_threshold), "must be in [1, 100]");
  positive("scan_timeout", scan_timeout);
  positive("odom_timeout", odom_timeout);
  positive("transform_timeout", transform_timeout);
  positive("patience", patience);
}

namespace {

// move_base's TrajectoryPlannerROS / DWAPlannerROS and Nav2 DWB names that
// mean one of fgdwa's parameters (the table in docs/ros.md), bare or under
// their planner's namespace.
struct MoveBaseAlias {
  const char* name;
  const char* target;
  XmlRpcValue (*transform)(const std::string&, const XmlRpcValue&);
};

XmlRpcValue period_of_frequency(const std::string& name, const XmlRpcValue& value) {
  const double frequency = as_number(name, value);
  if (!(frequency > 0.0) || !std::isfinite(frequency)) refuse(name, value, "must be a finite number > 0 (Hz)");
  return XmlRpcValue(1.0 / frequency);
}

constexpr MoveBaseAlias kAliases[] = {
    {"max_vel_x", "limits/v_max", nullptr},
    {"min_vel_x", "limits/v_min", nullptr},
    {"max_vel_theta", "limits/omega_max", nullptr},
    {"max_rot_vel", "limits/omega_max", nullptr},
    {"max_vel_trans", "limits/v_max", nullptr},
    {"acc_lim_x", "limits/acc_v", nullptr},
    {"acc_lim_theta", "limits/acc_omega", nullptr},
    {"decel_lim_x", "limits/brake_v", nullptr},
    {"decel_lim_theta", "limits/brake_omega", nullptr},
    {"vx_samples", "planner/window/n_v", nullptr},
    {"vtheta_samples", "planner/window/n_omega", nullptr},
    {"vth_samples", "planner/window/n_omega", nullptr},
    {"sim_time", "planner/sim_time", nullptr},
    {"xy_goal_tolerance", "planner/goal_tolerance", nullptr},
    {"robot_radius", "footprint_radius", nullptr},
    {"controller_frequency", "planner/dt", period_of_frequency},
};

const MoveBaseAlias* find_alias(const std::string& name) {
  std::string bare = name;
  for (const char* space : {"TrajectoryPlannerROS/", "DWAPlannerROS/", "FollowPath/"})
    if (bare.rfind(space, 0) == 0) bare = bare.substr(std::string(space).size());
  for (const MoveBaseAlias& alias : kAliases)
    if (bare == alias.name) return &alias;
  return nullptr;
}

}  // namespace

NodeConfig read_config(const ros::NodeHandle& private_nh) {
  NodeConfig config;
  auto read = [&](const Entry& entry) {
    XmlRpcValue value;
    if (private_nh.getParam(entry.name, value)) entry.set(value);
  };
  // The presets first: the other parameters replace their values.
  std::vector<Entry> table = entries(config);
  read(table[0]);
  read(table[1]);
  const auto presets = fgdwa::preset_names();
  if (std::find(presets.begin(), presets.end(), config.node.preset) == presets.end())
    throw Error("parameter ~preset = " + json_text(config.node.preset) + ": " + "unknown planner preset");
  const fgdwa::PlannerPreset preset = fgdwa::planner_preset(config.node.preset);
  config.planner = preset.params;
  config.fuzzy = preset.fuzzy;
  try {
    const fgdwa::RobotPreset robot = fgdwa::robot_preset(config.node.robot);
    config.limits = robot.limits;
    config.footprint = robot.footprint;
  } catch (const Error& e) {
    throw Error("parameter ~robot = " + json_text(config.node.robot) + ": " + e.what());
  }

  std::set<std::string> known;
  for (const Entry& entry : table) {
    known.insert(entry.name);
    read(entry);
  }
  std::vector<std::string> names;
  ros::param::getParamNames(names);
  const std::string prefix = private_nh.getNamespace() + "/";
  const std::vector<std::string> known_names(known.begin(), known.end());
  for (const std::string& full : names) {
    if (full.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string name = full.substr(prefix.size());
    if (known.count(name)) continue;
    if (const MoveBaseAlias* alias = find_alias(name)) {
      const Entry* target = nullptr;
      for (const Entry& entry : table)
        if (entry.name == alias->target) target = &entry;
      XmlRpcValue value;
      private_nh.getParam(name, value);
      if (alias->transform) value = alias->transform(name, value);
      target->set(value);
      ROS_INFO_STREAM("fgdwa_node: ~" << name << " (move_base's name) sets ~" << alias->target << " = " << shown(value));
      continue;
    }
    std::string hint;
    for (const std::string& near : fgdwa::nearest_names(name, known_names))
      hint += std::string(hint.empty() ? "; did you mean ~" : " or ~") + near;
    throw Error("parameter ~" + name + ": unknown to fgdwa_node" + (hint.empty() ? "" : hint + "?") +
                " (docs/parameters.md lists the names it reads)");
  }
  if (private_nh.hasParam("footprint") && private_nh.hasParam("footprint_radius"))
    throw Error("parameters ~footprint and ~footprint_radius: give one of them, not both");

  config.node.validate();
  check("limits", config.limits);
  check("planner", config.planner);
  check("navigator", config.navigator);
  check("detect_window", config.detect_window);
  fgdwa::LidarParams lidar;
  lidar.noise_std = config.lidar_noise_std;
  check("lidar", lidar);
  // Critic names and their params are checked when a planner is built: build one now, not at the first goal.
  std::vector<std::string> critic_names;
  try {
    fgdwa::LocalPlanner planner(config.limits, config.footprint, config.planner);
    critic_names = planner.last_result().critic_names;
  } catch (const Error& e) {
    throw Error(std::string("parameters ~planner/critics: ") + e.what());
  }
  const std::string& colour_by = config.node.rollout_colour_by;
  if (colour_by != "total" && std::find(critic_names.begin(), critic_names.end(), colour_by) == critic_names.end()) {
    std::string allowed = "total";
    for (const std::string& name : critic_names) allowed += ", " + name;
    throw Error("parameter ~rollout_colour_by = " + json_text(colour_by) + ": expected one of " + allowed +
                " (total, or a critic of ~planner/critics)");
  }
  return config;
}

std::string NodeConfig::to_json() const {
  // entries() wants mutable fields to read into; writing them out changes nothing.
  NodeConfig& self = const_cast<NodeConfig&>(*this);
  std::string out = "{";
  bool first = true;
  for (const Entry& entry : entries(self)) {
    out += std::string(first ? "" : ", ") + json_text(entry.name) + ": " + entry.json();
    first = false;
  }
  return out + "}";
}

}  // namespace fgdwa_ros
