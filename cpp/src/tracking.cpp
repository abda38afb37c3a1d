// Tracker: constant-velocity Kalman tracks of the clusters' disc centres.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "assignment.hpp"
#include "fgdwa/tracking.hpp"
#include "validation.hpp"

namespace fgdwa {

const char* to_string(TrackStatus status) {
  switch (status) {
    case TrackStatus::Tentative: return "tentative";
    case TrackStatus::Confirmed: return "confirmed";
    case TrackStatus::Lost: return "lost";
  }
  return "?";
}

namespace {

// Largest eigenvalue of a symmetric 2x2 matrix.
double largest_eigenvalue(const Eigen::Matrix2d& m) {
  const double mean = 0.5 * (m(0, 0) + m(1, 1)), half = 0.5 * (m(0, 0) - m(1, 1));
  return mean + std::sqrt(half * half + m(0, 1) * m(0, 1));
}

// Weight of a new cluster's radius in a track's: radii of near-side fits
// wobble with the viewpoint, so a track averages them.
constexpr double kRadiusSmoothing = 0.3;
// Std devs of measurement noise a cluster may lie beyond the reach of
// max_speed before the association is rejected.
constexpr double kSpeedCheckSigmas = 3.0;
// How much less an occluded cluster's centre is trusted (std factor): its
// disc was fitted to part of the object.
constexpr double kOccludedStdFactor = 4.0;
// Free-space evidence: a cluster displaces free space when at least this
// share of its hits (and two) lie where the other scan saw through, and a
// track may be labelled moving after this many such updates within its
// window, so one stray reading does not do it.
constexpr double kDisplacedShare = 0.2;
constexpr std::size_t kDisplacedUpdates = 3;
// Std devs of a hit's range noise the other scan's beams must have seen
// through it by, across their lines of sight.
constexpr double kLateralSigmas = 2.0;
// Earlier scans the leading side is tested against: half a moving_window
// back, a quarter, an eighth, ... this many in all.
constexpr int kLeadingLags = 4;
// Std devs by which the prediction window's slope must depart from the moving
// window's before the prediction takes it.
constexpr double kChangeSigmas = 1.0;

// Whether `scan` saw through `p`: every beam passing within `lateral` (m)
// of p, and at least its own and both neighbours, reached more than `margin`
// past it (or had no hit within max range, which lies beyond). The
// neighbours count because two scans' beams do not line up.
bool seen_through(const Scan& scan, const Vec2& p, double margin, double lateral = 0.0) {
  if (!(scan.angle_increment > 0.0)) return false;
  const Vec2 d = p - scan.pose.position();
  const double range = d.norm();
  const double reach = range + margin;
  double offset = angle_difference(std::atan2(d.y(), d.x()), scan.pose.theta) - scan.angle_min;
  if (offset < 0.0) offset += 2.0 * M_PI;
  const long beam = std::lround(offset / scan.angle_increment);
  const long n = static_cast<long>(scan.ranges.size());
  const double band = range > lateral ? std::asin(lateral / range) : M_PI;
  const long half = std::max(1L, static_cast<long>(std::ceil(band / scan.angle_increment)));
  if (beam - half < 0 || beam + half >= n) return false;
  for (long j = beam - half; j <= beam + half; ++j) {
    const double r = scan.ranges[static_cast<std::size_t>(j)];
    if (std::isfinite(r) ? r <= reach : reach >= scan.max_range) return false;
  }
  return true;
}

// How far a hit at `p` taken from `from`, with range noise `noise` along its
// own line of sight, may lie across the line of sight from `origin`: the
// noise times the sine of the angle between the two. A static face one scan
// saw edge-on is hit from the side by a later one, whose noisy hits lie
// beside the face, where the earlier beams grazed past.
double across_sight(const Vec2& origin, const Vec2& from, const Vec2& p, double noise) {
  const Vec2 d = p - origin, e = p - from;
  const double norms = d.norm() * e.norm();
  return norms > 1e-12 ? noise * std::abs(d.x() * e.y() - d.y() * e.x()) / norms : 0.0;
}

// Whether enough of `points` (hits taken from `from`, with range noise
// `noise`) lie where `scan` saw through.
bool share_seen_through(const Scan& scan, const std::vector<Vec2>& points, const Vec2& from, double margin,
                        double noise) {
  const Vec2 origin = scan.pose.position();
  std::size_t through = 0;
  for (const Vec2& p : points) through += seen_through(scan, p, margin, across_sight(origin, from, p, noise));
  return through >= 2 && static_cast<double>(through) >= kDisplacedShare * static_cast<double>(points.size());
}

// The centre of a circle of `radius` through `points`, by Gauss-Newton from
// `centre`: a partly hidden disc's own fit takes the arc it sees for the whole
// object, its radius too small and its centre pulled toward the hits. Damped,
// so that an arc too short to fix the centre along it leaves it near where it began.
Vec2 fixed_radius_centre(const std::vector<Vec2>& points, double radius, Vec2 centre) {
  const double damping = 1e-3 * static_cast<double>(points.size());
  for (int iteration = 0; iteration < 10; ++iteration) {
    Eigen::Matrix2d normal = damping * Eigen::Matrix2d::Identity();
    Vec2 rhs = Vec2::Zero();
    for (const Vec2& p : points) {
      const Vec2 d = p - centre;
      const double reach = d.norm();
      if (!(reach > 1e-9)) continue;
      const Vec2 u = d / reach;
      normal += u * u.transpose();
      rhs += u * (reach - radius);
    }
    const Vec2 step = normal.ldlt().solve(rhs);
    if (!step.allFinite()) break;
    centre += step;
    if (step.cwiseAbs().maxCoeff() < 1e-5) break;
  }
  return centre;
}

}  // namespace

double Track::position_std() const {
  return std::sqrt(std::max(largest_eigenvalue(covariance.topLeftCorner<2, 2>()), 0.0));
}

double Track::speed_std() const {
  const Eigen::Matrix2d p = covariance.bottomRightCorner<2, 2>();
  const double speed = velocity.norm();
  if (speed < 1e-9) return std::sqrt(std::max(largest_eigenvalue(p), 0.0));
  const Vec2 u = velocity / speed;
  return std::sqrt(std::max(u.dot(p * u), 0.0));
}

Tracker::Tracker(const TrackerParams& params)
    : params_(params), time_(std::numeric_limits<double>::quiet_NaN()) {
  params_.validate();
}

void Tracker::reset() {
  tracks_.clear();
  memory_.clear();
  scans_.clear();
  has_scans_ = false;
  cluster_tracks_.clear();
  time_ = std::numeric_limits<double>::quiet_NaN();
}

void Tracker::predict(double dt) {
  if (dt <= 0.0) return;
  Eigen::Matrix4d F = Eigen::Matrix4d::Identity();
  F(0, 2) = F(1, 3) = dt;
  // Discrete white-noise acceleration.
  const double q = params_.accel_std * params_.accel_std;
  Eigen::Matrix4d Q = Eigen::Matrix4d::Zero();
  Q.topLeftCorner<2, 2>() = Eigen::Matrix2d::Identity() * (0.25 * dt * dt * dt * dt * q);
  Q.topRightCorner<2, 2>() = Q.bottomLeftCorner<2, 2>() = Eigen::Matrix2d::Identity() * (0.5 * dt * dt * dt * q);
  Q.bottomRightCorner<2, 2>() = Eigen::Matrix2d::Identity() * (dt * dt * q);
  for (Track& t : tracks_) {
    t.position += dt * t.velocity;
    t.covariance = F * t.covariance * F.transpose() + Q;
    t.age += dt;
  }
}

double Tracker::measurement_variance(const Cluster& cluster) const {
  const double std = params_.measurement_std * (cluster.occluded ? kOccludedStdFactor : 1.0);
  return std * std;
}

void Tracker::correct(Track& t, const Cluster& cluster, double time) {
  const double r2 = measurement_variance(cluster);
  const Eigen::Matrix2d S = t.covariance.topLeftCorner<2, 2>() + r2 * Eigen::Matrix2d::Identity();
  const Eigen::Matrix<double, 4, 2> K = t.covariance.leftCols<2>() * S.inverse();
  const Vec2 innovation = cluster.center - t.position;
  Eigen::Vector4d x;
  x << t.position, t.velocity;
  x += K * innovation;
  t.position = x.head<2>();
  t.velocity = x.tail<2>();
  // Joseph form: stays symmetric and positive under rounding.
  Eigen::Matrix<double, 2, 4> H = Eigen::Matrix<double, 2, 4>::Zero();
  H(0, 0) = H(1, 1) = 1.0;
  const Eigen::Matrix4d I_KH = Eigen::Matrix4d::Identity() - K * H;
  t.covariance = I_KH * t.covariance * I_KH.transpose() + r2 * K * K.transpose();
  const double speed = t.velocity.norm();
  if (speed > params_.max_speed) t.velocity *= params_.max_speed / speed;
  // A partly hidden object's arc says little of its size.
  if (!cluster.occluded) t.radius += kRadiusSmoothing * (cluster.radius - t.radius);
  ++t.hits;
  t.last_seen = time;
  t.status = t.hits >= params_.confirm_hits ? TrackStatus::Confirmed : TrackStatus::Tentative;
}

// A track is labelled moving once its window speed, less moving_sigmas std
// devs, exceeds moving_speed and (given scans) its hits have displaced free
// space a few times within the window; it keeps the label until that speed
// drops below half of moving_speed. The window speed is a line fitted to a second of
// centres, its std from their own scatter (never below measurement_std): it
// does not hang on the filter's noise model, so static clutter whose centres
// wobble more than modelled is not called moving, and a mover's label does not
// flicker.
Tracker::LineFit Tracker::fit_line(const std::deque<Centre>& centres, double since) const {
  LineFit fit;
  // Weighted least squares; the weights are relative to an unoccluded centre,
  // whose std the scatter estimates.
  double w_sum = 0.0, t_mean = 0.0;
  Vec2 p_mean = Vec2::Zero();
  std::size_t n = 0;
  for (const Centre& c : centres) {
    if (c.time < since) continue;
    w_sum += c.weight, t_mean += c.weight * c.time, p_mean += c.weight * c.position;
    ++n;
  }
  if (n < 3) return fit;
  t_mean /= w_sum;
  p_mean /= w_sum;
  double stt = 0.0;
  Vec2 stp = Vec2::Zero();
  for (const Centre& c : centres) {
    if (c.time < since) continue;
    stt += c.weight * (c.time - t_mean) * (c.time - t_mean);
    stp += c.weight * (c.time - t_mean) * (c.position - p_mean);
  }
  if (!(stt > 0.0)) return fit;
  fit.velocity = stp / stt;
  double scatter = 0.0;
  for (const Centre& c : centres)
    if (c.time >= since) scatter += c.weight * (c.position - p_mean - (c.time - t_mean) * fit.velocity).squaredNorm();
  // Two coordinates per centre, two parameters fitted per coordinate.
  const double dof = 2.0 * (static_cast<double>(n) - 2.0);
  const double point_std = std::max(std::sqrt(scatter * static_cast<double>(n) / (w_sum * dof)), params_.measurement_std);
  fit.speed_std = point_std / std::sqrt(stt);
  return fit;
}

// Weighted least squares of p(tau) = p0 + v tau + a tau^2 / 2, tau the time
// since the newest centre: the acceleration's std from the scatter (never
// below measurement_std), as the line's.
Tracker::ParabolaFit Tracker::fit_parabola(const std::deque<Centre>& centres) const {
  ParabolaFit fit;
  if (centres.size() < 4) return fit;
  const double newest = centres.back().time;
  Eigen::Matrix3d normal = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> rhs = Eigen::Matrix<double, 3, 2>::Zero();
  double w_sum = 0.0;
  for (const Centre& c : centres) {
    const double tau = c.time - newest;
    const Eigen::Vector3d basis(1.0, tau, 0.5 * tau * tau);
    normal += c.weight * basis * basis.transpose();
    rhs += c.weight * basis * c.position.transpose();
    w_sum += c.weight;
  }
  const Eigen::LDLT<Eigen::Matrix3d> solver(normal);
  if (solver.info() != Eigen::Success || !(solver.rcond() > 1e-12)) return fit;
  const Eigen::Matrix<double, 3, 2> coefficients = solver.solve(rhs);
  double scatter = 0.0;
  for (const Centre& c : centres) {
    const double tau = c.time - newest;
    const Eigen::Vector3d basis(1.0, tau, 0.5 * tau * tau);
    scatter += c.weight * (c.position.transpose() - basis.transpose() * coefficients).squaredNorm();
  }
  // Two coordinates per centre, three parameters fitted per coordinate.
  const double n = static_cast<double>(centres.size());
  const double point_std = std::max(std::sqrt(scatter * n / (w_sum * 2.0 * (n - 3.0))), params_.measurement_std);
  const Eigen::Matrix3d inverse = solver.solve(Eigen::Matrix3d::Identity());
  fit.velocity = coefficients.row(1).transpose();
  fit.acceleration = coefficients.row(2).transpose();
  fit.acceleration_std = point_std * std::sqrt(std::max(inverse(2, 2), 0.0));
  return fit;
}

void Tracker::relabel(Track& t, const Memory& memory) const {
  const double newest = memory.centres.empty() ? 0.0 : memory.centres.back().time;
  const LineFit window = fit_line(memory.centres, -std::numeric_limits<double>::infinity());
  t.window_velocity = window.velocity;
  t.window_speed_std = window.speed_std;
  // The centres kept go back one moving_window: a longer prediction window is that one.
  const LineFit recent = fit_line(memory.centres, newest - params_.prediction_window - 1e-9);
  // The recent centres' slope where it departs from the window's by more than
  // their noise (a turn, a reversal, a change of pace); the whole window's,
  // steadier, where it does not (a mover going straight, a static object the
  // noise once labelled moving).
  const bool changed = std::isfinite(recent.speed_std) &&
                       (recent.velocity - window.velocity).norm() >
                           kChangeSigmas * std::hypot(recent.speed_std, window.speed_std);
  t.predicted_velocity = changed ? recent.velocity : window.velocity;
  // Only the second prediction reads the parabola: without it, no fit each update.
  if (params_.hypothesis_time > 0.0) {
    const ParabolaFit parabola = fit_parabola(memory.centres);
    t.current_velocity = parabola.velocity;
    t.acceleration = parabola.acceleration;
    t.acceleration_std = parabola.acceleration_std;
  }
  if (t.status == TrackStatus::Tentative) {
    t.moving = false;
    return;
  }
  if (t.status == TrackStatus::Lost) return;
  const double speed = t.window_velocity.norm();
  const bool fast = speed >= 0.5 * params_.moving_speed;
  if (!t.moving) {
    t.moving = speed - params_.moving_sigmas * t.window_speed_std > params_.moving_speed &&
               (!has_scans_ || memory.displaced.size() >= kDisplacedUpdates);
    if (t.moving) t.moving_since = t.last_fast = newest;
    return;
  }
  // Held only by a label earned over a whole window: noise that once passed
  // for motion does not stand as a mover for moving_hold more.
  const bool earned = t.last_fast - t.moving_since >= params_.moving_window - 1e-9;
  t.moving = fast || (earned && newest - t.last_fast < params_.moving_hold - 1e-9);
  if (fast) t.last_fast = newest;
}

// The newest of `items` (time-ordered pairs) at least `age` old (s). Until
// one is that old, the oldest before `time`: a fast mover leaves the
// free_margin behind within a scan or two, and waiting longer would leave it
// a static obstacle for that long.
template <class Item>
const Item* Tracker::reference_of(const std::deque<std::pair<double, Item>>& items, double time, double age) const {
  const Item* reference = nullptr;
  for (const auto& [t, item] : items) {
    if (t > time - age + 1e-9) {
      if (!reference && t < time - 1e-9) reference = &item;
      break;
    }
    reference = &item;
  }
  return reference;
}

bool Tracker::displaces_free_space(const Memory& memory, const Cluster& cluster, const Scan& scan,
                                   double time) const {
  // Its leading side where an earlier scan saw through: half a window back
  // (a slow mover needs that long to leave the free_margin behind), or a
  // quarter, an eighth, a sixteenth (a fast one does so sooner, and one that
  // just came out from behind something or out of the field of view was not
  // seen where it is now half a window ago) ...
  const double noise = kLateralSigmas * params_.measurement_std;
  const Scan* tested = nullptr;
  for (int halving = 1; halving <= kLeadingLags; ++halving) {
    const Scan* earlier = reference_of(scans_, time, params_.moving_window / static_cast<double>(1 << halving));
    if (!earlier || earlier == tested) continue;
    tested = earlier;
    if (share_seen_through(*earlier, cluster.points, scan.pose.position(), params_.free_margin, noise)) return true;
  }
  // ... or its trailing side, as seen half a window back, where this scan sees through.
  const Shape* before = reference_of(memory.shapes, time, 0.5 * params_.moving_window);
  return before && share_seen_through(scan, before->points, before->from, params_.free_margin, noise);
}

// An occluded cluster that a known track's disc may explain is refitted with
// that track's radius (the larger of the two), the centre kept behind the
// hits and within the radius of the cluster's own: what the gate, the filter
// and the velocity fits then read is the object's centre, not the visible
// arc's.
const std::vector<Cluster>& Tracker::refit_occluded(const std::vector<Cluster>& clusters, const Scan* scan) {
  if (!scan) return clusters;
  const Vec2 origin = scan->pose.position();
  bool any = false;
  for (std::size_t c = 0; c < clusters.size(); ++c) {
    const Cluster& cluster = clusters[c];
    if (!cluster.occluded) continue;
    const Track* owner = nullptr;
    double nearest = params_.gate;
    for (const Track& t : tracks_) {
      if (t.status == TrackStatus::Tentative) continue;
      const double d = (t.position - cluster.center).norm();
      if (d <= nearest) nearest = d, owner = &t;
    }
    if (!owner || owner->radius <= cluster.radius) continue;
    const Vec2 centre = fixed_radius_centre(cluster.points, owner->radius, cluster.center);
    Vec2 mean = Vec2::Zero();
    for (const Vec2& p : cluster.points) mean += p;
    mean /= static_cast<double>(cluster.points.size());
    if (!((centre - cluster.center).norm() <= owner->radius) ||
        (centre - origin).norm() <= (mean - origin).norm())
      continue;
    if (!any) refitted_ = clusters;
    any = true;
    refitted_[c].center = centre;
    refitted_[c].radius = owner->radius;
  }
  return any ? refitted_ : clusters;
}

void Tracker::update(const std::vector<Cluster>& given, double time, const Scan* scan) {
  detail::require_finite("tracker time", time);
  if (time < time_)
    throw Error(detail::describe("tracker time", time, "must not be before the last update's " + std::to_string(time_)));
  for (std::size_t i = 0; i < given.size(); ++i) given[i].validate("cluster[" + std::to_string(i) + "]");
  if (scan) {
    detail::require_finite("scan pose x", scan->pose.x);
    detail::require_finite("scan pose y", scan->pose.y);
    detail::require_finite("scan pose theta", scan->pose.theta);
    for (double r : scan->ranges)
      if (std::isnan(r)) throw Error("scan ranges: must not be NaN");
  }
  predict(std::isnan(time_) ? 0.0 : time - time_);
  time_ = time;
  const std::vector<Cluster>& clusters = refit_occluded(given, scan);
  // Occluded centres weigh less in the moving test: a partly hidden object's
  // centre shifts as it is uncovered.
  if (scan) has_scans_ = true;
  const double oldest = time - params_.moving_window - 1e-9;
  const auto remember = [&](Memory& memory, Track& track, const Cluster& cluster) {
    memory.seen_position = track.position;
    memory.centres.push_back(
        Centre{time, cluster.center, cluster.occluded ? 1.0 / (kOccludedStdFactor * kOccludedStdFactor) : 1.0});
    if (scan) {
      if (displaces_free_space(memory, cluster, *scan, time)) memory.displaced.push_back(time);
      memory.shapes.emplace_back(time, Shape{scan->pose.position(), cluster.points});
    }
    while (!memory.centres.empty() && memory.centres.front().time < oldest) memory.centres.pop_front();
    while (!memory.shapes.empty() && memory.shapes.front().first < oldest) memory.shapes.pop_front();
    while (!memory.displaced.empty() && memory.displaced.front() < oldest) memory.displaced.pop_front();
    relabel(track, memory);
  };

  // Past max_clusters, the nearest to the scanner (association is cubic in
  // the count); the others are left to the scan's points this update.
  std::vector<std::size_t>& taken = taken_;
  taken.resize(clusters.size());
  std::iota(taken.begin(), taken.end(), std::size_t{0});
  const auto limit = static_cast<std::size_t>(params_.max_clusters);
  if (taken.size() > limit) {
    const Vec2 from = scan ? Vec2(scan->pose.x, scan->pose.y) : Vec2::Zero();
    std::nth_element(taken.begin(), taken.begin() + static_cast<std::ptrdiff_t>(limit), taken.end(),
                     [&](std::size_t a, std::size_t b) {
                       return (clusters[a].center - from).squaredNorm() < (clusters[b].center - from).squaredNorm();
                     });
    taken.resize(limit);
    std::sort(taken.begin(), taken.end());
  }
  // Confirmed and lost tracks choose first, so a tentative track born of a
  // stray cluster cannot take a known object's cluster.
  cluster_tracks_.assign(clusters.size(), -1);
  const double gate2 = params_.gate_sigmas * params_.gate_sigmas;
  for (const bool tentative : {false, true}) {
    std::vector<std::size_t> rows, cols;
    for (std::size_t t = 0; t < tracks_.size(); ++t)
      if ((tracks_[t].status == TrackStatus::Tentative) == tentative) rows.push_back(t);
    for (const std::size_t c : taken)
      if (cluster_tracks_[c] < 0) cols.push_back(c);
    if (rows.empty() || cols.empty()) continue;
    Eigen::MatrixXd cost(rows.size(), cols.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const Track& t = tracks_[rows[i]];
      for (std::size_t j = 0; j < cols.size(); ++j) {
        const Cluster& cluster = clusters[cols[j]];
        const double r2 = measurement_variance(cluster);
        const Eigen::Matrix2d S = t.covariance.topLeftCorner<2, 2>() + r2 * Eigen::Matrix2d::Identity();
        const double reach = params_.max_speed * (time - t.last_seen) + kSpeedCheckSigmas * std::sqrt(r2);
        const Vec2& z = cluster.center;
        const Vec2 innovation = z - t.position;
        const double d2 = innovation.dot(S.inverse() * innovation);
        const bool allowed = innovation.norm() <= params_.gate && d2 <= gate2 &&
                             (z - memory_[rows[i]].seen_position).norm() <= reach;
        cost(i, j) = allowed ? d2 : std::numeric_limits<double>::infinity();
      }
    }
    const std::vector<int> chosen = detail::assign(cost, std::vector<double>(rows.size(), gate2));
    for (std::size_t i = 0; i < rows.size(); ++i) {
      if (chosen[i] < 0) continue;
      const std::size_t c = cols[static_cast<std::size_t>(chosen[i])];
      correct(tracks_[rows[i]], clusters[c], time);
      remember(memory_[rows[i]], tracks_[rows[i]], clusters[c]);
      cluster_tracks_[c] = tracks_[rows[i]].id;
    }
  }

  for (const std::size_t c : taken) {
    if (cluster_tracks_[c] >= 0) continue;
    if (tracks_.size() >= 2 * limit) break;  // a scene of clutter: no more tentative tracks this update
    Track t;
    t.id = next_id_++;
    t.position = clusters[c].center;
    t.radius = clusters[c].radius;
    // Nothing is known of the velocity yet but that it is below max_speed.
    const double v_std = 0.5 * params_.max_speed;
    const double p2 = measurement_variance(clusters[c]);
    t.covariance = Eigen::Vector4d(p2, p2, v_std * v_std, v_std * v_std).asDiagonal();
    t.hits = 1;
    t.last_seen = time;
    if (t.hits >= params_.confirm_hits) t.status = TrackStatus::Confirmed;
    cluster_tracks_[c] = t.id;
    memory_.emplace_back();
    remember(memory_.back(), t, clusters[c]);
    tracks_.push_back(t);
  }

  std::size_t kept = 0;
  for (std::size_t i = 0; i < tracks_.size(); ++i) {
    Track& t = tracks_[i];
    const double unseen = time - t.last_seen;
    if (unseen > 2.0 * params_.lost_time) continue;
    // A track this scan missed, whose predicted centre it saw through, is not
    // where it was predicted: kept, it would stand as a phantom for up to
    // 2 lost_time (the object, if near, has started a track of its own).
    if (unseen > 0.0 && scan && seen_through(*scan, t.position, params_.free_margin)) continue;
    if (unseen > params_.lost_time) t.status = TrackStatus::Lost;
    if (kept != i) {
      tracks_[kept] = std::move(t);
      memory_[kept] = std::move(memory_[i]);
    }
    ++kept;
  }
  tracks_.resize(kept);
  memory_.resize(kept);
  if (scan) {
    scans_.emplace_back(time, *scan);
    while (scans_.front().first < oldest) scans_.pop_front();
  }
}

std::vector<Disc> Tracker::moving_discs() const {
  std::vector<Disc> discs;
  for (const Track& t : tracks_) {
    if (!t.moving || t.status == TrackStatus::Tentative) continue;
    // Predicted with the velocity of the recent centres, steadier than the
    // filter's estimate of where it is heading and sooner through a turn than
    // the label's longer window; spreading with the filter's speed uncertainty, which holds the
    // model's acceleration noise: how far a turn or a reversal may take it
    // from the line. The window fit's own std says only how well the past
    // second's mean velocity is known, a tenth of that or less.
    const Disc steady{t.position,
                      t.radius + std::min(params_.uncertainty_sigmas * t.position_std(), params_.max_uncertainty),
                      t.predicted_velocity, params_.uncertainty_sigmas * t.speed_std()};
    discs.push_back(steady);
    // The second hypothesis, where the track's centres bend or slow with
    // confidence: a mover that turned or braked over the last second is
    // likelier to go on doing so than to straighten at once.
    const double a = t.acceleration.norm();
    if (params_.hypothesis_time > 0.0 && std::isfinite(t.acceleration_std) &&
        a - params_.acceleration_sigmas * t.acceleration_std > 0.0) {
      Disc bending = steady;
      const double v = t.current_velocity.norm();
      bending.velocity = v > params_.max_speed ? t.current_velocity * (params_.max_speed / v) : t.current_velocity;
      bending.acceleration = t.acceleration * (std::min(a, params_.max_acceleration) / a);
      bending.accel_time = params_.hypothesis_time;
      discs.push_back(bending);
    }
  }
  return discs;
}

bool Tracker::explains(const Vec2& point, double margin) const {
  detail::require_finite("explains point x", point.x());
  detail::require_finite("explains point y", point.y());
  detail::require_non_negative("explains margin", margin);
  for (const Track& t : tracks_) {
    if (!t.moving || t.status != TrackStatus::Confirmed) continue;
    if ((point - t.position).norm() <=
        t.radius + std::min(params_.uncertainty_sigmas * t.position_std(), params_.max_uncertainty) + margin)
      return true;
  }
  return false;
}

}  // namespace fgdwa
