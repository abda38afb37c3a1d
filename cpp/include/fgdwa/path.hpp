#pragma once
// The global path as the local planner sees it: a polyline with projection,
// deviation, segment directions, arc-length walking and key nodes
// (docs/algorithms.md, "Global guidance").
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <array>
#include <vector>

#include "fgdwa/geometry.hpp"
#include "fgdwa/params.hpp"

namespace fgdwa {

struct PathProjection {
  Vec2 point = Vec2::Zero();  // nearest point of the polyline
  std::size_t segment = 0;    // index of the segment holding it
  double arc_length = 0.0;    // m from the start of the path
  double distance = 0.0;      // m from the query point
};

// Threads: immutable once built; share it freely.
class GlobalPath {
 public:
  // At least two points; repeated consecutive points are dropped, and at least
  // two distinct ones must remain.
  explicit GlobalPath(std::vector<Vec2> points);

  const std::vector<Vec2>& points() const { return points_; }
  std::size_t segment_count() const { return points_.size() - 1; }
  double length() const { return cumulative_.back(); }
  // Arc length from the start to vertex i.
  double arc_length_at_vertex(std::size_t i) const { return cumulative_[i]; }
  // Direction of segment i, rad.
  double segment_direction(std::size_t i) const { return directions_[i]; }

  // Orthogonal projection onto the nearest segment (the first one on ties).
  PathProjection project(const Vec2& p) const;
  // Distance from p to the polyline (the deviation D).
  double deviation(const Vec2& p) const { return project(p).distance; }
  // The point at arc length s, clamped to [0, length()].
  Vec2 point_at(double s) const;
  // The segment holding arc length s (clamped).
  std::size_t segment_at(double s) const;

  // Vertices where the direction turns by more than `min_turn` rad, then the
  // last vertex (the goal). Indices into points().
  std::vector<std::size_t> key_nodes(double min_turn) const;

 private:
  std::vector<Vec2> points_;
  std::vector<double> cumulative_;
  std::vector<double> directions_;
};

// How the reference samples E of the similarity cost follow the path
// (docs/algorithms.md, "Similarity").
enum class ReferenceSampling : std::uint8_t {
  Segment,   // Eq. 9 as written: a straight line along the current segment
  Polyline,  // the same spacing walked along the path's arc length, turning its corners
};
const char* to_string(ReferenceSampling sampling);
constexpr std::array<ReferenceSampling, 2> enum_values(ReferenceSampling) {
  return {ReferenceSampling::Polyline, ReferenceSampling::Segment};
}

// E_i, i = 1..n: from the robot's projection P onto the path, i * v_ref * dt
// further along the current segment's direction (Segment) or along the path
// (Polyline, stopping at its end). Written into `out` (resized).
void reference_samples(const GlobalPath& path, const Vec2& robot, double v_ref, double dt, int n,
                       ReferenceSampling sampling, std::vector<Vec2>& out);

struct KeyNodeParams {
  double min_turn = 0.17453292519943295;  // 10 deg
  double reach_radius = 1.0;
  // Off (the paper as written) by default: on, it keeps robots from aiming
  // past a wall's end at a node behind it, but a robot circling a node it may
  // not leave can stray, and did into the C-shaped trap.
  bool require_sight = false;

  static constexpr const char* kName = "key_nodes";
  template <class V>
  static void fields(V& v) {
    v.real("min_turn", &KeyNodeParams::min_turn, "rad", Bounds::below(0, M_PI), "turn that makes a path vertex a key node");
    v.real("reach_radius", &KeyNodeParams::reach_radius, "m", Bounds::at_least(0), "a key node closer than this is reached");
    v.flag("require_sight", &KeyNodeParams::require_sight, "a key node within reach_radius counts as reached only once the next one is in sight");
  }
  void validate() const { validate_params(*this); }
};

// The temporary target of GDWA: the first key node not yet reached. A node is
// reached when the robot comes within reach_radius of it or its projection on
// the path passes it; reached nodes stay reached.
// Threads: one per planner; update() advances it.
class KeyNodeTracker {
 public:
  KeyNodeTracker(const GlobalPath& path, const KeyNodeParams& params);

  // Advances past reached nodes and returns the current target. `in_sight(a, b)`
  // tells whether the robot could drive straight from a to b (used with
  // require_sight; none: always in sight).
  Vec2 update(const Vec2& robot, const std::function<bool(const Vec2&, const Vec2&)>& in_sight = {});
  Vec2 target() const { return path_->points()[nodes_[current_]]; }
  // Position of the current target in key_nodes(), and the nodes themselves.
  std::size_t current() const { return current_; }
  const std::vector<std::size_t>& nodes() const { return nodes_; }

 private:
  const GlobalPath* path_;
  KeyNodeParams params_;
  std::vector<std::size_t> nodes_;
  std::size_t current_ = 0;
};

}  // namespace fgdwa
