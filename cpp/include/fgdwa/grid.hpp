#pragma once
// Occupancy grids and the Euclidean distance field built from them.
//
// Cell (row, col) covers x in [origin.x + col res, origin.x + (col + 1) res) and
// y in [origin.y + row res, origin.y + (row + 1) res): row 0 is the bottom row.
// Space outside the grid is free.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "fgdwa/geometry.hpp"

namespace fgdwa {

// Threads: const methods may run concurrently; set() may not run while
// anything else uses the grid.
class OccupancyGrid {
 public:
  // `cells` is row-major, rows x cols, 0 = free and any other value = obstacle.
  OccupancyGrid(int rows, int cols, double resolution, Vec2 origin, std::vector<std::uint8_t> cells);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  double resolution() const { return resolution_; }  // m per cell
  const Vec2& origin() const { return origin_; }     // m, lower-left corner of cell (0, 0)
  const std::vector<std::uint8_t>& cells() const { return cells_; }

  bool in_bounds(int row, int col) const { return row >= 0 && row < rows_ && col >= 0 && col < cols_; }
  bool occupied(int row, int col) const { return cells_[index(row, col)] != 0; }
  // Cell holding `p`; false when `p` lies outside the grid.
  bool cell_of(const Vec2& p, int& row, int& col) const;
  Vec2 cell_center(int row, int col) const;
  // Whether `p` lies in an occupied cell (outside the grid is free).
  bool occupied_at(const Vec2& p) const;
  std::size_t index(int row, int col) const { return static_cast<std::size_t>(row) * cols_ + col; }
  std::size_t occupied_count() const;
  // Marks cell `index` (a grid index) occupied or free.
  void set(std::size_t index, bool occupied) { cells_.at(index) = occupied ? 1 : 0; }

 private:
  int rows_;
  int cols_;
  double resolution_;
  Vec2 origin_;
  std::vector<std::uint8_t> cells_;
};

// Slope grades 0-4 on the same cell layout as an OccupancyGrid (Section 3.3.3):
// 0 is flat, 4 cannot be entered.
// Threads: immutable once built; share it freely.
class TerrainGrid {
 public:
  static constexpr int kMaxGrade = 4;
  TerrainGrid(int rows, int cols, double resolution, Vec2 origin, std::vector<std::uint8_t> grades);

  int rows() const { return rows_; }
  int cols() const { return cols_; }
  double resolution() const { return resolution_; }
  const Vec2& origin() const { return origin_; }
  const std::vector<std::uint8_t>& grades() const { return grades_; }
  int grade(int row, int col) const { return grades_[static_cast<std::size_t>(row) * cols_ + col]; }
  // Grade under `p`; 0 outside the grid.
  int grade_at(const Vec2& p) const;
  // Whether this terrain lies exactly on the cells of `grid`.
  bool matches(const OccupancyGrid& grid) const;

 private:
  int rows_;
  int cols_;
  double resolution_;
  Vec2 origin_;
  std::vector<std::uint8_t> grades_;
};

// Exact Euclidean distance transform of a grid (Felzenszwalb and Huttenlocher),
// kept up to date as cells change.
//
// `cell_distance(row, col)` is measured between cell centres: from this cell's
// centre to the nearest occupied cell's centre, in metres (0 on occupied cells,
// +inf when the grid has no obstacle); it equals scipy's
// distance_transform_edt(grid == 0) * resolution.
// `distance(p)` is the distance from a point to the nearest occupied cell's
// square (0 inside one), measured exactly to the nearest obstacles of the cells
// around `p`. Past the grid's edge the field keeps a margin of free cells of
// its own (edge_margin, 3 m by default), answered the same way; beyond it,
// exactly to the outermost obstacle of each row or column facing `p`.
//
// A build is linear in the cells. update() recomputes the column runs around
// each changed cell, the rows those runs cross, and the look-up data of the
// cells whose nearest obstacle changed and of their neighbours: its cost
// follows the change, and it gives the same field as a fresh build.
//
// bytes_per_cell() says what a field holds: about 27 bytes per cell at 5 cm
// (the grid's copy 1, each cell's nearest occupied row in its column 4, its
// candidates 12 and the others of cells with more than two about 2, the bound
// table 2 per piece, 8 at 2 x 2 pieces a cell), more at coarser cells, whose
// table is cut finer (16 pieces a cell at 10 cm), up to 4 million pieces in
// all. update() appends the candidates it redoes and compacts them once half
// are stale: a field that keeps being updated holds a little more. The edge
// margin's cells are counted too: on a large grid at most a sixteenth more, on a
// small one (10 m x 10 m at 0.1 m) 2.6 times the grid's cells.
//
// Threads: const methods may run concurrently on one field; update() may not
// run while anything else uses the field.
class DistanceField {
 public:
  // How far past the grid's edge, in metres, the field keeps free cells of its
  // own by default: a rollout of 3 s at 1 m/s leaving a local map.
  static constexpr double kDefaultEdgeMargin = 3.0;

