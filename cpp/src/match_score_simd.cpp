// A scan matcher candidate's score: lanes carry hits, whose table entries are
// gathered as 32-bit words at byte offsets (the table keeps one entry past
// its last) and cut to their 16 bits, then their weights gathered. Compiled by
// Highway for every instruction set and dispatched at run time like the batch
// DTW (dtw_simd.cpp); the placing is correctly rounded without contraction,
// the same bits as the scalar placing.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "match_score_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "match_score.hpp"

HWY_BEFORE_NAMESPACE();
namespace fgdwa {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

double MatchScoreSum(const double* HWY_RESTRICT x, const double* HWY_RESTRICT y, std::size_t m, double ox, double oy,
                     const DistanceField::LowerBounds& table, const float* HWY_RESTRICT weights, std::size_t n,
                     bool in_lanes) {
  if (!table.pieces) return 0.0;
  const double inv = table.inverse_piece;
  const auto scalar = [&](std::size_t k) {
    const std::uint16_t* at = table.piece_at(ox + x[k] * inv, oy + y[k] * inv);
    return at && *at < n ? static_cast<double>(weights[*at]) : 0.0;
  };
  const hn::ScalableTag<double> d;
  const hn::Rebind<std::int32_t, decltype(d)> d32;
  const hn::Rebind<float, decltype(d)> df;
  const std::size_t lanes = hn::Lanes(d);
  // Byte offsets fit in 32 bits below a thousand million pieces; past that,
  // or where lanes may not sum apart, the scalar look-up reads them in order.
  const bool vectors = in_lanes && table.rows * static_cast<double>(table.stride) < 1e9;
  const std::size_t vector_end = vectors ? m - m % lanes : 0;
  const auto Ox = hn::Set(d, ox), Oy = hn::Set(d, oy), Inv = hn::Set(d, inv), zero = hn::Zero(d);
  const auto cols = hn::Set(d, table.cols), rows = hn::Set(d, table.rows), stride = hn::Set(d, static_cast<double>(table.stride));
  const auto entries = hn::Set(d, static_cast<double>(n));
  constexpr bool kLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
  const auto low16 = hn::Set(d32, 0xFFFF);
  auto sum = zero;
  for (std::size_t k = 0; k < vector_end; k += lanes) {
    const auto gx = hn::Add(Ox, hn::Mul(hn::LoadU(d, x + k), Inv));
    const auto gy = hn::Add(Oy, hn::Mul(hn::LoadU(d, y + k), Inv));
    const auto on_table = hn::And(hn::And(hn::Ge(gx, zero), hn::Ge(gy, zero)), hn::And(hn::Lt(gx, cols), hn::Lt(gy, rows)));
    // Lanes off the table read the first entry and add nothing.
    const auto at = hn::IfThenElseZero(on_table, hn::Add(hn::Mul(hn::Trunc(gy), stride), hn::Trunc(gx)));
    const auto word = hn::GatherOffset(d32, reinterpret_cast<const std::int32_t*>(table.pieces), hn::DemoteTo(d32, hn::Add(at, at)));
    const auto entry = hn::PromoteTo(d, kLittleEndian ? hn::And(word, low16) : hn::And(hn::ShiftRight<16>(word), low16));
    const auto scored = hn::And(on_table, hn::Lt(entry, entries));
    const auto weight = hn::GatherIndex(df, weights, hn::DemoteTo(d32, hn::IfThenElseZero(scored, entry)));
    sum = hn::Add(sum, hn::IfThenElseZero(scored, hn::PromoteTo(d, weight)));
  }
  double total = hn::GetLane(hn::SumOfLanes(d, sum));
  for (std::size_t k = vector_end; k < m; ++k) total += scalar(k);
  return total;
}

}  // namespace HWY_NAMESPACE
}  // namespace fgdwa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fgdwa {
namespace detail {

HWY_EXPORT(MatchScoreSum);

double match_score_sum(const double* x, const double* y, std::size_t m, double ox, double oy,
                       const DistanceField::LowerBounds& table, const float* weights, std::size_t n, bool in_lanes) {
  return HWY_DYNAMIC_DISPATCH(MatchScoreSum)(x, y, m, ox, oy, table, weights, n, in_lanes);
}

bool exact_match_sums(const float* weights, std::size_t n, std::size_t points) {
  constexpr float kLeast = 1.0f / 128.0f;  // 2^-7: a float this large is a multiple of 2^-30
  constexpr std::size_t kMostPoints = std::size_t{1} << 22;  // the sums stay below 2^22, within 52 bits of 2^-30
  return points < kMostPoints && std::all_of(weights, weights + n, [](float w) { return w >= kLeast && w <= 1.0f; });
}

}  // namespace detail
}  // namespace fgdwa
#endif
