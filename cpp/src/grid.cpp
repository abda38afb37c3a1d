#include "fgdwa/grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "validation.hpp"

namespace fgdwa {

using detail::describe;

OccupancyGrid::OccupancyGrid(int rows, int cols, double resolution, Vec2 origin, std::vector<std::uint8_t> cells)
    : rows_(rows), cols_(cols), resolution_(resolution), origin_(origin), cells_(std::move(cells)) {
  detail::require_grid_size(rows, cols);
  detail::require_resolution("grid resolution", resolution);
  // Grids of sensed points (points_field) reach max_range past a robot at the
  // query limit: the bound of a distance field's points.
  detail::require_field_point("grid origin", origin);
  detail::require_field_point("grid far corner", origin + Vec2(cols * resolution, rows * resolution));
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
  detail::require_field_point("point", p);
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

// A piece's bound is held in 64ths of a piece, in 16 bits: at most 1024
// pieces (25.6 m at 2.5 cm), beyond which it stays there, still a bound.
constexpr double kBoundSteps = 64.0;
constexpr std::uint16_t kMostSteps = std::numeric_limits<std::uint16_t>::max();

// `bound` (>= 0) in steps, lowered by more than the rounding of the step's
// product and held at kMostSteps: its truncation, which for a value >= 0 is the
// floor (std::floor is a call, or a dozen instructions, without SSE4.1), is
// never above the bound.
double bound_in_steps(double bound, double inverse_step) {
  return std::min(bound * inverse_step * (1.0 - 1e-12), double(kMostSteps));
}

// The lower envelope of the parabolas (q - c)^2 + f[c] rooted at the columns
// c of first..last - 1 with f[c] >= 0 (f[c] < 0: nothing there), at every
// column q of 0..n - 1: arg[q] is the column of the lowest there, the leftmost
// of equals, or -1 when there is none. Where a parabola takes over from the
// one before is kept as a fraction num / den and compared by cross
// multiplication: exact, and no division in the loop.
void lower_envelope(const std::int64_t* f, int n, int* arg, std::vector<int>& v, std::vector<std::int64_t>& num,
                    std::vector<std::int64_t>& den, int first, int last) {
  using Wide = __int128;
  int count = 0;
  for (int q = first; q < last; ++q) {
    if (f[q] < 0) continue;
    const std::int64_t height = f[q] + std::int64_t{q} * q;
    std::int64_t s_num = 0, s_den = 1;
    while (count > 0) {
      const int p = v[count - 1];
      s_num = height - (f[p] + std::int64_t{p} * p);
      s_den = 2 * std::int64_t{q - p};
      // The first parabola is never dropped; another is, when q's takes over
      // no later than it did.
      if (count == 1 || Wide{s_num} * den[count - 1] > Wide{num[count - 1]} * s_den) break;
      --count;
    }
    v[count] = q;
    num[count] = s_num;
    den[count] = s_den;
    ++count;
  }
  if (count == 0) {
    std::fill(arg, arg + n, -1);
    return;
  }
  int k = 0;
  for (int q = 0; q < n; ++q) {
    while (k + 1 < count && num[k + 1] < std::int64_t{q} * den[k + 1]) ++k;
    arg[q] = v[k];
  }
}
}  // namespace

namespace {
// The free cells added on every side of a field's grid for an edge margin of
// `margin` metres: at most 64, and on a large grid at most a sixteenth more
// cells in all, so that memory follows the grid.
constexpr long kSmallPaddedCells = 1L << 14;

int edge_pad(const OccupancyGrid& grid, double margin) {
  detail::require_distance("edge_margin", margin);
  const long rows = grid.rows(), cols = grid.cols(), cells = rows * cols;
  const long budget = std::max(cells / 16, kSmallPaddedCells);
  int pad = static_cast<int>(std::min(64.0, std::ceil(margin / grid.resolution() - 1e-9)));
  const auto extra = [&](long p) { return (rows + 2 * p) * (cols + 2 * p) - cells; };
  while (pad > 0 && (extra(pad) > budget || cells + extra(pad) > limits::kMaxGridCells)) --pad;
  // Within the coordinates a grid may have (OccupancyGrid's own check).
  const double res = grid.resolution();
  const Vec2 lo = grid.origin() - Vec2(pad * res, pad * res);
  const Vec2 hi = grid.origin() + Vec2(static_cast<double>(cols + pad) * res, static_cast<double>(rows + pad) * res);
  if (!detail::is_field_point(lo) || !detail::is_field_point(hi)) pad = 0;
  return pad;
}

OccupancyGrid padded(const OccupancyGrid& grid, int pad) {
  if (pad == 0) return grid;
  const int rows = grid.rows() + 2 * pad, cols = grid.cols() + 2 * pad;
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(rows) * cols, 0);
  for (int r = 0; r < grid.rows(); ++r)
    std::copy_n(&grid.cells()[grid.index(r, 0)], grid.cols(), &cells[static_cast<std::size_t>(r + pad) * cols + pad]);
  return OccupancyGrid(rows, cols, grid.resolution(), grid.origin() - Vec2(pad * grid.resolution(), pad * grid.resolution()),
                       std::move(cells));
}
}  // namespace

