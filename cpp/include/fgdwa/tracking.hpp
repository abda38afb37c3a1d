#pragma once
// Moving obstacles from lidar scans: a scan's hits are cut into clusters,
// each fitted with a disc; a Tracker follows the discs from scan to scan with
// a constant-velocity Kalman filter and says which tracks move, so that the
// planner can predict them (moving_discs) and the static map can leave their
// hits out (explains).
//
// Lifecycle: segment_scan() every scan; Tracker::update() with its clusters,
// the scan's time (never going back) and the scan itself; read tracks(),
// moving_discs(), explains(); reset() to forget every track.
#include <Eigen/Core>
#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "fgdwa/clearance.hpp"
#include "fgdwa/geometry.hpp"
#include "fgdwa/params.hpp"
#include "fgdwa/perception.hpp"
#include "fgdwa/scan_frame.hpp"

namespace fgdwa {

struct SegmentParams {
  double base_gap = 0.15;
  double range_gap_factor = 0.03;
  int min_points = 3;
  double max_size = 1.6;
  double min_radius = 0.05;
  double range_noise = 0.03;
  double notch_depth = 0.15;
  int max_clusters = 128;

  static constexpr const char* kName = "segment";
  template <class V>
  static void fields(V& v) {
    using P = SegmentParams;
    v.real("base_gap", &P::base_gap, "m", Bounds::positive(), "consecutive hits farther apart than base_gap + range_gap_factor * range start a new cluster");
    v.real("range_gap_factor", &P::range_gap_factor, "m/m", Bounds::at_least(0, 1e3), "the gap's growth per metre of range (beams spread with range)");
    v.integer("min_points", &P::min_points, "", Bounds::closed(1, limits::kMaxBeams), "hits of the smallest cluster kept (smaller ones are noise)");
    v.real("max_size", &P::max_size, "m", Bounds::positive(), "clusters whose oriented box is longer (walls) are not tracked");
    v.real("min_radius", &P::min_radius, "m", Bounds::positive(), "smallest fitted disc radius (the largest is max_size / 2)");
    v.real("range_noise", &P::range_noise, "m", Bounds::positive(), "range noise std the disc fit assumes when weighing hits against the apparent width");
    v.real("notch_depth", &P::notch_depth, "m", Bounds::positive(), "a cluster is cut where two neighbouring hits lie this far behind the line over them from hits on either side (objects side by side, each convex toward the sensor)");
    v.integer("max_clusters", &P::max_clusters, "", Bounds::closed(1, limits::kMaxBeams), "clusters kept per scan, the nearest to the scanner; farther ones are dropped (the tracker's work grows with their cube)");
  }
  // min_radius <= max_size / 2.
  void check_relations(const ParamPath& path) const;
  void validate() const { validate_params(*this); }
};

// A box along the principal axes of a cluster's hits.
struct OrientedBox {
  Vec2 center = Vec2::Zero();        // m
  Vec2 half_extents = Vec2::Zero();  // m, along the major then the minor axis
  double angle = 0.0;                // rad, of the major axis
};

struct Cluster {
  std::vector<Vec2> points;  // m, world frame, in beam order
  int first_beam = 0;        // beam index of the first point
  int last_beam = 0;         // beam index of the last point
  // Fitted disc. A lidar sees only an object's near side, so the centre lies
  // behind the hits, not at their centroid.
  Vec2 center = Vec2::Zero();  // m
  double radius = 0.0;         // m
  OrientedBox box;
  // A beam next to an end hit something nearer, or an end is the field of
  // view's: part of the object may be hidden, so its disc is less certain.
  bool occluded = false;
  // Throws fgdwa::Error naming the field (after `name`) that is out of bounds:
  // a centre beyond the query coordinates, a radius that is not a distance, a
  // point that is not finite.
  void validate(const std::string& name = "cluster") const;
};

// Cuts the finite hits of `scan` into clusters of neighbouring hits, in beam
// order; beams whose `mask` entry is 0 are skipped (e.g. hits on walls the map
// already holds) when a mask of scan.ranges.size() entries is given. A cluster
// is cut at a notch deeper than notch_depth (two movers touching, a mover
// against a wall), the side of each cut occluded. Clusters
// with fewer than min_points hits or longer than max_size are dropped, and so
// are all but the max_clusters nearest. A scan covering the full circle joins
// the cluster across its seam.
std::vector<Cluster> segment_scan(const Scan& scan, const SegmentParams& params = {},
                                  const std::vector<std::uint8_t>* mask = nullptr);
// The same for a scan already taken apart once this cycle.
std::vector<Cluster> segment_scan(const ScanFrame& frame, const SegmentParams& params = {},
                                  const std::vector<std::uint8_t>* mask = nullptr);

enum class TrackStatus : std::uint8_t {
  Tentative,  // fewer than confirm_hits associations so far
  Confirmed,  // seen in the latest update, or not seen for at most lost_time
  Lost,       // not seen for more than lost_time; coasting until removed
};
const char* to_string(TrackStatus status);

struct TrackerParams {
  double gate = 1.0;
  double gate_sigmas = 4.0;
  double accel_std = 1.5;
  double measurement_std = 0.03;
  int confirm_hits = 3;
  double lost_time = 0.5;
  double moving_speed = 0.1;
  double moving_sigmas = 2.0;
  double moving_window = 1.0;
  double moving_hold = 2.0;
  // Shorter than the label's window, so that a turn or a reversal reaches the
  // prediction sooner; the label keeps the longer one, which a slow mover
  // needs to show its displacement above the noise, and the prediction too
  // while the recent slope does not depart from it (four centres at 10 Hz).
  double prediction_window = 0.3;
  double free_margin = 0.1;
  double max_speed = 3.0;
  double uncertainty_sigmas = 2.0;
  double max_uncertainty = 0.3;
  double hypothesis_time = 0.0;
  double acceleration_sigmas = 2.0;
  double max_acceleration = 3.0;
  int max_clusters = 200;

