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

DistanceField::DistanceField(const OccupancyGrid& grid) : DistanceField(grid, nullptr) {}

DistanceField::DistanceField(const OccupancyGrid& grid, const DistanceField& previous)
    : DistanceField(grid, &previous) {}

DistanceField::DistanceField(const OccupancyGrid& grid, const DistanceField* previous) : grid_(grid) {
  if (previous) {
    const OccupancyGrid& before = previous->grid();
    if (before.rows() != grid.rows() || before.cols() != grid.cols() || before.resolution() != grid.resolution() ||
        before.origin() != grid.origin())
      throw Error("DistanceField: the previous field's grid has another layout (rows, cols, resolution or origin)");
  }
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
  std::vector<long>& nearest = nearest_;
  nearest.resize(n_cells);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = grid.index(r, c);
      const bool far = squared[i] >= 0.5 * kFar;
      distances_[i] = far ? kInf : std::sqrt(squared[i]) * grid.resolution();
      const int col = nearest_col[i];
      nearest[i] = far ? -1 : static_cast<long>(grid.index(nearest_row[grid.index(r, col)], col));
    }

  // A cell's candidates and piece bounds depend only on the nearest obstacles
  // of the cells within two of it: where none of those changed, the previous
  // field's are taken as they are.
  std::vector<std::uint8_t> reuse(n_cells, 0);
  if (previous) {
    std::vector<std::uint8_t> changed(n_cells), near_change(n_cells, 0);
    for (std::size_t i = 0; i < n_cells; ++i) changed[i] = nearest[i] != previous->nearest_[i];
    for (int r = 0; r < rows; ++r)  // within two columns
      for (int c = 0; c < cols; ++c)
        for (int cc = std::max(0, c - 2); cc <= std::min(cols - 1, c + 2); ++cc)
          near_change[grid.index(r, c)] |= changed[grid.index(r, cc)];
    for (int r = 0; r < rows; ++r)  // then within two rows
      for (int c = 0; c < cols; ++c) {
        bool any = false;
        for (int rr = std::max(0, r - 2); rr <= std::min(rows - 1, r + 2); ++rr) any = any || near_change[grid.index(rr, c)];
        reuse[grid.index(r, c)] = !any;
      }
  }

  // The obstacle square nearest to a point is the one nearest to a cell centre
  // close to it: each cell keeps the distinct nearest obstacles of the cells
  // within two of it, usually one to three.
  candidate_start_.assign(n_cells + 1, 0);
  // Pieces of about kBoundPiece metres, at least 2 x 2 per cell, and no more
  // than kMaxBoundPieces in all.
  constexpr double kBoundPiece = 0.025;
  constexpr double kMaxBoundPieces = 4e6;
  subdivisions_ = std::max(2, static_cast<int>(std::ceil(grid.resolution() / kBoundPiece - 1e-9)));
  subdivisions_ = std::max(2, std::min(subdivisions_, static_cast<int>(std::sqrt(kMaxBoundPieces / n_cells))));
  const int sub = subdivisions_;
  inverse_resolution_ = 1.0 / grid.resolution();
  inverse_piece_ = sub / grid.resolution();
  bound_cols_ = static_cast<double>(sub * cols);
  bound_rows_ = static_cast<double>(sub * rows);
  bound_stride_ = static_cast<std::size_t>(sub * cols);
  piece_lower_bound_.assign(n_cells * sub * sub, std::numeric_limits<float>::infinity());
  std::vector<double> nearest_piece(static_cast<std::size_t>(sub * sub)), gap_x(sub), gap_y(sub);  // squared
  std::vector<long> found;  // a cell's distinct candidates, as grid indices
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const std::size_t first = candidates_.size();
      if (reuse[grid.index(r, c)]) {
        const std::size_t i = grid.index(r, c);
        candidates_.insert(candidates_.end(),
                           previous->candidates_.begin() + static_cast<std::ptrdiff_t>(previous->candidate_start_[i]),
                           previous->candidates_.begin() + static_cast<std::ptrdiff_t>(previous->candidate_start_[i + 1]));
        for (int pr = 0; pr < sub; ++pr) {
          const std::size_t at = static_cast<std::size_t>(sub * r + pr) * bound_stride_ + static_cast<std::size_t>(sub * c);
          std::copy_n(previous->piece_lower_bound_.begin() + static_cast<std::ptrdiff_t>(at), sub,
                      piece_lower_bound_.begin() + static_cast<std::ptrdiff_t>(at));
        }
        candidate_start_[i + 1] = candidates_.size();
        continue;
      }
      found.clear();
      for (int dr = -2; dr <= 2; ++dr)
        for (int dc = -2; dc <= 2; ++dc) {
          const int rr = std::clamp(r + dr, 0, rows - 1), cc = std::clamp(c + dc, 0, cols - 1);
          const long o = nearest[grid.index(rr, cc)];
          if (o >= 0 && std::find(found.begin(), found.end(), o) == found.end()) found.push_back(o);
        }
      for (const long o : found)
        candidates_.push_back(grid.cell_center(static_cast<int>(o / cols), static_cast<int>(o % cols)));
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
        const double limit = reach + 1e-9 * res;
        return dx * dx + dy * dy > limit * limit;
      };
      candidates_.erase(std::remove_if(candidates_.begin() + static_cast<std::ptrdiff_t>(first), candidates_.end(), beyond),
                        candidates_.end());
      // The candidates hold the nearest obstacle of every point of the cell, so
      // the nearest of them to a piece of the cell bounds that piece: an
      // obstacle square of half-size res / 2 against a piece of half-size
      // piece / 2. Its gaps along x and y depend on the piece's column and row
      // alone, so they are squared once per candidate.
      const double piece = res / sub, reach_apart = 0.5 * (res + piece);
      std::fill(nearest_piece.begin(), nearest_piece.end(), kInf);
      for (std::size_t k = first; k < candidates_.size(); ++k) {
        for (int j = 0; j < sub; ++j) {
          const double offset = (j + 0.5) * piece - 0.5 * res;
          const double gx = std::max(std::abs(centre.x() + offset - candidates_[k].x()) - reach_apart, 0.0);
          const double gy = std::max(std::abs(centre.y() + offset - candidates_[k].y()) - reach_apart, 0.0);
          gap_x[j] = gx * gx;
          gap_y[j] = gy * gy;
        }
        for (int pr = 0; pr < sub; ++pr)
          for (int pc = 0; pc < sub; ++pc)
            nearest_piece[pr * sub + pc] = std::min(nearest_piece[pr * sub + pc], gap_x[pc] + gap_y[pr]);
      }
      for (int pr = 0; pr < sub; ++pr)
        for (int pc = 0; pc < sub; ++pc) {
          // Lowered by 2^-22 before rounding to single precision (relative
          // error at most 2^-24), so the stored value stays below the bound.
          const double bound = std::sqrt(nearest_piece[pr * sub + pc]) * (1.0 - 0x1p-22);
          piece_lower_bound_[static_cast<std::size_t>(sub * r + pr) * bound_stride_ + static_cast<std::size_t>(sub * c + pc)] =
              static_cast<float>(bound);
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

namespace {
// Squared distance from the segment a + t d (t in [0, 1]) to the square of
// half-size h centred on the origin: 0 where they meet; otherwise the nearer
// of the segment's ends to the square and the square's corners to the segment
// (two disjoint convex shapes come nearest at a vertex of one of them).
double segment_square_distance2(const Vec2& a, const Vec2& d, double h) {
  double t0, t1;
  if (clip_segment_to_box(a, a + d, Vec2(-h, -h), Vec2(h, h), t0, t1)) return 0.0;
  const auto to_square = [h](const Vec2& q) {
    const double dx = std::max(std::abs(q.x()) - h, 0.0), dy = std::max(std::abs(q.y()) - h, 0.0);
    return dx * dx + dy * dy;
  };
  double best = std::min(to_square(a), to_square(a + d));
  const double length2 = d.squaredNorm();
  if (length2 > 0.0)
    for (const double cx : {-h, h})
      for (const double cy : {-h, h}) {
        const Vec2 corner(cx, cy);
        const double t = std::clamp((corner - a).dot(d) / length2, 0.0, 1.0);
        best = std::min(best, (a + t * d - corner).squaredNorm());
      }
  return best;
}
}  // namespace

double DistanceField::segment_distance(const Vec2& a, const Vec2& b) const {
  if (!has_obstacles_) return kInf;
  const double ax = (a.x() - grid_.origin().x()) * inverse_resolution_, ay = (a.y() - grid_.origin().y()) * inverse_resolution_;
  const double bx = (b.x() - grid_.origin().x()) * inverse_resolution_, by = (b.y() - grid_.origin().y()) * inverse_resolution_;
  const double x0 = std::min(ax, bx), x1 = std::max(ax, bx), y0 = std::min(ay, by), y1 = std::max(ay, by);
  if (!(x0 >= 0.0 && y0 >= 0.0 && x1 < grid_.cols() && y1 < grid_.rows()))
    return std::numeric_limits<double>::quiet_NaN();
  const double half = 0.5 * grid_.resolution();
  const Vec2 d = b - a;
  double best = kInf;  // squared
  // A square no nearer than `best` by its centre's distance less its half
  // diagonal is skipped.
  const auto consider = [&](const Vec2& centre) {
    const double reach = std::max(point_segment_distance(centre, a, b) - M_SQRT2 * half, 0.0);
    if (reach * reach < best) best = std::min(best, segment_square_distance2(a - centre, d, half));
  };
  for (int r = static_cast<int>(y0); r <= static_cast<int>(y1); ++r)
    for (int c = static_cast<int>(x0); c <= static_cast<int>(x1); ++c) {
      const CellCandidates& near = cell_candidates_[grid_.index(r, c)];
      consider(Vec2(near.x0, near.y0));
      if (near.x1 != near.x0 || near.y1 != near.y0) consider(Vec2(near.x1, near.y1));
      for (std::size_t k = near.more_begin; k < near.more_end; ++k) consider(candidates_[k]);
    }
  return std::sqrt(best);
}

double DistanceField::distance(const Vec2& p) const {
  if (!has_obstacles_) return kInf;
  const double half = 0.5 * grid_.resolution();
  const int rows = grid_.rows(), cols = grid_.cols();
  const double gx = (p.x() - grid_.origin().x()) * inverse_resolution_;
  const double gy = (p.y() - grid_.origin().y()) * inverse_resolution_;
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
