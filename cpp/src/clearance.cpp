#include "fgdwa/clearance.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "cover_bounds.hpp"
#include "disc_distance.hpp"
#include "validation.hpp"

namespace fgdwa {

void Disc::validate() const {
  detail::require_point("disc center", center);
  detail::require_distance("disc radius", radius);
  detail::require_xy("disc velocity", velocity.x(), velocity.y(), limits::kMaxSpeed);
  detail::require_non_negative("disc growth", growth);
  detail::require_at_most("disc growth", growth, limits::kMaxSpeed);
  detail::require_xy("disc acceleration", acceleration.x(), acceleration.y(), limits::kMaxAcceleration);
  detail::require_non_negative("disc accel_time", accel_time);
  detail::require_at_most("disc accel_time", accel_time, limits::kMaxHorizon);
  // Bounded as the velocity is, coordinate by coordinate.
  const Vec2 reached = velocity + accel_time * acceleration;
  detail::require_xy("disc velocity after accel_time", reached.x(), reached.y(), limits::kMaxSpeed);
}

namespace {

// q (relative to a pose) in the pose's frame, given the heading's cos c and sin s.
Vec2 in_frame(double c, double s, const Vec2& q) { return Vec2(c * q.x() + s * q.y(), -s * q.x() + c * q.y()); }

// The first t >= 0 at which |d + v t| <= R + g t (d the centre less the point);
// +inf if never. Squared: a t^2 + b t + c <= 0, with c > 0 when not covered now.
double linear_time_to_reach(const Vec2& d, const Vec2& velocity, double R, double growth) {
  const double c = d.squaredNorm() - R * R;
  if (c <= 0.0) return 0.0;
  const double a = velocity.squaredNorm() - growth * growth;
  const double b = 2.0 * (d.dot(velocity) - R * growth);
  const double inf = std::numeric_limits<double>::infinity();
  if (a == 0.0) return b < 0.0 ? -c / b : inf;
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return inf;  // a > 0 here: the parabola stays above 0
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  const double r1 = q / a, r2 = c / q;
  // a > 0: covered between two roots of one sign; a < 0: from the positive root on.
  if (a > 0.0) {
    const double first = std::min(r1, r2);
    return first > 0.0 ? first : inf;
  }
  return std::max(r1, r2);
}

}  // namespace

double Disc::time_to_reach(const Vec2& point, double reach) const {
  detail::require_query_point("time_to_reach point", point);
  detail::require_distance("time_to_reach reach", reach);
  const double R = radius + reach;
  if (accel_time > 0.0 && !acceleration.isZero()) {
    // The gap |centre - point| - (R + g t) falls no faster than the top
    // speed plus the growth: stepping by gap / that rate never steps over
    // a contact.
    const double rate = top_speed() + growth;
    const double least_step = accel_time * 1e-5;
    const auto gap = [&](double t) { return (center_at(t) - point).norm() - (R + growth * t); };
    for (double before = 0.0, t = 0.0; t < accel_time;) {
      if (gap(t) <= 0.0) {
        // Covered at t, not at `before`: the first contact lies between.
        for (int i = 0; i < 60 && t - before > 1e-12 * accel_time; ++i) {
          const double middle = 0.5 * (before + t);
          (gap(middle) <= 0.0 ? t : before) = middle;
        }
        return t;
      }
      before = t;
      t += rate > 0.0 ? std::max(gap(t) / rate, least_step) : accel_time;
    }
    // From accel_time on it moves at the velocity reached.
    const double rest = linear_time_to_reach(center_at(accel_time) - point, velocity + accel_time * acceleration,
                                             R + growth * accel_time, growth);
    return accel_time + rest;
  }
  return linear_time_to_reach(center - point, velocity, R, growth);
}

FieldClearance::FieldClearance(std::shared_ptr<const DistanceField> field, std::vector<Disc> discs)
    : field_(std::move(field)) {
  set_discs(std::move(discs));
}

void FieldClearance::set_discs(std::vector<Disc> discs) {
  if (discs.size() > static_cast<std::size_t>(limits::kMaxDiscs))
    throw Error(detail::describe("discs", discs.size(), "at most " + std::to_string(limits::kMaxDiscs)));
  obstacle_speed_ = 0.0;
  for (const Disc& d : discs) {
    d.validate();
    obstacle_speed_ = std::max(obstacle_speed_, d.top_speed() + d.growth);
  }
  discs_ = std::move(discs);
  moving_.clear();
  likely_moving_.clear();
  std::vector<Disc> still;
  for (const Disc& d : discs_) (d.moves() ? moving_ : still).push_back(d);
  if (std::any_of(moving_.begin(), moving_.end(), [](const Disc& d) { return d.growth > 0.0; })) {
    likely_moving_ = moving_;
    for (Disc& d : likely_moving_) d.growth = 0.0;
  }
  static_discs_.assign(still);
  split_moving();
}

void FieldClearance::StaticDiscs::assign(const std::vector<Disc>& still) {
  *this = StaticDiscs{};
  const std::size_t n = still.size();
  // Below this many, one vectorised pass over them all costs no more than buckets.
  constexpr std::size_t kBucketed = 24;
  constexpr double kSide = 0.25;  // m: a few lidar hits along a wall per bucket
  double x1 = 0.0, y1 = 0.0;
  if (n >= kBucketed) {
    x0 = x1 = still[0].center.x();
    y0 = y1 = still[0].center.y();
    for (const Disc& d : still) {
      x0 = std::min(x0, d.center.x()), x1 = std::max(x1, d.center.x());
      y0 = std::min(y0, d.center.y()), y1 = std::max(y1, d.center.y());
      largest_radius = std::max(largest_radius, d.radius);
    }
    // Wider buckets where the discs spread far, so there are never more
    // buckets than a few per disc.
    const double count = static_cast<double>(n);
    side = std::max({kSide, std::sqrt((x1 - x0) * (y1 - y0) / (2.0 * count)), std::max(x1 - x0, y1 - y0) / (2.0 * count)});
    cols = static_cast<int>(std::floor((x1 - x0) / side)) + 1;
    rows = static_cast<int>(std::floor((y1 - y0) / side)) + 1;
  }
  const auto bucket = [&](const Disc& d) -> std::size_t {
    if (cols == 0) return 0;
    const int col = std::min(cols - 1, static_cast<int>(std::floor((d.center.x() - x0) / side)));
    const int row = std::min(rows - 1, static_cast<int>(std::floor((d.center.y() - y0) / side)));
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(col);
  };
  const std::size_t buckets = cols == 0 ? 1 : static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  start.assign(buckets + 1, 0);
  for (const Disc& d : still) ++start[bucket(d) + 1];
  for (std::size_t b = 0; b < buckets; ++b) start[b + 1] += start[b];
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  x.resize(n), y.resize(n), radius.resize(n);
  for (const Disc& d : still) {
    const std::uint32_t at = next[bucket(d)]++;
    x[at] = d.center.x(), y[at] = d.center.y(), radius[at] = d.radius;
  }
}

template <class Run>
void FieldClearance::StaticDiscs::near(double px, double py, double reach, Run run) const {
  if (x.empty()) return;
  if (cols == 0 || !std::isfinite(reach) || !std::isfinite(px) || !std::isfinite(py)) {
    run(std::size_t{0}, x.size());
    return;
  }
  if (reach < 0.0) return;
  // Clamped, so that a square reaching past the buckets takes the edge ones
  // (more discs than needed never change a minimum; fewer would).
  const auto index = [&](double coordinate, double origin, int count) {
    return static_cast<int>(std::clamp(std::floor((coordinate - origin) / side), 0.0, static_cast<double>(count - 1)));
  };
  const int c0 = index(px - reach, x0, cols), c1 = index(px + reach, x0, cols);
  const int r0 = index(py - reach, y0, rows), r1 = index(py + reach, y0, rows);
  for (int row = r0; row <= r1; ++row) {
    const std::size_t first = start[static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c0)];
    const std::size_t last = start[static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c1) + 1];
    if (last > first) run(first, last - first);
  }
}

