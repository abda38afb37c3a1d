#include "fgdwa/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "validation.hpp"

namespace fgdwa {

using detail::describe;

OccupancyGrid::OccupancyGrid(int rows, int cols, double resolution, Vec2 origin, std::vector<std::uint8_t> cells)
    : rows_(rows), cols_(cols), resolution_(resolution), origin_(origin), cells_(std::move(cells)) {
  detail::require_at_least("grid rows", rows, 1);
  detail::require_at_least("grid cols", cols, 1);
  detail::require_positive("grid resolution", resolution);
  detail::require_finite("grid origin x", origin.x());
  detail::require_finite("grid origin y", origin.y());
  const std::size_t expected = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  if (cells_.size() != expected)
    throw Error(describe("grid cells", cells_.size(), "expected rows x cols = " + std::to_string(expected)));
}

bool OccupancyGrid::cell_of(const Vec2& p, int& row, int& col) const {
  const double fc = std::floor((p.x() - origin_.x()) / resolution_);
  const double fr = std::floor((p.y() - origin_.y()) / resolution_);
  if (!(fr >= 0.0 && fr < rows_ && fc >= 0.0 && fc < cols_)) return false;
  row = static_cast<int>(fr);
  col = static_cast<int>(fc);
  return true;
}

Vec2 OccupancyGrid::cell_center(int row, int col) const {
  return origin_ + Vec2((col + 0.5) * resolution_, (row + 0.5) * resolution_);
}

bool OccupancyGrid::occupied_at(const Vec2& p) const {
  int row, col;
  return cell_of(p, row, col) && occupied(row, col);
}

std::size_t OccupancyGrid::occupied_count() const {
  return static_cast<std::size_t>(std::count_if(cells_.begin(), cells_.end(), [](std::uint8_t c) { return c != 0; }));
}

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Stands for "no obstacle" in the squared transform: finite, so the parabola
// intersections below stay well defined, and far above any real squared distance.
constexpr double kFar = 1e30;

// 1-D squared distance transform of a sampled function: the lower envelope of
// the parabolas rooted at each sample.
void distance_transform_1d(const double* f, int n, double* d, std::vector<int>& v, std::vector<double>& z) {
  int k = 0;
  v[0] = 0;
  z[0] = -kInf;
  z[1] = kInf;
  for (int q = 1; q < n; ++q) {
    double s;
    while (true) {
      const int p = v[k];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s > z[k]) break;  // z[0] = -inf ends the loop
      --k;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = kInf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double diff = q - v[k];
    d[q] = diff * diff + f[v[k]];
  }
}
}  // namespace

DistanceField::DistanceField(const OccupancyGrid& grid) : grid_(grid) {
  const int rows = grid.rows(), cols = grid.cols();
  std::vector<double> squared(static_cast<std::size_t>(rows) * cols);
  for (std::size_t i = 0; i < squared.size(); ++i) squared[i] = grid.cells()[i] != 0 ? 0.0 : kFar;
  has_obstacles_ = grid.occupied_count() > 0;

  const int n = std::max(rows, cols);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  for (int c = 0; c < cols; ++c) {
    for (int r = 0; r < rows; ++r) f[r] = squared[grid.index(r, c)];
    distance_transform_1d(f.data(), rows, d.data(), v, z);
    for (int r = 0; r < rows; ++r) squared[grid.index(r, c)] = d[r];
  }
  for (int r = 0; r < rows; ++r) {
    double* row = &squared[grid.index(r, 0)];
    std::copy(row, row + cols, f.begin());
    distance_transform_1d(f.data(), cols, row, v, z);
  }
  distances_.resize(squared.size());
  for (std::size_t i = 0; i < squared.size(); ++i)
    distances_[i] = squared[i] >= 0.5 * kFar ? kInf : std::sqrt(squared[i]) * grid.resolution();
}

double DistanceField::distance(const Vec2& p) const {
  if (!has_obstacles_) return kInf;
  const double res = grid_.resolution();
  const int rows = grid_.rows(), cols = grid_.cols();
  // Outside the grid: obstacles all lie inside it, so from the projection q of p
  // onto the grid's rectangle, |p - o|^2 >= |q - o|^2 + |p - q|^2 for every o.
  const Vec2 lo = grid_.origin();
  const Vec2 hi = lo + Vec2(cols * res, rows * res);
  const Vec2 q(std::clamp(p.x(), lo.x(), hi.x()), std::clamp(p.y(), lo.y(), hi.y()));
  const double outside = (p - q).squaredNorm();

  int row, col;
  if (outside == 0.0 && grid_.cell_of(q, row, col) && grid_.occupied(row, col)) return 0.0;

  // Bilinear interpolation between the four surrounding cell centres.
  const double gx = std::clamp((q.x() - lo.x()) / res - 0.5, 0.0, cols - 1.0);
  const double gy = std::clamp((q.y() - lo.y()) / res - 0.5, 0.0, rows - 1.0);
  const int c0 = std::min(static_cast<int>(gx), cols - 1), r0 = std::min(static_cast<int>(gy), rows - 1);
  const int c1 = std::min(c0 + 1, cols - 1), r1 = std::min(r0 + 1, rows - 1);
  const double tx = gx - c0, ty = gy - r0;
  const double d00 = distances_[grid_.index(r0, c0)], d01 = distances_[grid_.index(r0, c1)];
  const double d10 = distances_[grid_.index(r1, c0)], d11 = distances_[grid_.index(r1, c1)];
  const double centre = (1 - ty) * ((1 - tx) * d00 + tx * d01) + ty * ((1 - tx) * d10 + tx * d11);
  const double inside = std::max(centre - 0.5 * res, 0.0);
  return outside == 0.0 ? inside : std::sqrt(inside * inside + outside);
}

}  // namespace fgdwa
