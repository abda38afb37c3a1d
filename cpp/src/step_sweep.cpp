#include "step_sweep.hpp"

namespace fgdwa::detail {
namespace {

// Whether the footprint stays clear along one piece of a turn (straight =
// false: `sweep` is the turn's reach) or of a drive (straight: `sweep` is its
// length), given the clearances c0 and c1 at the piece's ends. Pieces the ends
// do not settle are halved until they do, down to a millimetre. `pose(f)`,
// f in [0, 1], walks the piece.
template <typename PoseAt>
bool clear_along(const ClearanceSource& world, const Footprint& footprint, const StepSweep& step, bool straight,
                 const PoseAt& pose, double t0, double dt, double f0, double c0, double f1, double c1, double sweep,
                 double margin) {
  if (c0 <= 0.0 || c1 <= 0.0) return false;
  const double piece = straight ? step.relative((f1 - f0) * sweep, f1 - f0) : (f1 - f0) * sweep;
  if (straight ? step.drive_covered(c0, c1, piece) : c0 + c1 > piece) return true;
  if (piece < 1e-3) return false;
  const double fm = 0.5 * (f0 + f1);
  const double cm = world.clearance(footprint, pose(fm), t0 + fm * dt) - margin;
  return clear_along(world, footprint, step, straight, pose, t0, dt, f0, c0, fm, cm, sweep, margin) &&
         clear_along(world, footprint, step, straight, pose, t0, dt, fm, cm, f1, c1, sweep, margin);
}

}  // namespace

// The turn in place, for a footprint that is not a circle, then the straight drive.
bool step_clear(const ClearanceSource& world, const Footprint& footprint, const StepSweep& step, const Pose2& from,
                double c0, const Pose2& to, double c1, double t0, double dt, double margin) {
  if (step.covered(c0, c1)) return true;
  double c_turned = c0;
  if (!footprint.is_circle()) {
    const double turn = angle_difference(to.theta, from.theta);
    c_turned = world.clearance(footprint, Pose2{from.x, from.y, to.theta}, t0) - margin;
    const auto turning = [&](double f) { return Pose2{from.x, from.y, from.theta + f * turn}; };
    if (!clear_along(world, footprint, step, false, turning, t0, 0.0, 0.0, c0, 1.0, c_turned, step.turn_reach, margin))
      return false;
  }
  const auto driving = [&](double f) {
    return Pose2{from.x + f * (to.x - from.x), from.y + f * (to.y - from.y), to.theta};
  };
  return clear_along(world, footprint, step, true, driving, t0, dt, 0.0, c_turned, 1.0, c1,
                     std::hypot(to.x - from.x, to.y - from.y), margin);
}

}  // namespace fgdwa::detail
