#pragma once
// The entry checks of the DTW routines (both precisions): sizes bounded by
// limits::kMaxDtwCells, coordinates by limits::kMaxQueryCoordinate.
#include <cmath>
#include <cstddef>
#include <string>

#include "fgdwa/dtw.hpp"
#include "validation.hpp"

namespace fgdwa::detail {

// Sizes first, so a refused call costs nothing; then every coordinate.
inline void check_dtw_sizes(std::size_t n, std::size_t m, std::size_t count, int band) {
  if (n == 0 || m == 0 || count == 0)
    throw Error("DTW: both sequences (and the batch) need at least one point, got " + std::to_string(n) + " and " +
                std::to_string(m) + (count != 1 ? " points x " + std::to_string(count) : std::string(" points")));
  const double cells = static_cast<double>(n) * static_cast<double>(m) * static_cast<double>(count);
  if (cells > limits::kMaxDtwCells)
    throw Error(describe("DTW table", std::to_string(n) + " x " + std::to_string(m) + " x " + std::to_string(count),
                         "at most " + format_number(limits::kMaxDtwCells) + " cells"));
  if (band < kNoBand) throw Error(describe("band", band, "must be >= 0, or -1 for no band"));
}

template <typename T>
void check_dtw_coordinates(const char* field, const T* values, std::size_t size) {
  bool bad = false;
  for (std::size_t i = 0; i < size; ++i) bad |= !(std::abs(values[i]) <= limits::kMaxQueryCoordinate);
  if (!bad) return;
  for (std::size_t i = 0; i < size; ++i)
    require_magnitude(std::string(field) + "[" + std::to_string(i) + "]", static_cast<double>(values[i]),
                      limits::kMaxQueryCoordinate);
}

}  // namespace fgdwa::detail
