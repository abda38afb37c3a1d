#include "fgdwa/scan_matcher.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "fgdwa/error.hpp"
#include "match_score.hpp"
#include "validation.hpp"

namespace fgdwa {

void ScanMatchParams::check_relations(const ParamPath& path) const {
  using detail::format_number;
  if (step_xy > window_xy)
    fail_param(path.field("step_xy"), format_number(step_xy),
               "must not exceed window_xy (" + format_number(window_xy) + ")");
  if (final_step_xy > step_xy)
    fail_param(path.field("final_step_xy"), format_number(final_step_xy),
               "must not exceed step_xy (" + format_number(step_xy) + ")");
  if (step_theta > window_theta)
    fail_param(path.field("step_theta"), format_number(step_theta),
               "must not exceed window_theta (" + format_number(window_theta) + ")");
  if (min_points > max_points)
    fail_param(path.field("min_points"), format_number(min_points),
               "must not exceed max_points (" + std::to_string(max_points) + ")");
}

const char* to_string(MatchStatus status) {
  switch (status) {
    case MatchStatus::Accepted: return "accepted";
    case MatchStatus::Off: return "off";
    case MatchStatus::NoMap: return "no_map";
    case MatchStatus::TooFewPoints: return "too_few_points";
    case MatchStatus::PoorFit: return "poor_fit";
    case MatchStatus::NotBetter: return "not_better";
    case MatchStatus::Ambiguous: return "ambiguous";
  }
  return "?";
}

namespace {

// A pose of the search, as offsets from the pose given.
struct Candidate {
  double dx = 0.0, dy = 0.0, dtheta = 0.0, score = -1.0;
  // Equal scores go to the smaller move: a flat optimum (a hit anywhere in an
  // occupied cell scores the same) must not drift the pose.
  double move(double window_xy, double window_theta) const {
    return (dx * dx + dy * dy) / (window_xy * window_xy) + dtheta * dtheta / (window_theta * window_theta);
  }
};

// Scores hits (relative to the sensor, turned by the candidate's angle)
// against the distance field's look-up table, through a table of
// exp(-d^2 / (2 sigma^2)) per step of distance.
class Scorer {
 public:
  Scorer(const DistanceField& field, double sigma, std::size_t points) : table_(field.lower_bounds()) {
    const double reach = 3.0 * sigma;  // beyond, a hit scores less than 1 %: nothing
    const std::size_t n = static_cast<std::size_t>(std::min(65536.0, std::ceil(reach / table_.step) + 1.0));
    weights_.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      const double d = static_cast<double>(k) * table_.step;
      weights_[k] = static_cast<float>(std::exp(-0.5 * d * d / (sigma * sigma)));
    }
    vectors_ = detail::exact_match_sums(weights_.data(), n, points);
  }
  // The hits as x and y apart (relative to the sensor, turned by the candidate's angle).
  double operator()(const std::vector<double>& xs, const std::vector<double>& ys, double x, double y) const {
    const double inv = table_.inverse_piece;
    const double ox = (x - table_.origin_x) * inv, oy = (y - table_.origin_y) * inv;
    const double sum =
        detail::match_score_sum(xs.data(), ys.data(), xs.size(), ox, oy, table_, weights_.data(), weights_.size(), vectors_);
    return sum / static_cast<double>(xs.size());
  }

 private:
  DistanceField::LowerBounds table_;
  std::vector<float> weights_;
  // Whether every order of summing the weights gives the same bits, so that
  // lanes may sum apart.
  bool vectors_ = false;
};

void turn(const std::vector<Vec2>& in, double angle, std::vector<double>& xs, std::vector<double>& ys) {
  const double c = std::cos(angle), s = std::sin(angle);
  xs.resize(in.size());
  ys.resize(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    xs[i] = c * in[i].x() - s * in[i].y();
    ys[i] = s * in[i].x() + c * in[i].y();
  }
}

}  // namespace

ScanMatcher::ScanMatcher(const ScanMatchParams& params) : params_(params) { params_.validate(); }

