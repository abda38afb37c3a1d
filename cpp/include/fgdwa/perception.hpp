#pragma once
// What the robot senses (docs/algorithms.md, "Perception"): a planar lidar
// ray-cast against the true world, the detect window ahead of the robot and its
// obstacle density I (Eq. 13).
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/params.hpp"

namespace fgdwa {

struct LidarParams {
  double fov = 4.71238898038469;  // 270 deg
  int beams = 541;
  double max_range = 10.0;
  double noise_std = 0.0;
  double dropout = 0.0;

  static constexpr const char* kName = "lidar";
  template <class V>
  static void fields(V& v) {
    v.real("fov", &LidarParams::fov, "rad", Bounds::positive(2.0 * M_PI), "field of view centred on the heading");
    v.integer("beams", &LidarParams::beams, "", Bounds::closed(1, limits::kMaxBeams), "beams, both ends of the field of view included");
    v.real("max_range", &LidarParams::max_range, "m", Bounds::positive(), "a beam with no hit within it reads +inf");
    v.real("noise_std", &LidarParams::noise_std, "m", Bounds::at_least(0), "Gaussian noise added to each hit's range");
    v.real("dropout", &LidarParams::dropout, "", Bounds::below(0, 1), "probability that a beam returns nothing and reads +inf");
  }
  void validate() const { validate_params(*this); }
  double increment() const { return beams > 1 ? fov / (beams - 1) : 0.0; }
  // Beam i's angle relative to the heading, rad.
  double angle(int i) const { return -0.5 * fov + i * increment(); }
};

struct Scan {
  Pose2 pose;                  // where it was taken
  double angle_min = 0.0;      // rad, first beam relative to the heading
  double angle_increment = 0.0;
  double max_range = 0.0;      // m
  std::vector<double> ranges;  // m, +inf where nothing was hit within max_range
  // Throws fgdwa::Error naming the first bad field: a NaN or negative range,
  // more than limits::kMaxBeams beams, a pose or angles out of bounds.
  void validate() const;
  // World positions of the beams' hits.
  std::vector<Vec2> hit_points() const;
};

// Casts rays against a static distance field (the true world's grid) and
// moving discs. The field makes free space cheap: a ray jumps by the distance
// to the nearest obstacle, then walks cell by cell once near one.
// Threads: scan() and cast() are const and draw from the generator they are
// given, so threads may share a scanner, each with its own generator.
class LaserScanner {
 public:
  LaserScanner(const LidarParams& params, std::shared_ptr<const DistanceField> world);
  const LidarParams& params() const { return params_; }

  // One scan at `pose`, the discs placed `t` seconds ahead; noise and dropped
  // beams drawn from `rng` (nothing is drawn when both are off).
  void scan(const Pose2& pose, const std::vector<Disc>& discs, double t, std::mt19937_64& rng, Scan& out) const;
  // Range of one ray from `origin` along `angle` (world frame), no noise.
  double cast(const Vec2& origin, double angle, const std::vector<Disc>& discs, double t) const;

 private:
  // The grid's range along each of n directions from `origin` (+inf: no hit).
  void cast_grid(const Vec2& origin, const Vec2* directions, std::size_t n, double* out) const;
  // The nearer of `grid_range` and the discs' along `direction`, +inf past max_range.
  double with_discs(const Vec2& origin, const Vec2& direction, double grid_range, const std::vector<Disc>& discs,
                    double t) const;
  LidarParams params_;
  std::shared_ptr<const DistanceField> world_;
};

struct DetectWindowParams {
  double half_angle = 1.0471975511965976;  // 60 deg
  double radius = 2.0;
  double base = 0.5;

  static constexpr const char* kName = "detect_window";
  template <class V>
  static void fields(V& v) {
    v.real("half_angle", &DetectWindowParams::half_angle, "rad", Bounds::positive(M_PI), "the window spans +-half_angle about the heading");
    v.real("radius", &DetectWindowParams::radius, "m", Bounds::positive(), "the window's radius R");
    v.real("base", &DetectWindowParams::base, "", Bounds::positive(1e6), "the base c of the density's exponential weight (Eq. 13)");
  }
  void validate() const { validate_params(*this); }
};

struct DensityReading {
  double density = 0.0;     // I = S_d / S_w + c^max_gap, clamped to [0, 2]
  double area_ratio = 0.0;  // S_d / S_w: mean over window beams of 1 - (min(r, R) / R)^2
  double max_gap = 0.0;     // m, chord 2 R sin(phi / 2) of the widest run of free beams
  int beams = 0;            // beams inside the window
};

// Eq. 13 as docs/algorithms.md ("Perception") reads it: S_d / S_w is the share
// of the window's sector area at or beyond the beams' hits; max_gap the chord of
// the widest angular run phi of adjacent window beams with no hit within R (0
// when there is none).
DensityReading obstacle_density(const Scan& scan, const DetectWindowParams& params);

// A distance field of scattered obstacle points (lidar hits the map does not
// explain): their cells, at `resolution`, on a grid just covering them.
std::shared_ptr<DistanceField> points_field(const std::vector<Vec2>& points, double resolution);

}  // namespace fgdwa
