// The single-precision batch DTW, compiled once per instruction set (SSE2 up
// to AVX-512 on x86-64, NEON and SVE on ARM) by Highway and dispatched at run
// time to the widest the processor has. Lanes carry rollouts: the reference is
// shared, so every lane takes the same steps through the dynamic programme.
//
// Only correctly rounded operations are used (add, subtract, multiply, square
// root, min) and the file is compiled without floating-point contraction, so
// every instruction set, and the scalar tail, gives the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "dtw_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace fgdwa {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// previous and current hold m * K floats (rows i - 1 and i, column after
// column, K lanes each); the result of sequence k goes to out[k]. The cell to
// the left is the one just written in current.
void DtwBatchF32(const float* HWY_RESTRICT ax, const float* HWY_RESTRICT ay, std::size_t n, std::size_t K,
                 const float* HWY_RESTRICT bx, const float* HWY_RESTRICT by, std::size_t m, float* previous,
                 float* current, float* HWY_RESTRICT out) {
  const hn::ScalableTag<float> d;
  const std::size_t lanes = hn::Lanes(d);
  const std::size_t vector_end = K - K % lanes;
  const float inf = std::numeric_limits<float>::infinity();
  std::fill(previous, previous + m * K, inf);
  for (std::size_t i = 0; i < n; ++i) {
    const float* xi = ax + i * K;
    const float* yi = ay + i * K;
    for (std::size_t j = 0; j < m; ++j) {
      const auto bxj = hn::Set(d, bx[j]), byj = hn::Set(d, by[j]);
      float* cur = current + j * K;
      const float* up = previous + j * K;
      // The first cell has no predecessor; the first column only the one above.
      const float* diag = j > 0 ? previous + (j - 1) * K : nullptr;
      const float* left = j > 0 ? current + (j - 1) * K : nullptr;
      const bool origin = i == 0 && j == 0;
      std::size_t k = 0;
      for (; k < vector_end; k += lanes) {
        const auto dx = hn::Sub(hn::LoadU(d, xi + k), bxj);
        const auto dy = hn::Sub(hn::LoadU(d, yi + k), byj);
        const auto dist = hn::Sqrt(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)));
        auto best = origin ? hn::Zero(d) : hn::LoadU(d, up + k);
        if (left) best = hn::Min(hn::Min(hn::LoadU(d, left + k), best), hn::LoadU(d, diag + k));
        hn::StoreU(hn::Add(dist, best), d, cur + k);
      }
      for (; k < K; ++k) {
        const float dx = xi[k] - bx[j], dy = yi[k] - by[j];
        const float dist = std::sqrt(dx * dx + dy * dy);
        float best = origin ? 0.0f : up[k];
        if (left) best = std::min(std::min(left[k], best), diag[k]);
        cur[k] = dist + best;
      }
    }
    std::swap(previous, current);
  }
  std::copy(previous + (m - 1) * K, previous + m * K, out);
}

std::size_t VectorBytes() { return hn::Lanes(hn::ScalableTag<std::uint8_t>()); }

}  // namespace HWY_NAMESPACE
}  // namespace fgdwa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include <vector>

#include "fgdwa/dtw.hpp"
#include "fgdwa/error.hpp"
#include "dtw_checks.hpp"

namespace fgdwa {

HWY_EXPORT(DtwBatchF32);
HWY_EXPORT(VectorBytes);

void DtwWorkspace::distance_batch_f32(const float* ax, const float* ay, std::size_t n, std::size_t count,
                                      const float* bx, const float* by, std::size_t m, float* out) {
  detail::check_dtw_sizes(n, m, count, kNoBand);
  detail::check_dtw_coordinates("ax", ax, n * count);
  detail::check_dtw_coordinates("ay", ay, n * count);
  detail::check_dtw_coordinates("bx", bx, m);
  detail::check_dtw_coordinates("by", by, m);
  distance_batch_f32_unchecked(ax, ay, n, count, bx, by, m, out);
}

void DtwWorkspace::distance_batch_f32_unchecked(const float* ax, const float* ay, std::size_t n, std::size_t count,
                                                const float* bx, const float* by, std::size_t m, float* out) {
  detail::check_dtw_sizes(n, m, count, kNoBand);  // O(1): kept, an empty batch would read past the buffers
  rows_f32_.resize(2 * m * count);
  float* previous = rows_f32_.data();
  HWY_DYNAMIC_DISPATCH(DtwBatchF32)(ax, ay, n, count, bx, by, m, previous, previous + m * count, out);
}

std::size_t dtw_vector_bytes() { return HWY_DYNAMIC_DISPATCH(VectorBytes)(); }

const char* dtw_instruction_set() {
  // Highway orders its targets best first.
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  return targets.empty() ? "none" : hwy::TargetName(targets.front());
}

}  // namespace fgdwa
#endif