DistanceField::DistanceField(const OccupancyGrid& grid, double edge_margin)
    : shown_(grid), pad_(edge_pad(grid, edge_margin)), grid_(padded(grid, pad_)) {
  const int rows = grid_.rows(), cols = grid_.cols();
  // The grid's constructor bounds the cells (limits::kMaxGridCells), so cell
  // indices fit the 32-bit tables.
  const std::size_t n_cells = static_cast<std::size_t>(rows) * cols;
  static_assert(limits::kMaxGridCells <= std::numeric_limits<std::int32_t>::max());
  occupied_ = grid_.occupied_count();
  const int n = std::max(rows, cols);
  f_.resize(n);
  num_.resize(n);
  den_.resize(n);
  v_.resize(n);
  arg_.resize(n);
  column_nearest_.assign(n_cells, -1);
  while ((1 << col_bits_) < cols) ++col_bits_;
  col_mask_ = (std::uint32_t{1} << col_bits_) - 1;
  static_assert(2 * limits::kMaxGridCells <= std::numeric_limits<std::uint32_t>::max());
  centre_x_.resize(cols);
  centre_y_.resize(rows);
  // The bits of shown_.cell_center() on the given cells, so that a query at a
  // centre measures the same there whatever the margin.
  for (int c = 0; c < cols; ++c) centre_x_[c] = shown_.cell_center(0, c - pad_).x();
  for (int r = 0; r < rows; ++r) centre_y_[r] = shown_.cell_center(r - pad_, 0).y();
  // Pieces of about kBoundPiece metres, at least 2 x 2 per cell, and no more
  // than kMaxBoundPieces in all.
  constexpr double kBoundPiece = 0.025;
  constexpr double kMaxBoundPieces = 4e6;
  subdivisions_ = std::max(2, static_cast<int>(std::ceil(grid_.resolution() / kBoundPiece - 1e-9)));
  subdivisions_ = std::max(2, std::min(subdivisions_, static_cast<int>(std::sqrt(kMaxBoundPieces / n_cells))));
  const int sub = subdivisions_;
  inverse_resolution_ = 1.0 / grid_.resolution();
  inverse_piece_ = sub / grid_.resolution();
  bound_cols_ = static_cast<double>(sub * cols);
  bound_rows_ = static_cast<double>(sub * rows);
  bound_stride_ = static_cast<std::size_t>(sub * cols);
  bound_step_ = grid_.resolution() / sub / kBoundSteps;
  candidates_.assign(n_cells, CellCandidates{kNoCell, kNoCell, 0});
  more_.assign(1, 0);
  piece_scratch_.resize(static_cast<std::size_t>(sub) * sub);
  gap_x_.resize(sub);
  gap_y_.resize(sub);
  // One entry past the last, never a piece's: a 32-bit read at any piece stays in the table.
  piece_lower_bound_.assign(n_cells * sub * sub + 1, kMostSteps);
  for (int c = 0; c < cols; ++c) column_pass(c, 0, rows - 1, nullptr);
  for (int r = 0; r < rows; ++r) row_pass(r, nullptr);
  if (occupied_ > 0)
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) look_up_data(r, c, false);
  row_first_.resize(rows);
  row_last_.resize(rows);
  col_first_.resize(cols);
  col_last_.resize(cols);
  row_block_first_.assign(static_cast<std::size_t>((rows + kOutermostBlock - 1) / kOutermostBlock), -1);
  row_block_last_.assign(row_block_first_.size(), -1);
  col_block_first_.assign(static_cast<std::size_t>((cols + kOutermostBlock - 1) / kOutermostBlock), -1);
  col_block_last_.assign(col_block_first_.size(), -1);
  for (int r = 0; r < rows; ++r) row_outermost(r);
  for (int c = 0; c < cols; ++c) col_outermost(c);
}

DistanceField::DistanceField(const OccupancyGrid& grid, const DistanceField& previous) : DistanceField(previous) {
  update(grid);
}

void DistanceField::column_pass(int col, int from, int to, std::vector<ColumnChange>* changes) {
  const auto occupied = [&](int r) { return grid_.occupied(r, col); };
  int lower = -1;  // the nearest occupied row at or below r
  for (int r = from; r >= 0; --r)
    if (occupied(r)) {
      lower = r;
      break;
    }
  // The rows whose nearest changes are the ones a row pass must see again;
  // the old values are kept until the second sweep compares them.
  if (changes) {
    column_before_.clear();
    for (int r = from; r <= to; ++r) column_before_.push_back(column_nearest_[grid_.index(r, col)]);
  }
  for (int r = from; r <= to; ++r) {
    if (occupied(r)) lower = r;
    column_nearest_[grid_.index(r, col)] = lower;
  }
  int upper = -1;  // the nearest occupied row at or above r
  for (int r = to; r < grid_.rows(); ++r)
    if (occupied(r)) {
      upper = r;
      break;
    }
  for (int r = to; r >= from; --r) {
    if (occupied(r)) upper = r;
    std::int32_t& best = column_nearest_[grid_.index(r, col)];
    if (upper >= 0 && (best < 0 || upper - r < r - best)) best = upper;  // a tie keeps the lower row
    if (changes && best != column_before_[static_cast<std::size_t>(r - from)])
      changes->push_back(ColumnChange{r, col, column_before_[static_cast<std::size_t>(r - from)]});
  }
}

void DistanceField::row_pass(int row, std::vector<std::size_t>* changed) {
  const int cols = grid_.cols();
  const std::int32_t* nearest_row = &column_nearest_[grid_.index(row, 0)];
  // The margin's columns hold no obstacle: no parabola is rooted there.
  for (int c = pad_; c < cols - pad_; ++c) {
    const std::int64_t dr = row - nearest_row[c];
    f_[c] = nearest_row[c] < 0 ? -1 : dr * dr;
  }
  lower_envelope(f_.data(), cols, arg_.data(), v_, num_, den_, pad_, cols - pad_);
  for (int c = 0; c < cols; ++c) {
    const std::uint32_t nearest = arg_[c] < 0 ? kNoCell : pack(nearest_row[arg_[c]], arg_[c]);
    std::uint32_t& now = candidates_[grid_.index(row, c)].first;
    if (nearest == now) continue;
    now = nearest;
    if (changed) changed->push_back(grid_.index(row, c));
  }
}

