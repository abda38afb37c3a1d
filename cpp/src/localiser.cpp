#include "fgdwa/localiser.hpp"

namespace fgdwa {

const ScanMatch& Localiser::update(ScanFrame& frame, const DistanceField* field, double depth) {
  const Pose2 odom = frame.scan().pose;
  frame.move_to(to_map(odom));
  last_ = ScanMatch{};
  last_.pose = frame.scan().pose;
  if (field) last_ = matcher_.match(frame, *field, depth);
  else if (matcher_.params().enabled) last_.status = MatchStatus::NoMap;
  if (last_.accepted()) {
    // The correction that puts the odometry's scan pose where it fits.
    map_to_odom_ = compose(last_.pose, inverse(odom));
    frame.move_to(last_.pose);
  }
  return last_;
}

}  // namespace fgdwa
