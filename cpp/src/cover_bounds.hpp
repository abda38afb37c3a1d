#pragma once
// A polygon footprint's lower bounds at many poses from one field's table,
// vectorised (cover_bounds_simd.cpp).
#include <cstddef>

#include "fgdwa/grid.hpp"

namespace fgdwa {
namespace detail {

// out[k] = min over j of table(world point of cover disc j at pose k) - qr[j]:
// the poses (x[k], y[k]) with their heading's cosine c[k] and sine s[k], k < n;
// the cover discs' centres (qx[j], qy[j]) in the robot's frame and radii qr[j],
// j < m. The same bits as placing each disc and looking it up one at a time.
void cover_lower_bounds(const double* x, const double* y, const double* c, const double* s, std::size_t n,
                        const double* qx, const double* qy, const double* qr, std::size_t m,
                        const DistanceField::LowerBounds& table, double* out);

}  // namespace detail
}  // namespace fgdwa