void DistanceField::rows_after(std::vector<ColumnChange>& changes, std::vector<std::size_t>& changed) {
  // By row and column; of a cell's changes the first holds its value before them all.
  std::stable_sort(changes.begin(), changes.end(), [](const ColumnChange& a, const ColumnChange& b) {
    return a.row != b.row ? a.row < b.row : a.col < b.col;
  });
  std::vector<Lowered> lowered;
  std::vector<std::uint32_t> raised;  // the nearest obstacles the row's columns had before
  for (std::size_t at = 0; at < changes.size();) {
    const int row = changes[at].row;
    lowered.clear();
    raised.clear();
    for (; at < changes.size() && changes[at].row == row; ++at) {
      const ColumnChange& change = changes[at];
      if (at > 0 && changes[at - 1].row == row && changes[at - 1].col == change.col) continue;
      const std::int32_t now = column_nearest_[grid_.index(row, change.col)];
      if (now == change.before) continue;
      const std::int64_t height = std::int64_t{row - now} * (row - now);
      if (now >= 0 && (change.before < 0 || height < std::int64_t{row - change.before} * (row - change.before)))
        lowered.push_back(Lowered{change.col, now, height});
      else if (change.before >= 0)
        raised.push_back(pack(change.before, change.col));
    }
    // A column whose obstacle went farther off changes nothing if it was
    // nobody's nearest: it is beaten everywhere, and more so now.
    bool raised_mattered = false;
    if (!raised.empty())
      for (int q = 0; q < grid_.cols() && !raised_mattered; ++q) {
        const std::uint32_t nearest = candidates_[grid_.index(row, q)].first;
        raised_mattered = std::find(raised.begin(), raised.end(), nearest) != raised.end();
      }
    if (raised_mattered) row_pass(row, &changed);
    else if (!lowered.empty()) row_lowered(row, lowered, changed);
  }
}

void DistanceField::row_lowered(int row, const std::vector<Lowered>& lowered, std::vector<std::size_t>& changed) {
  const int cols = grid_.cols();
  for (int q = 0; q < cols; ++q) {
    std::uint32_t& nearest = candidates_[grid_.index(row, q)].first;
    std::uint32_t best = nearest;
    std::int64_t best_height = std::numeric_limits<std::int64_t>::max();
    int best_col = std::numeric_limits<int>::max();
    if (best != kNoCell) {
      const std::int64_t dr = row - row_of(best), dc = q - col_of(best);
      best_height = dr * dr + dc * dc;
      best_col = col_of(best);
    }
    for (const Lowered& l : lowered) {
      const std::int64_t dc = q - l.col, height = l.height + dc * dc;
      if (height < best_height || (height == best_height && l.col < best_col)) {
        best_height = height;
        best_col = l.col;
        best = pack(l.nearest, l.col);
      }
    }
    if (best == nearest) continue;
    nearest = best;
    changed.push_back(grid_.index(row, q));
  }
}

