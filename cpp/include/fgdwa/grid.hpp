#pragma once
// Occupancy grids and the Euclidean distance field built from them.
//
// Cell (row, col) covers x in [origin.x + col res, origin.x + (col + 1) res) and
// y in [origin.y + row res, origin.y + (row + 1) res): row 0 is the bottom row.
// Space outside the grid is free.
#include <cstdint>
#include <limits>
#include <vector>

#include "fgdwa/geometry.hpp"

namespace fgdwa {

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

 private:
  int rows_;
  int cols_;
  double resolution_;
  Vec2 origin_;
  std::vector<std::uint8_t> cells_;
};

// Slope grades 0-4 on the same cell layout as an OccupancyGrid (Section 3.3.3):
// 0 is flat, 4 cannot be entered.
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

// Exact Euclidean distance transform of a grid (Felzenszwalb and Huttenlocher).
//
// `cell_distance(row, col)` is measured between cell centres: from this cell's
// centre to the nearest occupied cell's centre, in metres (0 on occupied cells,
// +inf when the grid has no obstacle); it equals scipy's
// distance_transform_edt(grid == 0) * resolution.
// `distance(p)` is the distance from a point to the nearest occupied cell's
// square (0 inside one), measured exactly to the nearest obstacles of the cells
// around `p`; outside the grid, exactly to the outermost obstacle of each row or
// column facing `p`.
class DistanceField {
 public:
  explicit DistanceField(const OccupancyGrid& grid);
  // The same field as DistanceField(grid), built faster from the field of an
  // earlier grid with the same layout (a map that gained or lost a few
  // obstacles): where the nearest obstacles around a cell did not change, its
  // look-up data is copied. Throws fgdwa::Error if the layouts differ.
  DistanceField(const OccupancyGrid& grid, const DistanceField& previous);

  const OccupancyGrid& grid() const { return grid_; }
  double cell_distance(int row, int col) const { return distances_[grid_.index(row, col)]; }
  const std::vector<double>& cell_distances() const { return distances_; }
  bool has_obstacles() const { return has_obstacles_; }
  double distance(const Vec2& p) const;
  // The distance from the segment ab to the nearest obstacle square, exactly,
  // from the candidates of the cells its bounding box covers (meant for
  // segments of about a cell); NaN when that box leaves the grid.
  double segment_distance(const Vec2& a, const Vec2& b) const;
  // A value never above distance(p), from one table look-up: the distance
  // between the piece of p's cell that holds p and the nearest obstacle square
  // (0 outside the grid). Cells are cut into bound_subdivisions() x
  // bound_subdivisions() pieces of about 2.5 cm, at least 2 x 2.
  double lower_bound(const Vec2& p) const { return lower_bounds()(p.x(), p.y()); }

  // The table behind lower_bound(), copied out so that a loop over many points
  // keeps it in registers. Valid while the field lives.
  struct LowerBounds {
    const float* pieces;  // null: no obstacles
    double origin_x, origin_y, inverse_piece;
    double cols, rows;  // pieces across and down the grid
    std::ptrdiff_t stride;
    double operator()(double x, double y) const {
      if (!pieces) return std::numeric_limits<double>::infinity();
      const double gx = (x - origin_x) * inverse_piece, gy = (y - origin_y) * inverse_piece;
      if (!(gx >= 0.0 && gy >= 0.0 && gx < cols && gy < rows)) return 0.0;
      return pieces[static_cast<std::ptrdiff_t>(gy) * stride + static_cast<std::ptrdiff_t>(gx)];
    }
  };
  LowerBounds lower_bounds() const {
    return LowerBounds{has_obstacles_ ? piece_lower_bound_.data() : nullptr,
                       grid_.origin().x(),
                       grid_.origin().y(),
                       inverse_piece_,
                       bound_cols_,
                       bound_rows_,
                       static_cast<std::ptrdiff_t>(bound_stride_)};
  }
  int bound_subdivisions() const { return subdivisions_; }

 private:
  DistanceField(const OccupancyGrid& grid, const DistanceField* previous);

  OccupancyGrid grid_;
  std::vector<double> distances_;
  std::vector<long> nearest_;  // grid index of each cell's nearest obstacle cell, -1 for none
  // Per cell, the centres of the obstacles that can be nearest to a point in it
  // (compressed rows: cell i owns candidates_[candidate_start_[i] .. candidate_start_[i + 1])).
  std::vector<std::size_t> candidate_start_;
  std::vector<Vec2> candidates_;
  // The same, laid out for distance(): per cell its first two candidates (the
  // first twice if it has one) beside the range of any others, so most
  // look-ups read one record and run no loop.
  struct CellCandidates {
    double x0, y0, x1, y1;
    std::uint32_t more_begin, more_end;
  };
  std::vector<CellCandidates> cell_candidates_;
  // Outermost occupied column of each row and row of each column, -1 for none.
  std::vector<int> row_first_, row_last_, col_first_, col_last_;
  // Per piece of a cell (subdivisions_ x subdivisions_ per cell): its distance
  // to the nearest obstacle square, rounded down to a float, row-major.
  std::vector<float> piece_lower_bound_;
  int subdivisions_ = 2;
  double inverse_resolution_ = 1.0;      // cells per metre
  double inverse_piece_ = 1.0;           // pieces per metre
  double bound_cols_ = 0.0, bound_rows_ = 0.0;  // pieces across and down the grid
  std::size_t bound_stride_ = 0;
  bool has_obstacles_ = false;
};

}  // namespace fgdwa
