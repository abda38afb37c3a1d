#include "fgdwa/dtw.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dtw_checks.hpp"
#include "validation.hpp"

namespace fgdwa {

double DtwWorkspace::distance(const Vec2* a, std::size_t n, const Vec2* b, std::size_t m, int band) {
  detail::check_dtw_sizes(n, m, 1, band);
  detail::require_points("a", a, n, limits::kMaxQueryCoordinate);
  detail::require_points("b", b, m, limits::kMaxQueryCoordinate);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  bx_.resize(m);
  by_.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    bx_[j] = b[j].x();
    by_[j] = b[j].y();
  }
  previous_.assign(m, kInf);
  current_.resize(m);
  row_.resize(m);

  // Rows advance the diagonal by `slope` columns; the band must cover that step
  // for the allowed cells of consecutive rows to touch.
  const double slope = n > 1 ? double(m - 1) / double(n - 1) : 0.0;
  long width = band < 0 ? static_cast<long>(m) : band;
  width = std::max<long>(width, static_cast<long>(std::ceil(slope)));

  for (std::size_t i = 0; i < n; ++i) {
    const double centre = n > 1 ? slope * double(i) : 0.0;
    std::size_t lo = 0, hi = m - 1;
    if (band >= 0) {
      lo = static_cast<std::size_t>(std::max<long>(0, static_cast<long>(std::floor(centre)) - width));
      hi = static_cast<std::size_t>(std::min<long>(static_cast<long>(m) - 1, static_cast<long>(std::ceil(centre)) + width));
    }
    if (i == n - 1) hi = m - 1;
    if (i == 0) lo = 0;
    // Point distances of this row first: a loop the compiler vectorises.
    const double ax = a[i].x(), ay = a[i].y();
    for (std::size_t j = lo; j <= hi; ++j) {
      const double dx = ax - bx_[j], dy = ay - by_[j];
      row_[j] = std::sqrt(dx * dx + dy * dy);
    }
    std::fill(current_.begin(), current_.begin() + static_cast<std::ptrdiff_t>(lo), kInf);
    double left = kInf;
    for (std::size_t j = lo; j <= hi; ++j) {
      double best;
      if (i == 0 && j == 0) {
        best = 0.0;
      } else {
        best = std::min(left, previous_[j]);
        if (j > 0) best = std::min(best, previous_[j - 1]);
      }
      left = row_[j] + best;
      current_[j] = left;
    }
    std::fill(current_.begin() + static_cast<std::ptrdiff_t>(hi) + 1, current_.end(), kInf);
    std::swap(previous_, current_);
  }
  return previous_[m - 1];
}

void DtwWorkspace::distance_batch(const double* ax, const double* ay, std::size_t n, std::size_t count,
                                  const Vec2* b, std::size_t m, double* out) {
  detail::check_dtw_sizes(n, m, count, kNoBand);
  detail::check_dtw_coordinates("ax", ax, n * count);
  detail::check_dtw_coordinates("ay", ay, n * count);
  detail::require_points("b", b, m, limits::kMaxQueryCoordinate);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::size_t K = count;
  bx_.resize(m);
  by_.resize(m);
  for (std::size_t j = 0; j < m; ++j) {
    bx_[j] = b[j].x();
    by_[j] = b[j].y();
  }
  previous_.assign(m * K, kInf);
  current_.resize(m * K);
  left_.resize(K);
  for (std::size_t i = 0; i < n; ++i) {
    const double* xi = ax + i * K;
    const double* yi = ay + i * K;
    std::fill(left_.begin(), left_.end(), kInf);
    for (std::size_t j = 0; j < m; ++j) {
      const double bxj = bx_[j], byj = by_[j];
      double* cur = &current_[j * K];
      const double* up = &previous_[j * K];
      double* left = left_.data();
      // Three branch-free loops over the batch, so each one vectorises.
      if (i == 0 && j == 0) {
        for (std::size_t k = 0; k < K; ++k) {
          const double dx = xi[k] - bxj, dy = yi[k] - byj;
          left[k] = std::sqrt(dx * dx + dy * dy) + 0.0;
          cur[k] = left[k];
        }
      } else if (j == 0) {
        for (std::size_t k = 0; k < K; ++k) {
          const double dx = xi[k] - bxj, dy = yi[k] - byj;
          left[k] = std::sqrt(dx * dx + dy * dy) + std::min(left[k], up[k]);
          cur[k] = left[k];
        }
      } else {
        const double* diag = &previous_[(j - 1) * K];
        for (std::size_t k = 0; k < K; ++k) {
          const double dx = xi[k] - bxj, dy = yi[k] - byj;
          left[k] = std::sqrt(dx * dx + dy * dy) + std::min(std::min(left[k], up[k]), diag[k]);
          cur[k] = left[k];
        }
      }
    }
    std::swap(previous_, current_);
  }
  for (std::size_t k = 0; k < K; ++k) out[k] = previous_[(m - 1) * K + k];
}

double dtw(const std::vector<Vec2>& a, const std::vector<Vec2>& b, int band) {
  DtwWorkspace workspace;
  return workspace.distance(a, b, band);
}

}  // namespace fgdwa