  // edge_margin: free space the field adds around the grid (metres, >= 0).
  // Where it reaches, a point off the grid is measured from look-up data as
  // inside: distance() and lower_bound() cost the same on both sides of the
  // edge. It is held to 64 cells and, on grids over 262 144 cells, to a
  // sixteenth more cells in all; 0 for a field built anew every cycle.
  explicit DistanceField(const OccupancyGrid& grid, double edge_margin = kDefaultEdgeMargin);
  // The field of `grid`, from the field of an earlier grid with the same
  // layout: a copy of `previous` brought to `grid` by update(). Throws
  // fgdwa::Error if the layouts differ.
  DistanceField(const OccupancyGrid& grid, const DistanceField& previous);

  // Brings the field to `grid` (the same layout, else fgdwa::Error); the
  // result equals DistanceField(grid). Returns how many cells changed
  // occupancy. The first form compares every cell; the second only `cells`
  // (grid indices; every other cell must be unchanged), so its cost follows
  // the change alone.
  std::size_t update(const OccupancyGrid& grid);
  std::size_t update(const OccupancyGrid& grid, const std::vector<std::size_t>& cells);

  const OccupancyGrid& grid() const { return shown_; }
  // The free margin kept around the grid, in metres: edge_margin rounded up
  // to whole cells, less where the budget holds it.
  double edge_margin() const { return pad_ * shown_.resolution(); }
  double cell_distance(int row, int col) const;
  std::vector<double> cell_distances() const;
  bool has_obstacles() const { return occupied_ > 0; }
  double distance(const Vec2& p) const;
  // The distance from the segment ab to the nearest obstacle square, exactly
  // (meant for segments of about a cell): inside the grid from the candidates
  // of the cells its bounding box covers; outside, from the outermost obstacle
  // of each row (column) facing it, as distance() measures a point there.
  double segment_distance(const Vec2& a, const Vec2& b) const;
  // A value never above distance(p), from one table look-up: the distance
  // between the piece of p's cell that holds p and the nearest obstacle square,
  // rounded down to a 64th of a piece and held at 1024 pieces (25.6 m at
  // 2.5 cm) beyond: still a bound there, if a loose one. Cells are cut into
  // bound_subdivisions() x bound_subdivisions() pieces of about 2.5 cm, at
  // least 2 x 2. Outside the grid, from the point q of the
  // grid's edge nearest p: every obstacle lies in the grid, beyond q as seen
  // from p, so hypot(|p - q|, the bound at q) holds.
  double lower_bound(const Vec2& p) const { return lower_bounds()(p.x(), p.y()); }
  // A value never below distance(p), from the same look-up: the bound of p's
  // piece, one step up, plus the piece's diagonal (no point of the piece lies
  // farther from the piece's nearest point to an obstacle). +inf where the
  // table does not reach, at its largest value, or with no obstacles: a
  // caller asks distance() there.
  double upper_bound(const Vec2& p) const;