void DistanceField::look_up_data(int r, int c, bool first_unchanged) {
  const int rows = grid_.rows(), cols = grid_.cols();
  const double res = grid_.resolution();
  const int sub = subdivisions_;
  CellCandidates& cell = candidates_[grid_.index(r, c)];
  if (cell.first == kNoCell) {  // no obstacles: nothing to bound
    more_garbage_ += cell.more ? more_[cell.more] + 1 : 0;
    cell.second = cell.first;
    cell.more = 0;
    return;
  }
  // The obstacle square nearest to a point is the one nearest to a cell centre
  // close to it: each cell keeps the distinct nearest obstacles of the cells
  // within two of it, its own first. An occupied cell is the nearest square of
  // every point in it and needs no other.
  std::uint32_t found[25];
  found[0] = cell.first;
  int count = 1;
  if (!grid_.occupied(r, c)) {
    // Neighbours mostly share their nearest: one equal to the value read just
    // before is skipped without a search.
    std::uint32_t previous = cell.first;
    const auto consider = [&](std::uint32_t o) {
      if (o == previous) return;
      previous = o;
      if (o != kNoCell && std::find(found, found + count, o) == found + count) found[count++] = o;
    };
    if (r >= 2 && c >= 2 && r + 2 < rows && c + 2 < cols) {
      for (int dr = -2; dr <= 2; ++dr) {
        const CellCandidates* line = &candidates_[grid_.index(r + dr, c - 2)];
        for (int dc = 0; dc < 5; ++dc) consider(line[dc].first);
      }
    } else {
      for (int dr = -2; dr <= 2; ++dr)
        for (int dc = -2; dc <= 2; ++dc)
          consider(candidates_[grid_.index(std::clamp(r + dr, 0, rows - 1), std::clamp(c + dc, 0, cols - 1))].first);
    }
  }
  Vec2 centres[25];
  for (int k = 0; k < count; ++k) centres[k] = centre_of(found[k]);
  // Drop the candidates that cannot be nearest anywhere in the cell: their
  // square is farther from the whole cell than some other candidate's square
  // is from the cell's farthest corner. Clustered maps leave a dozen
  // candidates per cell before this and one to three after, and distance()
  // spends its time in this loop. The cell's own nearest is the one nearest
  // its centre, so it stays.
  const Vec2 centre = centre_of(pack(r, c));
  const double reach = (centre - centres[0]).norm();
  const auto beyond = [&](const Vec2& o) {
    const double dx = std::max(std::abs(centre.x() - o.x()) - res, 0.0);
    const double dy = std::max(std::abs(centre.y() - o.y()) - res, 0.0);
    const double limit = reach + 1e-9 * res;
    return dx * dx + dy * dy > limit * limit;
  };
  int kept = 1;
  for (int k = 1; k < count; ++k)
    if (!beyond(centres[k])) {
      found[kept] = found[k];
      centres[kept++] = centres[k];
    }
  count = kept;

  // The same candidates in the same order give the same bounds: a cell near a
  // change whose own nearest stayed often keeps them all.
  if (first_unchanged) {
    const std::uint32_t old_count = cell.more ? more_[cell.more] + 2 : (cell.second != cell.first ? 2 : 1);
    bool same = old_count == static_cast<std::uint32_t>(count) && (count < 2 || found[1] == cell.second);
    for (int k = 2; same && k < count; ++k) same = found[k] == more_[cell.more + static_cast<std::uint32_t>(k - 1)];
    if (same) return;
  }
  more_garbage_ += cell.more ? more_[cell.more] + 1 : 0;
  cell.second = cell.first;
  cell.more = 0;

  // The candidates hold the nearest obstacle of every point of the cell, so
  // the nearest of them to a piece of the cell bounds that piece: an
  // obstacle square of half-size res / 2 against a piece of half-size
  // piece / 2. Its gaps along x and y depend on the piece's column and row
  // alone, so they are squared once per candidate.
  const double piece = res / sub, reach_apart = 0.5 * (res + piece);
  std::vector<double>& nearest_piece = piece_scratch_;  // squared, as are the gaps
  std::vector<double>& gap_x = gap_x_;
  std::vector<double>& gap_y = gap_y_;
  std::fill(nearest_piece.begin(), nearest_piece.end(), kInf);
  for (int k = 0; k < count; ++k) {
    for (int j = 0; j < sub; ++j) {
      const double offset = (j + 0.5) * piece - 0.5 * res;
      const double gx = std::max(std::abs(centre.x() + offset - centres[k].x()) - reach_apart, 0.0);
      const double gy = std::max(std::abs(centre.y() + offset - centres[k].y()) - reach_apart, 0.0);
      gap_x[j] = gx * gx;
      gap_y[j] = gy * gy;
    }
    for (int pr = 0; pr < sub; ++pr)
      for (int pc = 0; pc < sub; ++pc)
        nearest_piece[pr * sub + pc] = std::min(nearest_piece[pr * sub + pc], gap_x[pc] + gap_y[pr]);
  }
  // Square roots and scaling over the whole cell first, so that they run
  // several to a vector; then the conversions.
  const double inverse_step = 1.0 / bound_step_;
  const std::size_t pieces = static_cast<std::size_t>(sub) * sub;
  for (std::size_t k = 0; k < pieces; ++k)
    nearest_piece[k] = bound_in_steps(std::sqrt(nearest_piece[k]), inverse_step);
  for (int pr = 0; pr < sub; ++pr) {
    std::uint16_t* out = &piece_lower_bound_[static_cast<std::size_t>(sub * r + pr) * bound_stride_ + static_cast<std::size_t>(sub * c)];
    const double* steps = &nearest_piece[static_cast<std::size_t>(pr) * sub];
    for (int pc = 0; pc < sub; ++pc) out[pc] = static_cast<std::uint16_t>(static_cast<std::int32_t>(steps[pc]));
  }

  if (count > 1) cell.second = found[1];
  if (count > 2) {
    // Indices stay 32-bit: the live entries are at most 24 a cell.
    if (more_.size() + count - 1 > std::numeric_limits<std::uint32_t>::max()) compact_more();
    cell.more = static_cast<std::uint32_t>(more_.size());
    more_.push_back(static_cast<std::uint32_t>(count - 2));
    more_.insert(more_.end(), found + 2, found + count);
  }
}

void DistanceField::compact_more() {
  std::vector<std::uint32_t> kept;
  kept.reserve(more_.size() - more_garbage_);
  kept.push_back(0);
  for (CellCandidates& cell : candidates_) {
    if (!cell.more) continue;
    const std::uint32_t at = static_cast<std::uint32_t>(kept.size());
    kept.insert(kept.end(), more_.begin() + cell.more, more_.begin() + cell.more + 1 + more_[cell.more]);
    cell.more = at;
  }
  more_ = std::move(kept);
  more_garbage_ = 0;
}

std::size_t DistanceField::update(const OccupancyGrid& grid) {
  std::vector<std::size_t> differ;
  const std::vector<std::uint8_t>& now = shown_.cells();
  if (grid.cells().size() == now.size())
    for (std::size_t i = 0; i < now.size(); ++i)
      if ((grid.cells()[i] != 0) != (now[i] != 0)) differ.push_back(i);
  return update(grid, differ);
}

