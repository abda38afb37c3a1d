#pragma once
// Minimum-cost assignment of rows (tracks) to columns (clusters) where a row
// may also stay unassigned at a price and some pairs are forbidden.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <vector>

namespace fgdwa::detail {

// For each row of `cost` (non-negative; +inf forbids the pair), its column or
// -1, minimising the total cost of the pairs plus unassigned[row] for each row
// left out; columns left out cost nothing. The Hungarian method on the square
// problem padded with one "leave out" column per row and one per column.
inline std::vector<int> assign(const Eigen::MatrixXd& cost, const std::vector<double>& unassigned) {
  const int rows = static_cast<int>(cost.rows()), cols = static_cast<int>(cost.cols());
  const int n = rows + cols;
  std::vector<int> result(static_cast<std::size_t>(rows), -1);
  if (rows == 0 || cols == 0) return result;
  // Larger than any sum of allowed costs: never chosen while a way round exists,
  // and one always does (everything left out).
  double big = 1.0;
  for (int r = 0; r < rows; ++r) {
    big += unassigned[static_cast<std::size_t>(r)];
    for (int c = 0; c < cols; ++c)
      if (std::isfinite(cost(r, c))) big += cost(r, c);
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Constant(n, n, big);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c)
      if (std::isfinite(cost(r, c))) a(r, c) = cost(r, c);
    a(r, cols + r) = unassigned[static_cast<std::size_t>(r)];
  }
  for (int c = 0; c < cols; ++c) a(rows + c, c) = 0.0;
  a.bottomRightCorner(cols, rows).setZero();

  // Shortest augmenting paths with potentials, 1-based with a sentinel column 0.
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<double> u(n + 1, 0.0), v(n + 1, 0.0);
  std::vector<int> owner(n + 1, 0), way(n + 1, 0);
  for (int i = 1; i <= n; ++i) {
    owner[0] = i;
    int j0 = 0;
    std::vector<double> min_v(n + 1, kInf);
    std::vector<bool> used(n + 1, false);
    do {
      used[j0] = true;
      const int i0 = owner[j0];
      double delta = kInf;
      int j1 = 0;
      for (int j = 1; j <= n; ++j) {
        if (used[j]) continue;
        const double reduced = a(i0 - 1, j - 1) - u[i0] - v[j];
        if (reduced < min_v[j]) min_v[j] = reduced, way[j] = j0;
        if (min_v[j] < delta) delta = min_v[j], j1 = j;
      }
      for (int j = 0; j <= n; ++j) {
        if (used[j]) {
          u[owner[j]] += delta;
          v[j] -= delta;
        } else {
          min_v[j] -= delta;
        }
      }
      j0 = j1;
    } while (owner[j0] != 0);
    do {
      const int j1 = way[j0];
      owner[j0] = owner[j1];
      j0 = j1;
    } while (j0 != 0);
  }
  for (int j = 1; j <= cols; ++j) {
    const int r = owner[j] - 1;
    if (r < rows && std::isfinite(cost(r, j - 1))) result[static_cast<std::size_t>(r)] = j - 1;
  }
  return result;
}

}  // namespace fgdwa::detail