double FieldClearance::StaticDiscs::distance_below(double px, double py, double inflate, double cutoff) const {
  double best = std::numeric_limits<double>::infinity();
  // A disc below the cutoff has its centre within inflate + cutoff + its
  // radius (a micrometre over, for the rounding of the buckets' edges).
  near(px, py, inflate + cutoff + largest_radius + 1e-6, [&](std::size_t first, std::size_t count) {
    detail::lower_to_discs(&px, &py, 1, x.data() + first, y.data() + first, radius.data() + first, count, inflate, &best);
  });
  return std::min(best, cutoff);
}

double FieldClearance::StaticDiscs::polygon_distance(const Footprint& footprint, double px, double py, double c,
                                                     double s, double cutoff) const {
  // The footprint's bounding box in its own frame: a point's distance from
  // it, along either axis, is a lower bound of the polygon's that costs no
  // root. A box footprint's bound is exact off its corners, so nearly every
  // disc is settled without measuring.
  const double box[4] = {footprint.box_min().x(), footprint.box_max().x(), footprint.box_min().y(),
                         footprint.box_max().y()};
  // In the robot's frame, with the pose's cos and sin (Footprint::signed_distance's bits).
  const auto measure = [&](std::size_t j) {
    return footprint.signed_distance_in_frame(in_frame(c, s, Vec2(x[j] - px, y[j] - py))) - radius[j];
  };
  // Only discs whose centre lies within the circumscribed radius and the
  // cutoff can come below it, and of those only the ones whose bound does:
  // kept with their bounds in one pass. The least bound's disc is measured
  // first, so that its measure settles the rest by their bounds.
  // Room for every disc once (near's runs never overlap), kept between calls
  // so that no call clears or fills it.
  thread_local std::vector<std::uint32_t> open;
  thread_local std::vector<double> open_low;
  if (open.size() < x.size()) open.resize(x.size()), open_low.resize(x.size());
  std::size_t opened = 0;
  const double reach = footprint.radius() + cutoff + largest_radius + 1e-6;
  near(px, py, reach, [&](std::size_t first, std::size_t count) {
    opened += detail::box_bounds_below(x.data() + first, y.data() + first, radius.data() + first, count, px, py, c, s,
                                       box, cutoff, static_cast<std::uint32_t>(first), open.data() + opened,
                                       open_low.data() + opened);
  });
  if (opened == 0) return cutoff;
  const std::size_t nearest =
      static_cast<std::size_t>(std::min_element(open_low.begin(), open_low.begin() + opened) - open_low.begin());
  double best = measure(open[nearest]);
  for (std::size_t k = 0; k < opened; ++k)
    if (k != nearest && open_low[k] < std::min(best, cutoff)) best = std::min(best, measure(open[k]));
  // At or above the cutoff, a disc passed over may hold a lower value, though none below the cutoff.
  return std::min(best, cutoff);
}

