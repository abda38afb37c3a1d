#pragma once
// What the robot's side reads from a scan it has already validated (a
// ScanFrame): the public function checks the scan on every call.
#include "fgdwa/perception.hpp"

namespace fgdwa::detail {

// obstacle_density() without checking the scan (the window's parameters are still checked).
DensityReading obstacle_density_of_checked(const Scan& scan, const DetectWindowParams& params);

}  // namespace fgdwa::detail
