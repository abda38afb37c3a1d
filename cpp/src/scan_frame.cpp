#include "fgdwa/scan_frame.hpp"

#include <cmath>
#include <string>

#include "fgdwa/error.hpp"

namespace fgdwa {

void ScanFrame::assign(const Scan& scan, int beams) {
  if (beams >= 0 && scan.ranges.size() != static_cast<std::size_t>(beams))
    throw Error("scan: " + std::to_string(scan.ranges.size()) + " ranges, but the lidar has " + std::to_string(beams) +
                " beams");
  scan.validate();
  scan_.pose = scan.pose;
  scan_.angle_min = scan.angle_min;
  scan_.angle_increment = scan.angle_increment;
  scan_.max_range = scan.max_range;
  scan_.ranges.assign(scan.ranges.begin(), scan.ranges.end());
  place();
}

void ScanFrame::move_to(const Pose2& pose) {
  if (!std::isfinite(pose.x) || !std::isfinite(pose.y) || !std::isfinite(pose.theta))
    throw Error("ScanFrame::move_to: the pose must be finite");
  scan_.pose = pose;
  place();
}

void ScanFrame::place() {
  const Scan& scan = scan_;
  const std::size_t n = scan.ranges.size();
  directions_.resize(n);
  beam_hits_.assign(n, Vec2::Zero());
  hit_points_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    directions_[i] = beam_direction(scan, i);
    if (!std::isfinite(scan.ranges[i])) continue;
    beam_hits_[i] = beam_hit(scan, i, directions_[i]);
    hit_points_.push_back(beam_hits_[i]);
  }
}

}  // namespace fgdwa