// The static part shares the fields: new fields are handed to it, and only
// new discs (or a static part a copy of this world shares) make a new one.
void FieldClearance::set_field(std::shared_ptr<const DistanceField> field) {
  field_ = std::move(field);
  if (fixed_ && fixed_.use_count() == 1) fixed_->set_field(field_);
  else split_moving();
}

void FieldClearance::set_sensed(std::shared_ptr<const DistanceField> sensed) {
  sensed_ = std::move(sensed);
  if (fixed_ && fixed_.use_count() == 1) fixed_->set_sensed(sensed_);
  else split_moving();
}

void FieldClearance::split_moving() {
  fixed_.reset();
  if (obstacle_speed_ <= 0.0) return;
  std::vector<Disc> still;
  for (const Disc& d : discs_)
    if (!d.moves()) still.push_back(d);
  fixed_ = std::make_shared<FieldClearance>(field_, std::move(still));
  fixed_->set_sensed(sensed_);
}

namespace {
// cos and sin of a heading, remembered: a control cycle places the footprint
// at thousands of poses but only at n_omega x n_steps headings, since every
// speed of the window turns alike. Keyed by the heading's bits, so a hit gives
// exactly what std::cos and std::sin would. Two entries per slot, the last
// used first: with one, a fifth of the look-ups of a 21 x 20 cycle missed,
// headings sharing a slot evicting each other pose after pose.
inline void heading_cos_sin(double theta, double& c, double& s) {
  struct Entry {
    std::uint64_t bits = ~std::uint64_t{0};  // a NaN no heading has
    double c = std::numeric_limits<double>::quiet_NaN(), s = std::numeric_limits<double>::quiet_NaN();
  };
  struct Slot {
    Entry recent, older;
  };
  thread_local std::array<Slot, 1024> remembered;
  std::uint64_t bits;
  std::memcpy(&bits, &theta, sizeof bits);
  Slot& slot = remembered[((bits ^ (bits >> 31)) * 0x9E3779B97F4A7C15ull) >> 54];
  if (slot.recent.bits != bits) {
    if (slot.older.bits == bits) {
      std::swap(slot.recent, slot.older);
    } else {
      slot.older = slot.recent;
      slot.recent.bits = bits;
      slot.recent.c = std::cos(theta);
      slot.recent.s = std::sin(theta);
    }
  }
  c = slot.recent.c;
  s = slot.recent.s;
}

// The cos and sin of a whole trajectory's headings: a control cycle asks for
// the same n_omega sequences of headings once per speed of the window, since
// every speed turns alike. Remembered by sequence, so that a hit costs one
// comparison per pose; the headings are all compared, so a hit gives exactly
// what heading_cos_sin would (which fills a miss).
struct HeadingColumns {
  const double* c;
  const double* s;
};
HeadingColumns trajectory_cos_sin(const Trajectory& poses) {
  struct Sequence {
    std::vector<std::uint64_t> bits;
    std::vector<double> c, s;
  };
  thread_local std::array<Sequence, 64> remembered;
  const std::size_t n = poses.size();
  if (n == 0) return HeadingColumns{nullptr, nullptr};
  const auto bits_of = [](double theta) {
    std::uint64_t bits;
    std::memcpy(&bits, &theta, sizeof bits);
    return bits;
  };
  const std::uint64_t key = bits_of(poses[0].theta);
  Sequence& slot = remembered[((key ^ (key >> 31) ^ n) * 0x9E3779B97F4A7C15ull) >> 58];
  bool hit = slot.bits.size() == n;
  for (std::size_t k = 0; hit && k < n; ++k) hit = slot.bits[k] == bits_of(poses[k].theta);
  if (!hit) {
    slot.bits.resize(n);
    slot.c.resize(n);
    slot.s.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      slot.bits[k] = bits_of(poses[k].theta);
      heading_cos_sin(poses[k].theta, slot.c[k], slot.s[k]);
    }
  }
  return HeadingColumns{slot.c.data(), slot.s.data()};
}

