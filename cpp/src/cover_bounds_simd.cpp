// The table's lower bounds at many points (a circle's centres, lanes carrying
// poses), at a polygon's cover discs at many poses (lanes carry poses, the
// discs are the outer loop) and at its outline's samples at one pose (lanes
// carry samples). Compiled by Highway for every
// instruction set and dispatched at run time like the batch DTW
// (dtw_simd.cpp). The placing and the table's arithmetic run in vectors, the
// table's 16-bit entries are gathered, and a vector with a lane off the table
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

// The table's bounds at the world points (wx, wy) of one vector. On the
// table, the entries are gathered as 32-bit words at byte offsets (the table
// keeps one entry past its last) and cut to their own 16 bits; with a lane
// off it, the scalar look-up (which walks off the grid) takes every lane.
template <class D>
HWY_INLINE hn::Vec<D> TableBounds(D d, hn::Vec<D> wx, hn::Vec<D> wy, const DistanceField::LowerBounds& table) {
  const hn::Rebind<std::int32_t, D> d32;
  const auto gx = hn::Mul(hn::Sub(wx, hn::Set(d, table.origin_x)), hn::Set(d, table.inverse_piece));
  const auto gy = hn::Mul(hn::Sub(wy, hn::Set(d, table.origin_y)), hn::Set(d, table.inverse_piece));
  const auto zero = hn::Zero(d);
  const auto on_table = hn::And(hn::And(hn::Ge(gx, zero), hn::Ge(gy, zero)),
                                hn::And(hn::Lt(gx, hn::Set(d, table.cols)), hn::Lt(gy, hn::Set(d, table.rows))));
  // Byte offsets fit in 32 bits below a thousand million pieces; past that
  // the scalar look-up reads them.
  if (hn::AllTrue(d, on_table) && table.rows * static_cast<double>(table.stride) < 1e9) {
    // Whole pieces below 2^53: the index is exact in a double.
    const auto at = hn::Add(hn::Mul(hn::Trunc(gy), hn::Set(d, static_cast<double>(table.stride))), hn::Trunc(gx));
    const auto word =
        hn::GatherOffset(d32, reinterpret_cast<const std::int32_t*>(table.pieces), hn::DemoteTo(d32, hn::Add(at, at)));
    constexpr bool kLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;
    const auto low16 = hn::Set(d32, 0xFFFF);
    const auto steps = kLittleEndian ? hn::And(word, low16) : hn::And(hn::ShiftRight<16>(word), low16);
    return hn::Mul(hn::Set(d, table.step), hn::PromoteTo(d, steps));
  }
  HWY_ALIGN double px[hn::MaxLanes(d)], py[hn::MaxLanes(d)], read[hn::MaxLanes(d)];
  hn::Store(wx, d, px);
  hn::Store(wy, d, py);
  for (std::size_t l = 0; l < hn::Lanes(d); ++l) read[l] = table(px[l], py[l]);
  return hn::Load(d, read);
}

void PointLowerBounds(const double* HWY_RESTRICT x, const double* HWY_RESTRICT y, std::size_t n,
                      const DistanceField::LowerBounds& table, double inflate, double* HWY_RESTRICT out) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  if (!table.pieces) {
    std::fill(out, out + n, std::numeric_limits<double>::infinity());
    return;
  }
  const auto R = hn::Set(d, inflate);
  std::size_t k = 0;
  for (; k + lanes <= n; k += lanes)
    hn::StoreU(hn::Sub(TableBounds(d, hn::LoadU(d, x + k), hn::LoadU(d, y + k), table), R), d, out + k);
  for (; k < n; ++k) out[k] = table(x[k], y[k]) - inflate;
}

