// The distance from many points to a set of discs that stand still (and the
// discs a box footprint may come near), compiled
// by Highway for every instruction set and dispatched at run time like the
// batch DTW (dtw_simd.cpp). Lanes carry points; the discs are the outer loop,
// so each lane keeps its own minimum and nothing is reduced across lanes.
// Correctly rounded operations only, without contraction: the same bits as
// the scalar (|p - c| - inflate) - r on every instruction set.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "disc_distance_simd.cpp"
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

void LowerToDiscs(const double* HWY_RESTRICT px, const double* HWY_RESTRICT py, std::size_t n,
                  const double* HWY_RESTRICT cx, const double* HWY_RESTRICT cy, const double* HWY_RESTRICT radius,
                  std::size_t m, double inflate, double* HWY_RESTRICT out) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  const std::size_t vector_end = n - n % lanes;
  const auto inflation = hn::Set(d, inflate);
  // Discs of one radius (points: all zero) need one square root per point:
  // the nearest centre is the nearest disc, and a rounded square root, like
  // subtracting the radius, keeps the order, so the bits are the same.
  const bool one_radius = std::all_of(radius, radius + m, [&](double r) { return r == radius[0]; });
  std::size_t k = 0;
  if (one_radius && m > 0) {
    const auto common = hn::Set(d, radius[0]);
    for (; k < vector_end; k += lanes) {
      const auto x = hn::LoadU(d, px + k), y = hn::LoadU(d, py + k);
      auto nearest = hn::Set(d, std::numeric_limits<double>::infinity());
      for (std::size_t j = 0; j < m; ++j) {
        const auto dx = hn::Sub(hn::Set(d, cx[j]), x), dy = hn::Sub(hn::Set(d, cy[j]), y);
        nearest = hn::Min(nearest, hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy)));
      }
      const auto distance = hn::Sub(hn::Sub(hn::Sqrt(nearest), inflation), common);
      hn::StoreU(hn::Min(hn::LoadU(d, out + k), distance), d, out + k);
    }
  }
  for (; k < vector_end; k += lanes) {
    const auto x = hn::LoadU(d, px + k), y = hn::LoadU(d, py + k);
    auto best = hn::LoadU(d, out + k);
    for (std::size_t j = 0; j < m; ++j) {
      const auto dx = hn::Sub(hn::Set(d, cx[j]), x), dy = hn::Sub(hn::Set(d, cy[j]), y);
      const auto distance = hn::Sub(hn::Sub(hn::Sqrt(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy))), inflation),
                                    hn::Set(d, radius[j]));
      best = hn::Min(best, distance);
    }
    hn::StoreU(best, d, out + k);
  }
  // The points left over (a single one, when the clearance of one pose is
  // asked): lanes carry discs instead, and their minimum is taken at the end.
  const std::size_t disc_end = m - m % lanes;
  for (std::size_t k = vector_end; k < n; ++k) {
    const auto x = hn::Set(d, px[k]), y = hn::Set(d, py[k]);
    auto best = hn::Set(d, out[k]);
    for (std::size_t j = 0; j < disc_end; j += lanes) {
      const auto dx = hn::Sub(hn::LoadU(d, cx + j), x), dy = hn::Sub(hn::LoadU(d, cy + j), y);
      best = hn::Min(best, hn::Sub(hn::Sub(hn::Sqrt(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy))), inflation),
                                   hn::LoadU(d, radius + j)));
    }
    double lowest = hn::GetLane(hn::MinOfLanes(d, best));
    for (std::size_t j = disc_end; j < m; ++j) {
      const double dx = cx[j] - px[k], dy = cy[j] - py[k];
      lowest = std::min(lowest, (std::sqrt(dx * dx + dy * dy) - inflate) - radius[j]);
    }
    out[k] = lowest;
  }
}

