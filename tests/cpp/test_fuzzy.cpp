#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "fgdwa/controller.hpp"
#include "fgdwa/fuzzy.hpp"
#include "fgdwa/weights.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

using MF = MembershipFunction;
using test::expect_error_naming;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

// Centroid of a clipped shoulder tri(0, 0, s) at level w, worked out by hand:
// a rectangle [0, x_w] of height w, then a triangle down to 0 at s.
double clipped_shoulder_centroid(double s, double w) {
  const double xw = s * (1.0 - w);
  const double rect = w * xw, tri = 0.5 * w * (s - xw);
  return (rect * xw / 2.0 + tri * (xw + (s - xw) / 3.0)) / (rect + tri);
}

// The engine's Mamdani inference computed the slow way: aggregate on a very fine
// grid and integrate with the trapezoid rule.
std::vector<double> brute_force(const MamdaniEngine& engine, const std::vector<double>& inputs, int points = 20001) {
  const auto firing = engine.firing_strengths(inputs);
  std::vector<double> out;
  for (const auto& v : engine.outputs()) {
    double area = 0.0, moment = 0.0;
    const double h = (v.hi - v.lo) / (points - 1);
    for (int k = 0; k < points; ++k) {
      const double x = v.lo + h * k;
      double y = 0.0;
      for (std::size_t r = 0; r < engine.rules().size(); ++r)
        for (const auto& c : engine.rules()[r].consequents)
          if (c.variable == v.name) y = std::max(y, std::min(firing[r], v.membership(c.term, x)));
      const double weight = (k == 0 || k == points - 1) ? 0.5 : 1.0;
      area += weight * y;
      moment += weight * x * y;
    }
    out.push_back(area > 0.0 ? moment / area : 0.5 * (v.lo + v.hi));
  }
  return out;
}

TEST(Membership, TriangleValuesAndShoulders) {
  const MF t = MF::triangle(0.0, 1.0, 3.0);
  EXPECT_DOUBLE_EQ(t(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(t(0.0), 0.0);
  EXPECT_DOUBLE_EQ(t(0.5), 0.5);
  EXPECT_DOUBLE_EQ(t(1.0), 1.0);
  EXPECT_DOUBLE_EQ(t(2.0), 0.5);
  EXPECT_DOUBLE_EQ(t(3.0), 0.0);
  EXPECT_DOUBLE_EQ(t(4.0), 0.0);
  const MF left = MF::triangle(0.0, 0.0, 1.0);  // a == b: a left shoulder
  EXPECT_DOUBLE_EQ(left(-0.1), 0.0);
  EXPECT_DOUBLE_EQ(left(0.0), 1.0);
  EXPECT_DOUBLE_EQ(left(0.25), 0.75);
  EXPECT_DOUBLE_EQ(left(1.0), 0.0);
  const MF right = MF::triangle(0.0, 1.0, 1.0);  // b == c: a right shoulder
  EXPECT_DOUBLE_EQ(right(1.0), 1.0);
  EXPECT_DOUBLE_EQ(right(0.75), 0.75);
  EXPECT_DOUBLE_EQ(right(1.1), 0.0);
  EXPECT_EQ(t.to_string(), "triangle(0, 1, 3)");
  EXPECT_TRUE(std::isnan(t(kNaN)));
}

TEST(Membership, TrapezoidAndGaussianValues) {
  const MF z = MF::trapezoid(0.0, 1.0, 2.0, 4.0);
  EXPECT_DOUBLE_EQ(z(-0.5), 0.0);
  EXPECT_DOUBLE_EQ(z(0.5), 0.5);
  EXPECT_DOUBLE_EQ(z(1.0), 1.0);
  EXPECT_DOUBLE_EQ(z(1.5), 1.0);
  EXPECT_DOUBLE_EQ(z(2.0), 1.0);
  EXPECT_DOUBLE_EQ(z(3.0), 0.5);
  EXPECT_DOUBLE_EQ(z(4.0), 0.0);
  const MF box = MF::trapezoid(1.0, 1.0, 2.0, 2.0);  // both shoulders: a crisp interval
  EXPECT_DOUBLE_EQ(box(1.0), 1.0);
  EXPECT_DOUBLE_EQ(box(2.0), 1.0);
  EXPECT_DOUBLE_EQ(box(2.01), 0.0);
  const MF g = MF::gaussian(1.0, 0.5);
  EXPECT_DOUBLE_EQ(g(1.0), 1.0);
  EXPECT_NEAR(g(1.5), std::exp(-0.5), 1e-15);
  EXPECT_NEAR(g(0.0), std::exp(-2.0), 1e-15);
  EXPECT_EQ(g.n_params(), 2u);
  EXPECT_EQ(g.shape_name(), "gaussian");
}

TEST(Membership, DegreesStayInTheUnitInterval) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5.0, 5.0);
  for (int i = 0; i < 200; ++i) {
    double p[4] = {u(rng), u(rng), u(rng), u(rng)};
    std::sort(p, p + 4);
    const MF shapes[3] = {MF::triangle(p[0], p[1], p[3]), MF::trapezoid(p[0], p[1], p[2], p[3]),
                          MF::gaussian(p[1], 0.1 + std::abs(p[2]))};
    for (const MF& mf : shapes)
      for (int k = 0; k < 50; ++k) {
        const double y = mf(u(rng) * 1.5);
        ASSERT_GE(y, 0.0);
        ASSERT_LE(y, 1.0);
      }
  }
}

