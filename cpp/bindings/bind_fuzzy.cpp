#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <sstream>

#include "convert.hpp"
#include "fgdwa/error.hpp"
#include "fgdwa/fuzzy.hpp"

namespace py = pybind11;
using namespace fgdwa;
using py_convert::FloatArg;
using py_convert::IntArg;
using py_convert::to_float;
using py_convert::to_int;
using py_convert::to_number;
using py_convert::to_word;

namespace {

using MF = MembershipFunction;
using DoubleArray = py::array_t<double, py::array::c_style>;

int to_resolution(const IntArg& resolution) {
  return to_int<int>(resolution, "resolution", MamdaniEngine::kMinResolution, MamdaniEngine::kMaxResolution);
}

// A float64 array of any shape, or an error naming `name`.
DoubleArray to_array(py::handle obj, const std::string& name) {
  py::array array;
  try {
    array = py::array::ensure(obj);
  } catch (const py::error_already_set&) {
  }
  if (!array) throw Error(name + ": expected an array of numbers");
  const char kind = array.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw Error(name + ": expected numbers, got dtype " + std::string(py::str(array.dtype())));
  return DoubleArray::ensure(array);
}

// f(x) for a float, or element-wise for an array of any shape.
template <typename F>
py::object map_values(py::handle x, const std::string& name, F&& f) {
  if (py::isinstance<py::float_>(x) || py::isinstance<py::int_>(x)) {
    const double value = to_number(x, name);
    if (std::isnan(value)) throw Error(name + " is NaN");
    return py::float_(f(value));
  }
  DoubleArray in = to_array(x, name);
  DoubleArray out(std::vector<py::ssize_t>(in.shape(), in.shape() + in.ndim()));
  for (py::ssize_t i = 0; i < in.size(); ++i) {
    if (std::isnan(in.data()[i])) throw Error(name + "[" + std::to_string(i) + "] is NaN");
    out.mutable_data()[i] = f(in.data()[i]);
  }
  if (in.ndim() == 0) return py::float_(out.data()[0]);
  return std::move(out);
}

std::string repr_number(double v) { return std::string(py::repr(py::float_(v))); }

std::string repr_mf(const MF& mf) {
  std::string s = "MembershipFunction." + mf.shape_name() + "(";
  for (std::size_t i = 0; i < mf.n_params(); ++i) s += (i ? ", " : "") + repr_number(mf.params[i]);
  return s + ")";
}

std::vector<FuzzyTerm> to_terms(py::handle terms, const std::string& variable) {
  const std::string field = "variable " + variable + " terms";
  std::vector<FuzzyTerm> out;
  const auto add = [&](py::handle name, py::handle mf) {
    const std::string term = to_word(name, field + " name");
    if (!py::isinstance<MF>(mf))
      throw Error(field + "['" + term + "']: expected a MembershipFunction, got " +
                  std::string(py::str(py::type::of(mf).attr("__name__"))));
    out.push_back({term, mf.cast<MF>()});
  };
  if (py::isinstance<py::dict>(terms)) {
    for (auto item : terms.cast<py::dict>()) add(item.first, item.second);
    return out;
  }
  if (py::isinstance<py::str>(terms) || !py::hasattr(terms, "__iter__"))
    throw Error(field + ": expected a dict {name: MembershipFunction} or (name, MembershipFunction) pairs");
  for (auto item : terms) {
    py::sequence pair;
    if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item) || py::len(item) != 2)
      throw Error(field + ": expected (name, MembershipFunction) pairs, got " + std::string(py::repr(item)));
    pair = item.cast<py::sequence>();
    add(pair[0], pair[1]);
  }
  return out;
}

std::pair<double, double> to_domain(py::handle domain, const std::string& variable) {
  const std::string field = "variable " + variable + " domain";
  if (py::isinstance<py::str>(domain) || !py::isinstance<py::sequence>(domain) || py::len(domain) != 2)
    throw Error(field + ": expected (lo, hi), got " + std::string(py::repr(domain)));
  auto seq = domain.cast<py::sequence>();
  return {to_number(seq[0], field + " lo"), to_number(seq[1], field + " hi")};
}