std::size_t BoxBoundsBelow(const double* HWY_RESTRICT cx, const double* HWY_RESTRICT cy,
                           const double* HWY_RESTRICT radius, std::size_t m, double px, double py, double c, double s,
                           const double* HWY_RESTRICT box, double cutoff, std::uint32_t first,
                           std::uint32_t* HWY_RESTRICT index, double* HWY_RESTRICT low) {
  // As the scalar bound: q = (c dx + s dy, -s dx + c dy), then
  // max(max(x_lo - qx, qx - x_hi), max(y_lo - qy, qy - y_hi)) - r - 1e-9.
  const auto bound = [&](double x, double y, double r) {
    const double dx = x - px, dy = y - py;
    const double qx = c * dx + s * dy, qy = -s * dx + c * dy;
    return std::max(std::max(box[0] - qx, qx - box[1]), std::max(box[2] - qy, qy - box[3])) - r - 1e-9;
  };
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  const std::size_t vector_end = m - m % lanes;
  const auto vx = hn::Set(d, px), vy = hn::Set(d, py), vc = hn::Set(d, c), vs = hn::Set(d, s), vns = hn::Set(d, -s);
  const auto x_lo = hn::Set(d, box[0]), x_hi = hn::Set(d, box[1]), y_lo = hn::Set(d, box[2]), y_hi = hn::Set(d, box[3]);
  const auto nano = hn::Set(d, 1e-9), limit = hn::Set(d, cutoff);
  HWY_ALIGN double lane_low[hn::MaxLanes(d)];
  std::size_t found = 0;
  for (std::size_t j = 0; j < vector_end; j += lanes) {
    const auto dx = hn::Sub(hn::LoadU(d, cx + j), vx), dy = hn::Sub(hn::LoadU(d, cy + j), vy);
    const auto qx = hn::Add(hn::Mul(vc, dx), hn::Mul(vs, dy));
    const auto qy = hn::Add(hn::Mul(vns, dx), hn::Mul(vc, dy));
    const auto out = hn::Max(hn::Max(hn::Sub(x_lo, qx), hn::Sub(qx, x_hi)), hn::Max(hn::Sub(y_lo, qy), hn::Sub(qy, y_hi)));
    const auto b = hn::Sub(hn::Sub(out, hn::LoadU(d, radius + j)), nano);
    // Most discs near a pose are far from its box: whole vectors pass at once.
    if (hn::AllFalse(d, hn::Lt(b, limit))) continue;
    hn::Store(b, d, lane_low);
    for (std::size_t k = 0; k < lanes; ++k)
      if (lane_low[k] < cutoff) index[found] = first + static_cast<std::uint32_t>(j + k), low[found++] = lane_low[k];
  }
  for (std::size_t j = vector_end; j < m; ++j) {
    const double b = bound(cx[j], cy[j], radius[j]);
    if (b < cutoff) index[found] = first + static_cast<std::uint32_t>(j), low[found++] = b;
  }
  return found;
}

}  // namespace HWY_NAMESPACE
}  // namespace fgdwa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "disc_distance.hpp"

namespace fgdwa {
namespace detail {

HWY_EXPORT(LowerToDiscs);
HWY_EXPORT(BoxBoundsBelow);

void lower_to_discs(const double* px, const double* py, std::size_t n, const double* cx, const double* cy,
                    const double* radius, std::size_t m, double inflate, double* out) {
  HWY_DYNAMIC_DISPATCH(LowerToDiscs)(px, py, n, cx, cy, radius, m, inflate, out);
}

std::size_t box_bounds_below(const double* cx, const double* cy, const double* radius, std::size_t m, double px,
                             double py, double c, double s, const double box[4], double cutoff, std::uint32_t first,
                             std::uint32_t* index, double* low) {
  return HWY_DYNAMIC_DISPATCH(BoxBoundsBelow)(cx, cy, radius, m, px, py, c, s, box, cutoff, first, index, low);
}

}  // namespace detail
}  // namespace fgdwa
#endif