TEST(Membership, RejectsBadParameters) {
  expect_error_naming([] { MF::triangle(1.0, 0.0, 2.0); }, "a <= b <= c");
  expect_error_naming([] { MF::triangle(0.0, 2.0, 1.0); }, "triangle(0, 2, 1)");
  expect_error_naming([] { MF::triangle(1.0, 1.0, 1.0); }, "a < c");
  expect_error_naming([] { MF::triangle(0.0, kNaN, 1.0); }, "finite");
  expect_error_naming([] { MF::trapezoid(0.0, 2.0, 1.0, 3.0); }, "a <= b <= c <= d");
  expect_error_naming([] { MF::trapezoid(0.0, 0.0, 0.0, 0.0); }, "a < d");
  expect_error_naming([] { MF::trapezoid(0.0, 1.0, 2.0, INFINITY); }, "finite");
  expect_error_naming([] { MF::gaussian(0.0, 0.0); }, "sigma");
  expect_error_naming([] { MF::gaussian(0.0, -1.0); }, "sigma");
  expect_error_naming([] { MF::gaussian(kNaN, 1.0); }, "finite");
  MF bad{MF::Shape::Triangle, {2.0, 1.0, 0.0, 0.0}};
  expect_error_naming([&] { bad.validate("my term"); }, "my term");
}

TEST(FuzzyVariable, UniformPartitionIsThePapersShapes) {
  const FuzzyVariable v = uniform_partition("D", 0.0, 5.0);
  ASSERT_EQ(v.terms.size(), 3u);
  EXPECT_EQ(v.terms[0].membership.to_string(), "triangle(0, 0, 2.5)");
  EXPECT_EQ(v.terms[1].membership.to_string(), "triangle(0, 2.5, 5)");
  EXPECT_EQ(v.terms[2].membership.to_string(), "triangle(2.5, 5, 5)");
  // A partition of unity over the domain.
  for (double x = 0.0; x <= 5.0; x += 0.01)
    ASSERT_NEAR(v.membership("S", x) + v.membership("M", x) + v.membership("L", x), 1.0, 1e-12) << x;
  EXPECT_DOUBLE_EQ(v.membership("S", 0.0), 1.0);
  EXPECT_DOUBLE_EQ(v.membership("L", 5.0), 1.0);
  EXPECT_DOUBLE_EQ(v.membership("M", 1.25), 0.5);
  EXPECT_EQ(v.term_index("L"), 2);
  EXPECT_EQ(v.term_index("X"), -1);
  // NaN has no degree: refused, naming the variable.
  try {
    v.membership("S", std::numeric_limits<double>::quiet_NaN());
    FAIL() << "NaN accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("variable D x = nan"), std::string::npos) << e.what();
  }
  expect_error_naming([&] { v.membership("X", 1.0); }, "no term 'X'");
  const FuzzyVariable five = uniform_partition("v", -1.0, 1.0, {"a", "b", "c", "d", "e"});
  EXPECT_EQ(five.terms[1].membership.to_string(), "triangle(-1, -0.5, 0)");
  expect_error_naming([] { uniform_partition("v", 0.0, 1.0, {"only"}); }, "at least 2 terms");
}

