// The distance and unit direction from a centre to many points (radial.hpp),
// compiled by Highway for every instruction set and dispatched at run time:
// a disc fit takes them for every hit at every iteration, and the square
// roots and divisions are its cost.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "radial_simd.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace fgdwa {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void Radial(const double* HWY_RESTRICT px, const double* HWY_RESTRICT py, std::size_t n, double cx, double cy,
            double floor, double* HWY_RESTRICT reach, double* HWY_RESTRICT ux, double* HWY_RESTRICT uy) {
  const hn::ScalableTag<double> d;
  const std::size_t lanes = hn::Lanes(d);
  const auto centre_x = hn::Set(d, cx), centre_y = hn::Set(d, cy), lowest = hn::Set(d, floor);
  std::size_t k = 0;
  for (; k + lanes <= n; k += lanes) {
    const auto dx = hn::Sub(hn::LoadU(d, px + k), centre_x), dy = hn::Sub(hn::LoadU(d, py + k), centre_y);
    const auto r = hn::Max(hn::Sqrt(hn::Add(hn::Mul(dx, dx), hn::Mul(dy, dy))), lowest);
    hn::StoreU(r, d, reach + k);
    hn::StoreU(hn::Div(dx, r), d, ux + k);
    hn::StoreU(hn::Div(dy, r), d, uy + k);
  }
  for (; k < n; ++k) {
    const double dx = px[k] - cx, dy = py[k] - cy;
    const double r = std::max(std::sqrt(dx * dx + dy * dy), floor);
    reach[k] = r;
    ux[k] = dx / r;
    uy[k] = dy / r;
  }
}

}  // namespace HWY_NAMESPACE
}  // namespace fgdwa
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "radial.hpp"

namespace fgdwa {
namespace detail {

HWY_EXPORT(Radial);

void radial(const double* px, const double* py, std::size_t n, double cx, double cy, double floor, double* reach,
            double* ux, double* uy) {
  HWY_DYNAMIC_DISPATCH(Radial)(px, py, n, cx, cy, floor, reach, ux, uy);
}

}  // namespace detail
}  // namespace fgdwa
#endif