std::vector<FuzzyClause> to_clauses(py::handle clauses, const std::string& field) {
  std::vector<FuzzyClause> out;
  if (py::isinstance<py::dict>(clauses)) {
    for (auto item : clauses.cast<py::dict>())
      out.push_back({to_word(item.first, field + " variable"), to_word(item.second, field + " term")});
    return out;
  }
  if (py::isinstance<py::str>(clauses) || !py::hasattr(clauses, "__iter__"))
    throw Error(field + ": expected a dict {variable: term} or (variable, term) pairs");
  for (auto item : clauses) {
    if (!py::isinstance<py::sequence>(item) || py::isinstance<py::str>(item) || py::len(item) != 2)
      throw Error(field + ": expected (variable, term) pairs, got " + std::string(py::repr(item)));
    auto pair = item.cast<py::sequence>();
    out.push_back({to_word(pair[0], field + " variable"), to_word(pair[1], field + " term")});
  }
  return out;
}

std::vector<FuzzyVariable> to_variables(py::handle vars, const std::string& field) {
  if (py::isinstance<py::str>(vars) || !py::hasattr(vars, "__iter__"))
    throw Error(field + ": expected a list of FuzzyVariable");
  std::vector<FuzzyVariable> out;
  for (auto v : vars) {
    if (!py::isinstance<FuzzyVariable>(v))
      throw Error(field + ": expected FuzzyVariable items, got " +
                  std::string(py::str(py::type::of(v).attr("__name__"))));
    out.push_back(v.cast<FuzzyVariable>());
  }
  return out;
}

std::vector<FuzzyRule> to_rules(py::handle rules) {
  if (py::isinstance<py::str>(rules) || !py::hasattr(rules, "__iter__"))
    throw Error("rules: expected a list of FuzzyRule or rule strings");
  std::vector<FuzzyRule> out;
  for (auto r : rules) {
    if (py::isinstance<py::str>(r))
      out.push_back(FuzzyRule::parse(r.cast<std::string>()));
    else if (py::isinstance<FuzzyRule>(r))
      out.push_back(r.cast<FuzzyRule>());
    else
      throw Error("rules[" + std::to_string(out.size()) + "]: expected a FuzzyRule or a rule string, got " +
                  std::string(py::str(py::type::of(r).attr("__name__"))));
  }
  return out;
}

// Inputs from positional values (in input order) and keywords, each input exactly once.
std::vector<py::object> gather_inputs(const MamdaniEngine& engine, const py::args& args, const py::kwargs& kwargs,
                                      const std::string& what) {
  const auto& inputs = engine.inputs();
  std::string names;
  for (const auto& v : inputs) names += (names.empty() ? "" : ", ") + v.name;
  if (args.size() > inputs.size())
    throw Error(what + ": expected at most " + std::to_string(inputs.size()) + " inputs (" + names + "), got " +
                std::to_string(args.size()));
  std::vector<py::object> values(inputs.size());
  for (std::size_t i = 0; i < args.size(); ++i) values[i] = py::reinterpret_borrow<py::object>(args[i]);
  for (auto item : kwargs) {
    const std::string name = item.first.cast<std::string>();
    const std::size_t i = engine.input_index(name);
    if (values[i]) throw Error(what + ": input " + name + " given twice");
    values[i] = py::reinterpret_borrow<py::object>(item.second);
  }
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (!values[i]) throw Error(what + ": missing input '" + inputs[i].name + "' (inputs: " + names + ")");
  return values;
}

std::vector<double> gather_numbers(const MamdaniEngine& engine, const py::args& args, const py::kwargs& kwargs,
                                   const std::string& what) {
  const auto objects = gather_inputs(engine, args, kwargs, what);
  std::vector<double> values(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i)
    values[i] = to_number(objects[i], "input " + engine.inputs()[i].name);
  return values;
}

py::dict name_values(const std::vector<FuzzyVariable>& vars, const std::vector<double>& values) {
  py::dict out;
  for (std::size_t i = 0; i < vars.size(); ++i) out[py::str(vars[i].name)] = values[i];
  return out;
}

std::string repr_variable(const FuzzyVariable& v) {
  std::string s = "FuzzyVariable('" + v.name + "', (" + repr_number(v.lo) + ", " + repr_number(v.hi) + "), {";
  for (std::size_t i = 0; i < v.terms.size(); ++i)
    s += (i ? ", '" : "'") + v.terms[i].name + "': " + repr_mf(v.terms[i].membership);
  return s + "})";
}

py::list clause_list(const std::vector<FuzzyClause>& clauses) {
  py::list out;
  for (const auto& c : clauses) out.append(py::make_tuple(c.variable, c.term));
  return out;
}

}  // namespace

