#pragma once
// The distance from many points to discs that stand still, vectorised
// (disc_distance_simd.cpp).
#include <cstddef>
#include <cstdint>

namespace fgdwa {
namespace detail {

// out[k] = min(out[k], min over j of (|p_k - c_j| - inflate) - radius_j), for
// the points (px[k], py[k]), k < n, and the discs (cx[j], cy[j], radius[j]), j < m.
void lower_to_discs(const double* px, const double* py, std::size_t n, const double* cx, const double* cy,
                    const double* radius, std::size_t m, double inflate, double* out);

// The discs (cx[j], cy[j], radius[j]), j < m, whose lower bound from a box
// footprint lies below `cutoff`: the box [box[0], box[1]] x [box[2], box[3]]
// in the frame of a pose at (px, py) with heading cos c and sin s, the bound
// the larger of the disc centre's distances beyond the box along the frame's
// axes, less its radius and a nanometre (for the rounding against an exact
// measure). Appends their indices (offset by `first`) to `index` and their
// bounds to `low`; returns how many. The same bits on every instruction set.
std::size_t box_bounds_below(const double* cx, const double* cy, const double* radius, std::size_t m, double px,
                             double py, double c, double s, const double box[4], double cutoff, std::uint32_t first,
                             std::uint32_t* index, double* low);

}  // namespace detail
}  // namespace fgdwa