void CoverLowerBounds(const double* HWY_RESTRICT x, const double* HWY_RESTRICT y, const double* HWY_RESTRICT c,
                      const double* HWY_RESTRICT s, std::size_t n, const Footprint::CoverDisc* HWY_RESTRICT cover,
                      std::size_t m, const DistanceField::LowerBounds& table, double* HWY_RESTRICT out) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  const std::size_t vector_end = table.pieces ? n - n % lanes : 0;
  for (std::size_t k = 0; k < vector_end; k += lanes) {
    const auto X = hn::LoadU(d, x + k), Y = hn::LoadU(d, y + k), C = hn::LoadU(d, c + k), S = hn::LoadU(d, s + k);
    auto best = hn::Set(d, kInf);
    for (std::size_t j = 0; j < m; ++j) {
      const auto Qx = hn::Set(d, cover[j].centre.x()), Qy = hn::Set(d, cover[j].centre.y());
      // As Placed::world: (x + c qx) - s qy, (y + s qx) + c qy.
      const auto wx = hn::Sub(hn::Add(X, hn::Mul(C, Qx)), hn::Mul(S, Qy));
      const auto wy = hn::Add(hn::Add(Y, hn::Mul(S, Qx)), hn::Mul(C, Qy));
      best = hn::Min(best, hn::Sub(TableBounds(d, wx, wy, table), hn::Set(d, cover[j].radius)));
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

double OutlineLowerBounds(double x, double y, double c, double s, const double* HWY_RESTRICT qx,
                          const double* HWY_RESTRICT qy, std::size_t n, const DistanceField::LowerBounds& table,
                          double* HWY_RESTRICT wx, double* HWY_RESTRICT wy, double* HWY_RESTRICT low) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  const std::size_t vector_end = table.pieces ? n - n % lanes : 0;
  const auto X = hn::Set(d, x), Y = hn::Set(d, y), C = hn::Set(d, c), S = hn::Set(d, s);
  auto least = hn::Set(d, std::numeric_limits<double>::infinity());
  for (std::size_t j = 0; j < vector_end; j += lanes) {
    const auto Qx = hn::LoadU(d, qx + j), Qy = hn::LoadU(d, qy + j);
    const auto Wx = hn::Sub(hn::Add(X, hn::Mul(C, Qx)), hn::Mul(S, Qy));
    const auto Wy = hn::Add(hn::Add(Y, hn::Mul(S, Qx)), hn::Mul(C, Qy));
    hn::StoreU(Wx, d, wx + j);
    hn::StoreU(Wy, d, wy + j);
    const auto bound = TableBounds(d, Wx, Wy, table);
    hn::StoreU(bound, d, low + j);
    least = hn::Min(least, bound);
  }
  double lowest = hn::GetLane(hn::MinOfLanes(d, least));
  for (std::size_t j = vector_end; j < n; ++j) {
    wx[j] = x + c * qx[j] - s * qy[j];
    wy[j] = y + s * qx[j] + c * qy[j];
    low[j] = table(wx[j], wy[j]);
    lowest = std::min(lowest, low[j]);
  }
  return lowest;
}

}  // namespace HWY_NAMESPACE
}  // namespace fgdwa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace fgdwa {
namespace detail {

HWY_EXPORT(PointLowerBounds);
HWY_EXPORT(CoverLowerBounds);
HWY_EXPORT(OutlineLowerBounds);

void point_lower_bounds(const double* x, const double* y, std::size_t n, const DistanceField::LowerBounds& table,
                        double inflate, double* out) {
  HWY_DYNAMIC_DISPATCH(PointLowerBounds)(x, y, n, table, inflate, out);
}

void cover_lower_bounds(const double* x, const double* y, const double* c, const double* s, std::size_t n,
                        const Footprint::CoverDisc* cover, std::size_t m, const DistanceField::LowerBounds& table,
                        double* out) {
  HWY_DYNAMIC_DISPATCH(CoverLowerBounds)(x, y, c, s, n, cover, m, table, out);
}

double outline_lower_bounds(double x, double y, double c, double s, const double* qx, const double* qy, std::size_t n,
                            const DistanceField::LowerBounds& table, double* wx, double* wy, double* low) {
  return HWY_DYNAMIC_DISPATCH(OutlineLowerBounds)(x, y, c, s, qx, qy, n, table, wx, wy, low);
}

}  // namespace detail
}  // namespace fgdwa
#endif