// A pose with its heading's cosine and sine, worked out once for every field
// and bound that places a polygon there (a circle needs neither).
struct Placed {
  const Pose2& pose;
  double c = 1.0, s = 0.0;
  Placed(const Pose2& p, const Footprint& footprint) : pose(p) {
    if (!footprint.is_circle()) heading_cos_sin(p.theta, c, s);
  }
  Placed(const Pose2& p, double cos_theta, double sin_theta) : pose(p), c(cos_theta), s(sin_theta) {}
  Vec2 world(const Vec2& q) const { return Vec2(pose.x + c * q.x() - s * q.y(), pose.y + s * q.x() + c * q.y()); }
};

// How near a piece of length `length` can come to an obstacle that lies at
// least da from one end and db from the other: the height over the piece of the
// triangle with sides da, db and length where its foot falls on the piece,
// else the nearer end's distance. Tighter than the field's Lipschitz bound
// (da + db - length) / 2: pieces a cell long between ends 0.3 m away are held
// to 0.296 m instead of 0.25 m. Shaved a little below the rounding.
double piece_lower_bound(double da, double db, double length) {
  if (!(da > 0.0 && db > 0.0)) return 0.0;
  const double foot = (da * da - db * db + length * length) / (2.0 * length);
  if (foot <= 0.0) return da * (1.0 - 1e-12);
  if (foot >= length) return db * (1.0 - 1e-12);
  return std::sqrt(std::max(da * da - foot * foot, 0.0)) * (1.0 - 1e-12);
}

// A polygon's bound from one field: every point of it lies in one of its cover discs.
double cover_lower_bound(const DistanceField::LowerBounds& bound, const Footprint& footprint, const Placed& at) {
  double best = std::numeric_limits<double>::infinity();
  for (const Footprint::CoverDisc& d : footprint.cover()) {
    const Vec2 p = at.world(d.centre);
    best = std::min(best, bound(p.x(), p.y()) - d.radius);
  }
  return best;
}

// The outline's samples in the robot's frame, a cell apart or less (half a
// cell apart, the pieces' bounds settled more of them but twice as many were
// looked up: 8 % slower), each with the length of the piece to the next, a
// little over. They depend on the footprint and the resolution alone, so
// each thread keeps the last ones it worked out.
struct OutlineSamples {
  std::vector<Vec2> vertices;
  double resolution = 0.0;
  std::vector<double> x, y;  // the points, column by column
  std::vector<double> lengths;
};

const OutlineSamples& outline_samples(const Footprint& footprint, double resolution) {
  thread_local OutlineSamples last;
  const std::vector<Vec2>& vertices = footprint.vertices();
  if (last.resolution == resolution && last.vertices == vertices) return last;
  last.vertices = vertices;
  last.resolution = resolution;
  last.x.clear();
  last.y.clear();
  last.lengths.clear();
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const Vec2 a = vertices[i], b = vertices[(i + 1) % vertices.size()];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / resolution)));
    // Rounding aside the pieces of an edge are equally long; the margin keeps
    // a piece's bound from cutting one that holds the minimum.
    const double length = (b - a).norm() / pieces * (1.0 + 1e-12) + 1e-15;
    for (int k = 0; k < pieces; ++k) {
      const Vec2 point = a + (b - a) * (double(k) / pieces);
      last.x.push_back(point.x());
      last.y.push_back(point.y());
      last.lengths.push_back(length);
    }
  }
  return last;
}