TEST(FuzzyVariable, ValidateNamesTheProblem) {
  const auto var = [](std::string name, double lo, double hi, std::vector<FuzzyTerm> terms) {
    return FuzzyVariable{std::move(name), lo, hi, std::move(terms)};
  };
  const FuzzyTerm s{"S", MF::triangle(0, 0, 1)};
  expect_error_naming([&] { var("x", 1.0, 1.0, {s}).validate(); }, "variable x domain = [1, 1]");
  expect_error_naming([&] { var("x", 2.0, 1.0, {s}).validate(); }, "lo < hi");
  expect_error_naming([&] { var("x", 0.0, kNaN, {s}).validate(); }, "variable x hi");
  expect_error_naming([&] { var("x", 0.0, 1.0, {}).validate(); }, "at least one term");
  expect_error_naming([&] { var("x", 0.0, 1.0, {s, s}).validate(); }, "term 'S' is defined twice");
  expect_error_naming([&] { var("", 0.0, 1.0, {s}).validate(); }, "variable name");
  expect_error_naming([&] { var("two words", 0.0, 1.0, {s}).validate(); }, "'two words'");
  expect_error_naming([&] { var("1x", 0.0, 1.0, {s}).validate(); }, "'1x'");
  expect_error_naming([&] { var("x", 0.0, 1.0, {{"S M", MF::triangle(0, 0, 1)}}).validate(); }, "term name");
  expect_error_naming([&] { var("x", 0.0, 1.0, {{"far", MF::triangle(2, 3, 4)}}).validate(); },
                      "variable x term far = triangle(2, 3, 4): is zero everywhere");
  expect_error_naming([&] { var("x", 0.0, 1.0, {{"bad", MF{MF::Shape::Gaussian, {0, -1, 0, 0}}}}).validate(); },
                      "variable x term bad = gaussian(0, -1)");
  // Touching the domain with a shoulder is enough.
  EXPECT_NO_THROW(var("x", 0.0, 1.0, {{"edge", MF::triangle(1, 1, 2)}}).validate());
}

TEST(FuzzyRule, ParsesAndPrints) {
  const FuzzyRule r = FuzzyRule::parse("IF I is S AND D is M THEN beta is S AND delta is M");
  ASSERT_EQ(r.antecedents.size(), 2u);
  ASSERT_EQ(r.consequents.size(), 2u);
  EXPECT_EQ(r.antecedents[1].variable, "D");
  EXPECT_EQ(r.antecedents[1].term, "M");
  EXPECT_EQ(r.consequents[0].variable, "beta");
  EXPECT_EQ(r.to_string(), "IF I is S AND D is M THEN beta is S AND delta is M");
  const FuzzyRule lower = FuzzyRule::parse("  if x IS low then  y is high ");
  EXPECT_EQ(lower.to_string(), "IF x is low THEN y is high");
  expect_error_naming([] { FuzzyRule::parse("x is low THEN y is high"); }, "must start with 'IF'");
  expect_error_naming([] { FuzzyRule::parse("IF x is low"); }, "no THEN part");
  expect_error_naming([] { FuzzyRule::parse("IF x = low THEN y is high"); }, "expected 'is' after 'x'");
  expect_error_naming([] { FuzzyRule::parse("IF x is low OR z is a THEN y is high"); }, "got 'OR'");
  expect_error_naming([] { FuzzyRule::parse("IF x is low THEN y is"); }, "cut short");
  expect_error_naming([] { FuzzyRule::parse(""); }, "rule ''");
}

MamdaniEngine one_in_one_out(std::vector<FuzzyRule> rules, int resolution = MamdaniEngine::kDefaultResolution) {
  return MamdaniEngine({uniform_partition("x", 0.0, 1.0, {"lo", "hi"})}, {uniform_partition("y", 2.0, 6.0)},
                       std::move(rules), resolution);
}

