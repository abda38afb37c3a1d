#include "fgdwa/perception.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fgdwa/scan_frame.hpp"
#include "checked_scan.hpp"
#include "validation.hpp"

namespace fgdwa {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

void Scan::validate() const {
  detail::require_query_pose("scan pose", pose);
  detail::require_magnitude("scan angle_min", angle_min, 2.0 * M_PI);
  detail::require_magnitude("scan angle_increment", angle_increment, 2.0 * M_PI);
  detail::require_distance("scan max_range", max_range);
  if (ranges.size() > static_cast<std::size_t>(limits::kMaxBeams))
    throw Error(detail::describe("scan ranges", ranges.size(),
                                 "a scan has at most " + std::to_string(limits::kMaxBeams) + " beams"));
  // One pass without branches (a scan is checked several times a cycle), then
  // the first bad range named.
  const auto valid = [](double r) { return (r >= 0.0) & ((r <= limits::kMaxLength) | (r == kInf)); };
  bool all_valid = true;
  for (const double r : ranges) all_valid &= valid(r);
  if (all_valid) return;
  for (std::size_t i = 0; i < ranges.size(); ++i)
    if (!valid(ranges[i]))
      throw Error(detail::describe("scan ranges[" + std::to_string(i) + "]", ranges[i], "must lie in [0, " + detail::format_number(limits::kMaxLength) + "] (+inf: no hit)"));
}


std::vector<Vec2> Scan::hit_points() const {
  validate();
  std::vector<Vec2> points;
  for (std::size_t i = 0; i < ranges.size(); ++i)
    if (std::isfinite(ranges[i])) points.push_back(beam_hit(*this, i, beam_direction(*this, i)));
  return points;
}

LaserScanner::LaserScanner(const LidarParams& params, std::shared_ptr<const DistanceField> world)
    : params_(params), world_(std::move(world)) {
  params_.validate();
}

namespace {

// Where a ray from `origin` along `dir` meets the grid, walking the cells from
// t (m along the ray) on: the distance at which it enters an occupied cell, or
// +inf past `max_range` or beyond the grid.
double walk_cells(const OccupancyGrid& grid, const Vec2& origin, const Vec2& dir, double t, double max_range) {
  const double res = grid.resolution();
  const Vec2 p = (origin + t * dir - grid.origin()) / res;
  // The floor, without the call std::floor is on plain x86-64 (p stays
  // within the grid and the range, far inside int's reach).
  const auto floor_of = [](double g) {
    const int i = static_cast<int>(g);
    return i > g ? i - 1 : i;
  };
  int col = floor_of(p.x()), row = floor_of(p.y());
  const int step_c = dir.x() > 0 ? 1 : -1, step_r = dir.y() > 0 ? 1 : -1;
  const double delta_c = dir.x() != 0.0 ? std::abs(res / dir.x()) : kInf;
  const double delta_r = dir.y() != 0.0 ? std::abs(res / dir.y()) : kInf;
  double t_c = dir.x() != 0.0 ? t + (step_c > 0 ? col + 1 - p.x() : p.x() - col) * delta_c : kInf;
  double t_r = dir.y() != 0.0 ? t + (step_r > 0 ? row + 1 - p.y() : p.y() - row) * delta_r : kInf;
  if (grid.in_bounds(row, col) && grid.occupied(row, col)) return t;
  while (true) {
    double entry;
    if (t_c < t_r) {
      col += step_c;
      entry = t_c;
      t_c += delta_c;
    } else {
      row += step_r;
      entry = t_r;
      t_r += delta_r;
    }
    if (entry >= max_range) return kInf;
    if (grid.in_bounds(row, col)) {
      if (grid.occupied(row, col)) return entry;
    } else if ((step_c > 0 ? col >= grid.cols() : col < 0) || (step_r > 0 ? row >= grid.rows() : row < 0)) {
      return kInf;  // beyond the grid on a side the ray only moves away from
    }
  }
}

}  // namespace

void LaserScanner::cast_grid(const Vec2& origin, const Vec2* directions, std::size_t n, double* out) const {
  if (!world_ || !world_->has_obstacles()) {
    std::fill(out, out + n, kInf);
    return;
  }
  const OccupancyGrid& grid = world_->grid();
  const double res = grid.resolution();
  const DistanceField::LowerBounds bound = world_->lower_bounds();
  // Obstacles lie only inside the grid: each ray is clipped to its rectangle.
  const Vec2 lo = grid.origin(), hi = lo + Vec2(grid.cols() * res, grid.rows() * res);
  // Far from obstacles a ray jumps by a lower bound of the clearance: nothing
  // lies closer. Each jump waits on its table look-up, so the rays of a batch
  // take their jumps in turn and their look-ups overlap.
  constexpr std::size_t kBatch = 8;
  for (std::size_t first = 0; first < n; first += kBatch) {
    const std::size_t count = std::min(kBatch, n - first);
    double t[kBatch], range[kBatch];
    bool jumping[kBatch];
    std::size_t left = 0;
    for (std::size_t l = 0; l < count; ++l) {
      const Vec2& dir = directions[first + l];
      double enter = 0.0, leave = 1.0;
      jumping[l] = clip_segment_to_box(origin, origin + params_.max_range * dir, lo, hi, enter, leave);
      t[l] = enter * params_.max_range;
      range[l] = leave * params_.max_range;
      if (!jumping[l]) t[l] = kInf;  // misses the grid
      left += jumping[l];
    }
    while (left > 0) {
      for (std::size_t l = 0; l < count; ++l) {
        if (!jumping[l]) continue;
        const Vec2& dir = directions[first + l];
        if (!(t[l] < range[l])) {
          jumping[l] = false;
          --left;
          continue;
        }
        const double d = bound(origin.x() + t[l] * dir.x(), origin.y() + t[l] * dir.y());
        if (d < res) {
          jumping[l] = false;
          --left;
          continue;
        }
        t[l] += d;
      }
    }
    // Near an obstacle, walk the cells along the ray; the hit is where the ray
    // enters an occupied cell.
    for (std::size_t l = 0; l < count; ++l)
      out[first + l] = t[l] < range[l] ? walk_cells(grid, origin, directions[first + l], t[l], params_.max_range) : kInf;
  }
}

double LaserScanner::cast(const Vec2& origin, double angle, const std::vector<Disc>& discs, double t) const {
  detail::require_query_point("origin", origin);
  detail::require_magnitude("angle", angle, limits::kMaxAngle);
  detail::require_magnitude("t", t, limits::kMaxHorizon);
  const Vec2 direction(std::cos(angle), std::sin(angle));
  double grid_range = kInf;
  cast_grid(origin, &direction, 1, &grid_range);
  return with_discs(origin, direction, grid_range, discs, t);
}

double LaserScanner::with_discs(const Vec2& origin, const Vec2& dir, double grid_range, const std::vector<Disc>& discs,
                                double t) const {
  double best = grid_range;
  for (const Disc& disc : discs) {
    // |origin + s dir - c| = r, smallest s >= 0.
    const Vec2 f = origin - disc.center_at(t);
    const double b = f.dot(dir);
    const double c = f.squaredNorm() - disc.radius * disc.radius;
    if (c <= 0.0) return 0.0;  // the origin lies inside the disc
    const double disc_sq = b * b - c;
    if (disc_sq < 0.0 || b > 0.0) continue;
    best = std::min(best, -b - std::sqrt(disc_sq));
  }
  return best <= params_.max_range ? best : kInf;
}

void LaserScanner::scan(const Pose2& pose, const std::vector<Disc>& discs, double t, std::mt19937_64& rng,
                        Scan& out) const {
  detail::require_query_pose("pose", pose);
  detail::require_magnitude("t", t, limits::kMaxHorizon);
  for (const Disc& disc : discs) disc.validate();
  out.pose = pose;
  out.angle_min = -0.5 * params_.fov;
  out.angle_increment = params_.increment();
  out.max_range = params_.max_range;
  out.ranges.resize(static_cast<std::size_t>(params_.beams));
  std::vector<Vec2> directions(out.ranges.size());
  for (std::size_t i = 0; i < directions.size(); ++i) directions[i] = beam_direction(out, i);
  const Vec2 origin = pose.position();
  // The grid's ranges of all beams first, in batches (a beam dropped below is
  // cast too); then, beam by beam, its drop, the discs and its noise.
  cast_grid(origin, directions.data(), directions.size(), out.ranges.data());
  std::normal_distribution<double> noise(0.0, params_.noise_std);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < params_.beams; ++i) {
    double& range = out.ranges[static_cast<std::size_t>(i)];
    // The drop is drawn for every beam, hit or not, so one beam's draws do not
    // depend on what the others saw.
    if (params_.dropout > 0.0 && uniform(rng) < params_.dropout) {
      range = kInf;
      continue;
    }
    double r = with_discs(origin, directions[static_cast<std::size_t>(i)], range, discs, t);
    if (std::isfinite(r) && params_.noise_std > 0.0) r = std::clamp(r + noise(rng), 0.0, params_.max_range);
    range = r;
  }
}

