#include "fgdwa/robot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "validation.hpp"

namespace fgdwa {

using detail::describe;

void RobotLimits::check_relations(const ParamPath& path) const {
  if (v_min > v_max)
    fail_param(path.field("v_min"), detail::format_number(v_min),
               "must be <= v_max = " + detail::format_number(v_max) + " (m/s)");
  for (const auto& [name, value] : {std::pair{"brake_v", brake_v}, std::pair{"brake_omega", brake_omega}})
    if (value != 0.0 && value < limits::kMinAcceleration)
      fail_param(path.field(name), detail::format_number(value),
                 "must be 0 (the acceleration's) or >= " + detail::format_number(limits::kMinAcceleration) + " (m/s^2)");
}

Footprint Footprint::circle(double radius) {
  detail::require_positive("footprint radius", radius);
  detail::require_at_most("footprint radius", radius, limits::kMaxFootprintRadius);
  Footprint fp;
  fp.radius_ = radius;
  fp.inscribed_radius_ = radius;
  fp.half_width_ = radius;
  fp.box_min_ = Vec2(-radius, -radius);
  fp.box_max_ = Vec2(radius, radius);
  fp.cover_.push_back({Vec2::Zero(), radius});
  return fp;
}

namespace {
double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
}  // namespace

Footprint Footprint::padded(double margin) const {
  detail::require_magnitude("footprint padding", margin, limits::kMaxFootprintRadius);
  if (margin < 0.0) throw Error(describe("footprint padding", margin, "must be >= 0 (m)"));
  if (margin == 0.0) return *this;
  if (is_circle()) return circle(radius_ + margin);
  // Each edge moves out by `margin` along its normal; a vertex moves to where
  // its two moved edges meet. Counter-clockwise, the outward normal of an
  // edge e is (e.y, -e.x) / |e|.
  const std::size_t n = vertices_.size();
  std::vector<Vec2> grown(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& prev = vertices_[(i + n - 1) % n];
    const Vec2& here = vertices_[i];
    const Vec2& next = vertices_[(i + 1) % n];
    const Vec2 a = (here - prev).normalized(), b = (next - here).normalized();
    const Vec2 na(a.y(), -a.x()), nb(b.y(), -b.x());
    // The point p with (p - here).na = (p - here).nb = margin.
    const Vec2 bisector = na + nb;
    grown[i] = here + bisector * (margin / (1.0 + na.dot(nb)));
  }
  return polygon(std::move(grown));
}

Footprint Footprint::polygon(std::vector<Vec2> vertices) {
  if (vertices.size() < 3)
    throw Error(describe("footprint vertices", vertices.size(), "a polygon needs at least 3 vertices"));
  if (vertices.size() > static_cast<std::size_t>(limits::kMaxPolygonVertices))
    throw Error(describe("footprint vertices", vertices.size(),
                         "a polygon has at most " + std::to_string(limits::kMaxPolygonVertices)));
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const std::string name = "footprint vertex " + std::to_string(i);
    detail::require_magnitude(name + " x", vertices[i].x(), limits::kMaxFootprintRadius);
    detail::require_magnitude(name + " y", vertices[i].y(), limits::kMaxFootprintRadius);
  }
  double area2 = 0.0;
  const size_t n = vertices.size();
  for (size_t i = 0; i < n; ++i) area2 += cross(vertices[i], vertices[(i + 1) % n]);
  if (std::abs(area2) < 1e-12) throw Error("footprint polygon has zero area");
  if (area2 < 0.0) std::reverse(vertices.begin(), vertices.end());
  for (size_t i = 0; i < n; ++i) {
    const Vec2 e1 = vertices[(i + 1) % n] - vertices[i];
    const Vec2 e2 = vertices[(i + 2) % n] - vertices[(i + 1) % n];
    if (cross(e1, e2) < -1e-12)
      throw Error(describe("footprint vertex", (i + 1) % n, "polygon is not convex at this vertex"));
  }
  // Turning the same way at every vertex, a simple outline turns once around;
  // a self-intersecting one (a star) turns two or more times.
  double turning = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const Vec2 e1 = vertices[(i + 1) % n] - vertices[i];
    const Vec2 e2 = vertices[(i + 2) % n] - vertices[(i + 1) % n];
    turning += std::atan2(cross(e1, e2), e1.dot(e2));
  }
  if (std::abs(turning - 2.0 * M_PI) > 1e-6)
    throw Error(describe("footprint polygon", detail::format_number(turning / (2.0 * M_PI)) + " turns",
                         "the outline intersects itself (a convex polygon turns once around)"));
  Footprint fp;
  fp.vertices_ = std::move(vertices);
  for (const Vec2& v : fp.vertices_) fp.radius_ = std::max(fp.radius_, v.norm());
  if (!fp.contains(Pose2{}, Vec2::Zero()))
    throw Error("footprint polygon must contain the robot origin (0, 0)");
  fp.inscribed_radius_ = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i)
    fp.inscribed_radius_ = std::min(
        fp.inscribed_radius_, point_segment_distance(Vec2::Zero(), fp.vertices_[i], fp.vertices_[(i + 1) % n]));
  // The width across each edge is the farthest vertex from its line; a disc
  // inside fits between that line and the parallel one through the vertex.
  fp.half_width_ = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < n; ++i) {
    const Vec2 a = fp.vertices_[i], edge = fp.vertices_[(i + 1) % n] - a;
    double width = 0.0;
    for (const Vec2& v : fp.vertices_) width = std::max(width, cross(edge, v - a));
    width /= edge.norm();
    fp.half_width_ = std::min(fp.half_width_, 0.5 * width);
  }
  Vec2 lo = fp.vertices_[0], hi = fp.vertices_[0];
  for (const Vec2& v : fp.vertices_) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  fp.box_min_ = lo;
  fp.box_max_ = hi;
  const Vec2 size = hi - lo;
  // A convex shape's chords along x are concave in y: the shortest lie at its
  // lowest and highest y.
  const auto chord_at = [&](double y) {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
    for (const Vec2& v : fp.vertices_)
      if (std::abs(v.y() - y) <= 1e-12 * std::max(1.0, size.y())) x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
    return x1 - x0;
  };
  fp.heading_chord_ = std::min(chord_at(lo.y()), chord_at(hi.y()));
  // Pieces of at most half the short side: a disc's reach beyond the outline,
  // which is what its bound gives away, shrinks with the piece.
  const double side = 0.5 * std::min(size.x(), size.y());
  const int nx = std::max(1, static_cast<int>(std::ceil(size.x() / side - 1e-9)));
  const int ny = std::max(1, static_cast<int>(std::ceil(size.y() / side - 1e-9)));
  const double px = size.x() / nx, py = size.y() / ny;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      fp.cover_.push_back({lo + Vec2((i + 0.5) * px, (j + 0.5) * py), 0.5 * std::hypot(px, py)});
  return fp;
}

