#include "fgdwa/collision.hpp"

#include "validation.hpp"

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/collision_object.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <limits>
#include <map>

namespace fgdwa {

namespace {
constexpr double kHeight = 1.0;  // every shape is a prism of the same height: distances are planar
using Geometry = std::shared_ptr<fcl::CollisionGeometryd>;

fcl::Transform3d planar_transform(double x, double y, double theta) {
  fcl::Transform3d tf = fcl::Transform3d::Identity();
  tf.translation() = fcl::Vector3d(x, y, 0.0);
  tf.linear() = Eigen::AngleAxisd(theta, fcl::Vector3d::UnitZ()).toRotationMatrix();
  return tf;
}

Geometry footprint_geometry(const Footprint& footprint) {
  if (footprint.is_circle()) return std::make_shared<fcl::Cylinderd>(footprint.radius(), kHeight);
  const auto& v = footprint.vertices();
  const int n = static_cast<int>(v.size());
  auto points = std::make_shared<std::vector<fcl::Vector3d>>();
  for (const Vec2& p : v) points->emplace_back(p.x(), p.y(), 0.5 * kHeight);
  for (const Vec2& p : v) points->emplace_back(p.x(), p.y(), -0.5 * kHeight);
  auto faces = std::make_shared<std::vector<int>>();
  faces->push_back(n);  // top, counter-clockwise seen from +z
  for (int i = 0; i < n; ++i) faces->push_back(i);
  faces->push_back(n);  // bottom, counter-clockwise seen from -z
  for (int i = n - 1; i >= 0; --i) faces->push_back(n + i);
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    faces->insert(faces->end(), {4, i, n + i, n + j, j});
  }
  return std::make_shared<fcl::Convexd>(points, n + 2, faces);
}

// FCL's own GJK for every query: libccd, FCL's default, misreports distances
// to cylinders (the circle footprint, the discs) by up to 0.28 m at 1-3 m
// apart, and reported a box prism beside a long wall box as touching 0.14 m away.
constexpr fcl::GJKSolverType kSolver = fcl::GST_INDEP;

struct DistanceData {
  double min_distance = std::numeric_limits<double>::infinity();
};

bool distance_callback(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data, double& dist) {
  auto* d = static_cast<DistanceData*>(data);
  fcl::DistanceRequestd request;
  request.gjk_solver_type = kSolver;
  request.distance_tolerance = 1e-9;
  fcl::DistanceResultd result;
  const double value = fcl::distance(a, b, request, result);
  d->min_distance = std::min(d->min_distance, std::max(value, 0.0));
  dist = d->min_distance;
  return d->min_distance <= 0.0;
}

bool collision_callback(fcl::CollisionObjectd* a, fcl::CollisionObjectd* b, void* data) {
  auto* hit = static_cast<bool*>(data);
  fcl::CollisionRequestd request;
  request.gjk_solver_type = kSolver;
  fcl::CollisionResultd result;
  fcl::collide(a, b, request, result);
  *hit = *hit || result.isCollision();
  return *hit;
}
}  // namespace

std::vector<CellRect> merge_occupied_cells(const OccupancyGrid& grid) {
  std::vector<CellRect> done;
  std::map<std::pair<int, int>, CellRect> open;  // (col, cols) -> rectangle reaching the previous row
  for (int row = 0; row < grid.rows(); ++row) {
    std::map<std::pair<int, int>, CellRect> next;
    for (int col = 0; col < grid.cols();) {
      if (!grid.occupied(row, col)) {
        ++col;
        continue;
      }
      int end = col;
      while (end < grid.cols() && grid.occupied(row, end)) ++end;
      const std::pair<int, int> key{col, end - col};
      auto it = open.find(key);
      if (it != open.end()) {
        CellRect rect = it->second;
        ++rect.rows;
        next[key] = rect;
        open.erase(it);
      } else {
        next[key] = CellRect{row, col, 1, end - col};
      }
      col = end;
    }
    for (const auto& [key, rect] : open) done.push_back(rect);
    open = std::move(next);
  }
  for (const auto& [key, rect] : open) done.push_back(rect);
  return done;
}

struct CollisionWorld::Impl {
  std::vector<CellRect> boxes;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> static_objects;
  fcl::DynamicAABBTreeCollisionManagerd manager;
  std::vector<Disc> discs;
  std::vector<Geometry> disc_geometry;

  void disc_object(std::size_t i, double t, std::unique_ptr<fcl::CollisionObjectd>& out) const {
    const Vec2 c = discs[i].center_at(t);
    out = std::make_unique<fcl::CollisionObjectd>(disc_geometry[i], planar_transform(c.x(), c.y(), 0.0));
  }
};