DensityReading obstacle_density(const Scan& scan, const DetectWindowParams& params) {
  params.validate();
  scan.validate();
  return detail::obstacle_density_of_checked(scan, params);
}

DensityReading detail::obstacle_density_of_checked(const Scan& scan, const DetectWindowParams& params) {
  params.validate();
  DensityReading reading;
  const double R = params.radius;
  double area = 0.0;
  int run = 0, widest = 0;
  for (std::size_t i = 0; i < scan.ranges.size(); ++i) {
    const double angle = scan.angle_min + static_cast<double>(i) * scan.angle_increment;
    if (std::abs(angle) > params.half_angle + 1e-9) continue;
    ++reading.beams;
    const double r = std::min(scan.ranges[i], R);
    area += 1.0 - (r / R) * (r / R);
    if (r >= R) {
      widest = std::max(widest, ++run);
    } else {
      run = 0;
    }
  }
  if (reading.beams == 0) throw Error("detect window: no lidar beam lies within it");
  reading.area_ratio = area / reading.beams;
  // A run of k beams spans (k - 1) increments.
  const double phi = widest > 1 ? (widest - 1) * scan.angle_increment : 0.0;
  reading.max_gap = 2.0 * R * std::sin(0.5 * phi);
  reading.density = std::clamp(reading.area_ratio + std::pow(params.base, reading.max_gap), 0.0, 2.0);
  return reading;
}

