#include <ompl/base/MotionValidator.h>
#include <ompl/base/Planner.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/objectives/StateCostIntegralObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/PathSimplifier.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <mutex>

#include "fgdwa/collision.hpp"
#include "fgdwa/global_planner.hpp"
#include "validation.hpp"

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace fgdwa {

void OmplParams::check_relations(const ParamPath& path) const {
  const auto names = OmplPlanner::planner_names();
  if (std::find(names.begin(), names.end(), planner) == names.end()) {
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    fail_param(path.field("planner"), "'" + planner + "'", "unknown OMPL planner (known: " + known + ")");
  }
  if (w_length + w_clearance + terrain_cost.w_risk <= 0.0)
    fail_param(path.field("w_length"), std::to_string(w_length), "every weight of the cost (w_length, w_clearance, terrain_cost.w_risk) is 0");
}

namespace {
using PlannerFactory = std::function<ob::PlannerPtr(const ob::SpaceInformationPtr&)>;

const std::map<std::string, PlannerFactory>& planner_factories() {
  static const std::map<std::string, PlannerFactory> factories = {
      {"RRTstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::RRTstar>(si); }},
      {"InformedRRTstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::InformedRRTstar>(si); }},
      {"PRMstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::PRMstar>(si); }},
      {"BITstar", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::BITstar>(si); }},
      {"RRTConnect", [](const ob::SpaceInformationPtr& si) { return std::make_shared<og::RRTConnect>(si); }},
  };
  return factories;
}

// OMPL's seed generator is process-wide: plans are serialised so that each one
// reseeds it and then creates its own random generators in a fixed order.
std::mutex& ompl_mutex() {
  static std::mutex m;
  return m;
}

// Motions of a point robot over the inflated grid, checked exactly cell by cell.
class GridMotionValidator : public ob::MotionValidator {
 public:
  GridMotionValidator(const ob::SpaceInformationPtr& si, const OccupancyGrid& grid,
                      const std::vector<std::uint8_t>& blocked)
      : ob::MotionValidator(si), grid_(grid), blocked_(blocked) {}

  bool checkMotion(const ob::State* s1, const ob::State* s2) const override {
    if (clear(s1, s2)) return true;
    ++invalid_;
    return false;
  }

  bool checkMotion(const ob::State* s1, const ob::State* s2, std::pair<ob::State*, double>& last_valid) const override {
    if (clear(s1, s2)) return true;
    ++invalid_;
    // The last valid state: walk back from s2 in quarter cells until the rest is clear.
    const double length = (point(s2) - point(s1)).norm();
    const int pieces = std::max(1, static_cast<int>(std::ceil(length / (0.25 * grid_.resolution()))));
    double t = 0.0;
    ob::State* probe = si_->allocState();
    for (int k = 1; k <= pieces; ++k) {
      si_->getStateSpace()->interpolate(s1, s2, double(k) / pieces, probe);
      if (!clear(s1, probe)) break;
      t = double(k) / pieces;
    }
    si_->freeState(probe);
    if (last_valid.first) si_->getStateSpace()->interpolate(s1, s2, t, last_valid.first);
    last_valid.second = t;
    return false;
  }

 private:
  static Vec2 point(const ob::State* s) {
    const auto* st = s->as<ob::RealVectorStateSpace::StateType>();
    return {st->values[0], st->values[1]};
  }
  bool clear(const ob::State* s1, const ob::State* s2) const {
    return segment_free(grid_, point(s1), point(s2), [this](int r, int c) { return !blocked_[grid_.index(r, c)]; });
  }
  const OccupancyGrid& grid_;
  const std::vector<std::uint8_t>& blocked_;
};

// A state's cost from a function of its planar pose.
class PoseCostObjective : public ob::StateCostIntegralObjective {
 public:
  PoseCostObjective(const ob::SpaceInformationPtr& si, std::function<double(const Pose2&)> cost,
                    std::function<Pose2(const ob::State*)> pose)
      : ob::StateCostIntegralObjective(si, false), cost_(std::move(cost)), pose_(std::move(pose)) {}
  ob::Cost stateCost(const ob::State* s) const override { return ob::Cost(cost_(pose_(s))); }

 private:
  std::function<double(const Pose2&)> cost_;
  std::function<Pose2(const ob::State*)> pose_;
};
}  // namespace

std::vector<std::string> OmplPlanner::planner_names() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : planner_factories()) names.push_back(name);
  return names;
}

struct OmplPlanner::Impl {
  OccupancyGrid grid;
  Footprint footprint;
  OmplParams params;
  std::optional<TerrainGrid> terrain;
  std::vector<std::uint8_t> blocked;    // inflated grid, circle footprint
  std::shared_ptr<DistanceField> field;
  std::unique_ptr<CollisionWorld> world;  // exact footprint checks, polygon footprint

  bool se2() const { return !footprint.is_circle(); }

  Pose2 pose_of(const ob::State* s) const {
    if (se2()) {
      const auto* st = s->as<ob::SE2StateSpace::StateType>();
      return {st->getX(), st->getY(), st->getYaw()};
    }
    const auto* st = s->as<ob::RealVectorStateSpace::StateType>();
    return {st->values[0], st->values[1], 0.0};
  }

  bool valid(const Pose2& p) const {
    int r, c;
    if (!grid.cell_of(p.position(), r, c)) return false;
    if (terrain && terrain->grade(r, c) >= TerrainGrid::kMaxGrade) return false;
    if (se2()) return !world->in_collision(footprint, p);
    return !blocked[grid.index(r, c)];
  }

  double clearance(const Pose2& p) const {
    return se2() ? world->clearance(footprint, p, 0.0) : field->distance(p.position()) - params.inflation_radius;
  }
};

OmplPlanner::OmplPlanner(const OccupancyGrid& grid, const Footprint& footprint, const OmplParams& params,
                         std::optional<TerrainGrid> terrain)
    : impl_(std::make_unique<Impl>(Impl{grid, footprint, params, std::move(terrain), {}, nullptr, nullptr})) {
  impl_->params.validate();
  const TerrainGrid* t = impl_->terrain ? &*impl_->terrain : nullptr;
  impl_->blocked = inflate(grid, params.inflation_radius, t);
  impl_->field = std::make_shared<DistanceField>(grid);
  if (!footprint.is_circle()) impl_->world = std::make_unique<CollisionWorld>(grid);
}

OmplPlanner::~OmplPlanner() = default;
OmplPlanner::OmplPlanner(OmplPlanner&&) noexcept = default;
OmplPlanner& OmplPlanner::operator=(OmplPlanner&&) noexcept = default;

GlobalPlan OmplPlanner::plan(const Vec2& start, const Vec2& goal) const {
  const auto tic = std::chrono::steady_clock::now();
  const Impl& im = *impl_;
  detail::require_point("start", start);
  detail::require_point("goal", goal);
  const auto where = [](const Vec2& p) {
    return "(" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ")";
  };
  int r, c;
  if (!im.grid.cell_of(start, r, c)) throw Error("start " + where(start) + " lies outside the map");
  if (im.grid.occupied(r, c)) throw Error("start " + where(start) + " lies inside an obstacle");
  if (!im.grid.cell_of(goal, r, c)) throw Error("goal " + where(goal) + " lies outside the map");
  if (im.grid.occupied(r, c)) throw Error("goal " + where(goal) + " lies inside an obstacle");
  const double heading = std::atan2(goal.y() - start.y(), goal.x() - start.x());
  if (!im.valid(Pose2{start.x(), start.y(), heading}))
    throw Error("start " + where(start) + " is too close to an obstacle for the robot's footprint");
  if (!im.valid(Pose2{goal.x(), goal.y(), heading}))
    throw Error("goal " + where(goal) + " is too close to an obstacle for the robot's footprint");

  std::lock_guard<std::mutex> lock(ompl_mutex());
  ompl::msg::setLogLevel(im.params.verbose ? ompl::msg::LOG_INFO : ompl::msg::LOG_NONE);
  ompl::RNG::setSeed(im.params.seed + 1);  // OMPL ignores a seed of 0

  const Vec2 lo = im.grid.origin();
  const Vec2 hi = lo + Vec2(im.grid.cols(), im.grid.rows()) * im.grid.resolution();
  ob::StateSpacePtr space;
  if (im.se2()) {
    auto se2 = std::make_shared<ob::SE2StateSpace>();
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, lo.x()), bounds.setHigh(0, hi.x()), bounds.setLow(1, lo.y()), bounds.setHigh(1, hi.y());
    se2->setBounds(bounds);
    space = se2;
  } else {
    auto r2 = std::make_shared<ob::RealVectorStateSpace>(2);
    r2->setBounds(ob::RealVectorBounds(2));
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, lo.x()), bounds.setHigh(0, hi.x()), bounds.setLow(1, lo.y()), bounds.setHigh(1, hi.y());
    r2->setBounds(bounds);
    space = r2;
  }
  auto si = std::make_shared<ob::SpaceInformation>(space);
  si->setStateValidityChecker([&im](const ob::State* s) { return im.valid(im.pose_of(s)); });
  if (im.se2()) {
    // The footprint turns along a motion: its poses are checked every quarter cell.
    si->setStateValidityCheckingResolution(0.25 * im.grid.resolution() / space->getMaximumExtent());
  } else {
    si->setMotionValidator(std::make_shared<GridMotionValidator>(si, im.grid, im.blocked));
  }
  si->setup();

  const auto pose_of = [&im](const ob::State* s) { return im.pose_of(s); };
  auto objective = std::make_shared<ob::MultiOptimizationObjective>(si);
  if (im.params.w_length > 0.0)
    objective->addObjective(std::make_shared<ob::PathLengthOptimizationObjective>(si), im.params.w_length);
  if (im.params.w_clearance > 0.0) {
    const double ref = im.params.clearance_reference;
    objective->addObjective(std::make_shared<PoseCostObjective>(
                                si, [&im, ref](const Pose2& p) { return std::max(0.0, ref - im.clearance(p)) / ref; },
                                pose_of),
                            im.params.w_clearance);
  }
  if (im.terrain && im.params.terrain_cost.w_risk > 0.0) {
    objective->addObjective(std::make_shared<PoseCostObjective>(
                                si,
                                [&im](const Pose2& p) {
                                  const int g = std::min(im.terrain->grade_at(p.position()), TerrainGrid::kMaxGrade - 1);
                                  return im.params.terrain_cost.risk[static_cast<std::size_t>(g)];
                                },
                                pose_of),
                            im.params.terrain_cost.w_risk);
  }
  objective->lock();

  ob::ScopedState<> s(space), g(space);
  s[0] = start.x(), s[1] = start.y();
  g[0] = goal.x(), g[1] = goal.y();
  if (im.se2()) s[2] = heading, g[2] = heading;
  auto pdef = std::make_shared<ob::ProblemDefinition>(si);
  pdef->setStartAndGoalStates(s, g, 0.5 * im.grid.resolution());
  pdef->setOptimizationObjective(objective);

  ob::PlannerPtr planner = planner_factories().at(im.params.planner)(si);
  if (im.params.range > 0.0 && planner->params().hasParam("range"))
    planner->params().setParam("range", std::to_string(im.params.range));
  planner->setProblemDefinition(pdef);
  planner->setup();
  ob::PlannerTerminationCondition stop = ob::timedPlannerTerminationCondition(im.params.time_limit);
  if (im.params.max_iterations > 0) {
    // Planners ask the condition once per iteration: counting the asks bounds
    // the work independently of the machine's speed.
    auto asked = std::make_shared<std::uint64_t>(0);
    const std::uint64_t limit = im.params.max_iterations;
    stop = ob::plannerOrTerminationCondition(
        stop, ob::PlannerTerminationCondition([asked, limit] { return ++*asked > limit; }));
  }
  const ob::PlannerStatus status = planner->solve(stop);

  GlobalPlan plan;
  if (status == ob::PlannerStatus::EXACT_SOLUTION) {
    auto path = *pdef->getSolutionPath()->as<og::PathGeometric>();
    if (im.params.simplify) og::PathSimplifier(si, pdef->getGoal(), objective).simplifyMax(path);
    const double length = path.length();
    path.interpolate(std::max<unsigned>(2, static_cast<unsigned>(std::ceil(length / im.params.interpolation)) + 1));
    plan.status = GlobalStatus::Found;
    for (std::size_t i = 0; i < path.getStateCount(); ++i) plan.path.push_back(im.pose_of(path.getState(i)).position());
    plan.path.front() = start;
    plan.path.back() = goal;
    plan.cost = path.cost(objective).value();
  } else {
    plan.status = GlobalStatus::Timeout;
  }
  plan.planning_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - tic).count();
  return plan;
}

}  // namespace fgdwa