ScanMatch ScanMatcher::match(const ScanFrame& frame, const DistanceField& field, double depth) const {
  const ScanMatchParams& p = params_;
  const Pose2 given = frame.scan().pose;
  ScanMatch out;
  out.pose = given;
  if (!p.enabled || frame.empty()) return out;
  if (!field.has_obstacles()) {
    out.status = MatchStatus::NoMap;
    return out;
  }

  // The hits relative to the sensor, in world axes at the heading given;
  // thinned so that a wall seen up close does not outvote the rest.
  thread_local std::vector<Vec2> kept, points;
  thread_local std::vector<double> turned_x, turned_y;
  kept.clear();
  const std::vector<Vec2>& directions = frame.directions();
  for (std::size_t i = 0; i < frame.size(); ++i) {
    if (!frame.has_hit(i)) continue;
    const Vec2 q = (frame.range(i) + depth) * directions[i];
    if (kept.empty() || (q - kept.back()).norm() >= p.point_spacing) kept.push_back(q);
  }
  if (kept.size() < static_cast<std::size_t>(p.min_points)) {
    out.status = MatchStatus::TooFewPoints;
    out.points = kept.size();
    return out;
  }
  const std::size_t m = std::min(kept.size(), static_cast<std::size_t>(p.max_points));
  points.resize(m);
  for (std::size_t k = 0; k < m; ++k) points[k] = kept[k * kept.size() / m];
  out.points = m;

  const Scorer score(field, p.sigma, m);
  const auto count = [](double window, double step) { return static_cast<int>(std::floor(window / step + 1e-9)); };
  const int nxy = count(p.window_xy, p.step_xy), ntheta = count(p.window_theta, p.step_theta);
  const auto better = [&](const Candidate& a, const Candidate& b) {
    if (a.score != b.score) return a.score > b.score;
    return a.move(p.window_xy, p.window_theta) < b.move(p.window_xy, p.window_theta);
  };

  // Coarse: every pose of the window.
  thread_local std::vector<Candidate> coarse;
  coarse.clear();
  Candidate best;
  for (int a = -ntheta; a <= ntheta; ++a) {
    const double dtheta = a * p.step_theta;
    turn(points, dtheta, turned_x, turned_y);
    for (int i = -nxy; i <= nxy; ++i)
      for (int j = -nxy; j <= nxy; ++j) {
        Candidate c{i * p.step_xy, j * p.step_xy, dtheta, 0.0};
        c.score = score(turned_x, turned_y, given.x + c.dx, given.y + c.dy);
        coarse.push_back(c);
        if (a == 0 && i == 0 && j == 0) out.given_score = c.score;
        if (better(c, best)) best = c;
      }
  }

  // Fine: halved steps around the best, never leaving the window.
  double step_xy = p.step_xy, step_theta = p.step_theta;
  const double eps = 1e-9;
  while (step_xy > p.final_step_xy * (1.0 + 1e-9)) {
    step_xy *= 0.5;
    step_theta *= 0.5;
    const Candidate centre = best;
    for (int a = -1; a <= 1; ++a) {
      const double dtheta = centre.dtheta + a * step_theta;
      if (std::abs(dtheta) > p.window_theta + eps) continue;
      turn(points, dtheta, turned_x, turned_y);
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) {
          if (a == 0 && i == 0 && j == 0) continue;
          Candidate c{centre.dx + i * step_xy, centre.dy + j * step_xy, dtheta, 0.0};
          if (std::abs(c.dx) > p.window_xy + eps || std::abs(c.dy) > p.window_xy + eps) continue;
          c.score = score(turned_x, turned_y, given.x + c.dx, given.y + c.dy);
          if (better(c, best)) best = c;
        }
    }
  }

  out.pose = Pose2{given.x + best.dx, given.y + best.dy, wrap_angle(given.theta + best.dtheta)};
  out.score = best.score;
  for (const Candidate& c : coarse)
    if (std::hypot(c.dx - best.dx, c.dy - best.dy) > p.ambiguity_radius) out.runner_up = std::max(out.runner_up, c.score);
  if (out.score < p.min_score) out.status = MatchStatus::PoorFit;
  else if (out.score < out.given_score + p.margin) out.status = MatchStatus::NotBetter;
  else if (out.runner_up > out.score - p.margin) out.status = MatchStatus::Ambiguous;
  else out.status = MatchStatus::Accepted;
  return out;
}

}  // namespace fgdwa
