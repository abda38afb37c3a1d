#pragma once
// Minimum-cost assignment of rows (tracks) to columns (clusters) where a row
// may also stay unassigned at a price and some pairs are forbidden.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace fgdwa::detail {

// assign() for one connected problem: the Hungarian method on the square
// problem padded with one "leave out" column per row and one per column.
inline std::vector<int> assign_connected(const Eigen::MatrixXd& cost, const std::vector<double>& unassigned) {
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

// For each row of `cost` (non-negative; +inf forbids the pair), its column or
// -1, minimising the total cost of the pairs plus unassigned[row] for each row
// left out; columns left out cost nothing. Rows and columns linked by allowed
// pairs form independent problems, each solved on its own: the Hungarian
// method costs the cube of its size, and gating leaves most pairs forbidden.
inline std::vector<int> assign(const Eigen::MatrixXd& cost, const std::vector<double>& unassigned) {
  const int rows = static_cast<int>(cost.rows()), cols = static_cast<int>(cost.cols());
  std::vector<int> result(static_cast<std::size_t>(rows), -1);
  // Union-find over rows 0..rows-1 and columns rows..rows+cols-1.
  std::vector<int> parent(static_cast<std::size_t>(rows + cols));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];  // halving the path on the way
    return x;
  };
  std::vector<bool> linked(static_cast<std::size_t>(rows), false);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      if (std::isfinite(cost(r, c))) {
        linked[static_cast<std::size_t>(r)] = true;
        const int a = root(r), b = root(rows + c);
        if (a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
      }
  // A row with no allowed pair stays out; each other row's problem is solved
  // once, from its first row.
  std::vector<bool> done(static_cast<std::size_t>(rows), false);
  std::vector<int> part_rows, part_cols;
  for (int r = 0; r < rows; ++r) {
    if (!linked[static_cast<std::size_t>(r)] || done[static_cast<std::size_t>(r)]) continue;
    const int id = root(r);
    part_rows.clear();
    part_cols.clear();
    for (int q = r; q < rows; ++q)
      if (linked[static_cast<std::size_t>(q)] && root(q) == id) {
        part_rows.push_back(q);
        done[static_cast<std::size_t>(q)] = true;
      }
    for (int c = 0; c < cols; ++c)
      if (root(rows + c) == id) part_cols.push_back(c);
    Eigen::MatrixXd part(static_cast<Eigen::Index>(part_rows.size()), static_cast<Eigen::Index>(part_cols.size()));
    std::vector<double> part_unassigned(part_rows.size());
    for (std::size_t i = 0; i < part_rows.size(); ++i) {
      part_unassigned[i] = unassigned[static_cast<std::size_t>(part_rows[i])];
      for (std::size_t j = 0; j < part_cols.size(); ++j)
        part(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = cost(part_rows[i], part_cols[j]);
    }
    const std::vector<int> chosen = assign_connected(part, part_unassigned);
    for (std::size_t i = 0; i < part_rows.size(); ++i)
      if (chosen[i] >= 0)
        result[static_cast<std::size_t>(part_rows[i])] = part_cols[static_cast<std::size_t>(chosen[i])];
  }
  return result;
}

}  // namespace fgdwa::detail