  static constexpr const char* kName = "tracker";
  template <class V>
  static void fields(V& v) {
    using P = TrackerParams;
    using limits::kMaxHorizon;
    using limits::kMaxSpeed;
    v.real("gate", &P::gate, "m", Bounds::positive(), "largest distance between a track's prediction and a cluster it may take");
    v.real("gate_sigmas", &P::gate_sigmas, "", Bounds::positive(1e3), "the same gate in standard deviations of the prediction (Mahalanobis)");
    v.real("accel_std", &P::accel_std, "m/s^2", Bounds::positive(limits::kMaxAcceleration), "white-noise acceleration of the constant-velocity model");
    v.real("measurement_std", &P::measurement_std, "m", Bounds::positive(), "std of an unoccluded cluster centre (and the least scatter the moving test assumes)");
    v.integer("confirm_hits", &P::confirm_hits, "", Bounds::closed(1, limits::kMaxEventCount), "associations before a tentative track is confirmed");
    v.real("lost_time", &P::lost_time, "s", Bounds::positive(kMaxHorizon), "time without association before a track is lost; removed after another lost_time");
    v.real("moving_speed", &P::moving_speed, "m/s", Bounds::at_least(0, kMaxSpeed), "a confirmed track whose window speed, less moving_sigmas std, exceeds this is moving");
    v.real("moving_sigmas", &P::moving_sigmas, "", Bounds::at_least(0, 1e3), "std devs taken off the window speed before comparing it with moving_speed");
    v.real("moving_window", &P::moving_window, "s", Bounds::positive(kMaxHorizon), "the window speed is the slope of a line fitted to the centres this far back");
    v.real("moving_hold", &P::moving_hold, "s", Bounds::at_least(0, kMaxHorizon), "a track labelled moving for a whole moving_window keeps its label this long after its window speed fell below half moving_speed: what paused (a robot waiting, a disc turning back) may go on");
    v.real("prediction_window", &P::prediction_window, "s", Bounds::positive(kMaxHorizon), "the predicted velocity is the slope of the centres this far back (no farther than moving_window) where it departs from moving_window's by more than 1 std, else moving_window's");
    v.real("free_margin", &P::free_margin, "m", Bounds::positive(), "a hit counts as in space an earlier scan saw free when that scan's beams reached this far past it");
    v.real("max_speed", &P::max_speed, "m/s", Bounds::positive(kMaxSpeed), "an association implying more speed is rejected");
    v.real("uncertainty_sigmas", &P::uncertainty_sigmas, "", Bounds::at_least(0, 1e3), "std devs of position added to a moving disc's radius, and of the filter's speed to its growth per second ahead");
    v.real("max_uncertainty", &P::max_uncertainty, "m", Bounds::at_least(0), "the most the position's uncertainty adds to a disc (a coasting track's grows)");
    v.real("hypothesis_time", &P::hypothesis_time, "s", Bounds::at_least(0, kMaxHorizon), "how long a second prediction keeps a moving track's significant acceleration (turning, slowing, reversing) before its velocity holds; 0: constant velocity alone");
    v.real("acceleration_sigmas", &P::acceleration_sigmas, "", Bounds::at_least(0, 1e3), "std devs the fitted acceleration must exceed before the second prediction is made");
    v.real("max_acceleration", &P::max_acceleration, "m/s^2", Bounds::positive(limits::kMaxAcceleration), "the most acceleration the second prediction keeps");
    v.integer("max_clusters", &P::max_clusters, "", Bounds::closed(1, 10000), "clusters an update tracks, the nearest to the scanner first (association costs the cube of the count); the rest stay the scan's points, and new tracks stop at twice this");
  }
  void validate() const { validate_params(*this); }
};

struct Track {
  int id = 0;  // unique over the tracker's life (reset() included)
  TrackStatus status = TrackStatus::Tentative;
  Vec2 position = Vec2::Zero();  // m, at the last update
  Vec2 velocity = Vec2::Zero();  // m/s, the filter's: follows turns within a few scans, noisier
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Identity();  // of (x, y, vx, vy)
  double radius = 0.0;     // m, smoothed over the unoccluded clusters taken
  bool moving = false;     // confirmed, fast enough with confidence, and displacing free space (with hysteresis)
  // m/s, slope of a line through the centres (occluded ones weighing less) of the last
  // moving_window (as of the last association): steadier than `velocity`,
  // half a window late through turns. The moving label uses it.
  Vec2 window_velocity = Vec2::Zero();
  double window_speed_std = 0.0;  // m/s, its std (infinite until three centres)
  // m/s, moving_discs' predicted velocity: the same slope over the last
  // prediction_window where it departs from window_velocity by more than 1 std
  // of the two, else window_velocity.
  Vec2 predicted_velocity = Vec2::Zero();
  // A parabola through the window's centres: the velocity at the last one
  // (m/s), the acceleration (m/s^2) and its std per coordinate (m/s^2;
  // infinite until four centres). The second prediction uses them; fitted
  // only while hypothesis_time > 0 (else 0, 0 and inf).
  Vec2 current_velocity = Vec2::Zero();
  Vec2 acceleration = Vec2::Zero();
  double acceleration_std = std::numeric_limits<double>::infinity();
  int hits = 0;            // associations, the first cluster included
  double last_seen = 0.0;  // s, time of the last association
  double moving_since = 0.0;  // s, the association at which the track was last labelled moving
  double last_fast = 0.0;  // s, the last association at which a moving track's window speed held its label
  double age = 0.0;        // s since the first cluster
  // m, std along the position's most uncertain direction.
  double position_std() const;
  // m/s, std of the speed (along the velocity; the largest when at rest).
  double speed_std() const;
};

// Threads: one per thread; update() changes every track.
class Tracker {
 public:
  explicit Tracker(const TrackerParams& params = {});
  const TrackerParams& params() const { return params_; }

