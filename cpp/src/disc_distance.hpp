#pragma once
// The distance from many points to discs that stand still, vectorised
// (disc_distance_simd.cpp).
#include <cstddef>

namespace fgdwa {
namespace detail {

// out[k] = min(out[k], min over j of (|p_k - c_j| - inflate) - radius_j), for
// the points (px[k], py[k]), k < n, and the discs (cx[j], cy[j], radius[j]), j < m.
void lower_to_discs(const double* px, const double* py, std::size_t n, const double* cx, const double* cy,
                    const double* radius, std::size_t m, double inflate, double* out);

}  // namespace detail
}  // namespace fgdwa