std::shared_ptr<DistanceField> points_field(const std::vector<Vec2>& points, double resolution) {
  detail::require_resolution("resolution", resolution);
  if (points.empty()) return nullptr;
  if (points.size() > static_cast<std::size_t>(limits::kMaxPoints))
    throw Error(detail::describe("points", points.size(), "at most " + std::to_string(limits::kMaxPoints)));
  Vec2 lo = points.front(), hi = points.front();
  detail::require_points("points", points.data(), points.size(), limits::kMaxQueryCoordinate + limits::kMaxLength);
  for (const Vec2& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double spread = (std::floor((hi.x() - lo.x()) / resolution) + 2.0) * (std::floor((hi.y() - lo.y()) / resolution) + 2.0);
  if (spread > static_cast<double>(limits::kMaxGridCells))
    throw Error(detail::describe("points", points.size(),
                                 "spread over about " + detail::format_number(spread) + " cells of " +
                                     detail::format_number(resolution) + " m: more than " +
                                     std::to_string(limits::kMaxGridCells)));
  // Cells aligned to multiples of the resolution, so fields of successive scans agree.
  const Vec2 origin(std::floor(lo.x() / resolution) * resolution, std::floor(lo.y() / resolution) * resolution);
  const int cols = static_cast<int>(std::floor((hi.x() - origin.x()) / resolution)) + 1;
  const int rows = static_cast<int>(std::floor((hi.y() - origin.y()) / resolution)) + 1;
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(rows) * cols, 0);
  for (const Vec2& p : points) {
    const int c = std::clamp(static_cast<int>(std::floor((p.x() - origin.x()) / resolution)), 0, cols - 1);
    const int r = std::clamp(static_cast<int>(std::floor((p.y() - origin.y()) / resolution)), 0, rows - 1);
    cells[static_cast<std::size_t>(r) * cols + c] = 1;
  }
  // Built anew every cycle, and the points are mostly far: no edge margin.
  return std::make_shared<DistanceField>(OccupancyGrid(rows, cols, resolution, origin, std::move(cells)), 0.0);
}

}  // namespace fgdwa
