// segment_scan: breakpoint clustering of a scan's hits and the disc and box
// fitted to each cluster.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <limits>
#include <string>

#include "fgdwa/tracking.hpp"
#include "radial.hpp"
#include "validation.hpp"

namespace fgdwa {

void SegmentParams::check_relations(const ParamPath& path) const {
  if (min_radius > 0.5 * max_size)
    fail_param(path.field("min_radius"), detail::format_number(min_radius), "must be <= max_size / 2 (m)");
}

void Cluster::validate(const std::string& name) const {
  detail::require_query_point(name + " center", center);
  detail::require_distance(name + " radius", radius);
  for (const Vec2& p : points)
    if (!p.allFinite()) throw Error(name + " points: must be finite");
}

namespace {

OrientedBox principal_box(const std::vector<Vec2>& points) {
  Vec2 mean = Vec2::Zero();
  for (const Vec2& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const Vec2& p : points) scatter += (p - mean) * (p - mean).transpose();
  // Major axis angle of a symmetric 2x2 matrix, in closed form.
  const double angle = 0.5 * std::atan2(2.0 * scatter(0, 1), scatter(0, 0) - scatter(1, 1));
  const Vec2 major(std::cos(angle), std::sin(angle)), minor(-major.y(), major.x());
  Vec2 lo = Vec2::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Vec2& p : points) {
    const Vec2 q((p - mean).dot(major), (p - mean).dot(minor));
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const Vec2 mid = 0.5 * (lo + hi);
  return OrientedBox{mean + mid.x() * major + mid.y() * minor, 0.5 * (hi - lo), angle};
}

// Per-point columns fit_disc() reuses from cluster to cluster.
struct FitScratch {
  std::vector<double> px, py, reach, ux, uy;
  void resize(std::size_t m) {
    for (std::vector<double>* column : {&px, &py, &reach, &ux, &uy}) column->resize(m);
  }
};

// The disc of least squares distance to the hits, its radius pulled toward
// the one the cluster's angular width implies. The width pins the radius
// where the hits' curvature cannot (few hits, a far or flat-looking arc), so
// the fit never runs off; with many hits the hits decide. Fitting the centre
// rather than taking the centroid keeps it in place as the viewpoint moves.
void fit_disc(Cluster& cluster, const Vec2& origin, double increment, const SegmentParams& params, FitScratch& scratch) {
  const std::vector<Vec2>& points = cluster.points;
  const double max_radius = 0.5 * params.max_size;
  Vec2 centroid = Vec2::Zero();
  for (const Vec2& p : points) centroid += p;
  centroid /= static_cast<double>(points.size());
  const Vec2 ray = centroid - origin;
  const double distance = ray.norm();
  const Vec2 along = distance > 0.0 ? Vec2(ray / distance) : Vec2(1.0, 0.0);

  // A disc of radius r at distance D spans 2 asin(r / D) of bearing, and its
  // nearest point lies at D - r. The outermost beams fall on average half an
  // increment inside its edges.
  const double heading = std::atan2(along.y(), along.x());
  double lo = 0.0, hi = 0.0, nearest = std::numeric_limits<double>::infinity();
  for (const Vec2& p : points) {
    const Vec2 d = p - origin;
    const double bearing = angle_difference(std::atan2(d.y(), d.x()), heading);
    lo = std::min(lo, bearing);
    hi = std::max(hi, bearing);
    nearest = std::min(nearest, d.norm());
  }
  const double s = std::sin(std::min(0.5 * (hi - lo + increment), 1.2));
  const double apparent = std::clamp(nearest * s / (1.0 - s), params.min_radius, max_radius);
  // How far the apparent radius may be off: a beam's spread at that range.
  const double apparent_std = 0.5 * distance * increment + 0.02;

  // Gauss-Newton on (cx, cy, r), started from the centroid pushed back along
  // the ray by the mean depth of a visible half circle (2 / pi of its radius).
  Eigen::Vector3d x(centroid.x() + 0.64 * apparent * along.x(), centroid.y() + 0.64 * apparent * along.y(),
                    apparent);
  const double w_point = 1.0 / (params.range_noise * params.range_noise);
  const double w_prior = 1.0 / (apparent_std * apparent_std);
  // Each point's distance to the centre and the unit vector toward it come
  // first, all together: the square roots and divisions, most of the cost,
  // then run several to a vector.
  const std::size_t m = points.size();
  scratch.resize(m);
  for (std::size_t i = 0; i < m; ++i) {
    scratch.px[i] = points[i].x();
    scratch.py[i] = points[i].y();
  }
  for (int iteration = 0; iteration < 20; ++iteration) {
    detail::radial(scratch.px.data(), scratch.py.data(), m, x[0], x[1], 1e-9, scratch.reach.data(), scratch.ux.data(),
                   scratch.uy.data());
    // normal += w J J^T and gradient += w J (reach - r), J = (-ux, -uy, -1),
    // term by term in plain doubles: Eigen's 3 x 3 sums went through the
    // stack, each load waiting on stores it could not be forwarded from.
    // The lower triangle alone, the one the LDLT reads.
    double n00 = 0.0, n10 = 0.0, n11 = 0.0, n20 = 0.0, n21 = 0.0, n22 = 0.0;
    double g0 = 0.0, g1 = 0.0, g2 = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
      const double j0 = -scratch.ux[i], j1 = -scratch.uy[i], j2 = -1.0;
      const double w0 = w_point * j0, w1 = w_point * j1, w2 = w_point * j2;
      n00 += j0 * w0;
      n10 += j0 * w1, n11 += j1 * w1;
      n20 += j0 * w2, n21 += j1 * w2, n22 += j2 * w2;
      const double residual = scratch.reach[i] - x[2];
      g0 += w0 * residual, g1 += w1 * residual, g2 += w2 * residual;
    }
    Eigen::Matrix3d normal;
    normal << n00, n10, n20, n10, n11, n21, n20, n21, n22;
    Eigen::Vector3d gradient(g0, g1, g2);
    normal(2, 2) += w_prior;
    gradient[2] += w_prior * (x[2] - apparent);
    const Eigen::Vector3d step = normal.ldlt().solve(-gradient);
    if (!step.allFinite()) break;
    x += step;
    x[2] = std::clamp(x[2], params.min_radius, max_radius);
    if (step.cwiseAbs().maxCoeff() < 1e-6) break;
  }
  const Vec2 fitted(x[0], x[1]);
  // A centre nearer the sensor than the hits would be a hollow; keep it behind.
  // Hits on a flat or nearly straight run can drive the fit far off along the
  // normal (the radius is clamped, the centre is not): a centre farther from
  // the hits than the disc can reach is no fit.
  if (fitted.allFinite() && (fitted - origin).dot(along) >= distance &&
      (fitted - centroid).norm() <= x[2] + max_radius) {
    cluster.center = fitted;
    cluster.radius = x[2];
  } else {
    cluster.center = centroid + 0.64 * apparent * along;
    cluster.radius = apparent;
  }
}

// The hit at which to cut `points` (in beam order, counterclockwise about the
// sensor and within half a turn of it), 0 for none. An object's near side
// is convex toward the sensor; where two side by side meet, the hits fall
// back behind the near side of the whole run (the chain of hits no hit lies
// in front of). The cut goes at the deepest hit whose deeper neighbour lies
// more than `threshold` (m) behind as well: two hits, so that noise on one
// cannot cut a wall.
struct NotchScratch {
  std::vector<std::size_t> hull;
  std::vector<double> depth;
};
std::size_t deepest_notch(const std::vector<Vec2>& points, double threshold, NotchScratch& scratch) {
  const std::size_t m = points.size();
  if (m < 5) return 0;
  const auto cross = [](const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); };
  // The near side: a hit stays on it while it lies in front of (on the
  // sensor's side of) the line from the one before it to the next hit.
  std::vector<std::size_t>& hull = scratch.hull;
  std::vector<double>& depth = scratch.depth;
  hull.clear();
  for (std::size_t i = 0; i < m; ++i) {
    while (hull.size() >= 2) {
      const Vec2& a = points[hull[hull.size() - 2]];
      if (cross(points[i] - a, points[hull.back()] - a) > 0.0) break;
      hull.pop_back();
    }
    hull.push_back(i);
  }
  depth.assign(m, 0.0);
  for (std::size_t h = 0; h + 1 < hull.size(); ++h) {
    const Vec2& a = points[hull[h]];
    const Vec2 edge = points[hull[h + 1]] - a;
    const double length = edge.norm();
    if (length <= 0.0) continue;
    for (std::size_t j = hull[h] + 1; j < hull[h + 1]; ++j) depth[j] = -cross(edge, points[j] - a) / length;
  }
  std::size_t best = 0;
  double best_depth = threshold;
  for (std::size_t j = 1; j + 1 < m; ++j) {
    const double supported = std::min(depth[j], std::max(depth[j - 1], depth[j + 1]));
    if (supported > best_depth) best = j, best_depth = supported;
  }
  return best;
}

