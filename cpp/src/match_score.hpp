#pragma once
// A scan matcher candidate's score, vectorised (match_score_simd.cpp).
#include <cstddef>

#include "fgdwa/grid.hpp"

namespace fgdwa {
namespace detail {

// The sum over the points k < m of weights[e], e the table's entry at the piece
// (ox + x[k] * inverse_piece, oy + y[k] * inverse_piece), for the points on the
// table whose entry is below n (the others add nothing). With `in_lanes`, lanes
// sum apart, which gives the one-by-one sum's bits only where every partial
// sum is exact: weights of at least 2^-7 (multiples of 2^-30 as floats) and
// fewer than 2^22 points (exact_match_sums); without, one point after another.
double match_score_sum(const double* x, const double* y, std::size_t m, double ox, double oy,
                       const DistanceField::LowerBounds& table, const float* weights, std::size_t n, bool in_lanes);

// Whether match_score_sum over up to `points` points with these weights is
// the sequential sum bit for bit.
bool exact_match_sums(const float* weights, std::size_t n, std::size_t points);

}  // namespace detail
}  // namespace fgdwa