TEST(MamdaniEngine, RejectsBadRulesAndVariables) {
  const auto rule = [](const char* text) { return FuzzyRule::parse(text); };
  expect_error_naming([&] { one_in_one_out({rule("IF z is lo THEN y is S")}); }, "unknown input variable 'z'");
  expect_error_naming([&] { one_in_one_out({rule("IF x is mid THEN y is S")}); }, "variable x has no term 'mid'");
  expect_error_naming([&] { one_in_one_out({rule("IF x is lo THEN y is XL")}); }, "variable y has no term 'XL'");
  expect_error_naming([&] { one_in_one_out({rule("IF x is lo THEN q is S")}); }, "unknown output variable 'q'");
  expect_error_naming([&] { one_in_one_out({rule("IF y is S THEN y is S")}); }, "y is an output");
  expect_error_naming([&] { one_in_one_out({rule("IF x is lo THEN x is hi")}); }, "x is an input");
  expect_error_naming([&] { one_in_one_out({rule("IF x is lo THEN y is S"), rule("IF x is hi THEN y is Q")}); },
                      "rule 1 'IF x is hi THEN y is Q'");
  expect_error_naming([&] { one_in_one_out({FuzzyRule{{}, {{"y", "S"}}}}); }, "after IF");
  expect_error_naming([&] { one_in_one_out({FuzzyRule{{{"x", "lo"}}, {}}}); }, "after THEN");
  expect_error_naming([&] { one_in_one_out({}); }, "rules");
  expect_error_naming([&] { one_in_one_out({rule("IF x is lo THEN y is S")}, 2); }, "resolution");
  expect_error_naming([&] { MamdaniEngine({}, {uniform_partition("y", 0, 1)}, {rule("IF x is lo THEN y is S")}); },
                      "inputs");
  expect_error_naming([&] { MamdaniEngine({uniform_partition("x", 0, 1)}, {}, {rule("IF x is S THEN y is S")}); },
                      "outputs");
  expect_error_naming(
      [&] {
        MamdaniEngine({uniform_partition("x", 0, 1)}, {uniform_partition("x", 0, 1)}, {rule("IF x is S THEN x is S")});
      },
      "variable name 'x' is used twice");
  const FuzzyVariable twice{"y", 0.0, 1.0, {{"S", MF::triangle(0, 0, 1)}, {"S", MF::triangle(0, 1, 1)}}};
  expect_error_naming([&] { MamdaniEngine({uniform_partition("x", 0, 1)}, {twice}, {rule("IF x is S THEN y is S")}); },
                      "term 'S' is defined twice");
  // A term narrower than the output grid could never contribute.
  const FuzzyVariable spike{"y", 0.0, 1.0, {{"spike", MF::triangle(0.3001, 0.3002, 0.3003)}}};
  expect_error_naming(
      [&] { MamdaniEngine({uniform_partition("x", 0, 1)}, {spike}, {rule("IF x is S THEN y is spike")}, 11); },
      "output y term spike");
}

TEST(MamdaniEngine, RejectsBadInputs) {
  const MamdaniEngine engine = paper_fuzzy_controller();
  expect_error_naming([&] { engine.evaluate(std::vector<double>{1.0}); }, "expected 2 values (I, D), got 1");
  expect_error_naming([&] { engine.evaluate(std::vector<double>{1.0, 2.0, 3.0}); }, "got 3");
  expect_error_naming([&] { engine.evaluate(std::vector<double>{1.0, kNaN}); }, "input D = nan");
  expect_error_naming([&] { engine.evaluate(std::map<std::string, double>{{"I", 1.0}}); }, "missing input 'D'");
  expect_error_naming([&] { engine.evaluate(std::map<std::string, double>{{"I", 1.0}, {"D", 1.0}, {"X", 1.0}}); },
                      "unknown input 'X'");
  double in[2] = {1.0, 1.0}, out[1];
  expect_error_naming([&] { engine.evaluate(in, 2, out, 1); }, "outputs: expected room for 2");
  expect_error_naming([&] { engine.firing_strengths({kNaN, 0.0}); }, "input I = nan");
  expect_error_naming([&] { engine.output_index("gamma"); }, "unknown output 'gamma' (outputs: beta, delta)");
  EXPECT_EQ(engine.input_index("D"), 1u);
  EXPECT_EQ(engine.output_index("delta"), 1u);
}

TEST(MamdaniEngine, NoFiringRuleGivesTheDomainMidpoint) {
  const MamdaniEngine engine = one_in_one_out({FuzzyRule::parse("IF x is hi THEN y is L")});
  EXPECT_DOUBLE_EQ(engine.evaluate(std::vector<double>{0.0})[0], 4.0);  // hi is 0 at x = 0
  EXPECT_DOUBLE_EQ(engine.firing_strengths({0.0})[0], 0.0);
  // As soon as the rule fires at all, the output is L's clipped centroid.
  EXPECT_GT(engine.evaluate(std::vector<double>{0.01})[0], 5.0);
}