// The `count` clusters nearest `origin` (by their centres; ties to the lower
// beam), still in beam order.
std::vector<Cluster> nearest_clusters(std::vector<Cluster> clusters, const Vec2& origin, std::size_t count) {
  if (clusters.size() <= count) return clusters;
  std::vector<std::size_t> order(clusters.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto nearer = [&](std::size_t a, std::size_t b) {
    const double da = (clusters[a].center - origin).squaredNorm(), db = (clusters[b].center - origin).squaredNorm();
    return da < db || (da == db && a < b);
  };
  std::nth_element(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(count), order.end(), nearer);
  order.resize(count);
  std::sort(order.begin(), order.end());
  std::vector<Cluster> nearest;
  nearest.reserve(count);
  for (const std::size_t i : order) nearest.push_back(std::move(clusters[i]));
  return nearest;
}

}  // namespace

std::vector<Cluster> segment_scan(const Scan& scan, const SegmentParams& params,
                                  const std::vector<std::uint8_t>* mask) {
  detail::require_non_negative("scan angle_increment", scan.angle_increment);
  return segment_scan(ScanFrame(scan), params, mask);
}

std::vector<Cluster> segment_scan(const ScanFrame& frame, const SegmentParams& params,
                                  const std::vector<std::uint8_t>* mask) {
  params.validate();
  const Scan& scan = frame.scan();
  detail::require_non_negative("scan angle_increment", scan.angle_increment);
  const std::size_t n = scan.ranges.size();
  if (mask && mask->size() != n)
    throw Error(detail::describe("segment mask size", mask->size(), "must equal the scan's " + std::to_string(n) + " beams"));

  const Vec2 origin = scan.pose.position();
  std::vector<Cluster> clusters;
  std::vector<std::vector<int>> beams;  // each cluster's hits' beam indices
  Cluster current;
  std::vector<int> current_beams;
  double previous_range = 0.0;
  const auto close = [&]() {
    if (!current.points.empty()) {
      clusters.push_back(std::move(current));
      beams.push_back(std::move(current_beams));
    }
    current = Cluster{};
    current_beams.clear();
  };
  for (std::size_t i = 0; i < n; ++i) {
    const double r = scan.ranges[i];
    if (!std::isfinite(r) || (mask && (*mask)[i] == 0)) continue;
    const Vec2& p = frame.beam_hits()[i];
    if (!current.points.empty() &&
        (p - current.points.back()).norm() > params.base_gap + params.range_gap_factor * std::max(r, previous_range))
      close();
    current.points.push_back(p);
    current_beams.push_back(static_cast<int>(i));
    previous_range = r;
  }
  close();

  // A full circle's last beam neighbours its first: one object across the seam.
  const bool full_circle = scan.angle_increment * static_cast<double>(n) >= 2.0 * M_PI - 1e-9;
  if (clusters.size() > 1 && full_circle) {
    Cluster& first = clusters.front();
    Cluster& last = clusters.back();
    const double range_first = (first.points.front() - origin).norm(), range_last = (last.points.back() - origin).norm();
    if ((first.points.front() - last.points.back()).norm() <=
        params.base_gap + params.range_gap_factor * std::max(range_first, range_last)) {
      last.points.insert(last.points.end(), first.points.begin(), first.points.end());
      beams.back().insert(beams.back().end(), beams.front().begin(), beams.front().end());
      clusters.erase(clusters.begin());
      beams.erase(beams.begin());
    }
  }

  // Whether the beam beside `beam` (step -1 or +1) hides what lies beyond an
  // end at `range`: it hit something nearer, or there is no such beam.
  const auto hides = [&](int beam, int step, double range) {
    int next = beam + step;
    if (next < 0 || next >= static_cast<int>(n)) {
      if (!full_circle) return true;
      next = (next + static_cast<int>(n)) % static_cast<int>(n);
    }
    return scan.ranges[static_cast<std::size_t>(next)] < range;
  };
  // Clusters cut at their notches: each piece's beams, and whether a cut
  // bounds it before its first hit or after its last.
  struct Piece {
    Cluster cluster;
    std::vector<int> beams;
    bool cut_before = false, cut_after = false;
  };
  std::vector<Piece> pieces, work;
  NotchScratch notch;
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    work.push_back(Piece{std::move(clusters[k]), std::move(beams[k])});
    while (!work.empty()) {
      Piece piece = std::move(work.back());
      work.pop_back();
      const std::vector<int>& b = piece.beams;
      const int span = (b.back() - b.front() + static_cast<int>(n)) % static_cast<int>(n);
      const std::size_t cut = static_cast<double>(span) * scan.angle_increment < M_PI
                                  ? deepest_notch(piece.cluster.points, params.notch_depth, notch)
                                  : 0;
      if (cut == 0) {
        pieces.push_back(std::move(piece));
        continue;
      }
      // The notch's hit belongs to neither side.
      Piece before, after;
      before.cluster.points.assign(piece.cluster.points.begin(), piece.cluster.points.begin() + static_cast<std::ptrdiff_t>(cut));
      before.beams.assign(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(cut));
      after.cluster.points.assign(piece.cluster.points.begin() + static_cast<std::ptrdiff_t>(cut) + 1, piece.cluster.points.end());
      after.beams.assign(b.begin() + static_cast<std::ptrdiff_t>(cut) + 1, b.end());
      before.cut_before = piece.cut_before, before.cut_after = true;
      after.cut_before = true, after.cut_after = piece.cut_after;
      work.push_back(std::move(after));
      work.push_back(std::move(before));
    }
  }
  std::vector<Cluster> kept;
  FitScratch scratch;
  for (Piece& piece : pieces) {
    Cluster& c = piece.cluster;
    if (static_cast<int>(c.points.size()) < params.min_points) continue;
    c.first_beam = piece.beams.front();
    c.last_beam = piece.beams.back();
    c.occluded = piece.cut_before || piece.cut_after || hides(c.first_beam, -1, (c.points.front() - origin).norm()) ||
                 hides(c.last_beam, +1, (c.points.back() - origin).norm());
    c.box = principal_box(c.points);
    if (2.0 * c.box.half_extents.maxCoeff() > params.max_size) continue;
    fit_disc(c, origin, scan.angle_increment, params, scratch);
    kept.push_back(std::move(c));
  }
  return nearest_clusters(std::move(kept), origin, static_cast<std::size_t>(params.max_clusters));
}

}  // namespace fgdwa
