#pragma once
// Whether one step of a rollout (a turn in place, then a straight drive) keeps
// the footprint clear: first from the clearances at its ends alone, then by
// halving the pieces they cannot vouch for.
#include <algorithm>
#include <cmath>
#include <limits>

#include "fgdwa/clearance.hpp"
#include "fgdwa/geometry.hpp"
#include "fgdwa/robot.hpp"

namespace fgdwa::detail {

// How one step of a rollout moves the footprint and what its end clearances
// alone can settle. The step turns in place by `turn` (rad), which moves no
// footprint point farther than `turn_reach`, then drives `drive` metres
// straight along the new heading. Clearances count from the safety margin.
// Moving obstacles move during the step too: against a disc moving straight,
// the footprint's motion relative to it is still a straight drive, at most
// `obstacle_travel` longer (and no longer along the heading, so the polygon's
// chord argument is dropped then).
struct StepSweep {
  double turn_reach = 0.0;  // m, 0 for a circle, whose turns move nothing
  double drive = 0.0;       // m, the robot's own drive
  double obstacle_travel = 0.0;  // m, the most an obstacle moves (or grows) in one step
  double rho = 0.0;         // m, a circle's radius plus the margin; 0 for a polygon
  double chord = 0.0;       // m, the polygon's Footprint::heading_chord(); 0 for a circle or among moving obstacles

  StepSweep(const Footprint& footprint, double margin, double turn, double drive_length, double travel = 0.0)
      : turn_reach(footprint.is_circle() ? 0.0 : footprint.radius() * std::abs(wrap_angle(turn))),
        drive(drive_length),
        obstacle_travel(travel),
        rho(footprint.is_circle() ? footprint.radius() + margin : 0.0),
        chord(footprint.is_circle() || travel > 0.0 ? 0.0 : footprint.heading_chord()) {}

  // The longest relative drive over the fraction `share` of the step's drive.
  double relative(double length, double share) const { return length + share * obstacle_travel; }

  // Whether a straight drive of `length` between placements of clearance c0 and
  // c1 > 0 is clear. Each footprint point's path lies in the open discs of radii
  // c0 and c1 around its ends when c0 + c1 > length. A polygon does better: any
  // point of its sweep lies in one of the two placements, or within
  // length - chord of one along the heading. A disc of radius rho does better
  // still: its swept capsule lies in the obstacle-free discs of radius rho + c0
  // and rho + c1 around the end centres when
  // sqrt(c0 (2 rho + c0)) + sqrt(c1 (2 rho + c1)) > length (each term is how far
  // the capsule's edge, rho from its axis, stays inside one disc).
  bool drive_covered(double c0, double c1, double length) const {
    if (c0 + c1 > length - chord) return true;
    if (rho <= 0.0) return false;
    const double a0 = c0 * (2.0 * rho + c0), a1 = c1 * (2.0 * rho + c1);  // the terms squared
    // (sqrt(a0) + sqrt(a1))^2 >= a0 + a1: most steps pass without a square root.
    return a0 + a1 > length * length || std::sqrt(a0) + std::sqrt(a1) > length;
  }

  // A clearance after the step from which on covered(c0, c1) holds (+inf:
  // none, for c0 <= 0). Beyond turn_reach, c0 vouches for the turned placement
  // and c1 has only to cover the rest of the drive; short of it, c1 must also
  // vouch for the turned placement, a drive back from it. A micrometre above,
  // for the rounding of the sums.
  double settling_clearance(double c0) const {
    if (!(c0 > 0.0)) return std::numeric_limits<double>::infinity();
    const double length = relative(drive, 1.0);
    const double need = c0 > turn_reach ? length - chord - (c0 - turn_reach) : length + turn_reach - c0;
    return std::max(need, 0.0) + 1e-6;
  }

  // A sufficient condition for covered(c0, c1) with fewer tests: the turned
  // placement then keeps c0 - turn_reach > 0, and with c1 it spans the drive.
  // Floating-point sums are monotonic, so each of covered()'s tests holds too.
  bool clear_by_bounds(double c0, double c1) const {
    return c1 > 0.0 && c0 > turn_reach && (c0 - turn_reach) + c1 > relative(drive, 1.0) - chord;
  }