std::size_t DistanceField::update(const OccupancyGrid& grid, const std::vector<std::size_t>& cells) {
  if (grid.rows() != shown_.rows() || grid.cols() != shown_.cols() || grid.resolution() != shown_.resolution() ||
      grid.origin() != shown_.origin())
    throw Error("DistanceField::update: the grid has another layout (rows, cols, resolution or origin) than the field's");
  const int rows = grid_.rows(), cols = grid_.cols();
  for (const std::size_t i : cells)  // all checked before anything changes
    if (i >= grid.cells().size())
      throw Error(describe("DistanceField::update cell", i, "must be below rows x cols = " + std::to_string(grid.cells().size())));
  std::vector<std::size_t> flipped;  // in the padded grid
  for (const std::size_t i : cells) {
    const bool occupied = grid.cells()[i] != 0;
    if (occupied == (shown_.cells()[i] != 0)) continue;
    shown_.set(i, occupied);
    const std::size_t j = grid_.index(static_cast<int>(i / shown_.cols()) + pad_, static_cast<int>(i % shown_.cols()) + pad_);
    grid_.set(j, occupied);
    occupied_ = occupied ? occupied_ + 1 : occupied_ - 1;
    flipped.push_back(j);
  }
  if (flipped.empty()) return 0;

  // A cell's column run changes between the occupied cells above and below it.
  std::vector<ColumnChange> column_changes;
  for (const std::size_t i : flipped) {
    const int r0 = static_cast<int>(i / cols), c0 = static_cast<int>(i % cols);
    int below = r0 - 1, above = r0 + 1;
    while (below >= 0 && !grid_.occupied(below, c0)) --below;
    while (above < rows && !grid_.occupied(above, c0)) ++above;
    column_pass(c0, below + 1, above - 1, &column_changes);
  }
  std::vector<std::size_t> changed;
  rows_after(column_changes, changed);

  // Look-up data read the nearest obstacles of the cells within two.
  std::vector<std::size_t> stale;
  stale_mark_.resize(grid_.cells().size());
  for (const std::size_t i : changed) {
    const int r = static_cast<int>(i / cols), c = static_cast<int>(i % cols);
    for (int rr = std::max(0, r - 2); rr <= std::min(rows - 1, r + 2); ++rr)
      for (int cc = std::max(0, c - 2); cc <= std::min(cols - 1, c + 2); ++cc) {
        const std::size_t j = grid_.index(rr, cc);
        if (stale_mark_[j]) continue;
        stale_mark_[j] = 1;
        stale.push_back(j);
      }
  }
  for (const std::size_t i : changed) stale_mark_[i] = 2;
  for (const std::size_t i : stale) {
    look_up_data(static_cast<int>(i / cols), static_cast<int>(i % cols), stale_mark_[i] == 1);
    stale_mark_[i] = 0;
  }
  if (more_garbage_ > 4096 && 2 * more_garbage_ > more_.size()) compact_more();

  std::vector<int> flipped_rows, flipped_cols;
  for (const std::size_t i : flipped) {
    flipped_rows.push_back(static_cast<int>(i / cols));
    flipped_cols.push_back(static_cast<int>(i % cols));
  }
  for (std::vector<int>* lines : {&flipped_rows, &flipped_cols}) {
    std::sort(lines->begin(), lines->end());
    lines->erase(std::unique(lines->begin(), lines->end()), lines->end());
  }
  for (const int r : flipped_rows) row_outermost(r);
  for (const int c : flipped_cols) col_outermost(c);
  return flipped.size();
}

namespace {
// The smallest first and the largest last of the block of lines holding `line`.
void refresh_block(const std::vector<int>& first, const std::vector<int>& last, int line, int block_size,
                   std::vector<int>& block_first, std::vector<int>& block_last) {
  const std::size_t block = static_cast<std::size_t>(line / block_size);
  const std::size_t begin = block * static_cast<std::size_t>(block_size);
  const std::size_t end = std::min(first.size(), begin + static_cast<std::size_t>(block_size));
  int lo = -1, hi = -1;
  for (std::size_t i = begin; i < end; ++i) {
    if (first[i] < 0) continue;
    lo = lo < 0 ? first[i] : std::min(lo, first[i]);
    hi = std::max(hi, last[i]);
  }
  block_first[block] = lo;
  block_last[block] = hi;
}
}  // namespace

void DistanceField::row_outermost(int row) {
  row_first_[row] = row_last_[row] = -1;
  for (int c = 0; c < grid_.cols(); ++c)
    if (grid_.occupied(row, c)) {
      if (row_first_[row] < 0) row_first_[row] = c;
      row_last_[row] = c;
    }
  refresh_block(row_first_, row_last_, row, kOutermostBlock, row_block_first_, row_block_last_);
}

void DistanceField::col_outermost(int col) {
  col_first_[col] = col_last_[col] = -1;
  for (int r = 0; r < grid_.rows(); ++r)
    if (grid_.occupied(r, col)) {
      if (col_first_[col] < 0) col_first_[col] = r;
      col_last_[col] = r;
    }
  refresh_block(col_first_, col_last_, col, kOutermostBlock, col_block_first_, col_block_last_);
}

double DistanceField::cell_distance(int row, int col) const {
  if (!shown_.in_bounds(row, col))
    throw Error("cell (" + std::to_string(row) + ", " + std::to_string(col) + ") is outside the grid");
  row += pad_;
  col += pad_;
  const std::uint32_t o = candidates_[grid_.index(row, col)].first;
  if (o == kNoCell) return kInf;
  const double dr = row - row_of(o), dc = col - col_of(o);
  return std::sqrt(dr * dr + dc * dc) * grid_.resolution();
}

std::vector<double> DistanceField::cell_distances() const {
  std::vector<double> out(shown_.cells().size());
  for (int r = 0; r < shown_.rows(); ++r)
    for (int c = 0; c < shown_.cols(); ++c) out[shown_.index(r, c)] = cell_distance(r, c);
  return out;
}

