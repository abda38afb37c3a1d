#pragma once
// A polygon footprint's lower bounds at many poses from one field's table,
// vectorised (cover_bounds_simd.cpp).
#include <cstddef>

#include "fgdwa/grid.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {
namespace detail {

// out[k] = min over j of table(world point of cover[j]'s centre at pose k) -
// cover[j].radius: the poses (x[k], y[k]) with their heading's cosine c[k] and
// sine s[k], k < n; the m cover discs in the robot's frame
// (Footprint::cover()). The same bits as placing each disc and looking it up
// one at a time.
void cover_lower_bounds(const double* x, const double* y, const double* c, const double* s, std::size_t n,
                        const Footprint::CoverDisc* cover, std::size_t m, const DistanceField::LowerBounds& table,
                        double* out);

}  // namespace detail
}  // namespace fgdwa
