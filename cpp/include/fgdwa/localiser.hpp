#pragma once
// Where the robot is on its own map while its odometry drifts: the
// correction from the odometry's frame to the map's (map_to_odom, as a
// localiser publishes the map -> odom transform), kept up to date by matching
// each scan to the map (ScanMatcher). The odometry given is never changed:
// the pose on the map is map_to_odom composed with it.
//
// Lifecycle: construct once per robot (the correction starts at the
// identity: the map's frame is the odometry's at the start); update() with
// each scan before it goes into the map; to_map() for every pose the
// odometry gives.
#include "fgdwa/geometry.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/scan_frame.hpp"
#include "fgdwa/scan_matcher.hpp"

namespace fgdwa {

// Threads: one per robot.
class Localiser {
 public:
  explicit Localiser(const ScanMatchParams& params = {}) : matcher_(params) {}

  // `frame`: this cycle's scan, its pose the odometry's. On return it is
  // placed on the map (at the corrected pose). `field` (null while the map
  // is empty) the map it is matched to; `depth` as in ScanMatcher::match.
  const ScanMatch& update(ScanFrame& frame, const DistanceField* field, double depth);

  // The odometry's pose `odom` on the map.
  Pose2 to_map(const Pose2& odom) const { return compose(map_to_odom_, odom); }
  const Pose2& map_to_odom() const { return map_to_odom_; }
  const ScanMatch& last() const { return last_; }

 private:
  ScanMatcher matcher_;
  Pose2 map_to_odom_;
  ScanMatch last_;
};

}  // namespace fgdwa