double DistanceField::bytes_per_cell() const {
  const auto bytes = [](const auto& v) { return static_cast<double>(v.capacity() * sizeof(v[0])); };
  const double total = sizeof(*this) + bytes(shown_.cells()) + bytes(grid_.cells()) + bytes(column_nearest_) + bytes(candidates_) + bytes(more_) +
                       bytes(centre_x_) + bytes(centre_y_) + bytes(piece_lower_bound_) + bytes(row_first_) +
                       bytes(row_last_) + bytes(col_first_) + bytes(col_last_) + bytes(row_block_first_) +
                       bytes(row_block_last_) + bytes(col_block_first_) + bytes(col_block_last_) + bytes(f_) +
                       bytes(num_) + bytes(den_) + bytes(v_) + bytes(arg_) + bytes(piece_scratch_) + bytes(gap_x_) +
                       bytes(gap_y_) + bytes(stale_mark_) + bytes(column_before_);
  return total / static_cast<double>(shown_.cells().size());
}

namespace {
// Squared distance from the segment a + t d (t in [0, 1]) to the square of
// half-size h centred on the origin: 0 where they meet; otherwise the nearer
// of the segment's ends to the square and the square's corners to the segment
// (two disjoint convex shapes come nearest at a vertex of one of them).
// `apart`: the segment is known to miss the square, and is not clipped.
// A corner no nearer the segment's line than the least so far, or than
// `below`, is not projected: its distance cannot lower a result below `below`
// (the 1e-9 keeps the test on the safe side of the rounding). Clipping and
// projecting divide; most squares a segment is measured against need neither.
double segment_square_distance2(const Vec2& a, const Vec2& d, double h, double below, bool apart) {
  double t0, t1;
  if (!apart && clip_segment_to_box(a, a + d, Vec2(-h, -h), Vec2(h, h), t0, t1)) return 0.0;
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
        const Vec2 to_corner = corner - a;
        const double cross = d.x() * to_corner.y() - d.y() * to_corner.x();  // |d| times the line's distance
        if (cross * cross >= std::min(best, below) * length2 * (1.0 + 1e-9)) continue;
        const double t = std::clamp(to_corner.dot(d) / length2, 0.0, 1.0);
        best = std::min(best, (a + t * d - corner).squaredNorm());
      }
  return best;
}

// The segment ab measured against obstacle squares of half-size `half`, one
// after another, each lowering a squared best. A square is measured only when
// its centre lies nearer the segment than the best's root and the half
// diagonal together. That test compares squares, with the segment's inverse
// length taken once: no division or root per square. It is a little generous
// (1e-9), so that it takes every square the exact test would.
class SegmentProbe {
 public:
  SegmentProbe(const Vec2& a, const Vec2& b, double half) : a_(a), d_(b - a), half_(half), diagonal_(M_SQRT2 * half) {
    const double length2 = d_.squaredNorm();
    inverse_length2_ = length2 > 0.0 ? 1.0 / length2 : 0.0;
    // Beyond the half diagonal, a nanometre over for the rounding, the segment misses the square.
    const double apart = diagonal_ * (1.0 + 1e-9) + 1e-9;
    apart2_ = apart * apart;
  }

  void measure(const Vec2& centre, double& best) {
    if (best != limit_for_) {
      limit_for_ = best;
      const double reach = std::sqrt(best) + diagonal_;
      limit_ = reach * reach * (1.0 + 1e-9);
    }
    const Vec2 to_centre = centre - a_;
    const double t = std::clamp(to_centre.dot(d_) * inverse_length2_, 0.0, 1.0);
    const double gap2 = (to_centre - t * d_).squaredNorm();
    if (gap2 < limit_)
      best = std::min(best, segment_square_distance2(a_ - centre, d_, half_, best, gap2 > apart2_));
  }

 private:
  Vec2 a_, d_;  // d_ = b - a
  double half_, diagonal_, inverse_length2_ = 0.0, apart2_ = 0.0;
  double limit_for_ = std::numeric_limits<double>::quiet_NaN(), limit_ = 0.0;
};
}  // namespace

inline double DistanceField::cell_square_distance(std::size_t cell, const Vec2& a) const {
  const double half = 0.5 * grid_.resolution();
  const auto from = [&](std::uint32_t o) {
    const Vec2 centre = centre_of(o);
    const double dx = std::max(std::abs(a.x() - centre.x()) - half, 0.0);
    const double dy = std::max(std::abs(a.y() - centre.y()) - half, 0.0);
    return dx * dx + dy * dy;
  };
  const CellCandidates& near = candidates_[cell];
  double best = std::min(from(near.first), from(near.second));
  if (near.more)
    for (std::uint32_t k = 1; k <= more_[near.more]; ++k) best = std::min(best, from(more_[near.more + k]));
  return best;
}

// The conversion truncates where std::floor would round down: they differ
// only below 0, which the clamp sends to cell 0 either way, and truncation
// is one instruction (std::floor, a dozen without SSE4.1).
namespace {
int clamped_cell(double g, int count) { return std::clamp(static_cast<int>(g), 0, count - 1); }
}  // namespace

inline std::size_t DistanceField::cell_at(double gx, double gy) const {
  return grid_.index(clamped_cell(gy, grid_.rows()), clamped_cell(gx, grid_.cols()));
}

