#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "fgdwa/critics.hpp"
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
  EXPECT_EQ(ClearanceCritic(0.5).score(rollout_ending_at(poses, 0.7)), 0.5);
  expect_error_naming([] { ClearanceCritic(0.0); }, "cap");
  expect_error_naming([] { ClearanceCritic(-1.0); }, "cap");
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

}  // namespace
}  // namespace fgdwa
