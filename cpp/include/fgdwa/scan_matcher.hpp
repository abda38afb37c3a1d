#pragma once
// Where a scan fits the map: a correlative scan-to-map matcher (Olson's
// real-time correlative matching, the one behind Cartographer's real-time
// scan matcher). The scan's hits, thinned, are scored against the map's
// distance field at every pose of a bounded window around the pose the scan
// was placed at: coarse steps over the whole window, then halved steps around
// the best so far. Each hit scores exp(-d^2 / (2 sigma^2)), d its distance to
// the nearest obstacle; the pose's score is the mean.
//
// A match is refused unless it is clearly better than none: the map must
// explain enough of the scan, the best pose must beat the one given by a
// margin, and no pose well away from it may come as close (a corridor seen
// along its axis, a row of equal posts). A refused match leaves the pose as
// it was: a wrong correction does more harm than drift.
//
// Lifecycle: construct with the params; match() once per scan.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fgdwa/geometry.hpp"
#include "fgdwa/grid.hpp"
#include "fgdwa/limits.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/scan_frame.hpp"

namespace fgdwa {

struct ScanMatchParams {
  bool enabled = false;
  double window_xy = 0.15;
  double window_theta = 0.0523598775598299;  // 3 degrees
  double step_xy = 0.05;
  double step_theta = 0.0174532925199433;  // 1 degree
  double final_step_xy = 0.0125;
  double sigma = 0.05;
  double point_spacing = 0.05;
  int max_points = 180;
  int min_points = 30;
  double min_score = 0.4;
  double margin = 0.02;
  double ambiguity_radius = 0.1;

  static constexpr const char* kName = "scan_match";
  template <class V>
  static void fields(V& v) {
    using P = ScanMatchParams;
    const Bounds length = Bounds::positive(10.0);
    const Bounds angle = Bounds::positive(3.141592653589793);
    const Bounds share = Bounds::closed(0, 1);
    v.flag("enabled", &P::enabled, "align each scan to the map before it goes in, and plan at the corrected pose (false: odometry is the pose)");
    v.real("window_xy", &P::window_xy, "m", length, "farthest the search moves the scan from where odometry places it, in x and in y");
    v.real("window_theta", &P::window_theta, "rad", angle, "farthest the search turns the scan, either way");
    v.real("step_xy", &P::step_xy, "m", length, "the coarse search's translation step over the whole window");
    v.real("step_theta", &P::step_theta, "rad", angle, "the coarse search's rotation step; refined by halves with the translation");
    v.real("final_step_xy", &P::final_step_xy, "m", length, "the refinement halves the steps until the translation step is this fine");
    v.real("sigma", &P::sigma, "m", length, "a hit this far from the map's nearest obstacle scores exp(-1/2)");
    v.real("point_spacing", &P::point_spacing, "m", Bounds::at_least(0, 10.0), "hits nearer than this to the last one kept (in beam order) are skipped");
    v.integer("max_points", &P::max_points, "", Bounds::closed(1, limits::kMaxBeams), "hits scored at most (evenly picked from those kept)");
    v.integer("min_points", &P::min_points, "", Bounds::closed(1, limits::kMaxBeams), "fewer hits kept than this: no match");
    v.real("min_score", &P::min_score, "", share, "the best pose's mean score below this: the map does not know the place yet, no match");
    v.real("margin", &P::margin, "", share, "the best pose must score this much above the pose odometry gives, and this much above every pose farther than ambiguity_radius from it");
    v.real("ambiguity_radius", &P::ambiguity_radius, "m", length, "a pose this far from the best that scores within margin of it makes the match ambiguous");
  }
  // final_step_xy <= step_xy <= window_xy, step_theta <= window_theta, min_points <= max_points.
  void check_relations(const ParamPath& path) const;
  void validate() const { validate_params(*this); }
};

// Why a match was or was not used.
enum class MatchStatus : std::uint8_t {
  Accepted,      // the pose found replaces the one given
  Off,           // matching is disabled, or there was no scan
  NoMap,         // the map has no obstacles yet
  TooFewPoints,  // the scan has too few hits to match
  PoorFit,       // the map explains too little of the scan (min_score)
  NotBetter,     // the best pose is not clearly better than the one given (margin)
  Ambiguous,     // a pose far from the best scores nearly as well (ambiguity_radius)
};
const char* to_string(MatchStatus status);

struct ScanMatch {
  MatchStatus status = MatchStatus::Off;
  Pose2 pose;                   // the scan's best pose found (the one given when none was searched)
  double score = 0.0;           // its mean score, in [0, 1]
  double given_score = 0.0;     // the mean score at the pose given
  double runner_up = 0.0;       // the best score farther than ambiguity_radius from it
  std::size_t points = 0;       // hits scored
  bool accepted() const { return status == MatchStatus::Accepted; }
};

// Threads: match() is const and keeps its scratch in a thread_local buffer.
class ScanMatcher {
 public:
  explicit ScanMatcher(const ScanMatchParams& params = {});

  // The pose at which `frame`'s hits fit `field` best, within the window
  // around the frame's own pose. Each hit is pushed `depth` (m) further along
  // its beam first: where the map built from scans marks it.
  ScanMatch match(const ScanFrame& frame, const DistanceField& field, double depth = 0.0) const;

  const ScanMatchParams& params() const { return params_; }

 private:
  ScanMatchParams params_;
};

}  // namespace fgdwa
