#pragma once
// What the global path keeps off among moving obstacles: the floor each one
// covers over the next few seconds at its predicted velocity.
#include <cstdint>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/geometry.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/path.hpp"

namespace fgdwa::detail {

// A disc swept along a segment: where a mover is now (`from`) and where its
// predicted velocity takes it (`to`), at its present radius.
struct SweptDisc {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  double radius = 0.0;  // m
};

// The sweep of a moving disc over `horizon` seconds.
SweptDisc sweep_of(const Disc& disc, double horizon);

// Distance (m) from `p` to the swept disc; negative inside it.
double distance_to(const SweptDisc& sweep, const Vec2& p);

// Sets to 1 the cells of `grid` (one flag per cell, row-major) whose centres
// lie in the sweep, except cells within `keep` metres of `a` or `b` (the
// robot and the goal, which the path must be able to leave and reach).
void close_swept_cells(const OccupancyGrid& grid, const SweptDisc& sweep, const Vec2& a, const Vec2& b, double keep,
                       std::vector<std::uint8_t>& cells);

// Whether the next `lookahead` metres of `path` past the projection of
// `position` come nearer than `clearance` to any sweep; the stretch within
// `goal_keep` metres of the path's end is not checked.
bool path_meets_sweeps(const GlobalPath& path, const Vec2& position, const std::vector<SweptDisc>& sweeps,
                       double lookahead, double clearance, double goal_keep);

}  // namespace fgdwa::detail
