#pragma once
// The bounds every public entry of the library checks its input against.
// Values outside them are refused with fgdwa::Error naming the argument: they
// are never a real robot's, and past them sizes overflow memory, products
// overflow to inf and casts to cell indices overflow.
#include <cstddef>

namespace fgdwa::limits {

// m: a coordinate given by the user (poses, path points, map origins, disc
// centres). 1000 km holds any map at any resolution down to kMinResolution.
inline constexpr double kMaxCoordinate = 1e6;
// m: a coordinate a geometric query accepts (clearance, distance, contains).
// Ten times kMaxCoordinate, so every pose a planner derives from valid input
// (a rollout of at most kMaxSpeed for kMaxHorizon from a valid pose) passes.
inline constexpr double kMaxQueryCoordinate = 1e7;
// rad: a heading (an unwrapped odometry heading included); a wrapped angle
// still carries 1e-9 rad at it.
inline constexpr double kMaxAngle = 1e7;
// m/s and rad/s: a speed, a turn rate, a disc's velocity or growth.
inline constexpr double kMaxSpeed = 1e3;
// m/s^2 and rad/s^2: an acceleration or a deceleration (stopping takes at
// most kMaxSpeed / kMinAcceleration).
inline constexpr double kMinAcceleration = 1e-3;
inline constexpr double kMaxAcceleration = 1e4;
// s: a time step (control period, simulation step).
inline constexpr double kMinTimeStep = 1e-4;
inline constexpr double kMaxTimeStep = 10.0;
// s: the time a rollout covers, and any time argument.
inline constexpr double kMaxHorizon = 3600.0;
// Steps of one rollout.
inline constexpr long kMaxRolloutSteps = 100000;
// Samples of the dynamic window per axis, and in all.
inline constexpr long kMaxWindowSamplesPerAxis = 10000;
inline constexpr long kMaxWindowSamples = 1000000;
// Poses the planner rolls out in one cycle: window samples x rollout steps
// (about 240 MB of rollouts at the cap).
inline constexpr long kMaxRolloutPoses = 10000000;
// m per cell of any grid.
inline constexpr double kMinResolution = 1e-4;
inline constexpr double kMaxResolution = 1e3;
// Cells of any grid: 10 000 x 10 000.
inline constexpr long kMaxGridCells = 100000000;
// m: a length the robot's geometry or its sensors are given (radii,
// inflation, ranges, distances in parameters).
inline constexpr double kMaxLength = 1e6;
// m: the circumscribed radius of a footprint.
inline constexpr double kMaxFootprintRadius = 100.0;
// Vertices of a footprint polygon.
inline constexpr long kMaxPolygonVertices = 1000;
// Points of a global path or of a point set (a scan's hits, a DTW sequence).
inline constexpr long kMaxPoints = 10000000;
// m: the length of a global path; walks along it at a fraction of a cell
// then always advance.
inline constexpr double kMaxPathLength = 1e9;
// Cells of one DTW table (n x m, times the batch): about a second of work.
inline constexpr double kMaxDtwCells = 1e9;
// Beams of a lidar.
inline constexpr long kMaxBeams = 100000;
// Discs of one world.
inline constexpr long kMaxDiscs = 1000000;
// A count of events a parameter sets (hits that confirm a track, recoveries
// in a row).
inline constexpr long kMaxEventCount = 1000000;

}  // namespace fgdwa::limits
