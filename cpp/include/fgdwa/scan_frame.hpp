#pragma once
// One scan as the robot's side reads it: checked once, each beam's world
// direction and hit point worked out once, then handed to every stage of the
// cycle (the map's rays, segmentation, the unexplained points, the density).
#include <cmath>
#include <cstddef>
#include <vector>

#include "fgdwa/perception.hpp"

namespace fgdwa {

// (cos a, sin a) of beam `i`'s world angle a = theta + angle_min + i angle_increment:
// the one formula the scanner and the robot's side share, so they agree to the bit.
inline Vec2 beam_direction(const Scan& scan, std::size_t i) {
  const double a = scan.pose.theta + scan.angle_min + static_cast<double>(i) * scan.angle_increment;
  return Vec2(std::cos(a), std::sin(a));
}

// Where beam `i` hit, along its `direction` (finite ranges only).
inline Vec2 beam_hit(const Scan& scan, std::size_t i, const Vec2& direction) {
  const double r = scan.ranges[i];
  return Vec2(scan.pose.x + r * direction.x(), scan.pose.y + r * direction.y());
}

// Threads: a value; one thread fills it, any may read it afterwards.
class ScanFrame {
 public:
  ScanFrame() = default;
  // Throws fgdwa::Error if the scan is not valid (Scan::validate).
  explicit ScanFrame(const Scan& scan) { assign(scan); }

  // Takes this scan in place of the last, reusing the buffers. `beams` >= 0:
  // the scanner's beam count, which the scan must match.
  void assign(const Scan& scan, int beams = -1);
  // The same readings taken at `pose` instead (a finite pose): what the
  // scan says once the robot knows better where it was.
  void move_to(const Pose2& pose);

  const Scan& scan() const { return scan_; }
  std::size_t size() const { return scan_.ranges.size(); }
  bool empty() const { return scan_.ranges.empty(); }
  double range(std::size_t beam) const { return scan_.ranges[beam]; }
  // Whether the beam hit something within the scanner's range.
  bool has_hit(std::size_t beam) const { return std::isfinite(scan_.ranges[beam]); }
  // (cos a, sin a) of each beam's world angle a = theta + angle_min + i angle_increment.
  const std::vector<Vec2>& directions() const { return directions_; }
  // Each beam's hit in the world ((0, 0) where it hit nothing).
  const std::vector<Vec2>& beam_hits() const { return beam_hits_; }
  // The hits alone, in beam order: Scan::hit_points().
  const std::vector<Vec2>& hit_points() const { return hit_points_; }

 private:
  // Each beam's direction and hit at scan_.pose.
  void place();

  Scan scan_;
  std::vector<Vec2> directions_, beam_hits_, hit_points_;
};

}  // namespace fgdwa