  // Whether the whole step, turn and drive, is clear given the clearances c0
  // before it and c1 after it. The turned placement's clearance is at least
  // c0 - turn_reach and at least c1 - drive: each footprint point moves no
  // farther than that between them.
  bool covered(double c0, double c1) const {
    if (c0 <= 0.0 || c1 <= 0.0) return false;
    const double length = relative(drive, 1.0);
    if (turn_reach == 0.0) return drive_covered(c0, c1, length);
    const double turned = std::max(c0 - turn_reach, c1 - length);
    return turned > 0.0 && c0 + turned > turn_reach && drive_covered(turned, c1, length);
  }
};

namespace sweep {

// The clearance a piece's two halves need at its middle to be settled at once
// (their first tests), a hair above for the rounding: `length` is each
// half's piece as clear_along measures it.
inline double settling(double length_a, double length_b) {
  return std::max(length_a, length_b) * (1.0 + 1e-9) + 1e-9;
}

// Whether the footprint stays clear along one piece of a turn (straight =
// false: `length` is the turn's reach) or of a drive (straight: `length` is
// its length), given the clearances c0 and c1 at the piece's ends. Pieces the
// ends do not settle are halved until they do, down to a millimetre.
// `pose(f)`, f in [0, 1], walks the piece; `below(pose, t, cutoff)` is the
// clearance from the margin, exact below the cutoff (above it, a value from
// the cutoff up): a middle clear by as much as its halves need settles them
// both whatever its exact value.
template <typename PoseAt, typename Below>
bool clear_along(const Below& below, const StepSweep& step, bool straight, const PoseAt& pose, double t0, double dt,
                 double f0, double c0, double f1, double c1, double length) {
  if (c0 <= 0.0 || c1 <= 0.0) return false;
  const auto piece_of = [&](double from, double to) {
    return straight ? step.relative((to - from) * length, to - from) : (to - from) * length;
  };
  const double piece = piece_of(f0, f1);
  if (straight ? step.drive_covered(c0, c1, piece) : c0 + c1 > piece) return true;
  if (piece < 1e-3) return false;
  const double fm = 0.5 * (f0 + f1);
  const double cm = below(pose(fm), t0 + fm * dt, settling(piece_of(f0, fm), piece_of(fm, f1)));
  return clear_along(below, step, straight, pose, t0, dt, f0, c0, fm, cm, length) &&
         clear_along(below, step, straight, pose, t0, dt, fm, cm, f1, c1, length);
}

}  // namespace sweep

// Whether the footprint is clear along the step from `from` (clearance c0, at
// time t0) to `to` (clearance c1), checked where the end clearances do not
// settle it: the turn in place, for a footprint that is not a circle, then the
// straight drive. Clearances count from the margin; `below(pose, t, cutoff)`
// gives them, exact below the cutoff (above it, a value from the cutoff up).
template <typename Below>
bool step_clear(const Below& below, const Footprint& footprint, const StepSweep& step, const Pose2& from, double c0,
                const Pose2& to, double c1, double t0, double dt) {
  if (step.covered(c0, c1)) return true;
  const double drive = std::hypot(to.x - from.x, to.y - from.y);
  double c_turned = c0;
  if (!footprint.is_circle()) {
    const double turn = angle_difference(to.theta, from.theta);
    // As clear as the turn's reach and the drive need, both settle at once.
    c_turned = below(Pose2{from.x, from.y, to.theta}, t0, sweep::settling(step.turn_reach, step.relative(drive, 1.0)));
    const auto turning = [&](double f) { return Pose2{from.x, from.y, from.theta + f * turn}; };
    if (!sweep::clear_along(below, step, false, turning, t0, 0.0, 0.0, c0, 1.0, c_turned, step.turn_reach))
      return false;
  }
  const auto driving = [&](double f) {
    return Pose2{from.x + f * (to.x - from.x), from.y + f * (to.y - from.y), to.theta};
  };
  return sweep::clear_along(below, step, true, driving, t0, dt, 0.0, c_turned, 1.0, c1, drive);
}

}  // namespace fgdwa::detail