namespace {
Vec2 to_robot_frame(const Pose2& pose, const Vec2& p) {
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  const double dx = p.x() - pose.x, dy = p.y() - pose.y;
  return {c * dx + s * dy, -s * dx + c * dy};
}
}  // namespace

bool Footprint::contains(const Pose2& pose, const Vec2& p) const {
  detail::require_query_pose("pose", pose);
  detail::require_query_point("point", p);
  if (is_circle()) return (p - pose.position()).norm() <= radius_;
  return polygon_contains(to_robot_frame(pose, p));
}

bool Footprint::polygon_contains(const Vec2& q) const {
  const size_t n = vertices_.size();
  for (size_t i = 0; i < n; ++i)
    if (cross(vertices_[(i + 1) % n] - vertices_[i], q - vertices_[i]) < 0.0) return false;
  return true;
}

double Footprint::signed_distance(const Pose2& pose, const Vec2& p) const {
  detail::require_query_pose("pose", pose);
  detail::require_query_point("point", p);
  if (is_circle()) return (p - pose.position()).norm() - radius_;
  return signed_distance_in_frame(to_robot_frame(pose, p));
}

double Footprint::signed_distance_in_frame(const Vec2& q) const {
  detail::require_query_point("point", q);
  if (is_circle()) return q.norm() - radius_;
  // The least squared distance to an edge, then one root: the root is
  // monotonic and correctly rounded, so the least root is the root of the least.
  double d2 = std::numeric_limits<double>::infinity();
  const size_t n = vertices_.size();
  for (size_t i = 0; i < n; ++i) d2 = std::min(d2, detail::point_segment_distance2(q, vertices_[i], vertices_[i + 1 == n ? 0 : i + 1]));
  const double d = std::sqrt(d2);
  return polygon_contains(q) ? -d : d;
}

Pose2 unicycle_step(const Pose2& pose, const Twist& twist, double dt) {
  detail::require_query_pose("pose", pose);
  detail::require_twist("twist", twist);
  detail::require_step_length("dt", dt);
  Pose2 next;
  next.theta = wrap_angle(pose.theta + twist.omega * dt);
  next.x = pose.x + twist.v * std::cos(next.theta) * dt;
  next.y = pose.y + twist.v * std::sin(next.theta) * dt;
  return next;
}

void RolloutHeadings::assign(double start_theta, double cos_start, double sin_start, double omega, double dt,
                             int n_steps) {
  assign(start_theta, cos_start, sin_start, omega, omega, 1.0, 1.0, dt, n_steps);
}

