#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <hwy/targets.h>

#include "fgdwa/critics.hpp"
#include "fgdwa/dtw.hpp"
#include "fgdwa/path.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

using test::expect_error_naming;

Rollout rollout_ending_at(const Trajectory& poses, double min_clearance = 1.0, double v = 0.5) {
  Rollout r;
  r.command = Twist{v, 0.0};
  r.poses = &poses;
  r.min_clearance = min_clearance;
  r.free_distance = test::kInf;
  return r;
}

TEST(HeadingCritic, PiMinusTheAngleToTheTargetFromTheFinalPose) {
  HeadingCritic critic;
  CriticContext context;
  context.target = Vec2(5.0, 5.0);
  critic.prepare(context);
  const auto score_at = [&](double x, double y, double theta) {
    const Trajectory poses = {Pose2{0, 0, 1.0}, Pose2{x, y, theta}};  // only the last pose counts
    return critic.score(rollout_ending_at(poses));
  };
  EXPECT_NEAR(score_at(0.0, 0.0, M_PI / 4), M_PI, 1e-12);       // facing the target
  EXPECT_NEAR(score_at(0.0, 0.0, -3 * M_PI / 4), 0.0, 1e-12);   // facing away
  EXPECT_NEAR(score_at(0.0, 0.0, 3 * M_PI / 4), M_PI / 2, 1e-12);
  EXPECT_NEAR(score_at(5.0, 0.0, 0.0), M_PI / 2, 1e-12);        // target straight left
  EXPECT_NEAR(score_at(5.0, 0.0, M_PI / 2 + 2 * M_PI), M_PI, 1e-12);  // unwrapped heading
  EXPECT_NEAR(score_at(5.0, 5.0, 2.0), M_PI, 1e-12);            // on the target: any heading is fine
  EXPECT_EQ(critic.name(), "heading");
  // Symmetric in the side the target lies on, and always within [0, pi].
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int i = 0; i < 1000; ++i) {
    const double s = score_at(u(rng), u(rng), u(rng));
    ASSERT_GE(s, 0.0);
    ASSERT_LE(s, M_PI);
  }
  EXPECT_NEAR(score_at(0.0, 0.0, M_PI / 4 + 0.3), score_at(0.0, 0.0, M_PI / 4 - 0.3), 1e-12);
}

TEST(ClearanceCritic, ClipsToZeroAndTheCap) {
  const Trajectory poses = {Pose2{}};
  ClearanceCritic critic;  // default cap: the 2 m detect window
  EXPECT_EQ(critic.cap(), 2.0);
  EXPECT_EQ(critic.score(rollout_ending_at(poses, 0.7)), 0.7);
  EXPECT_EQ(critic.score(rollout_ending_at(poses, -0.2)), 0.0);
  EXPECT_EQ(critic.score(rollout_ending_at(poses, 2.5)), 2.0);
  EXPECT_EQ(critic.score(rollout_ending_at(poses, test::kInf)), 2.0);
  EXPECT_EQ(ClearanceCritic(ClearanceParams{0.5}).score(rollout_ending_at(poses, 0.7)), 0.5);
  expect_error_naming([] { ClearanceCritic(ClearanceParams{0.0}); }, "cap");
  expect_error_naming([] { ClearanceCritic(ClearanceParams{-1.0}); }, "cap");
}

TEST(VelocityCritic, IsTheCommandedSpeed) {
  const Trajectory poses = {Pose2{}};
  EXPECT_EQ(VelocityCritic().score(rollout_ending_at(poses, 1.0, 0.8)), 0.8);
  EXPECT_EQ(VelocityCritic().score(rollout_ending_at(poses, 1.0, 0.0)), 0.0);
}