  // The table behind lower_bound(), copied out so that a loop over many points
  // keeps it in registers. Valid while the field lives and is not updated.
  struct LowerBounds {
    const std::uint16_t* pieces;  // in steps, rounded down; null: no obstacles. One more follows the last.
    double step;                  // m per step
    double origin_x, origin_y, inverse_piece;
    double cols, rows;  // pieces across and down the grid
    std::ptrdiff_t stride;
    double operator()(double x, double y) const {
      if (!pieces) return std::numeric_limits<double>::infinity();
      const double gx = (x - origin_x) * inverse_piece, gy = (y - origin_y) * inverse_piece;
      if (const std::uint16_t* at = piece_at(gx, gy)) return step * *at;
      return outside(gx, gy);
    }
    // The piece at (gx, gy), in pieces from the origin; null off the table
    // (or not a number).
    const std::uint16_t* piece_at(double gx, double gy) const {
      if (!(gx >= 0.0 && gy >= 0.0 && gx < cols && gy < rows)) return nullptr;
      return &pieces[static_cast<std::ptrdiff_t>(gy) * stride + static_cast<std::ptrdiff_t>(gx)];
    }
    // Not a number in, 0 out: never above the distance.
    double outside(double gx, double gy) const {
      if (std::isnan(gx) || std::isnan(gy)) return 0.0;
      const double qx = std::clamp(gx, 0.0, cols), qy = std::clamp(gy, 0.0, rows);
      const double at_q = step * pieces[static_cast<std::ptrdiff_t>(std::min(qy, rows - 1.0)) * stride +
                                        static_cast<std::ptrdiff_t>(std::min(qx, cols - 1.0))];
      const double dx = (gx - qx) / inverse_piece, dy = (gy - qy) / inverse_piece;
      // Lowered a little below the rounding of the sum.
      return std::sqrt(dx * dx + dy * dy + at_q * at_q) * (1.0 - 1e-12);
    }
  };
  LowerBounds lower_bounds() const {
    return LowerBounds{has_obstacles() ? piece_lower_bound_.data() : nullptr,
                       bound_step_,
                       grid_.origin().x(),
                       grid_.origin().y(),
                       inverse_piece_,
                       bound_cols_,
                       bound_rows_,
                       static_cast<std::ptrdiff_t>(bound_stride_)};
  }
  int bound_subdivisions() const { return subdivisions_; }
  // Bytes held per cell, everything counted (the field's copy of the grid too).
  double bytes_per_cell() const;

 private:
  // A cell in one word, its row above its column's bits (rows x 2^col_bits_
  // stays below 2 x kMaxGridCells): a candidate takes 4 bytes, and reads back
  // with a shift and a mask. kNoCell: none.
  static constexpr std::uint32_t kNoCell = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t pack(int row, int col) const {
    return static_cast<std::uint32_t>(row) << col_bits_ | static_cast<std::uint32_t>(col);
  }
  int row_of(std::uint32_t cell) const { return static_cast<int>(cell >> col_bits_); }
  int col_of(std::uint32_t cell) const { return static_cast<int>(cell & col_mask_); }
  // The same double as grid_.cell_center(), from two small tables (indexed
  // unsigned: no sign extension in distance()'s inner loop).
  Vec2 centre_of(std::uint32_t cell) const { return Vec2(centre_x_[cell & col_mask_], centre_y_[cell >> col_bits_]); }

