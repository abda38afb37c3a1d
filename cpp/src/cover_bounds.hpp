#pragma once
// A footprint's lower bounds from one field's table, vectorised
// (cover_bounds_simd.cpp): a circle's at many poses, a polygon's cover discs'
// at many poses, its outline's samples' at one.
#include <cstddef>

#include "fgdwa/grid.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa {
namespace detail {

// out[k] = table(x[k], y[k]) - inflate, k < n: a circle's bounds at its
// centres. The same bits as the table's operator() one point at a time.
void point_lower_bounds(const double* x, const double* y, std::size_t n, const DistanceField::LowerBounds& table,
                        double inflate, double* out);

// out[k] = min over j of table(world point of cover[j]'s centre at pose k) -
// cover[j].radius: the poses (x[k], y[k]) with their heading's cosine c[k] and
// sine s[k], k < n; the m cover discs in the robot's frame
// (Footprint::cover()). The same bits as placing each disc and looking it up
// one at a time.
void cover_lower_bounds(const double* x, const double* y, const double* c, const double* s, std::size_t n,
                        const Footprint::CoverDisc* cover, std::size_t m, const DistanceField::LowerBounds& table,
                        double* out);

// At one pose (x, y, heading cosine c and sine s), the n points (qx[j], qy[j])
// of the robot's frame placed in the world, (wx[j], wy[j]), and the table's
// bound there, low[j]. The same bits as Placed::world and the table's
// operator() one point at a time. Returns the least of the bounds (+inf for
// n = 0), found in vectors.
double outline_lower_bounds(double x, double y, double c, double s, const double* qx, const double* qy, std::size_t n,
                            const DistanceField::LowerBounds& table, double* wx, double* wy, double* low);

}  // namespace detail
}  // namespace fgdwa