// The footprint's clearance from the field's obstacles where it is below
// `cutoff`; elsewhere a value from cutoff up to it. Both give the same bits
// below the cutoff: the result is the least of the distances and piece bounds
// the search reaches, and what a lower starting point prunes lies above it.
double field_clearance(const DistanceField* field, const Footprint& footprint, const Placed& at,
                       double cutoff = std::numeric_limits<double>::infinity()) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!field || !field->has_obstacles()) return kInf;
  const Pose2& pose = at.pose;
  if (footprint.is_circle()) {
    // The table's bound often settles a cutoff at one look-up (the planner's
    // evasion asks only whether the margin is reached).
    if (cutoff < kInf) {
      const double low = field->lower_bounds()(pose.x, pose.y) - footprint.radius();
      if (low >= cutoff) return low;
    }
    return field->distance(pose.position()) - footprint.radius();
  }
  // The circumscribed circle often settles a cutoff at one look-up (a field
  // of sensed points far from the robot nearly always does). The cover discs
  // are not tried: the planner asks only where their bound is below the
  // cutoff, and 4 % of its queries were settled by them.
  const DistanceField::LowerBounds bounds = field->lower_bounds();
  if (cutoff < kInf && bounds(pose.x, pose.y) - footprint.radius() >= cutoff) return cutoff;

  // Polygon: the distance from its outline, sampled (outline_samples).
  // Exact distances are asked where the table's lower bounds leave it open:
  // first at the sample of lowest bound, then at every sample whose bound is
  // below the best so far; then the pieces between samples whose bound
  // (piece_lower_bound) could still be below it are measured whole, inside
  // the grid or out.
  const double res = field->grid().resolution();
  const OutlineSamples& outline = outline_samples(footprint, res);
  const std::size_t n = outline.x.size();
  // Columns on the stack for the usual footprint; this runs thousands of
  // times per control cycle. The samples' world points (wx, wy), the table's
  // bounds there (low), their exact distances (NaN until asked), and the
  // pieces left open by the first pass (open).
  constexpr std::size_t kOnStack = 96;
  double on_stack[4 * kOnStack];
  std::uint32_t open_on_stack[kOnStack];
  std::vector<double> spilled;
  std::vector<std::uint32_t> open_spilled;
  double* columns = on_stack;
  std::uint32_t* open = open_on_stack;
  const std::size_t m = std::max(n, kOnStack);
  if (n > kOnStack) {
    spilled.resize(4 * m);
    open_spilled.resize(n);
    columns = spilled.data();
    open = open_spilled.data();
  }
  double* const wx = columns;
  double* const wy = columns + m;
  double* const low = columns + 2 * m;
  double* const exact_at = columns + 3 * m;
  const double lowest_low =
      detail::outline_lower_bounds(pose.x, pose.y, at.c, at.s, outline.x.data(), outline.y.data(), n, bounds, wx, wy, low);
  std::fill(exact_at, exact_at + n, std::numeric_limits<double>::quiet_NaN());
  // Placing the samples rounds their coordinates: a few units in the last
  // place of the largest one, which the pieces' lengths must allow for.
  const double placing_slack =
      8.0 * std::numeric_limits<double>::epsilon() * (std::abs(pose.x) + std::abs(pose.y) + footprint.radius());
  // The lowest bound's sample (the first of equals): its value came from
  // the kernel, where a search by index waited on a load per sample.
  std::size_t lowest = 0;
  while (lowest + 1 < n && low[lowest] != lowest_low) ++lowest;
  const OccupancyGrid& grid = field->grid();
  const Vec2 grid_lo = grid.origin(), grid_hi = grid.origin() + res * Vec2(grid.cols(), grid.rows());
  const auto on_grid = [&](std::size_t j) {
    return wx[j] >= grid_lo.x() && wy[j] >= grid_lo.y() && wx[j] <= grid_hi.x() && wy[j] <= grid_hi.y();
  };
  const auto exact = [&](std::size_t j) {
    if (std::isnan(exact_at[j])) exact_at[j] = field->distance(Vec2(wx[j], wy[j]));
    return exact_at[j];
  };
  // The exact distance where asked, else the bound, without a branch: the
  // bound never exceeds the distance, and max(low, NaN) is low.
  const auto known = [&](std::size_t j) { return std::max(low[j], exact_at[j]); };
  double best = low[lowest] < cutoff ? std::min(cutoff, exact(lowest)) : cutoff;
  for (std::size_t j = 0; j < n; ++j)
    if (low[j] < best) best = std::min(best, exact(j));
  // The field's Lipschitz bound settles most pieces, those far from the
  // nearest obstacle: a first pass without branches keeps the others. What
  // it settles stays settled, the best only falling and what is known at the
  // ends only rising; the others are taken in turn as before.
  std::size_t opened = 0;
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t next = j + 1 == n ? 0 : j + 1;
    open[opened] = static_cast<std::uint32_t>(j);
    opened += 0.5 * (known(j) + known(next) - (outline.lengths[j] + placing_slack)) < best;
  }
  for (std::size_t i = 0; i < opened; ++i) {
    const std::size_t j = open[i], next = j + 1 == n ? 0 : j + 1;
    const double length = outline.lengths[j] + placing_slack;
    const double da = known(j), db = known(next);
    if (0.5 * (da + db - length) >= best || piece_lower_bound(da, db, length) >= best) continue;
    if (!on_grid(j) || !on_grid(next)) {
      // Off the grid (always so for a small field of sensed cells) a segment
      // walks rows or columns; the exact distances at its ends often settle it.
      best = std::min({best, exact(j), exact(next)});
      if (piece_lower_bound(exact_at[j], exact_at[next], length) >= best) continue;
    }
    best = std::min(best, field->segment_distance(Vec2(wx[j], wy[j]), Vec2(wx[next], wy[next])));
  }
  // An obstacle cell can sit wholly inside a footprint wider than a cell; its
  // centre then lies at least `best` and half a cell inside the outline, which
  // no point farther in than half the footprint's width can. The disc of that
  // radius around it lies in the footprint, and so in the circumscribed
  // circle: the centre is within `reach` of the pose, and so is the field's
  // nearest obstacle (a nanometre over, for the rounding).
  const double reach = footprint.radius() - best - 0.5 * res + 1e-9;
  if (best <= 0.0 || best + 0.5 * res > footprint.half_width() || field->lower_bound(pose.position()) > reach ||
      field->distance(pose.position()) > reach)
    return best;
  const Vec2 lo = pose.position() - Vec2(reach, reach), hi = pose.position() + Vec2(reach, reach);
  // Clamped before the cast: a query far off the grid has no int index.
  const auto index = [&](double coordinate, double origin, int count) {
    return static_cast<int>(std::clamp(std::floor((coordinate - origin) / res), -1.0, static_cast<double>(count)));
  };
  const int r0 = std::max(0, index(lo.y(), grid.origin().y(), grid.rows()));
  const int c0 = std::max(0, index(lo.x(), grid.origin().x(), grid.cols()));
  const int r1 = std::min(grid.rows() - 1, index(hi.y(), grid.origin().y(), grid.rows()));
  const int c1 = std::min(grid.cols() - 1, index(hi.x(), grid.origin().x(), grid.cols()));
  for (int row = r0; row <= r1; ++row)
    for (int col = c0; col <= c1; ++col)
      if (grid.occupied(row, col) && footprint.contains(pose, grid.cell_center(row, col))) return 0.0;
  return best;
}

}  // namespace

