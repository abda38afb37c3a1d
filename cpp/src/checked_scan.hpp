#pragma once
// What the robot's side reads from a scan it has already validated: the
// public functions check the scan on every call, and a control cycle would
// check the same 541 ranges three times over.
#include <vector>

#include "fgdwa/perception.hpp"

namespace fgdwa::detail {

// Scan::hit_points() without checking the scan, into `out` (cleared first).
void hit_points_of_checked(const Scan& scan, std::vector<Vec2>& out);

// obstacle_density() without checking the scan (the window's parameters are still checked).
DensityReading obstacle_density_of_checked(const Scan& scan, const DetectWindowParams& params);

}  // namespace fgdwa::detail
