#pragma once
// The world directions of a scan's beams, which the navigator's stages each
// need once per scan (hits, the map's rays, the unexplained points).
#include <vector>

#include "fgdwa/perception.hpp"

namespace fgdwa::detail {

// (cos a_i, sin a_i) for a_i = pose.theta + angle_min + i angle_increment,
// the same bits as computing them in place. The last scan's are kept per
// thread, so the reference is valid until this thread asks for another
// scan's directions.
const std::vector<Vec2>& beam_directions(const Scan& scan);

}  // namespace fgdwa::detail