void ClearanceSource::clearance_lower_bounds(const Footprint& footprint, const Trajectory& poses, double dt,
                                             double* out) const {
  detail::require_query_poses("poses", poses);
  detail::require_time_step("dt", dt);
  lower_bounds(footprint, poses, dt, out);
}

void FieldClearance::lower_bounds(const Footprint& footprint, const Trajectory& poses, double dt, double* out) const {
  rollouts_lower_bounds(footprint, &poses, 1, poses.size(), dt, out);
}

void FieldClearance::rollouts_lower_bounds(const Footprint& footprint, const Trajectory* rollouts, std::size_t count,
                                           std::size_t steps, double dt, double* out) const {
  const double r = footprint.radius();
  const std::size_t n = count * steps;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Positions (and a polygon's headings) column by column, every rollout's
  // poses in one run, so that lanes carry poses across rollouts; one
  // thread-local look-up per call, the columns filled once for every kernel.
  struct Columns {
    std::vector<double> x, y, c, s;
    std::vector<double> sensed;  // the sensed field's bounds for the circumscribed circle
  };
  thread_local Columns columns;
  Columns& in = columns;
  in.x.resize(n);
  in.y.resize(n);
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t k = 0; k < steps; ++k) {
      in.x[i * steps + k] = rollouts[i][k].x;
      in.y[i * steps + k] = rollouts[i][k].y;
    }
  if (!footprint.is_circle()) {
    in.c.resize(n);
    in.s.resize(n);
    for (std::size_t i = 0; i < count; ++i) {
      const HeadingColumns heading = trajectory_cos_sin(rollouts[i]);
      std::copy(heading.c, heading.c + steps, in.c.begin() + static_cast<std::ptrdiff_t>(i * steps));
      std::copy(heading.s, heading.s + steps, in.s.begin() + static_cast<std::ptrdiff_t>(i * steps));
    }
    // Every point of the polygon lies in one of its cover discs: the map's
    // bounds at the discs, for all poses at once.
    if (field_) {
      const std::vector<Footprint::CoverDisc>& cover = footprint.cover();
      detail::cover_lower_bounds(in.x.data(), in.y.data(), in.c.data(), in.s.data(), n, cover.data(), cover.size(),
                                 field_->lower_bounds(), out);
    } else {
      std::fill(out, out + n, kInf);
    }
  } else {
    if (field_) detail::point_lower_bounds(in.x.data(), in.y.data(), n, field_->lower_bounds(), r, out);
    else std::fill(out, out + n, kInf);
  }
  // The sensed cells: the circumscribed circle's bound at every pose, which
  // is a circle's bound itself; a polygon's, being mostly far from them,
  // then leaves the least unchanged, else its cover discs are asked.
  if (sensed_) {
    const DistanceField::LowerBounds bound = sensed_->lower_bounds();
    in.sensed.resize(n);
    detail::point_lower_bounds(in.x.data(), in.y.data(), n, bound, r, in.sensed.data());
    if (footprint.is_circle()) {
      for (std::size_t k = 0; k < n; ++k) out[k] = std::min(out[k], in.sensed[k]);
    } else {
      for (std::size_t k = 0; k < n; ++k)
        if (in.sensed[k] < out[k])
          out[k] = std::min(out[k], cover_lower_bound(bound, footprint,
                                                      Placed(rollouts[k / steps][k % steps], in.c[k], in.s[k])));
    }
  }
  if (!static_discs_.x.empty()) {
    const StaticDiscs& d = static_discs_;
    detail::lower_to_discs(in.x.data(), in.y.data(), n, d.x.data(), d.y.data(), d.radius.data(), d.x.size(), r, out);
  }
  // A mover's place and size at each step serve every rollout.
  for (const Disc& disc : moving_)
    for (std::size_t k = 0; k < steps; ++k) {
      const double t = static_cast<double>(k + 1) * dt;
      const Vec2 centre = disc.center_at(t);
      const double radius = disc.radius_at(t);
      for (std::size_t i = 0; i < count; ++i) {
        double& bound = out[i * steps + k];
        bound = std::min(bound, ((centre - rollouts[i][k].position()).norm() - r) - radius);
      }
    }
}