void RolloutHeadings::assign(double start_theta, double cos_start, double sin_start, double omega_now, double omega,
                             double rise, double fall, double dt, int n_steps, double response) {
  const std::size_t n = static_cast<std::size_t>(std::max(n_steps, 0));
  theta.resize(n);
  cos.resize(n);
  sin.resize(n);
  max_turn = std::abs(omega * dt);
  double c = cos_start, s = sin_start, heading = wrap_angle(start_theta);
  std::size_t k = 0;
  // The ramp's steps, each with its own turn.
  for (; k < n && omega_now != omega; ++k) {
    const double turn = response_step(omega_now, omega, rise, fall, response, dt) * dt;
    max_turn = std::max(max_turn, std::abs(turn));
    const double cos_turn = std::cos(turn), sin_turn = std::sin(turn);
    const double c_next = c * cos_turn - s * sin_turn;
    s = s * cos_turn + c * sin_turn;
    c = c_next;
    heading = wrap_angle(heading + turn);
    theta[k] = heading;
    cos[k] = c;
    sin[k] = s;
  }
  // The heading turns by the same angle every step, so its cosine and sine are
  // advanced by a rotation instead of one sin/cos pair per pose.
  const double cos_turn = std::cos(omega * dt), sin_turn = std::sin(omega * dt), turn = wrap_angle(omega * dt);
  for (; k < n; ++k) {
    const double c_next = c * cos_turn - s * sin_turn;
    s = s * cos_turn + c * sin_turn;
    c = c_next;
    heading += turn;
    if (heading > M_PI) heading -= 2.0 * M_PI;
    else if (heading <= -M_PI) heading += 2.0 * M_PI;
    theta[k] = heading;
    cos[k] = c;
    sin[k] = s;
  }
}

void rollout(const Pose2& start, const Twist& twist, double dt, int n_steps, Trajectory& out) {
  detail::require_query_pose("start", start);
  detail::require_twist("twist", twist);
  detail::require_step_length("dt", dt);
  detail::require_count("n_steps", n_steps, 0, limits::kMaxRolloutSteps);
  thread_local RolloutHeadings headings;  // storage reused by a control loop's calls
  headings.assign(start.theta, std::cos(start.theta), std::sin(start.theta), twist.omega, dt, n_steps);
  rollout(start, twist.v * dt, headings, out);
}

void rollout(const Pose2& start, double step_length, const RolloutHeadings& headings, Trajectory& out) {
  const std::size_t n = headings.theta.size();
  out.resize(n);
  double x = start.x, y = start.y;
  for (std::size_t k = 0; k < n; ++k) {
    x += step_length * headings.cos[k];
    y += step_length * headings.sin[k];
    out[k] = Pose2{x, y, headings.theta[k]};
  }
}

Trajectory rollout(const Pose2& start, const Twist& twist, double dt, int n_steps) {
  Trajectory out;
  rollout(start, twist, dt, n_steps, out);
  return out;
}

double ramp_step(double& value, double target, double rise, double fall, double dt) {
  double t = 0.0, area = 0.0;
  // At most two pieces: toward zero at `fall`, then away from it at `rise`.
  for (int piece = 0; piece < 2 && t < dt && value != target; ++piece) {
    const bool shrinking = value > 0.0 ? target < value : value < 0.0 && target > value;
    const bool crossing = shrinking && (value > 0.0 ? target < 0.0 : target > 0.0);
    const double goal = crossing ? 0.0 : target;
    const double rate = shrinking ? fall : rise;
    const double need = std::abs(goal - value) / rate;
    const double tau = std::min(need, dt - t);
    const double next = tau == need ? goal : value + std::copysign(rate * tau, goal - value);
    area += 0.5 * (value + next) * tau;
    value = next;
    t += tau;
  }
  area += value * (dt - t);
  return area / dt;
}

double response_step(double& value, double target, double rise, double fall, double response, double dt) {
  if (response <= 0.0) return ramp_step(value, target, rise, fall, dt);
  const double keep = std::exp(-dt / response);  // what remains of the gap at the step's end
  const double mean_keep = response / dt * (1.0 - keep);  // its mean over the step
  const double lagged = target + (value - target) * keep;
  double ramped = value;
  const double ramp_mean = ramp_step(ramped, lagged, rise, fall, dt);
  const double lag_mean = target + (value - target) * mean_keep;
  // A lag never quite arrives: within a millionth (per second) it has, and the velocity holds from there.
  value = std::abs(ramped - target) < 1e-6 ? target : ramped;
  // The acceleration limits hold the wheels back further when the ramp falls short of the lag.
  return ramped == lagged ? lag_mean : ramp_mean;
}

void rollout(const Pose2& start, const Twist& current, const Twist& command, const RobotLimits& limits, double dt,
             int n_steps, Trajectory& out) {
  detail::require_query_pose("start", start);
  detail::require_twist("current", current);
  detail::require_twist("command", command);
  limits.validate();
  detail::require_step_length("dt", dt);
  detail::require_count("n_steps", n_steps, 0, limits::kMaxRolloutSteps);
  out.resize(static_cast<std::size_t>(n_steps));
  Pose2 pose = start;
  Twist now = current;
  for (int k = 0; k < n_steps; ++k) {
    Twist mean;
    mean.v = ramp_step(now.v, command.v, limits.acc_v, limits.braking_v(), dt);
    mean.omega = ramp_step(now.omega, command.omega, limits.acc_omega, limits.braking_omega(), dt);
    pose = unicycle_step(pose, mean, dt);
    out[static_cast<std::size_t>(k)] = pose;
  }
}

Trajectory rollout(const Pose2& start, const Twist& current, const Twist& command, const RobotLimits& limits,
                   double dt, int n_steps) {
  Trajectory out;
  rollout(start, current, command, limits, dt, n_steps, out);
  return out;
}

}  // namespace fgdwa