TEST(MamdaniEngine, InputsAreClampedIntoTheirDomains) {
  const MamdaniEngine engine = paper_fuzzy_controller();
  const auto at = [&](double i, double d) { return engine.evaluate(std::vector<double>{i, d}); };
  EXPECT_EQ(at(-3.0, -1.0), at(0.0, 0.0));
  EXPECT_EQ(at(9.0, 1e9), at(2.0, 5.0));
  EXPECT_EQ(at(INFINITY, -INFINITY), at(2.0, 0.0));
  EXPECT_EQ(at(0.7, 12.0), at(0.7, 5.0));
}

TEST(MamdaniEngine, SingleRuleCentroidsMatchHandWorkedValues) {
  // Fully fired shoulder S = tri(2, 2, 4) on [2, 6]: the centroid of a right triangle.
  const MamdaniEngine engine = one_in_one_out({FuzzyRule::parse("IF x is lo THEN y is S")});
  EXPECT_NEAR(engine.evaluate(std::vector<double>{0.0})[0], 2.0 + 2.0 / 3.0, 1e-12);
  // Clipped at 0.3 (the clip corner falls between grid points).
  EXPECT_NEAR(engine.evaluate(std::vector<double>{0.7})[0], 2.0 + clipped_shoulder_centroid(2.0, 0.3), 1e-6);
  // A symmetric output term gives its centre whatever the clip level.
  const MamdaniEngine mid = one_in_one_out({FuzzyRule::parse("IF x is hi THEN y is M")});
  for (double x : {0.05, 0.3, 0.77, 1.0}) EXPECT_NEAR(mid.evaluate(std::vector<double>{x})[0], 4.0, 1e-12);
}

TEST(MamdaniEngine, PaperControllerCornerValues) {
  const MamdaniEngine engine = paper_fuzzy_controller();
  ASSERT_EQ(engine.n_inputs(), 2u);
  ASSERT_EQ(engine.n_outputs(), 2u);
  EXPECT_EQ(engine.rules().size(), 9u);
  EXPECT_EQ(engine.resolution(), 1001);
  const auto at = [&](double i, double d) { return engine.evaluate(std::vector<double>{i, d}); };
  // At the corners a single rule fires fully; a shoulder's centroid is a third of its base in.
  const double beta_s = 1.0 / 6.0, beta_l = 5.0 / 6.0, delta_s = 2.5 / 3.0, delta_l = 5.0 - 2.5 / 3.0;
  const double tol = 1e-12;
  EXPECT_NEAR(at(0, 0)[0], beta_s, tol);  // D=S, I=S: beta S, delta S
  EXPECT_NEAR(at(0, 0)[1], delta_s, tol);
  EXPECT_NEAR(at(2, 0)[0], beta_l, tol);  // D=S, I=L: beta L, delta S
  EXPECT_NEAR(at(2, 0)[1], delta_s, tol);
  EXPECT_NEAR(at(0, 5)[0], beta_s, tol);  // D=L, I=S: beta S, delta L
  EXPECT_NEAR(at(0, 5)[1], delta_l, tol);
  EXPECT_NEAR(at(2, 5)[0], 0.5, tol);     // D=L, I=L: beta M, delta M
  EXPECT_NEAR(at(2, 5)[1], 2.5, tol);
  EXPECT_NEAR(at(1, 2.5)[0], 0.5, tol);   // D=M, I=M: beta M, delta M
  EXPECT_NEAR(at(1, 2.5)[1], 2.5, tol);
  EXPECT_NEAR(at(2, 2.5)[0], beta_l, tol);  // D=M, I=L: beta L, delta M
  EXPECT_NEAR(at(0, 2.5)[1], 2.5, tol);
  // Between the corners: four rules at 0.5 each.
  const auto firing = engine.firing_strengths({0.5, 1.25});
  EXPECT_EQ(std::count(firing.begin(), firing.end(), 0.5), 4);
  EXPECT_EQ(std::count(firing.begin(), firing.end(), 0.0), 5);
  // More obstacles never lower beta while the robot is on its path (Table 3, row D=S).
  double last = -1.0;
  for (double i = 0.0; i <= 2.0; i += 0.05) {
    const double beta = at(i, 0.0)[0];
    EXPECT_GE(beta, last - 1e-12) << i;
    last = beta;
  }
}

