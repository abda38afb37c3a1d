// The lower bounds of a polygon's cover discs at many poses, compiled by
// Highway for every instruction set and dispatched at run time like the batch
// DTW (dtw_simd.cpp). Lanes carry poses; the discs are the outer loop. The
// placing and the table's arithmetic run in vectors, the table's 16-bit
// entries are gathered, and a vector with a lane off the table
// asks the scalar look-up (which walks off the grid) for every lane.
// Correctly rounded operations only, without contraction: the same bits as
// the scalar placing and look-up on every instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "cover_bounds_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "cover_bounds.hpp"

HWY_BEFORE_NAMESPACE();
namespace fgdwa {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void CoverLowerBounds(const double* HWY_RESTRICT x, const double* HWY_RESTRICT y, const double* HWY_RESTRICT c,
                      const double* HWY_RESTRICT s, std::size_t n, const Footprint::CoverDisc* HWY_RESTRICT cover,
                      std::size_t m, const DistanceField::LowerBounds& table, double* HWY_RESTRICT out) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const hn::ScalableTag<double> d;
  const hn::RebindToSigned<decltype(d)> di;
  const std::size_t lanes = hn::Lanes(d);
  const std::size_t vector_end = table.pieces ? n - n % lanes : 0;
  const auto origin_x = hn::Set(d, table.origin_x), origin_y = hn::Set(d, table.origin_y);
  const auto inverse = hn::Set(d, table.inverse_piece), step = hn::Set(d, table.step);
  const auto cols = hn::Set(d, table.cols), rows = hn::Set(d, table.rows);
  const auto stride = hn::Set(d, static_cast<double>(table.stride)), zero = hn::Zero(d);
  // The table's entries are gathered in 32-bit lanes at byte offsets, while
  // those fit in 32 bits; past that (a table of a thousand million pieces)
  // they are read one lane at a time.
  const hn::Rebind<std::int32_t, decltype(d)> d32;
  const bool gather = table.rows * static_cast<double>(table.stride) < 1e9;
  const std::int32_t* words = reinterpret_cast<const std::int32_t*>(table.pieces);
  const auto low16 = hn::Set(d32, 0xFFFF);
  constexpr bool kLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
  HWY_ALIGN double px[hn::MaxLanes(d)], py[hn::MaxLanes(d)], read[hn::MaxLanes(d)];
  HWY_ALIGN std::int64_t index[hn::MaxLanes(d)];
  for (std::size_t k = 0; k < vector_end; k += lanes) {
    const auto X = hn::LoadU(d, x + k), Y = hn::LoadU(d, y + k), C = hn::LoadU(d, c + k), S = hn::LoadU(d, s + k);
    auto best = hn::Set(d, kInf);
    for (std::size_t j = 0; j < m; ++j) {
      const auto Qx = hn::Set(d, cover[j].centre.x()), Qy = hn::Set(d, cover[j].centre.y());
      // As Placed::world: (x + c qx) - s qy, (y + s qx) + c qy.
      const auto wx = hn::Sub(hn::Add(X, hn::Mul(C, Qx)), hn::Mul(S, Qy));
      const auto wy = hn::Add(hn::Add(Y, hn::Mul(S, Qx)), hn::Mul(C, Qy));
      const auto gx = hn::Mul(hn::Sub(wx, origin_x), inverse), gy = hn::Mul(hn::Sub(wy, origin_y), inverse);
      const auto on_table = hn::And(hn::And(hn::Ge(gx, zero), hn::Ge(gy, zero)), hn::And(hn::Lt(gx, cols), hn::Lt(gy, rows)));
      hn::Vec<decltype(d)> bound;
      if (hn::AllTrue(d, on_table)) {
        // Whole pieces below 2^53: the index is exact in a double.
        const auto at = hn::Add(hn::Mul(hn::Trunc(gy), stride), hn::Trunc(gx));
        if (gather) {
          // 32 bits from each piece's first byte (the table keeps an entry
          // past its last); its own 16 are the half the byte order puts first.
          const auto word = hn::GatherOffset(d32, words, hn::DemoteTo(d32, hn::Add(at, at)));
          const auto steps = kLittleEndian ? hn::And(word, low16) : hn::And(hn::ShiftRight<16>(word), low16);
          bound = hn::Mul(step, hn::PromoteTo(d, steps));
        } else {
          hn::Store(hn::ConvertTo(di, at), di, index);
          for (std::size_t l = 0; l < lanes; ++l) read[l] = static_cast<double>(table.pieces[index[l]]);
          bound = hn::Mul(step, hn::Load(d, read));
        }
      } else {
        hn::Store(wx, d, px);
        hn::Store(wy, d, py);
        for (std::size_t l = 0; l < lanes; ++l) read[l] = table(px[l], py[l]);
        bound = hn::Load(d, read);
      }
      best = hn::Min(best, hn::Sub(bound, hn::Set(d, cover[j].radius)));
    }
    hn::StoreU(best, d, out + k);
  }
  for (std::size_t k = vector_end; k < n; ++k) {
    double best = kInf;
    for (std::size_t j = 0; j < m; ++j) {
      const double qx = cover[j].centre.x(), qy = cover[j].centre.y();
      best = std::min(best, table(x[k] + c[k] * qx - s[k] * qy, y[k] + s[k] * qx + c[k] * qy) - cover[j].radius);
    }
    out[k] = best;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fgdwa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fgdwa {
namespace detail {

HWY_EXPORT(CoverLowerBounds);

void cover_lower_bounds(const double* x, const double* y, const double* c, const double* s, std::size_t n,
                        const Footprint::CoverDisc* cover, std::size_t m, const DistanceField::LowerBounds& table,
                        double* out) {
  HWY_DYNAMIC_DISPATCH(CoverLowerBounds)(x, y, c, s, n, cover, m, table, out);
}

}  // namespace detail
}  // namespace fgdwa
#endif