inline double DistanceField::outside_start(const Vec2& p, double gx, double gy) const {
  // The distance to the grid's nearest point q, plus q's own (from q's cell),
  // a little raised so that the obstacle giving it is still visited. Started
  // from infinity, a point beside an edge with no obstacle near it walked
  // line after line before the gap alone beat the best.
  const double qx = std::clamp(gx, 0.0, static_cast<double>(grid_.cols()));
  const double qy = std::clamp(gy, 0.0, static_cast<double>(grid_.rows()));
  const Vec2 q(grid_.origin().x() + qx * grid_.resolution(), grid_.origin().y() + qy * grid_.resolution());
  const double bound = (p - q).norm() + std::sqrt(cell_square_distance(cell_at(qx, qy), q));
  return bound * bound * (1.0 + 1e-9) + 1e-300;
}

// Lines (rows or columns) taken outward from those the span [lo, hi] covers
// (in cells, across the lines; a point's span is one value), each through
// `candidate(line)`, until a line's gap alone (its distance from the span
// across the lines) is no nearer than `best` (squared, which the candidates
// lower): the same minimum as over every line.
//
// Lines come in blocks of kOutermostBlock; a block is skipped whole when its
// gap and the reach of its outermost obstacle along the lines (`along`, the
// distance from the span to the block's extreme outermost square) together
// are no nearer than the best: far from the grid the best is far, and without
// the blocks every line would be visited.
template <class Along, class Candidate>
void DistanceField::walk_outward(int lines, double lo, double hi, const std::vector<int>& outermost,
                                 const std::vector<int>& block_extreme, const Along& along, const Candidate& candidate,
                                 const double& best) const {
  const double res = grid_.resolution();
  const int nearest = static_cast<int>(std::clamp(std::floor(lo), 0.0, lines - 1.0));
  const auto gap = [&](int line) {
    const double g = std::max({line - hi, lo - line - 1.0, 0.0}) * res;
    return g * g;
  };
  // The gap is rounded unlike the candidates' distances: a line or block
  // within a rounding error of the best is still taken.
  const auto visit_block = [&](int block, int from, int to) {  // lines from..to, nearest first
    if (block_extreme[static_cast<std::size_t>(block)] < 0) return;
    const double reach = along(block_extreme[static_cast<std::size_t>(block)]);
    if ((reach * reach + gap(from)) * (1.0 - 1e-9) >= best) return;
    const int step = to >= from ? 1 : -1;
    for (int line = from; line != to + step && gap(line) * (1.0 - 1e-9) < best; line += step)
      if (outermost[static_cast<std::size_t>(line)] >= 0) candidate(line);
  };
  for (int line = nearest; line >= 0 && gap(line) * (1.0 - 1e-9) < best;) {
    const int block = line / kOutermostBlock, first = block * kOutermostBlock;
    visit_block(block, line, first);
    line = first - 1;
  }
  for (int line = nearest + 1; line < lines && gap(line) * (1.0 - 1e-9) < best;) {
    const int block = line / kOutermostBlock, last = std::min(lines - 1, (block + 1) * kOutermostBlock - 1);
    visit_block(block, line, last);
    line = last + 1;
  }
}

// ab inside the grid (ga, gb: its ends in cells): every point's nearest
// obstacle is a candidate of its cell.
inline void DistanceField::segment_inside(const Vec2& a, const Vec2& b, const Vec2& ga, const Vec2& gb, double& best) const {
  const int r0 = clamped_cell(std::min(ga.y(), gb.y()), grid_.rows());
  const int r1 = clamped_cell(std::max(ga.y(), gb.y()), grid_.rows());
  const int c0 = clamped_cell(std::min(ga.x(), gb.x()), grid_.cols());
  const int c1 = clamped_cell(std::max(ga.x(), gb.x()), grid_.cols());
  double nearest = best;  // a local: the tables' doubles cannot alias it
  SegmentProbe probe(a, b, 0.5 * grid_.resolution());
  // Neighbouring cells mostly share their nearest obstacles: those the cell
  // before gave are not measured again.
  std::uint32_t last_first = std::numeric_limits<std::uint32_t>::max(), last_second = last_first;
  for (int r = r0; r <= r1; ++r)
    for (int c = c0; c <= c1; ++c) {
      const CellCandidates& near = candidates_[grid_.index(r, c)];
      const auto seen = [&](std::uint32_t o) { return o == last_first || o == last_second; };
      if (!seen(near.first)) probe.measure(centre_of(near.first), nearest);
      if (near.second != near.first && !seen(near.second)) probe.measure(centre_of(near.second), nearest);
      last_first = near.first, last_second = near.second;
      if (near.more)
        for (std::uint32_t k = 1; k <= more_[near.more]; ++k) probe.measure(centre_of(more_[near.more + k]), nearest);
    }
  best = nearest;
}