TEST(MamdaniEngine, AgreesWithBruteForceInference) {
  // Mixed shapes, overlapping rules on the same term, three inputs, and
  // enough terms (> 128) to take the heap-scratch path.
  std::vector<std::string> many;
  for (int i = 0; i < 130; ++i) many.push_back("t" + std::to_string(i));
  FuzzyVariable a = uniform_partition("a", -1.0, 1.0);
  a.terms[1].membership = MF::gaussian(0.1, 0.3);
  FuzzyVariable b = uniform_partition("b", 0.0, 10.0, {"lo", "hi"});
  FuzzyVariable c = uniform_partition("c", 0.0, 1.0, many);
  FuzzyVariable y{"y", -2.0, 3.0,
                  {{"neg", MF::trapezoid(-3.0, -2.0, -1.0, 0.5)}, {"zero", MF::gaussian(0.2, 0.4)},
                   {"pos", MF::triangle(0.0, 2.0, 3.0)}, {"top", MF::triangle(2.0, 3.0, 3.0)}}};
  FuzzyVariable z = uniform_partition("z", 10.0, 20.0, {"S", "M", "L"});
  std::vector<FuzzyRule> rules;
  for (const char* text : {"IF a is S AND b is lo THEN y is neg AND z is L", "IF a is M THEN y is zero",
                           "IF a is L AND b is hi THEN y is pos", "IF b is hi THEN y is top AND z is S",
                           "IF a is S AND b is hi THEN y is pos AND z is M", "IF c is t3 THEN z is L",
                           "IF c is t100 AND a is L THEN y is neg"})
    rules.push_back(FuzzyRule::parse(text));
  const MamdaniEngine engine({a, b, c}, {y, z}, rules), fine({a, b, c}, {y, z}, rules, 20001);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> ua(-1.2, 1.2), ub(-1.0, 11.0), uc(0.0, 0.05);
  for (int trial = 0; trial < 30; ++trial) {
    const std::vector<double> in = {ua(rng), ub(rng), trial % 3 ? uc(rng) : 100.0 / 129.0};
    const auto got = engine.evaluate(in);
    const auto want = brute_force(engine, in);
    // The default grid misses clip corners by up to half a step: an error well
    // below 1e-4 of the domain; on the brute force's own grid the two agree closely.
    ASSERT_NEAR(got[0], want[0], 1e-4 * 5.0) << trial;
    ASSERT_NEAR(got[1], want[1], 1e-4 * 10.0) << trial;
    const auto same_grid = fine.evaluate(in);
    ASSERT_NEAR(same_grid[0], want[0], 1e-7) << trial;
    ASSERT_NEAR(same_grid[1], want[1], 1e-7) << trial;
    double buffer[2];
    engine.evaluate(in.data(), in.size(), buffer, 2);
    EXPECT_EQ(buffer[0], got[0]);
    EXPECT_EQ(buffer[1], got[1]);
  }
}

TEST(MamdaniEngine, ResolutionOnlyRefinesTheCentroid) {
  const MamdaniEngine coarse = paper_fuzzy_controller(101), fine = paper_fuzzy_controller(4001);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> ui(0.0, 2.0), ud(0.0, 5.0);
  for (int trial = 0; trial < 50; ++trial) {
    const std::vector<double> in = {ui(rng), ud(rng)};
    const auto c = coarse.evaluate(in), f = fine.evaluate(in);
    EXPECT_NEAR(c[0], f[0], 2e-3);
    EXPECT_NEAR(c[1], f[1], 1e-2);
    EXPECT_GE(f[0], 0.0);
    EXPECT_LE(f[0], 1.0);
    EXPECT_GE(f[1], 0.0);
    EXPECT_LE(f[1], 5.0);
  }
}

}  // namespace
}  // namespace fgdwa

using namespace fgdwa;