  // The squared distance from a, in or on the edge of cell `cell`, to the
  // nearest obstacle square: from the cell's candidates.
  double cell_square_distance(std::size_t cell, const Vec2& a) const;
  // The cell holding the point at (gx, gy) in cells from the origin, clamped to the grid.
  std::size_t cell_at(double gx, double gy) const;
  // For p outside the grid (at gx, gy in cells): a squared distance a little
  // above p's, from the grid's point nearest p; where the walks outward start.
  double outside_start(const Vec2& p, double gx, double gy) const;
  template <class Along, class Candidate>
  void walk_outward(int lines, double lo, double hi, const std::vector<int>& outermost,
                    const std::vector<int>& block_extreme, const Along& along, const Candidate& candidate,
                    const double& best) const;
  // segment_distance()'s part inside the grid (ga, gb: the ends in cells from
  // the origin), lowering the squared `best`.
  void segment_inside(const Vec2& a, const Vec2& b, const Vec2& ga, const Vec2& gb, double& best) const;
  // The obstacles that can be nearest to a point or segment outside the grid, walked outward.
  template <class Measure>
  void walk_outside(const Vec2& a, const Vec2& b, const Vec2& ga, const Vec2& gb, const Measure& measure,
                    const double& best) const;
  // A cell whose nearest occupied row in its column changed, and what it was.
  struct ColumnChange {
    int row, col;
    std::int32_t before;
  };
  // Nearest occupied rows of column `col` over rows from..to; the cells whose
  // value changed are appended to `changes` when given.
  void column_pass(int col, int from, int to, std::vector<ColumnChange>* changes);
  // The nearest obstacles of row `row` from the column runs; appends the cells whose nearest changed.
  void row_pass(int row, std::vector<std::size_t>* changed);
  // A column of row `row` whose nearest obstacle came nearer: now `nearest`
  // (its row), at squared distance `height` in cells.
  struct Lowered {
    int col;
    std::int32_t nearest;
    std::int64_t height;
  };
  // row_pass() where every change of the row's column runs brought an
  // obstacle nearer or took away one that was no cell's nearest: each cell
  // keeps its nearest unless a lowered column's beats it (the leftmost of
  // equals, as the full pass picks), with no envelope.
  void row_lowered(int row, const std::vector<Lowered>& lowered, std::vector<std::size_t>& changed);
  // The row passes that `changes` (in any order, a cell more than once) call for.
  void rows_after(std::vector<ColumnChange>& changes, std::vector<std::size_t>& changed);
  // Candidates and piece bounds of one cell, from the nearest obstacles around
  // it; with first_unchanged (its own nearest is the one they were built
  // with), they are rebuilt only if the candidates differ.
  void look_up_data(int row, int col, bool first_unchanged);
  void row_outermost(int row);
  void col_outermost(int col);
  void compact_more();

  OccupancyGrid shown_;  // the grid as given, which grid() returns
  // The field works on shown_ with pad_ free cells added on every side
  // (edge_pad in grid.cpp): a point there is inside grid_.
  int pad_ = 0;
  OccupancyGrid grid_;
  std::size_t occupied_ = 0;
  // Per cell: the row of the nearest occupied cell in its column (-1: none).
  std::vector<std::int32_t> column_nearest_;
  std::vector<std::int32_t> column_before_;  // column_pass's scratch
  // Per cell, the obstacles whose squares can be nearest to a point in it
  // (usually one to three), packed: `first` is the cell's own nearest
  // obstacle (kNoCell: the grid has none), which cell_distance() and the
  // neighbours' look-up data read; `second` another, or `first` again; when
  // there are more, more_[more] says how many follow it in more_ (more = 0:
  // none; more_[0] is unused).
  struct CellCandidates {
    std::uint32_t first, second, more;
  };
  std::vector<CellCandidates> candidates_;
  std::vector<std::uint32_t> more_;
  std::size_t more_garbage_ = 0;
  int col_bits_ = 0;
  std::uint32_t col_mask_ = 0;
  std::vector<double> centre_x_, centre_y_;  // per column and per row
  // Outermost occupied column of each row and row of each column, -1 for none;
  // per block of kOutermostBlock rows (columns), the outermost of its rows
  // (columns) on each side.
  static constexpr int kOutermostBlock = 16;
  std::vector<int> row_first_, row_last_, col_first_, col_last_;
  std::vector<int> row_block_first_, row_block_last_, col_block_first_, col_block_last_;
  // Per piece of a cell (subdivisions_ x subdivisions_ per cell): its distance
  // to the nearest obstacle square in whole steps of bound_step_ (a 64th of a
  // piece), rounded down and held at 65535 beyond, row-major: two bytes a
  // piece, and a step is far below the slack of the piece itself.
  std::vector<std::uint16_t> piece_lower_bound_;
  double bound_step_ = 1.0;  // m
  int subdivisions_ = 2;
  double inverse_resolution_ = 1.0;      // cells per metre
  double inverse_piece_ = 1.0;           // pieces per metre
  double bound_cols_ = 0.0, bound_rows_ = 0.0;  // pieces across and down the grid
  std::size_t bound_stride_ = 0;
  // Scratch of the passes.
  std::vector<std::int64_t> f_, num_, den_;
  std::vector<int> v_, arg_;
  std::vector<double> piece_scratch_, gap_x_, gap_y_;
  // Per cell, while update() runs (all 0 between calls): 1 when its look-up
  // data must be checked, 2 when its own nearest obstacle changed too.
  std::vector<std::uint8_t> stale_mark_;
};

}  // namespace fgdwa