  // Predicts every track to `time` (s, not before the last update), assigns
  // clusters to tracks (gated, optimal: confirmed and lost tracks first, then
  // tentative ones), corrects the assigned tracks, starts tentative tracks
  // from the clusters left, then marks tracks lost and removes the long lost.
  //
  // `scan`, the one the clusters came from (unmasked), gives the moving label
  // its second test: half a moving_window apart (or, until a scan that old is
  // kept, apart from the oldest kept), a mover's hits lie where the
  // other scan saw through (its leading side in the earlier scan's free
  // space, or its trailing side in the later one's), a static object's never,
  // however its apparent outline changes as the robot drives past. The
  // leading side is also tested against scans a quarter, an eighth and a
  // sixteenth of a window old: a fast mover that just came into view was
  // hidden half a window ago. Without scans (detections from elsewhere) only
  // the window speed decides.
  void update(const std::vector<Cluster>& clusters, double time, const Scan* scan = nullptr);
  const std::vector<Track>& tracks() const { return tracks_; }
  // For each cluster of the last update, the id of the track that took it.
  const std::vector<int>& cluster_tracks() const { return cluster_tracks_; }
  // s, time of the last update (NaN before the first).
  double time() const { return time_; }

  // Moving tracks, confirmed or lost (still coasting), as discs at the last
  // update's time with their predicted velocity; the radius grown by
  // uncertainty_sigmas position std devs (at most max_uncertainty) and, per
  // second ahead, by uncertainty_sigmas std devs of the filter's speed (Disc::growth):
  // the spread that the model's acceleration noise (accel_std) gives a mover
  // that may turn or reverse. A track whose acceleration exceeds
  // acceleration_sigmas std devs gets a second disc (same place, size and
  // growth): the hypothesis that it goes on turning, slowing or reversing,
  // from its current velocity at that acceleration (at most max_acceleration)
  // for hypothesis_time. The planner keeps clear of both, the worse of the two
  // at every instant.
  std::vector<Disc> moving_discs() const;
  // Whether `point` lies within `margin` (m) of the grown disc of a confirmed
  // moving track, e.g. a hit the static map should not take.
  bool explains(const Vec2& point, double margin = 0.0) const;
  // Forgets every track; ids keep counting.
  void reset();