TEST(WeightPolicy, WeightsComeByCriticName) {
  const FixedWeights pair(0.3, 1.5);
  EXPECT_EQ(pair.weights(0.0, 0.0), (CriticWeights{{"clearance", 0.3}, {"similarity", 1.5}}));
  const FixedWeights named(CriticWeights{{"dwb_obstacle", 0.02}});
  EXPECT_EQ(named.weights(1.0, 1.0), (CriticWeights{{"dwb_obstacle", 0.02}}));
  // The paper's controller: beta sets the clearance critic, delta the similarity critic.
  const FuzzyWeights fuzzy;
  const CriticWeights w = fuzzy.weights(1.8, 0.1);
  ASSERT_EQ(w.size(), 2u);
  double out[2];
  const double in[2] = {1.8, 0.1};
  fuzzy.engine().evaluate(in, 2, out, 2);
  EXPECT_DOUBLE_EQ(w.at("clearance"), out[fuzzy.engine().output_index("beta")]);
  EXPECT_DOUBLE_EQ(w.at("similarity"), out[fuzzy.engine().output_index("delta")]);
  // Outputs mapped to other critics.
  const FuzzyWeights remapped(paper_fuzzy_controller(), {{"beta", "dwb_obstacle"}, {"delta", "dwb_path_dist"}});
  EXPECT_DOUBLE_EQ(remapped.weights(1.8, 0.1).at("dwb_obstacle"), w.at("clearance"));

  fgdwa::test::expect_error_naming([] { FixedWeights(-0.1, 1.0); }, "beta");
  fgdwa::test::expect_error_naming([] { FixedWeights(CriticWeights{{"", 1.0}}); }, "empty");
  fgdwa::test::expect_error_naming([] { FixedWeights(CriticWeights{{"velocity", -1.0}}); }, "velocity");
  fgdwa::test::expect_error_naming([] { FuzzyWeights(paper_fuzzy_controller(), {{"beta", "clearance"}}); }, "outputs");
  fgdwa::test::expect_error_naming(
      [] { FuzzyWeights(paper_fuzzy_controller(), {{"beta", "clearance"}, {"gamma", "velocity"}}); }, "gamma");
}

// With no mover on its way (T at or beyond its domain) the mover-aware
// controller is the paper's to the bit; the sooner a contact, the less the
// similarity weighs, never more than the paper's; beta is the paper's.
TEST(WeightPolicy, TheMoverAwareControllerLowersDeltaAsAContactNears) {
  const FuzzyWeights mover(mover_fuzzy_controller()), paper;
  const double inf = std::numeric_limits<double>::infinity();
  for (double I = 0.0; I <= 2.0; I += 0.25)
    for (double D = 0.0; D <= 5.0; D += 0.5) {
      SCOPED_TRACE(::testing::Message() << "I " << I << ", D " << D);
      const CriticWeights p = paper.weights(I, D);
      EXPECT_EQ(mover.weights(I, D, inf), p);
      EXPECT_EQ(mover.weights(I, D, kContactTimeRange), p);
      EXPECT_EQ(mover.weights(I, D), p);
      double before = p.at("similarity");
      for (double T = kContactTimeRange; T >= 0.0; T -= 0.25) {
        const CriticWeights w = mover.weights(I, D, T);
        EXPECT_DOUBLE_EQ(w.at("clearance"), p.at("clearance")) << "T " << T;
        EXPECT_LE(w.at("similarity"), before + 1e-9) << "T " << T;
        before = w.at("similarity");
      }
    }
  // Where the paper's delta is large, an imminent contact brings it down to the domain's middle.
  EXPECT_GT(paper.weights(0.0, 5.0).at("similarity"), 4.0);
  EXPECT_NEAR(mover.weights(0.0, 5.0, 0.0).at("similarity"), 2.5, 1e-6);
  fgdwa::test::expect_error_naming([&] { mover.weights(0.0, 0.0, -1.0); }, "contact time");
  fgdwa::test::expect_error_naming([&] { mover.weights(0.0, 0.0, std::nan("")); }, "contact time");
  // A third input other than T is refused by name.
  fgdwa::test::expect_error_naming(
      [] {
        MamdaniEngine e({uniform_partition("I", 0.0, 2.0), uniform_partition("D", 0.0, 5.0), uniform_partition("X", 0.0, 1.0)},
                        {uniform_partition("beta", 0.0, 1.0), uniform_partition("delta", 0.0, 5.0)},
                        {FuzzyRule::parse("IF I IS S THEN beta IS S AND delta IS S")});
        FuzzyWeights w(e);
      },
      "T");
}

