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

TerrainGrid::TerrainGrid(int rows, int cols, double resolution, Vec2 origin, std::vector<std::uint8_t> grades)
    : rows_(rows), cols_(cols), resolution_(resolution), origin_(origin), grades_(std::move(grades)) {
  // The occupancy grid's constructor checks the same layout rules.
  OccupancyGrid layout(rows, cols, resolution, origin, std::vector<std::uint8_t>(grades_.size()));
  for (std::size_t i = 0; i < grades_.size(); ++i)
    if (grades_[i] > kMaxGrade)
      throw Error(describe("terrain grade at cell " + std::to_string(i), int(grades_[i]), "must be 0-4"));
}

int TerrainGrid::grade_at(const Vec2& p) const {
  const double fc = std::floor((p.x() - origin_.x()) / resolution_);
  const double fr = std::floor((p.y() - origin_.y()) / resolution_);
  if (!(fr >= 0.0 && fr < rows_ && fc >= 0.0 && fc < cols_)) return 0;
  return grade(static_cast<int>(fr), static_cast<int>(fc));
}

bool TerrainGrid::matches(const OccupancyGrid& grid) const {
  return rows_ == grid.rows() && cols_ == grid.cols() && std::abs(resolution_ - grid.resolution()) < 1e-12 &&
         (origin_ - grid.origin()).norm() < 1e-12;
}

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();

// Stands for "no obstacle" in the squared transform: finite, so the parabola
// intersections below stay well defined, and far above any real squared distance.
constexpr double kFar = 1e30;

// 1-D squared distance transform of a sampled function: the lower envelope of
// the parabolas rooted at each sample.
void distance_transform_1d(const double* f, int n, double* d, int* arg, std::vector<int>& v, std::vector<double>& z) {
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
    arg[q] = v[k];
  }
}
}  // namespace

DistanceField::DistanceField(const OccupancyGrid& grid) : grid_(grid) {
  const int rows = grid.rows(), cols = grid.cols();
  const std::size_t n_cells = static_cast<std::size_t>(rows) * cols;
  std::vector<double> squared(n_cells);
  for (std::size_t i = 0; i < n_cells; ++i) squared[i] = grid.cells()[i] != 0 ? 0.0 : kFar;
  has_obstacles_ = grid.occupied_count() > 0;

  // Columns first (nearest obstacle row per column), then rows, keeping the
  // argmin of each pass so every cell knows its nearest occupied cell.
  const int n = std::max(rows, cols);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n), arg(n);
  std::vector<int> nearest_row(n_cells), nearest_col(n_cells);
  for (int c = 0; c < cols; ++c) {
    for (int r = 0; r < rows; ++r) f[r] = squared[grid.index(r, c)];
    distance_transform_1d(f.data(), rows, d.data(), arg.data(), v, z);
    for (int r = 0; r < rows; ++r) {
      squared[grid.index(r, c)] = d[r];
      nearest_row[grid.index(r, c)] = arg[r];
    }
  }
  for (int r = 0; r < rows; ++r) {
    double* row = &squared[grid.index(r, 0)];
    std::copy(row, row + cols, f.begin());
    distance_transform_1d(f.data(), cols, row, arg.data(), v, z);
    for (int c = 0; c < cols; ++c) nearest_col[grid.index(r, c)] = arg[c];
  }
  distances_.resize(n_cells);
  std::vector<Vec2> nearest(n_cells);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = grid.index(r, c);
      const bool far = squared[i] >= 0.5 * kFar;
      distances_[i] = far ? kInf : std::sqrt(squared[i]) * grid.resolution();
      const int col = nearest_col[i];
      nearest[i] = far ? Vec2(kInf, kInf) : grid.cell_center(nearest_row[grid.index(r, col)], col);
    }

  // The obstacle square nearest to a point is the one nearest to a cell centre
  // close to it: each cell keeps the distinct nearest obstacles of the cells
  // within two of it, usually one to three.
  candidate_start_.assign(n_cells + 1, 0);
  quarter_lower_bound_.assign(4 * n_cells, kInf);
  inverse_half_resolution_ = 2.0 / grid.resolution();
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const std::size_t first = candidates_.size();
      for (int dr = -2; dr <= 2; ++dr)
        for (int dc = -2; dc <= 2; ++dc) {
          const int rr = std::clamp(r + dr, 0, rows - 1), cc = std::clamp(c + dc, 0, cols - 1);
          const Vec2& o = nearest[grid.index(rr, cc)];
          if (!std::isfinite(o.x())) continue;
          if (std::find(candidates_.begin() + static_cast<std::ptrdiff_t>(first), candidates_.end(), o) ==
              candidates_.end())
            candidates_.push_back(o);
        }
      // Drop the candidates that cannot be nearest anywhere in the cell: their
      // square is farther from the whole cell than some other candidate's square
      // is from the cell's farthest corner. Clustered maps leave a dozen
      // candidates per cell before this and one to three after, and distance()
      // spends its time in this loop.
      const Vec2 centre = grid.cell_center(r, c);
      const double res = grid.resolution();
      // A square's largest distance from the cell is from the far corner: the
      // centre-to-centre distance.
      double reach = kInf;
      for (std::size_t k = first; k < candidates_.size(); ++k) reach = std::min(reach, (centre - candidates_[k]).norm());
      const auto beyond = [&](const Vec2& o) {
        const double dx = std::max(std::abs(centre.x() - o.x()) - res, 0.0);
        const double dy = std::max(std::abs(centre.y() - o.y()) - res, 0.0);
        return std::hypot(dx, dy) > reach + 1e-9 * res;
      };
      candidates_.erase(std::remove_if(candidates_.begin() + static_cast<std::ptrdiff_t>(first), candidates_.end(), beyond),
                        candidates_.end());
      // The candidates hold the nearest obstacle of every point of the cell, so
      // the nearest of them to a quarter of the cell bounds that quarter.
      for (int qr = 0; qr < 2; ++qr)
        for (int qc = 0; qc < 2; ++qc) {
          const Vec2 quarter = centre + Vec2((qc - 0.5) * 0.5 * res, (qr - 0.5) * 0.5 * res);
          double bound = kInf;
          for (std::size_t k = first; k < candidates_.size(); ++k) {
            // Square of half-size res / 2 against a quarter of half-size res / 4.
            const double dx = std::max(std::abs(quarter.x() - candidates_[k].x()) - 0.75 * res, 0.0);
            const double dy = std::max(std::abs(quarter.y() - candidates_[k].y()) - 0.75 * res, 0.0);
            bound = std::min(bound, std::hypot(dx, dy));
          }
          quarter_lower_bound_[static_cast<std::size_t>(2 * r + qr) * (2 * cols) + static_cast<std::size_t>(2 * c + qc)] =
              bound;
        }
      candidate_start_[grid.index(r, c) + 1] = candidates_.size();
    }

  cell_candidates_.resize(n_cells);
  for (std::size_t i = 0; i < n_cells; ++i) {
    const std::size_t begin = candidate_start_[i], end = candidate_start_[i + 1];
    const Vec2 a = end > begin ? candidates_[begin] : Vec2(kInf, kInf);
    const Vec2 b = end > begin + 1 ? candidates_[begin + 1] : a;
    cell_candidates_[i] = CellCandidates{a.x(), a.y(), b.x(), b.y(), static_cast<std::uint32_t>(std::min(begin + 2, end)),
                                         static_cast<std::uint32_t>(end)};
  }

  row_first_.assign(rows, -1);
  row_last_.assign(rows, -1);
  col_first_.assign(cols, -1);
  col_last_.assign(cols, -1);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (grid.occupied(r, c)) {
        if (row_first_[r] < 0) row_first_[r] = c;
        row_last_[r] = c;
        if (col_first_[c] < 0) col_first_[c] = r;
        col_last_[c] = r;
      }
}