CollisionWorld::CollisionWorld() : impl_(std::make_unique<Impl>()) { impl_->manager.setup(); }

CollisionWorld::CollisionWorld(const OccupancyGrid& grid, std::vector<Disc> discs) : CollisionWorld() {
  impl_->boxes = merge_occupied_cells(grid);
  const double res = grid.resolution();
  std::vector<fcl::CollisionObjectd*> raw;
  for (const CellRect& r : impl_->boxes) {
    auto box = std::make_shared<fcl::Boxd>(r.cols * res, r.rows * res, kHeight);
    const Vec2 centre = grid.origin() + Vec2((r.col + 0.5 * r.cols) * res, (r.row + 0.5 * r.rows) * res);
    impl_->static_objects.push_back(
        std::make_unique<fcl::CollisionObjectd>(box, planar_transform(centre.x(), centre.y(), 0.0)));
    raw.push_back(impl_->static_objects.back().get());
  }
  if (!raw.empty()) impl_->manager.registerObjects(raw);
  impl_->manager.setup();
  set_discs(std::move(discs));
}

CollisionWorld::~CollisionWorld() = default;
CollisionWorld::CollisionWorld(CollisionWorld&&) noexcept = default;
CollisionWorld& CollisionWorld::operator=(CollisionWorld&&) noexcept = default;

void CollisionWorld::set_discs(std::vector<Disc> discs) {
  if (discs.size() > static_cast<std::size_t>(limits::kMaxDiscs))
    throw Error(detail::describe("discs", discs.size(), "at most " + std::to_string(limits::kMaxDiscs)));
  for (const Disc& d : discs) d.validate();
  impl_->discs = std::move(discs);
  impl_->disc_geometry.clear();
  for (const Disc& d : impl_->discs)
    // A point obstacle still needs a body for FCL: a disc a micrometre wide.
    impl_->disc_geometry.push_back(std::make_shared<fcl::Cylinderd>(std::max(d.radius, 1e-6), kHeight));
}

const std::vector<Disc>& CollisionWorld::discs() const { return impl_->discs; }

double CollisionWorld::moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const {
  return moving_disc_clearance(impl_->discs, footprint, pose, t);
}

double CollisionWorld::obstacle_speed() const {
  double fastest = 0.0;
  for (const Disc& d : impl_->discs) fastest = std::max(fastest, d.top_speed() + d.growth);
  return fastest;
}
const std::vector<CellRect>& CollisionWorld::boxes() const { return impl_->boxes; }

double CollisionWorld::clearance(const Footprint& footprint, const Pose2& pose, double t) const {
  detail::require_query_pose("pose", pose);
  detail::require_magnitude("t", t, limits::kMaxHorizon);
  fcl::CollisionObjectd robot(footprint_geometry(footprint), planar_transform(pose.x, pose.y, pose.theta));
  robot.computeAABB();
  DistanceData data;
  if (!impl_->static_objects.empty()) impl_->manager.distance(&robot, &data, distance_callback);
  std::unique_ptr<fcl::CollisionObjectd> disc;
  for (std::size_t i = 0; i < impl_->discs.size() && data.min_distance > 0.0; ++i) {
    impl_->disc_object(i, t, disc);
    // A disc that grows is the disc of its radius now, reached growth x t sooner.
    DistanceData one;
    double ignored;
    distance_callback(&robot, disc.get(), &one, ignored);
    data.min_distance = std::min(data.min_distance, std::max(0.0, one.min_distance - impl_->discs[i].growth * t));
  }
  return data.min_distance;
}

bool CollisionWorld::in_collision(const Footprint& footprint, const Pose2& pose, double t) const {
  detail::require_query_pose("pose", pose);
  detail::require_magnitude("t", t, limits::kMaxHorizon);
  fcl::CollisionObjectd robot(footprint_geometry(footprint), planar_transform(pose.x, pose.y, pose.theta));
  robot.computeAABB();
  bool hit = false;
  if (!impl_->static_objects.empty()) impl_->manager.collide(&robot, &hit, collision_callback);
  std::unique_ptr<fcl::CollisionObjectd> disc;
  for (std::size_t i = 0; i < impl_->discs.size() && !hit; ++i) {
    impl_->disc_object(i, t, disc);
    if (impl_->discs[i].growth > 0.0 && t > 0.0) {
      DistanceData one;
      double ignored;
      distance_callback(&robot, disc.get(), &one, ignored);
      hit = one.min_distance <= impl_->discs[i].growth * t;
    } else {
      collision_callback(&robot, disc.get(), &hit);
    }
  }
  return hit;
}

}  // namespace fgdwa