// For the segment ab (a point when a == b) wholly on one side outside the
// grid (ga, gb: its ends in cells): every cell of a row lies on the same side
// of it in x (beside the grid) or of a column in y (beyond it), so the row's
// (column's) outermost obstacle toward it is its nearest. Each is handed to
// `measure(centre)`, which lowers the squared `best`.
template <class Measure>
void DistanceField::walk_outside(const Vec2& a, const Vec2& b, const Vec2& ga, const Vec2& gb, const Measure& measure,
                                 const double& best) const {
  const int rows = grid_.rows(), cols = grid_.cols();
  const double half = 0.5 * grid_.resolution();
  const double mid_x = 0.5 * (ga.x() + gb.x()), mid_y = 0.5 * (ga.y() + gb.y());
  const bool beside = mid_x < 0.0 || mid_x > cols;
  // Across the lines: y beside the grid, x beyond it; along them the other.
  const int axis = beside ? 0 : 1;
  const bool low_side = beside ? mid_x < 0.0 : mid_y < 0.0;
  const std::vector<int>& outermost = beside ? (low_side ? row_first_ : row_last_) : (low_side ? col_first_ : col_last_);
  const std::vector<int>& blocks =
      beside ? (low_side ? row_block_first_ : row_block_last_) : (low_side ? col_block_first_ : col_block_last_);
  const std::vector<double>& along_centres = beside ? centre_x_ : centre_y_;
  const std::vector<double>& across_centres = beside ? centre_y_ : centre_x_;
  const double lo = std::min(a[axis], b[axis]), hi = std::max(a[axis], b[axis]);
  const auto along = [&](int at) {
    return std::max({along_centres[at] - half - hi, lo - along_centres[at] - half, 0.0});
  };
  const auto line = [&](int l) {
    const double x = along_centres[outermost[l]], y = across_centres[l];
    measure(beside ? Vec2(x, y) : Vec2(y, x));
  };
  walk_outward(beside ? rows : cols, std::min(ga[1 - axis], gb[1 - axis]), std::max(ga[1 - axis], gb[1 - axis]),
               outermost, blocks, along, line, best);
}

double DistanceField::segment_distance(const Vec2& a, const Vec2& b) const {
  detail::require_field_point("a", a);
  detail::require_field_point("b", b);
  if (!has_obstacles()) return kInf;
  const double rows = grid_.rows(), cols = grid_.cols();
  const auto in_cells = [&](const Vec2& p) {
    return Vec2((p.x() - grid_.origin().x()) * inverse_resolution_, (p.y() - grid_.origin().y()) * inverse_resolution_);
  };
  const Vec2 ga = in_cells(a), gb = in_cells(b);
  const auto inside = [&](const Vec2& g) { return g.x() >= 0.0 && g.x() <= cols && g.y() >= 0.0 && g.y() <= rows; };
  double best = kInf;  // squared
  if (inside(ga) && inside(gb)) {
    segment_inside(a, b, ga, gb, best);
    return std::sqrt(best);
  }
  // Cut where the segment crosses the grid's edges: each piece lies inside the
  // grid or wholly on one side of it.
  double cuts[6] = {0.0, 1.0};
  int n = 2;
  const auto cut = [&](double from, double to, double edge) {
    if (!((from < edge && edge < to) || (to < edge && edge < from))) return;
    // Kept in order (at most four cuts).
    const double t = (edge - from) / (to - from);
    int at = n++;
    for (; at > 0 && cuts[at - 1] > t; --at) cuts[at] = cuts[at - 1];
    cuts[at] = t;
  };
  cut(ga.x(), gb.x(), 0.0);
  cut(ga.x(), gb.x(), cols);
  cut(ga.y(), gb.y(), 0.0);
  cut(ga.y(), gb.y(), rows);
  for (int i = 0; i + 1 < n; ++i) {
    if (cuts[i + 1] <= cuts[i]) continue;  // a corner crossed: the same cut twice
    const auto at = [&](const Vec2& from, const Vec2& to, double t) { return t == 1.0 ? to : from + t * (to - from); };
    const Vec2 pa = at(a, b, cuts[i]), pb = at(a, b, cuts[i + 1]);
    const Vec2 qa = at(ga, gb, cuts[i]), qb = at(ga, gb, cuts[i + 1]);
    if (inside(0.5 * (qa + qb))) segment_inside(pa, pb, qa, qb, best);
    else {
      best = std::min(best, outside_start(pa, qa.x(), qa.y()));
      SegmentProbe probe(pa, pb, 0.5 * grid_.resolution());
      walk_outside(pa, pb, qa, qb, [&](const Vec2& centre) { probe.measure(centre, best); }, best);
    }
  }
  return std::sqrt(best);
}

double DistanceField::upper_bound(const Vec2& p) const {
  detail::require_field_point("point", p);
  if (!has_obstacles()) return kInf;
  const LowerBounds table = lower_bounds();
  const std::uint16_t* at = table.piece_at((p.x() - table.origin_x) * table.inverse_piece,
                                           (p.y() - table.origin_y) * table.inverse_piece);
  if (!at || *at == kMostSteps) return kInf;
  const std::uint16_t steps = *at;
  // Raised a little above the rounding of the stored bound and of the sum.
  return ((steps + 1.0) * bound_step_ + std::sqrt(2.0) / inverse_piece_) * (1.0 + 1e-9);
}

double DistanceField::distance(const Vec2& p) const {
  detail::require_field_point("point", p);
  if (!has_obstacles()) return kInf;
  const double half = 0.5 * grid_.resolution();
  const int rows = grid_.rows(), cols = grid_.cols();
  const double gx = (p.x() - grid_.origin().x()) * inverse_resolution_;
  const double gy = (p.y() - grid_.origin().y()) * inverse_resolution_;
  // Inside the grid (its far edges included): the candidates of p's cell.
  if (!(gx < 0.0 || gx > cols || gy < 0.0 || gy > rows)) return std::sqrt(cell_square_distance(cell_at(gx, gy), p));
  const auto square_distance = [&](const Vec2& o) {
    const double dx = std::max(std::abs(p.x() - o.x()) - half, 0.0);
    const double dy = std::max(std::abs(p.y() - o.y()) - half, 0.0);
    return dx * dx + dy * dy;
  };
  double best = outside_start(p, gx, gy);
  const Vec2 g(gx, gy);
  walk_outside(p, p, g, g, [&](const Vec2& o) { best = std::min(best, square_distance(o)); }, best);
  return std::sqrt(best);
}

}  // namespace fgdwa