double DistanceField::distance(const Vec2& p) const {
  if (!has_obstacles_) return kInf;
  const double half = 0.5 * grid_.resolution();
  const int rows = grid_.rows(), cols = grid_.cols();
  const double gx = (p.x() - grid_.origin().x()) * inverse_half_resolution_ * 0.5;
  const double gy = (p.y() - grid_.origin().y()) * inverse_half_resolution_ * 0.5;
  const auto square_distance = [&](const Vec2& o) {
    const double dx = std::max(std::abs(p.x() - o.x()) - half, 0.0);
    const double dy = std::max(std::abs(p.y() - o.y()) - half, 0.0);
    return dx * dx + dy * dy;
  };
  double best = kInf;
  if (gx < 0.0 || gx > cols) {
    // Outside the grid every cell of a row lies on the same side of p in x, so
    // the row's outermost obstacle toward p is its nearest.
    const std::vector<int>& outermost = gx < 0.0 ? row_first_ : row_last_;
    for (int r = 0; r < rows; ++r)
      if (outermost[r] >= 0) best = std::min(best, square_distance(grid_.cell_center(r, outermost[r])));
  } else if (gy < 0.0 || gy > rows) {
    // Likewise per column in y.
    const std::vector<int>& outermost = gy < 0.0 ? col_first_ : col_last_;
    for (int c = 0; c < cols; ++c)
      if (outermost[c] >= 0) best = std::min(best, square_distance(grid_.cell_center(outermost[c], c)));
  } else {
    // Inside the grid (its far edges included): the candidates of p's cell.
    const std::size_t cell = grid_.index(std::min(static_cast<int>(gy), rows - 1), std::min(static_cast<int>(gx), cols - 1));
    const CellCandidates& near = cell_candidates_[cell];
    best = std::min(square_distance(Vec2(near.x0, near.y0)), square_distance(Vec2(near.x1, near.y1)));
    for (std::size_t k = near.more_begin; k < near.more_end; ++k) best = std::min(best, square_distance(candidates_[k]));
  }
  return std::sqrt(best);
}

}  // namespace fgdwa