void init_fuzzy(py::module_& m) {
  py::class_<MF>(m, "MembershipFunction",
                 "A fuzzy membership function: degrees in [0, 1]. Build one with triangle(a, b, c), "
                 "trapezoid(a, b, c, d) or gaussian(mean, sigma); a == b or b == c makes a shoulder. "
                 "Calling it gives the degree of a number, or of every element of an array.")
      .def_static(
          "triangle",
          [](FloatArg a, FloatArg b, FloatArg c) {
            return MF::triangle(to_float(a, "a"), to_float(b, "b"), to_float(c, "c"));
          },
          py::arg("a"), py::arg("b"), py::arg("c"), "Zero outside [a, c], 1 at b, linear in between (a <= b <= c, a < c).")
      .def_static(
          "trapezoid",
          [](FloatArg a, FloatArg b, FloatArg c, FloatArg d) {
            return MF::trapezoid(to_float(a, "a"), to_float(b, "b"), to_float(c, "c"), to_float(d, "d"));
          },
          py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
          "Zero outside [a, d], 1 on [b, c], linear in between (a <= b <= c <= d, a < d).")
      .def_static(
          "gaussian",
          [](FloatArg mean, FloatArg sigma) { return MF::gaussian(to_float(mean, "mean"), to_float(sigma, "sigma")); },
          py::arg("mean"), py::arg("sigma"), "exp(-((x - mean) / sigma)^2 / 2), sigma > 0.")
      .def_property_readonly("shape", &MF::shape_name, "'triangle', 'trapezoid' or 'gaussian'.")
      .def_property_readonly(
          "params",
          [](const MF& mf) {
            py::tuple out(mf.n_params());
            for (std::size_t i = 0; i < mf.n_params(); ++i) out[i] = py::float_(mf.params[i]);
            return out;
          },
          "The shape's parameters: (a, b, c), (a, b, c, d) or (mean, sigma).")
      .def(
          "__call__", [](const MF& mf, py::handle x) { return map_values(x, "x", [&](double v) { return mf(v); }); },
          py::arg("x"), "Degree of x (a number or an array) in this set.")
      .def("__eq__", [](const MF& a, const MF& b) { return a.shape == b.shape && a.params == b.params; })
      .def("__repr__", &repr_mf);

  py::class_<FuzzyVariable>(m, "FuzzyVariable",
                            "A linguistic variable: a name, a domain (lo, hi) and named terms "
                            "(a dict {name: MembershipFunction}, in order). Names are letters, digits "
                            "and '_'. Every term must reach a positive degree inside the domain.")
      .def(py::init([](py::handle name, py::handle domain, py::handle terms) {
             const std::string n = to_word(name, "variable name");
             const auto [lo, hi] = to_domain(domain, n);
             FuzzyVariable v{n, lo, hi, to_terms(terms, n)};
             v.validate();
             return v;
           }),
           py::arg("name"), py::arg("domain"), py::arg("terms"))
      .def_static(
          "uniform",
          [](const std::string& name, py::handle domain, std::vector<std::string> terms) {
            const auto [lo, hi] = to_domain(domain, name);
            return uniform_partition(name, lo, hi, terms);
          },
          py::arg("name"), py::arg("domain"), py::arg("terms") = std::vector<std::string>{"S", "M", "L"},
          "The uniform triangular partition of the domain: evenly spaced peaks, shoulders at both "
          "ends (for S, M, L: S = tri(lo, lo, mid), M = tri(lo, mid, hi), L = tri(mid, hi, hi)).")
      .def_property_readonly("name", [](const FuzzyVariable& v) { return v.name; })
      .def_property_readonly("lo", [](const FuzzyVariable& v) { return v.lo; })
      .def_property_readonly("hi", [](const FuzzyVariable& v) { return v.hi; })
      .def_property_readonly("domain", [](const FuzzyVariable& v) { return py::make_tuple(v.lo, v.hi); })
      .def_property_readonly(
          "terms",
          [](const FuzzyVariable& v) {
            py::dict out;
            for (const auto& t : v.terms) out[py::str(t.name)] = py::cast(t.membership);
            return out;
          },
          "{name: MembershipFunction}, in order.")
      .def_property_readonly("term_names",
                             [](const FuzzyVariable& v) {
                               std::vector<std::string> names;
                               for (const auto& t : v.terms) names.push_back(t.name);
                               return names;
                             })
      .def(
          "membership",
          [](const FuzzyVariable& v, const std::string& term, py::handle x) {
            v.membership(term, v.lo);  // names an unknown term
            const MF& mf = v.terms[static_cast<std::size_t>(v.term_index(term))].membership;
            return map_values(x, "x", [&](double value) { return mf(value); });
          },
          py::arg("term"), py::arg("x"), "Degree of x (a number or an array, not clamped) in the named term.")
      .def("__repr__", &repr_variable);

  py::class_<FuzzyRule>(m, "FuzzyRule",
                        "IF every antecedent holds (AND = min) THEN every consequent. Build one from "
                        "text, FuzzyRule('IF I is S AND D is M THEN beta is S AND delta is M'), or from "
                        "{variable: term} dicts: FuzzyRule({'I': 'S', 'D': 'M'}, {'beta': 'S'}).")
      .def(py::init([](py::handle antecedents, py::handle consequents) {
             if (consequents.is_none()) {
               if (!py::isinstance<py::str>(antecedents))
                 throw Error("rule: give the rule text, or both antecedents and consequents");
               return FuzzyRule::parse(antecedents.cast<std::string>());
             }
             return FuzzyRule{to_clauses(antecedents, "rule antecedents"), to_clauses(consequents, "rule consequents")};
           }),
           py::arg("antecedents"), py::arg("consequents") = py::none())
      .def_static("parse", &FuzzyRule::parse, py::arg("text"),
                  "Read 'IF v is t AND ... THEN v is t AND ...' (keywords in any case).")
      .def_property_readonly("antecedents", [](const FuzzyRule& r) { return clause_list(r.antecedents); },
                             "[(variable, term)] of the IF part.")
      .def_property_readonly("consequents", [](const FuzzyRule& r) { return clause_list(r.consequents); },
                             "[(variable, term)] of the THEN part.")
      .def("__str__", &FuzzyRule::to_string)
      .def("__repr__", [](const FuzzyRule& r) { return "FuzzyRule('" + r.to_string() + "')"; });

  py::class_<MamdaniEngine>(
      m, "MamdaniEngine",
      "Mamdani inference: AND = min, implication = min (clip), aggregation = max, centroid "
      "defuzzification on a uniform grid of `resolution` points per output domain (the centroid of "
      "the piecewise-linear aggregate through those points). Inputs outside their domains are "
      "clamped. When no rule fires for an output, it is the midpoint of its domain.")
      .def(py::init([](py::handle inputs, py::handle outputs, py::handle rules, IntArg resolution) {
             return MamdaniEngine(to_variables(inputs, "inputs"), to_variables(outputs, "outputs"), to_rules(rules),
                                  to_resolution(resolution));
           }),
           py::arg("inputs"), py::arg("outputs"), py::arg("rules"),
           py::arg("resolution") = MamdaniEngine::kDefaultResolution,
           "inputs and outputs: lists of FuzzyVariable; rules: FuzzyRule objects or rule strings.")
      .def(
          "evaluate",
          [](const MamdaniEngine& e, const py::args& args, const py::kwargs& kwargs) {
            const auto values = gather_numbers(e, args, kwargs, "evaluate");
            return name_values(e.outputs(), e.evaluate(values));
          },
          "evaluate(*values, **inputs) -> {output: value}: one inference, inputs by position (in the "
          "order of `inputs`) or by name, e.g. engine.evaluate(I=0.4, D=1.2).")
      .def(
          "evaluate_grid",
          [](const MamdaniEngine& e, const py::args& args, const py::kwargs& kwargs) {
            const auto objects = gather_inputs(e, args, kwargs, "evaluate_grid");
            py::list arrays;
            for (std::size_t i = 0; i < objects.size(); ++i)
              arrays.append(to_array(objects[i], "input " + e.inputs()[i].name));
            py::tuple broadcast;
            try {
              broadcast = py::module_::import("numpy").attr("broadcast_arrays")(*arrays);
            } catch (const py::error_already_set& err) {
              throw Error(std::string("evaluate_grid: the input arrays do not broadcast together (") + err.what() +
                          ")");
            }
            std::vector<DoubleArray> in;
            for (auto a : broadcast) in.push_back(DoubleArray::ensure(a));  // contiguous copies
            const std::vector<py::ssize_t> shape(in[0].shape(), in[0].shape() + in[0].ndim());
            std::vector<DoubleArray> out;
            for (std::size_t o = 0; o < e.n_outputs(); ++o) out.emplace_back(shape);
            const py::ssize_t n = in[0].size();
            for (std::size_t i = 0; i < in.size(); ++i)
              for (py::ssize_t k = 0; k < n; ++k)
                if (std::isnan(in[i].data()[k]))
                  throw Error("input " + e.inputs()[i].name + ": element " + std::to_string(k) + " is nan");
            std::vector<const double*> src;
            std::vector<double*> dst;
            for (auto& a : in) src.push_back(a.data());
            for (auto& a : out) dst.push_back(a.mutable_data());
            {
              py::gil_scoped_release release;
              std::vector<double> x(in.size()), y(out.size());
              for (py::ssize_t k = 0; k < n; ++k) {
                for (std::size_t i = 0; i < src.size(); ++i) x[i] = src[i][k];
                e.evaluate(x.data(), x.size(), y.data(), y.size());
                for (std::size_t o = 0; o < dst.size(); ++o) dst[o][k] = y[o];
              }
            }
            py::dict result;
            for (std::size_t o = 0; o < out.size(); ++o) result[py::str(e.outputs()[o].name)] = out[o];
            return result;
          },
          "evaluate_grid(*arrays, **inputs) -> {output: array}: one inference per element of input "
          "arrays that broadcast together (numpy rules), e.g. "
          "engine.evaluate_grid(*np.meshgrid(I_axis, D_axis)). Each output has the broadcast shape.")
      .def(
          "firing_strengths",
          [](const MamdaniEngine& e, const py::args& args, const py::kwargs& kwargs) {
            return e.firing_strengths(gather_numbers(e, args, kwargs, "firing_strengths"));
          },
          "Firing strength of each rule (in the order of `rules`) for these inputs.")
      .def_property_readonly("inputs", &MamdaniEngine::inputs)
      .def_property_readonly("outputs", &MamdaniEngine::outputs)
      .def_property_readonly("rules", &MamdaniEngine::rules)
      .def_property_readonly("resolution", &MamdaniEngine::resolution)
      .def_property_readonly("input_names",
                             [](const MamdaniEngine& e) {
                               std::vector<std::string> names;
                               for (const auto& v : e.inputs()) names.push_back(v.name);
                               return names;
                             })
      .def_property_readonly("output_names",
                             [](const MamdaniEngine& e) {
                               std::vector<std::string> names;
                               for (const auto& v : e.outputs()) names.push_back(v.name);
                               return names;
                             })
      .def("__repr__", [](const MamdaniEngine& e) {
        const auto list = [](const std::vector<FuzzyVariable>& vars) {
          std::ostringstream s;
          for (std::size_t i = 0; i < vars.size(); ++i)
            s << (i ? ", " : "") << vars[i].name << " in [" << vars[i].lo << ", " << vars[i].hi << "]";
          return s.str();
        };
        return "MamdaniEngine(inputs: " + list(e.inputs()) + "; outputs: " + list(e.outputs()) + "; " +
               std::to_string(e.rules().size()) + " rules; resolution " + std::to_string(e.resolution()) + ")";
      });

  m.def(
      "paper_fuzzy_controller", [](IntArg resolution) { return paper_fuzzy_controller(to_resolution(resolution)); },
      py::arg("resolution") = MamdaniEngine::kDefaultResolution,
      "The paper's weight controller (Section 2.2.2, Tables 3 and 4): inputs I (obstacle density, "
      "[0, 2]) and D (path deviation, [0, 5] m), outputs beta ([0, 1]) and delta ([0, 5]), S/M/L "
      "uniform triangular partitions, 9 rules.");
  m.def(
      "mover_fuzzy_controller", [](IntArg resolution) { return mover_fuzzy_controller(to_resolution(resolution)); },
      py::arg("resolution") = MamdaniEngine::kDefaultResolution,
      "The paper's controller with a third input, T ([0, 3] s): the time to the nearest predicted contact with a "
      "mover. The paper's rules stand; as a contact nears (T 'near' below 3 s, 'imminent' below 1.5 s) rules "
      "adding the delta term one and two lower fire; beta is the paper's. FuzzyWeights(mover_fuzzy_controller()) runs it.");
  m.attr("CONTACT_TIME_RANGE") = kContactTimeRange;
}