TEST(MakeCritic, BuildsEveryRegisteredCriticByName) {
  const auto names = critic_names();
  for (const char* expected : {"heading", "clearance", "velocity"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  for (const std::string& name : names) EXPECT_EQ(make_critic({name, 1.0, {}})->name(), name);
  auto clearance = make_critic({"clearance", 0.3, {{"cap", 0.75}}});
  EXPECT_EQ(dynamic_cast<ClearanceCritic&>(*clearance).cap(), 0.75);
}

TEST(MakeCritic, RejectsUnknownNamesParametersAndBadValues) {
  expect_error_naming([] { make_critic({"obstacle", 1.0, {}}); }, "obstacle");
  expect_error_naming([] { make_critic({"clearance", 1.0, {{"radius", 1.0}}}); }, "radius");
  expect_error_naming([] { make_critic({"heading", 1.0, {{"cap", 1.0}}}); }, "cap");
  expect_error_naming([] { make_critic({"clearance", 1.0, {{"cap", -1.0}}}); }, "cap");
  expect_error_naming([] { make_critic({"clearance", 1.0, {{"cap", std::nan("")}}}); }, "cap");
  expect_error_naming([] { make_critic({"velocity", std::nan(""), {}}); }, "weight");
}

// The float batch DTW: each sequence's result is its double DTW within float
// rounding, whatever its place in the batch, and every instruction set the
// processor runs gives the same bits.
TEST(DtwSingle, MatchesDoubleAndGivesTheSameBitsOnEveryInstructionSet) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<float> u(-3.0f, 3.0f);
  DtwWorkspace workspace;
  std::vector<std::vector<float>> results;
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  for (int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    SCOPED_TRACE(hwy::TargetName(target));
    std::mt19937 same(7);
    std::vector<float> all;
    // Batch sizes round the lane counts (4, 8, 16) and a scalar tail.
    for (std::size_t count : {1u, 3u, 8u, 17u, 64u}) {
      for (std::size_t n : {1u, 2u, 20u}) {
        const std::size_t m = 1 + same() % 25;
        std::vector<float> ax(n * count), ay(n * count), bx(m), by(m), out(count);
        for (float& v : ax) v = u(same);
        for (float& v : ay) v = u(same);
        for (float& v : bx) v = u(same);
        for (float& v : by) v = u(same);
        workspace.distance_batch_f32(ax.data(), ay.data(), n, count, bx.data(), by.data(), m, out.data());
        std::vector<Vec2> b(m);
        for (std::size_t j = 0; j < m; ++j) b[j] = Vec2(bx[j], by[j]);
        for (std::size_t k = 0; k < count; ++k) {
          std::vector<Vec2> a(n);
          for (std::size_t i = 0; i < n; ++i) a[i] = Vec2(ax[i * count + k], ay[i * count + k]);
          const double exact = dtw(a, b);
          EXPECT_NEAR(out[k], exact, 1e-5 * (n + m) * (1.0 + exact));
        }
        all.insert(all.end(), out.begin(), out.end());
      }
    }
    results.push_back(all);
  }
  hwy::SetSupportedTargetsForTest(0);
  for (std::size_t t = 1; t < results.size(); ++t) {
    ASSERT_EQ(results[t].size(), results[0].size());
    EXPECT_EQ(std::memcmp(results[t].data(), results[0].data(), results[0].size() * sizeof(float)), 0)
        << hwy::TargetName(targets[t]) << " against " << hwy::TargetName(targets[0]);
  }
  std::printf("DTW batch checked on %zu instruction sets; dispatched: %s\n", targets.size(), dtw_instruction_set());
  EXPECT_THROW(workspace.distance_batch_f32(nullptr, nullptr, 0, 1, nullptr, nullptr, 1, nullptr), Error);
}

// The vectors' width reported for each instruction set the processor runs is
// that set's: what the benchmarks' floors divide the work by.
TEST(DtwSingle, ReportsTheVectorWidthOfEachInstructionSet) {
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  std::vector<std::size_t> widths;
  for (int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    const std::string name = hwy::TargetName(target);
    SCOPED_TRACE(name);
    const std::size_t bytes = dtw_vector_bytes();
    widths.push_back(bytes);
    EXPECT_EQ(bytes & (bytes - 1), 0u) << bytes << " is not a power of two";
    if (name.rfind("AVX3", 0) == 0) EXPECT_EQ(bytes, 64u);
    else if (name == "AVX2") EXPECT_EQ(bytes, 32u);
    else if (name.rfind("SSE", 0) == 0 || name == "SSSE3" || name == "EMU128" || name == "NEON") EXPECT_EQ(bytes, 16u);
    else if (name == "SCALAR") EXPECT_EQ(bytes, 1u);
    else EXPECT_GE(bytes, 16u);
  }
  // Without a test's choice, the widest the processor has (Highway lists it first).
  hwy::SetSupportedTargetsForTest(0);
  EXPECT_EQ(dtw_vector_bytes(), widths.front());
}

// With the similarity critic in single precision, a rollout scores alike alone
// and in a batch, and within float rounding of double precision.
TEST(SimilarityCritic, SinglePrecisionScoresAloneAsInABatchAndCloseToDouble) {
  const GlobalPath path({Vec2(100.0, 50.0), Vec2(103.0, 51.0), Vec2(105.0, 54.0)});
  CriticContext context;
  context.state.pose = Pose2{100.1, 50.05, 0.3};
  context.dt = 0.1;
  context.n_steps = 20;
  context.path = &path;
  context.v_max = 1.2;
  auto single = make_critic(CriticConfig("similarity"));
  auto reference = make_critic(CriticConfig("similarity", 1.0, {}, {{"precision", "double"}}));
  single->prepare(context);
  reference->prepare(context);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Trajectory> trajectories(37);
  std::vector<Rollout> batch;
  for (Trajectory& poses : trajectories) {
    const double v = 0.6 + 0.5 * u(rng), w = u(rng);
    Pose2 p = context.state.pose;
    for (int i = 0; i <= 20; ++i) {
      poses.push_back(p);
      p = Pose2{p.x + v * 0.1 * std::cos(p.theta), p.y + v * 0.1 * std::sin(p.theta), p.theta + w * 0.1};
    }
    batch.push_back(rollout_ending_at(poses));
  }
  std::vector<double> scores(batch.size());
  single->score_all(batch, scores.data());
  for (std::size_t k = 0; k < batch.size(); ++k) {
    EXPECT_EQ(scores[k], single->score(batch[k]));
    EXPECT_NEAR(scores[k], reference->score(batch[k]), 1e-6);
  }
  EXPECT_THROW(make_critic(CriticConfig("similarity", 1.0, {}, {{"precision", "half"}})), Error);
}

}  // namespace
}  // namespace fgdwa