bool FieldClearance::lower_bounds_exact(const Footprint& footprint) const {
  const auto empty = [](const std::shared_ptr<const DistanceField>& field) { return !field || !field->has_obstacles(); };
  return footprint.is_circle() && empty(field_) && empty(sensed_);
}

namespace {
// A lower bound of a footprint's signed distance from q (in its frame): how
// far q lies beyond its bounding box along the farther axis, a nanometre
// under for the rounding (as box_bounds_below takes it). Off a box
// footprint's corners it is the distance itself.
double box_lower_bound(const Footprint& footprint, const Vec2& q) {
  const Vec2& lo = footprint.box_min();
  const Vec2& hi = footprint.box_max();
  return std::max(std::max(lo.x() - q.x(), q.x() - hi.x()), std::max(lo.y() - q.y(), q.y() - hi.y())) - 1e-9;
}

// moving_disc_clearance() without the checks, for callers that made them;
// bit for bit below `cutoff`, elsewhere a value from cutoff up to it. `every`:
// measures still discs too (a likely disc may have moved by its growth alone).
double moving_disc_clearance_unchecked(const std::vector<Disc>& discs, const Footprint& footprint, const Pose2& pose,
                                       double t, double cutoff = std::numeric_limits<double>::infinity(),
                                       bool every = false) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double best = kInf;
  if (footprint.is_circle()) {
    for (const Disc& disc : discs) {
      if (!every && !disc.moves()) continue;
      const double radius = disc.radius_at(t);
      const double gap = (disc.center_at(t) - pose.position()).norm();
      // The circumscribed circle settles the far ones, once there is a best to beat.
      if (best < kInf && gap - radius - footprint.radius() >= best) continue;
      // As signed_distance_in_frame(q) would give it, from the norm already taken.
      best = std::min(best, (gap - footprint.radius()) - radius);
    }
    return best;
  }
  // A polygon: the disc nearest by the circumscribed circle is measured first,
  // so that its clearance settles the others by that circle alone (taken in
  // turn, the first disc was measured wherever it lay). The least is the same
  // whichever order the measured ones come in. Nothing is kept between the
  // passes: a centre and a norm again cost less than storing them.
  const auto circumscribed = [&](const Disc& disc) {
    return (disc.center_at(t) - pose.position()).norm() - disc.radius_at(t) - footprint.radius();
  };
  const Disc* nearest = nullptr;
  double nearest_low = kInf;
  for (const Disc& disc : discs) {
    if (!every && !disc.moves()) continue;
    const double low = circumscribed(disc);
    if (!nearest || low < nearest_low) nearest = &disc, nearest_low = low;
  }
  if (!nearest) return best;
  // No disc comes within the cutoff: the circumscribed circle's clearance is all that is asked.
  if (nearest_low >= cutoff) return nearest_low;
  double c = 0.0, s = 0.0;
  heading_cos_sin(pose.theta, c, s);
  const auto placed = [&](const Disc& disc) { return in_frame(c, s, disc.center_at(t) - pose.position()); };
  best = std::min(best, footprint.signed_distance_in_frame(placed(*nearest)) - nearest->radius_at(t));
  // The others by the circumscribed circle, then by the bounding box, before they are measured.
  for (const Disc& disc : discs) {
    if (!(every || disc.moves()) || &disc == nearest || circumscribed(disc) >= std::min(best, cutoff)) continue;
    const Vec2 q = placed(disc);
    const double radius = disc.radius_at(t);
    if (box_lower_bound(footprint, q) - radius >= std::min(best, cutoff)) continue;
    best = std::min(best, footprint.signed_distance_in_frame(q) - radius);
  }
  // At or above the cutoff, the discs passed over may hold a lower clearance,
  // though none below the cutoff.
  return std::min(best, cutoff);
}
}  // namespace