 private:
  double measurement_variance(const Cluster& cluster) const;
  void predict(double dt);
  void correct(Track& track, const Cluster& cluster, double time);
  const std::vector<Cluster>& refit_occluded(const std::vector<Cluster>& clusters, const Scan* scan);
  // What a track remembers of its clusters.
  // A cluster centre as the window speed weighs it: an occluded one counts
  // 1 / kOccludedStdFactor^2 of an unoccluded one.
  struct Centre {
    double time;    // s
    Vec2 position;  // m
    double weight;
  };
  // The hits of a cluster taken and where the scan took them from.
  struct Shape {
    Vec2 from;                 // m
    std::vector<Vec2> points;  // m
  };
  struct Memory {
    Vec2 seen_position;                            // m, after its last association
    std::deque<Centre> centres;                    // the clusters' centres within moving_window
    std::deque<std::pair<double, Shape>> shapes;   // (s, -) the clusters taken within moving_window
    std::deque<double> displaced;                  // s, updates whose hits displaced free space
  };
  // A line through the centres since `since` (s): its slope and that slope's
  // std (infinite with fewer than three centres).
  struct LineFit {
    Vec2 velocity = Vec2::Zero();
    double speed_std = std::numeric_limits<double>::infinity();
  };
  LineFit fit_line(const std::deque<Centre>& centres, double since) const;
  // A parabola through all the centres, about the newest.
  struct ParabolaFit {
    Vec2 velocity = Vec2::Zero();
    Vec2 acceleration = Vec2::Zero();
    double acceleration_std = std::numeric_limits<double>::infinity();
  };
  ParabolaFit fit_parabola(const std::deque<Centre>& centres) const;
  void relabel(Track& track, const Memory& memory) const;
  bool displaces_free_space(const Memory& memory, const Cluster& cluster, const Scan& scan, double time) const;
  template <class Item>
  const Item* reference_of(const std::deque<std::pair<double, Item>>& items, double time, double age) const;
  TrackerParams params_;
  std::vector<Track> tracks_;
  std::vector<Memory> memory_;  // one per track
  std::deque<std::pair<double, Scan>> scans_;  // (s, scan) within moving_window
  bool has_scans_ = false;                      // scans were given: the moving label needs free-space evidence
  std::vector<int> cluster_tracks_;
  std::vector<std::size_t> taken_;  // scratch: the clusters an update tracks
  std::vector<Cluster> refitted_;   // scratch: an update's clusters, occluded ones refitted
  double time_;
  int next_id_ = 0;
};

}  // namespace fgdwa
