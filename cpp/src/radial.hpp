#pragma once
// The distance and the unit direction from a centre to many points,
// vectorised (radial_simd.cpp).
#include <cstddef>

namespace fgdwa {
namespace detail {

// For k < n: reach[k] = max(|p_k - c|, floor), ux[k] = (px[k] - cx) / reach[k],
// uy[k] = (py[k] - cy) / reach[k]. Correctly rounded operations, no
// contraction: the same bits as the scalar expressions on every instruction set.
void radial(const double* px, const double* py, std::size_t n, double cx, double cy, double floor, double* reach,
            double* ux, double* uy);

}  // namespace detail
}  // namespace fgdwa