double moving_disc_clearance(const std::vector<Disc>& discs, const Footprint& footprint, const Pose2& pose, double t) {
  detail::require_query_pose("pose", pose);
  detail::require_magnitude("t", t, limits::kMaxHorizon);
  return moving_disc_clearance_unchecked(discs, footprint, pose, t);
}

double FieldClearance::moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const {
  detail::require_query_pose("pose", pose);
  detail::require_magnitude("t", t, limits::kMaxHorizon);
  return moving_disc_clearance_unchecked(moving_, footprint, pose, t);
}

double FieldClearance::moving_clearance_below(const Footprint& footprint, const Pose2& pose, double t,
                                              double cutoff) const {
  return moving_disc_clearance_unchecked(moving_, footprint, pose, t, cutoff);
}

double FieldClearance::likely_moving_clearance(const Footprint& footprint, const Pose2& pose, double t) const {
  return likely_moving_.empty() ? moving_disc_clearance_unchecked(moving_, footprint, pose, t)
                                : moving_disc_clearance_unchecked(likely_moving_, footprint, pose, t,
                                                                  std::numeric_limits<double>::infinity(), true);
}

void FieldClearance::moving_clearances(const Footprint& footprint, const Pose2& pose, double t, double& grown,
                                       double& likely) const {
  if (likely_moving_.empty()) {
    grown = likely = moving_disc_clearance_unchecked(moving_, footprint, pose, t);
    return;
  }
  grown = likely = std::numeric_limits<double>::infinity();
  // likely_moving_ is moving_ without the growth, disc for disc: the centre
  // and the distance to it serve both, each less its own radius (as
  // moving_disc_clearance_unchecked takes them). A disc whose bounds (the
  // circumscribed circle's, the bounding box's) reach neither best cannot
  // lower either.
  const bool circle = footprint.is_circle();
  double c = 0.0, s = 0.0;
  if (!circle) heading_cos_sin(pose.theta, c, s);
  for (std::size_t j = 0; j < moving_.size(); ++j) {
    const Disc& disc = moving_[j];
    const double grown_radius = disc.radius_at(t), likely_radius = likely_moving_[j].radius_at(t);
    const Vec2 q = disc.center_at(t) - pose.position();
    const double gap = q.norm();
    const auto beats = [&](double low) { return low - grown_radius < grown || low - likely_radius < likely; };
    double distance = gap - footprint.radius();  // a circle's, a polygon's lower bound
    if (!beats(distance)) continue;
    if (!circle) {
      const Vec2 placed = in_frame(c, s, q);
      if (!beats(box_lower_bound(footprint, placed))) continue;
      distance = footprint.signed_distance_in_frame(placed);
    }
    grown = std::min(grown, distance - grown_radius);
    likely = std::min(likely, distance - likely_radius);
  }
}

double FieldClearance::clearance(const Footprint& footprint, const Pose2& pose, double t) const {
  detail::require_query_pose("pose", pose);
  detail::require_magnitude("t", t, limits::kMaxHorizon);
  return clearance_below(footprint, pose, t, std::numeric_limits<double>::infinity());
}

double FieldClearance::clearance_below(const Footprint& footprint, const Pose2& pose, double t, double cutoff) const {
  const Placed at(pose, footprint);
  double best = field_clearance(field_.get(), footprint, at, cutoff);
  if (sensed_) best = std::min(best, field_clearance(sensed_.get(), footprint, at, std::min(best, cutoff)));
  if (!static_discs_.x.empty()) {
    const double below = std::min(best, cutoff);
    best = std::min(best, footprint.is_circle()
                              ? static_discs_.distance_below(pose.x, pose.y, footprint.radius(), below)
                              : static_discs_.polygon_distance(footprint, pose.x, pose.y, at.c, at.s, below));
  }
  return moving_.empty() ? best : std::min(best, moving_disc_clearance_unchecked(moving_, footprint, pose, t));
}

}  // namespace fgdwa
