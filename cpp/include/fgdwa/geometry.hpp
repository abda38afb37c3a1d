#pragma once
// Plain value types of the plane: poses, velocity commands, trajectories.
#include <Eigen/Core>
#include <vector>

namespace fgdwa {

using Vec2 = Eigen::Vector2d;

struct Pose2 {
  double x = 0.0;      // m
  double y = 0.0;      // m
  double theta = 0.0;  // rad, counter-clockwise from +x
  Vec2 position() const { return {x, y}; }
};

struct Twist {
  double v = 0.0;      // m/s, forward speed
  double omega = 0.0;  // rad/s, counter-clockwise
};

// Poses after each time step of a rollout; the start pose is not included.
using Trajectory = std::vector<Pose2>;

// Angle in (-pi, pi].
double wrap_angle(double angle);

// Smallest signed difference a - b, in (-pi, pi].
double angle_difference(double a, double b);

// Distance from p to the segment a-b (to a when the segment is a point).
double point_segment_distance(const Vec2& p, const Vec2& a, const Vec2& b);

}  // namespace fgdwa