// T: when the nearest moving disc would first touch the robot's circle.
TEST(WeightPolicy, TheControllerReportsTheTimeToTheNearestContact) {
  PlannerParams params;
  Controller controller(RobotLimits{}, Footprint::circle(0.25), params);
  RobotState state;
  const Vec2 goal(3.0, 0.0);
  controller.step(state, goal, static_cast<const Scan*>(nullptr), {});
  EXPECT_TRUE(std::isinf(controller.report().contact_time));
  // 3 m off, 0.5 m radius, coming at 1 m/s: touches the 0.25 m circle after 2.25 s.
  controller.step(state, goal, static_cast<const Scan*>(nullptr), {Disc{Vec2(3.0, 0.0), 0.5, Vec2(-1.0, 0.0)}});
  EXPECT_NEAR(controller.report().contact_time, 2.25, 1e-12);
  // Going away, or passing 2 m to the side, never; a static disc is no mover.
  controller.step(state, goal, static_cast<const Scan*>(nullptr),
                  {Disc{Vec2(3.0, 0.0), 0.5, Vec2(1.0, 0.0)}, Disc{Vec2(3.0, 2.0), 0.5, Vec2(-1.0, 0.0)},
                   Disc{Vec2(1.0, 0.0), 0.2}});
  EXPECT_TRUE(std::isinf(controller.report().contact_time));
  // Growing by 0.5 m/s while standing 2 m off: (2 - 0.5 - 0.25) / 0.5 = 2.5 s; the nearer contact counts.
  controller.step(state, goal, static_cast<const Scan*>(nullptr),
                  {Disc{Vec2(0.0, 2.0), 0.5, Vec2::Zero(), 0.5}, Disc{Vec2(3.0, 0.0), 0.5, Vec2(-1.0, 0.0)}});
  EXPECT_NEAR(controller.report().contact_time, 2.25, 1e-12);
  controller.step(state, goal, static_cast<const Scan*>(nullptr), {Disc{Vec2(0.0, 2.0), 0.5, Vec2::Zero(), 0.5}});
  EXPECT_NEAR(controller.report().contact_time, 2.5, 1e-12);
  // Already touching: 0.
  controller.step(state, goal, static_cast<const Scan*>(nullptr), {Disc{Vec2(0.5, 0.0), 0.5, Vec2(1.0, 0.0)}});
  EXPECT_EQ(controller.report().contact_time, 0.0);
  // Bad input is refused by name, by the disc's query and by any policy.
  const Disc disc{Vec2(3.0, 0.0), 0.5, Vec2(-1.0, 0.0)};
  fgdwa::test::expect_error_naming([&] { disc.time_to_reach(Vec2(std::nan(""), 0.0), 0.25); }, "time_to_reach point");
  fgdwa::test::expect_error_naming([&] { disc.time_to_reach(Vec2::Zero(), -0.1); }, "time_to_reach reach");
  fgdwa::test::expect_error_naming([] { FixedWeights(0.2, 0.5).weights(0.0, 0.0, -1.0); }, "contact time");
  EXPECT_EQ(FixedWeights(0.2, 0.5).weights(0.0, 0.0, std::numeric_limits<double>::infinity()),
            FixedWeights(0.2, 0.5).weights(0.0, 0.0));
}

TEST(WeightPolicy, TheControllerSetsTheWeightsOfTheCriticsItsPlannerHas) {
  PlannerParams params;
  params.critics = {{"heading", 0.5}, {"clearance", 0.15}, {"velocity", 1.0}};  // no similarity critic
  auto policy = std::make_shared<FixedWeights>(CriticWeights{{"clearance", 0.7}, {"similarity", 2.0}, {"velocity", 0.4}});
  Controller controller(RobotLimits{}, Footprint::circle(0.25), params, nullptr, policy);
  Scan scan;
  scan.angle_min = -1.0;
  scan.angle_increment = 0.01;
  scan.max_range = 10.0;
  scan.ranges.assign(201, std::numeric_limits<double>::infinity());
  RobotState state;
  controller.step(state, Vec2(3.0, 0.0), &scan);
  EXPECT_DOUBLE_EQ(controller.planner().weight("clearance"), 0.7);
  EXPECT_DOUBLE_EQ(controller.planner().weight("velocity"), 0.4);
  EXPECT_DOUBLE_EQ(controller.planner().weight("heading"), 0.5);
  EXPECT_DOUBLE_EQ(controller.report().beta, 0.7);
  EXPECT_TRUE(std::isnan(controller.report().delta));
}
