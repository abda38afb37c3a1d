#pragma once
// Seeded maps shared by the benchmark programs, so that their figures describe
// the same worlds. Header-only: the benchmarks are separate executables.
#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "fgdwa/grid.hpp"

namespace fgdwa::bench {

// A cells x cells map whose obstacles are rectangles of 1-8 cells a side, as in
// real maps, dropped until `fraction` of the cells are occupied. With the
// defaults it is the 10 m x 10 m map at 0.1 m of bench_planner and bench_fgdwa.
inline OccupancyGrid rectangle_map(std::mt19937& rng, int cells = 100, double resolution = 0.1,
                                   double fraction = 0.15) {
  std::uniform_int_distribution<int> side(1, 8), cell(0, cells - 1);
  std::vector<std::uint8_t> grid(static_cast<std::size_t>(cells) * cells, 0);
  const std::size_t target = static_cast<std::size_t>(fraction * cells * cells);
  std::size_t occupied = 0;
  while (occupied < target) {
    const int r0 = cell(rng), c0 = cell(rng), h = side(rng), w = side(rng);
    for (int r = r0; r < std::min(cells, r0 + h); ++r)
      for (int c = c0; c < std::min(cells, c0 + w); ++c) {
        auto& value = grid[static_cast<std::size_t>(r) * cells + c];
        if (!value) ++occupied;
        value = 1;
      }
  }
  return OccupancyGrid(cells, cells, resolution, Vec2::Zero(), std::move(grid));
}

// A cells x cells map with exactly round(fraction * cells^2) occupied cells
// drawn uniformly at random, then the 2 x 2 blocks at the lower-left and
// upper-right corners cleared for a start and a goal (so the occupied share
// ends up a hair below `fraction`). Cell choice uses the generator's raw
// output, not a std distribution, so the map is the same with any standard library.
inline OccupancyGrid random_cell_map(std::mt19937& rng, int cells, double resolution, double fraction) {
  const std::size_t n = static_cast<std::size_t>(cells) * cells;
  std::vector<std::uint8_t> grid(n, 0);
  const std::size_t target = static_cast<std::size_t>(fraction * static_cast<double>(n) + 0.5);
  for (std::size_t occupied = 0; occupied < target;) {
    auto& value = grid[static_cast<std::size_t>(rng()) % n];
    if (!value) ++occupied;
    value = 1;
  }
  for (int r : {0, 1, cells - 2, cells - 1})
    for (int c : {0, 1, cells - 2, cells - 1})
      if ((r < 2) == (c < 2)) grid[static_cast<std::size_t>(r) * cells + c] = 0;
  return OccupancyGrid(cells, cells, resolution, Vec2::Zero(), std::move(grid));
}

}  // namespace fgdwa::bench
