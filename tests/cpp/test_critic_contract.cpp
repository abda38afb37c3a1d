// The contract every registered critic keeps: finite scores, the batch equal to
// the single score, and a preference that no normalisation reverses; vetoes
// rejected and counted against the critic that cast them.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "fgdwa/critics.hpp"
#include "fgdwa/planner.hpp"
#include "test_support.hpp"

using namespace fgdwa;

namespace {

// A room with a post beside a bending path: every critic has something to say.
struct Scene {
  std::shared_ptr<DistanceField> field;
  GlobalPath path{{Vec2(0.5, 1.0), Vec2(2.5, 1.0), Vec2(3.5, 2.5)}};
  RobotState state;
  Scene() {
    field = std::make_shared<DistanceField>(test::grid_with_boxes(40, 50, 0.1, Vec2(0.0, 0.0), {{14, 18, 4, 3}}));
    state.pose = Pose2{0.8, 1.1, 0.2};
    state.twist = Twist{0.5, 0.1};
  }
};

// One critic chooses alone: among every admissible sample (prefer_clear off:
// which rollouts keep clear of the walls is no critic's preference).
PlannerParams single(const std::string& critic, Normalization normalization) {
  PlannerParams p;
  p.normalization = normalization;
  p.prefer_clear = false;
  p.critics = {{critic, 1.0}};
  return p;
}

// The sample a critic prefers by its raw scores and declared sense (the first on ties).
int preferred(const PlanResult& r) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(r.samples.size()); ++i) {
    if (r.reasons[static_cast<std::size_t>(i)] != RejectReason::None) continue;
    const double s = r.senses[0] == CriticSense::Cost ? -r.raw(i, 0) : r.raw(i, 0);
    if (best < 0 || s > (r.senses[0] == CriticSense::Cost ? -r.raw(best, 0) : r.raw(best, 0))) best = i;
  }
  return best;
}

// Vetoes every sample turning left; scores the rest by their speed.
class NoLeftTurns : public Critic {
 public:
  std::string name() const override { return "test_no_left_turns"; }
  double score(const Rollout& r) const override { return r.command.omega > 1e-9 ? veto() : r.command.v; }
};

}  // namespace

TEST(CriticContract, EveryRegisteredCriticScoresFinitelyAndBatchEqualsSingle) {
  const Scene scene;
  const FieldClearance world(scene.field);
  for (const std::string& name : critic_names()) {
    if (name.rfind("test_", 0) == 0) continue;
    SCOPED_TRACE(name);
    LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25), single(name, Normalization::Sum));
    planner.set_global_path(scene.path);
    const PlanResult& r = planner.plan(scene.state, Vec2(3.5, 2.5), world);
    ASSERT_GT(r.admissible_count(), 10);
    // Score the admissible rollouts again one by one with a fresh critic, prepared alike.
    auto critic = make_critic(CriticConfig(name, 1.0));
    CriticContext context;
    context.state = scene.state;
    context.goal = context.target = Vec2(3.5, 2.5);
    context.dt = planner.params().dt;
    context.n_steps = planner.params().n_steps();
    context.path = planner.global_path();
    context.v_max = RobotLimits{}.v_max;
    context.world = &world;
    context.footprint = &planner.footprint();
    critic->prepare(context);
    std::vector<Rollout> batch;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < r.samples.size(); ++i) {
      if (r.reasons[i] != RejectReason::None) continue;
      batch.push_back(Rollout{r.samples[i], &planner.rollouts()[i], r.min_clearance[i], r.free_distance[i]});
      index.push_back(i);
    }
    std::vector<double> scores(batch.size());
    critic->score_all(batch, scores.data());
    for (std::size_t a = 0; a < batch.size(); ++a) {
      ASSERT_TRUE(std::isfinite(scores[a]));
      EXPECT_NEAR(scores[a], critic->score(batch[a]), 1e-9 * (1.0 + std::abs(scores[a])));
      EXPECT_NEAR(scores[a], r.raw(static_cast<Eigen::Index>(index[a]), 0), 1e-9 * (1.0 + std::abs(scores[a])));
    }
  }
}

TEST(CriticContract, NoNormalisationReversesACriticsPreference) {
  const Scene scene;
  const FieldClearance world(scene.field);
  for (const std::string& name : critic_names()) {
    if (name.rfind("test_", 0) == 0) continue;
    SCOPED_TRACE(name);
    for (Normalization n : {Normalization::Sum, Normalization::MinMax, Normalization::None}) {
      SCOPED_TRACE(to_string(n));
      LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25), single(name, n));
      planner.set_global_path(scene.path);
      const PlanResult& r = planner.plan(scene.state, Vec2(3.5, 2.5), world);
      ASSERT_GE(r.best_index, 0);
      EXPECT_EQ(r.best_index, preferred(r));
    }
  }
}

TEST(CriticContract, DwbCostCriticsUnderSumNormalisationPickTheLowestCost) {
  // The goal-distance cost alone: the chosen rollout ends nearest the local goal.
  const Scene scene;
  const FieldClearance world(scene.field);
  LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25), single("dwb_goal_dist", Normalization::Sum));
  planner.set_global_path(scene.path);
  const PlanResult& r = planner.plan(scene.state, Vec2(3.5, 2.5), world);
  ASSERT_EQ(r.senses[0], CriticSense::Cost);
  ASSERT_GE(r.best_index, 0);
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    if (r.reasons[i] == RejectReason::None) {
      EXPECT_LE(r.raw(r.best_index, 0), r.raw(static_cast<Eigen::Index>(i), 0));
    }
  }
}

TEST(CriticContract, RegisteredCriticsVetoWithTheirNameCounted) {
  register_critic("test_no_left_turns", [](std::map<std::string, double>&, std::map<std::string, std::string>&) {
    return std::make_unique<NoLeftTurns>();
  });
  fgdwa::test::expect_error_naming(
      [] { register_critic("test_no_left_turns", [](auto&, auto&) { return std::make_unique<NoLeftTurns>(); }); },
      "already registered");
  fgdwa::test::expect_error_naming([] { register_critic("", [](auto&, auto&) { return std::make_unique<NoLeftTurns>(); }); },
                                   "empty");
  const auto names = critic_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "test_no_left_turns"), names.end());

  PlannerParams params;
  params.critics = {{"heading", 0.5}, {"test_no_left_turns", 1.0}};
  LocalPlanner planner(RobotLimits{}, Footprint::circle(0.25), params);
  const FieldClearance open;
  RobotState s;
  s.pose = Pose2{0.0, 0.0, 0.0};
  const PlanResult& r = planner.plan(s, Vec2(0.0, 3.0), open);  // the goal is to the left
  int vetoed = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const bool left = r.samples[i].omega > 1e-9;
    EXPECT_EQ(r.reasons[i] == RejectReason::Critic, left);
    EXPECT_EQ(r.vetoed_by[i], left ? 1 : -1);
    EXPECT_EQ(std::isfinite(r.total(static_cast<Eigen::Index>(i))), !left);
    vetoed += left;
  }
  ASSERT_GT(vetoed, 0);
  EXPECT_EQ(r.critic_vetoes, (std::vector<int>{0, vetoed}));
  EXPECT_EQ(r.reject_counts[static_cast<std::size_t>(RejectReason::Critic)], vetoed);
  EXPECT_EQ(r.admissible_count() + vetoed, static_cast<int>(r.samples.size()));
  EXPECT_LE(r.command.omega, 1e-9);
}
