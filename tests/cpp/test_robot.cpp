#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <vector>

#include "fgdwa/error.hpp"
#include "fgdwa/presets.hpp"
#include "fgdwa/robot.hpp"
#include "test_support.hpp"

namespace fgdwa {
namespace {

using test::expect_error_naming;

TEST(RobotLimits, DefaultsAreValidAndBrakingFallsBackToAcceleration) {
  RobotLimits limits;
  EXPECT_NO_THROW(limits.validate());
  EXPECT_EQ(limits.braking_v(), limits.acc_v);
  EXPECT_EQ(limits.braking_omega(), limits.acc_omega);
  limits.brake_v = 3.0;
  limits.brake_omega = 4.0;
  EXPECT_EQ(limits.braking_v(), 3.0);
  EXPECT_EQ(limits.braking_omega(), 4.0);
}

TEST(RobotLimits, RejectsNonFiniteAndNegativeFieldsByName) {
  struct Field {
    const char* name;
    double RobotLimits::*member;
  };
  const Field fields[] = {
      {"v_min", &RobotLimits::v_min},         {"v_max", &RobotLimits::v_max},
      {"omega_max", &RobotLimits::omega_max}, {"acc_v", &RobotLimits::acc_v},
      {"acc_omega", &RobotLimits::acc_omega}, {"brake_v", &RobotLimits::brake_v},
      {"brake_omega", &RobotLimits::brake_omega},
  };
  for (const Field& f : fields) {
    for (double bad : {std::nan(""), test::kInf, -test::kInf, -0.5}) {
      SCOPED_TRACE(std::string(f.name) + " = " + std::to_string(bad));
      RobotLimits limits;
      limits.*f.member = bad;
      expect_error_naming([&] { limits.validate(); }, f.name);
    }
  }
  // Zero is a valid minimum speed and means "same as acceleration" for braking,
  // but a zero top speed, turn rate or acceleration leaves the robot unable to move.
  for (const Field& f : fields) {
    RobotLimits limits;
    limits.*f.member = 0.0;
    const std::string name = f.name;
    if (name == "v_min" || name == "brake_v" || name == "brake_omega")
      EXPECT_NO_THROW(limits.validate()) << name;
    else
      expect_error_naming([&] { limits.validate(); }, f.name);
  }
}

TEST(RobotLimits, RejectsInvertedSpeedRange) {
  RobotLimits limits;
  limits.v_min = 1.5;
  limits.v_max = 1.0;
  expect_error_naming([&] { limits.validate(); }, "v_min");
  limits.v_min = 1.0;  // equal ends are a fixed speed, still valid
  EXPECT_NO_THROW(limits.validate());
}

TEST(Footprint, CircleRejectsNonPositiveRadius) {
  for (double r : {0.0, -0.1, std::nan(""), test::kInf}) expect_error_naming([&] { Footprint::circle(r); }, "radius");
  const Footprint fp = Footprint::circle(0.3);
  EXPECT_TRUE(fp.is_circle());
  EXPECT_EQ(fp.radius(), 0.3);
  EXPECT_EQ(fp.inscribed_radius(), 0.3);
}

TEST(Footprint, PolygonRejectsBadShapes) {
  expect_error_naming([] { Footprint::polygon({{1, 0}, {0, 1}}); }, "vertices");
  expect_error_naming([] { Footprint::polygon({}); }, "vertices");
  expect_error_naming([] { Footprint::polygon({{1, 0}, {0, 1}, {-1, std::nan("")}}); }, "vertex");
  // Collinear points enclose no area.
  expect_error_naming([] { Footprint::polygon({{-1, 0}, {0, 0}, {1, 0}}); }, "area");
  // An arrow head: the notch at (-0.5, 0) makes it non-convex while the origin stays inside.
  expect_error_naming([] { Footprint::polygon({{1, 0}, {-1, 1}, {-0.5, 0}, {-1, -1}}); }, "convex");
  // A square that does not contain the robot's origin.
  expect_error_naming([] { Footprint::polygon({{1, 1}, {2, 1}, {2, 2}, {1, 2}}); }, "origin");
}

TEST(Footprint, PolygonAcceptsEitherWindingAndStoresCounterClockwise) {
  const Footprint cw = Footprint::polygon({{0.3, 0.2}, {0.3, -0.2}, {-0.1, -0.2}, {-0.1, 0.2}});
  const auto& v = cw.vertices();
  ASSERT_EQ(v.size(), 4u);
  double area2 = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec2 a = v[i], b = v[(i + 1) % v.size()];
    area2 += a.x() * b.y() - a.y() * b.x();
  }
  EXPECT_NEAR(area2, 2 * 0.4 * 0.4, 1e-12);  // positive: counter-clockwise
  EXPECT_NEAR(cw.radius(), std::hypot(0.3, 0.2), 1e-15);
  EXPECT_NEAR(cw.inscribed_radius(), 0.1, 1e-15);
  // Off-centre, the footprint is still 0.4 m wide: a point inside can lie 0.2 m in.
  EXPECT_NEAR(cw.half_width(), 0.2, 1e-15);
  EXPECT_NEAR(cw.signed_distance(Pose2{}, {0.1, 0.0}), -0.2, 1e-15);
}

TEST(Footprint, HalfWidthBoundsHowDeepAPointLiesInside) {
  EXPECT_EQ(Footprint::circle(0.3).half_width(), 0.3);
  // A right triangle with legs 1 and 2: its least width is its height over the hypotenuse.
  const Footprint triangle = Footprint::polygon({{-0.3, -0.3}, {0.7, -0.3}, {-0.3, 1.7}});
  EXPECT_NEAR(triangle.half_width(), 0.5 * 2.0 / std::sqrt(5.0), 1e-15);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 1.7);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 p(u(rng), u(rng));
    EXPECT_GE(triangle.signed_distance(Pose2{}, p), -triangle.half_width() - 1e-15);
  }
}

// The signed distance is the least edge distance, to the bit (one root of
// the least square), negative inside: for a rectangle, a triangle and a
// pentagon.
TEST(Footprint, SignedDistanceIsTheLeastEdgeDistanceToTheBit) {
  const Footprint shapes[] = {Footprint::polygon({{-0.21, -0.165}, {0.21, -0.165}, {0.21, 0.165}, {-0.21, 0.165}}),
                              Footprint::polygon({{0.6, 0.0}, {-0.3, 0.45}, {-0.3, -0.45}}),
                              Footprint::polygon({{0.4, -0.2}, {0.5, 0.0}, {0.4, 0.2}, {-0.3, 0.25}, {-0.35, -0.1}})};
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int inside = 0;
  for (const Footprint& shape : shapes) {
    const std::vector<Vec2>& v = shape.vertices();
    for (int i = 0; i < 20000; ++i) {
      const Vec2 q(u(rng), u(rng));
      double least = std::numeric_limits<double>::infinity();
      for (std::size_t j = 0; j < v.size(); ++j) least = std::min(least, point_segment_distance(q, v[j], v[(j + 1) % v.size()]));
      const bool in = shape.contains(Pose2{}, q);
      ASSERT_EQ(shape.signed_distance_in_frame(q), in ? -least : least) << q.transpose();
      inside += in;
    }
  }
  EXPECT_GT(inside, 3000);
}

TEST(Footprint, SignedDistanceOfCircleAndPolygon) {
  const Footprint circle = Footprint::circle(0.5);
  const Pose2 pose{1.0, 2.0, 0.7};
  EXPECT_NEAR(circle.signed_distance(pose, {1.0, 3.0}), 0.5, 1e-15);
  EXPECT_NEAR(circle.signed_distance(pose, {1.2, 2.0}), -0.3, 1e-15);
  EXPECT_TRUE(circle.contains(pose, {1.2, 2.0}));

  // A 0.4 x 0.2 rectangle, forward of the origin, rotated a quarter turn.
  const Footprint rect = Footprint::polygon({{-0.1, -0.1}, {0.3, -0.1}, {0.3, 0.1}, {-0.1, 0.1}});
  const Pose2 up{0.0, 0.0, M_PI / 2};
  EXPECT_NEAR(rect.signed_distance(up, {0.0, 1.3}), 1.0, 1e-12);   // ahead of the front edge
  EXPECT_NEAR(rect.signed_distance(up, {0.5, 0.0}), 0.4, 1e-12);   // right of the right edge
  EXPECT_NEAR(rect.signed_distance(up, {0.0, 0.25}), -0.05, 1e-12);
  EXPECT_NEAR(rect.signed_distance(up, {0.4, 0.6}), std::hypot(0.3, 0.3), 1e-12);  // off a corner
  EXPECT_FALSE(rect.contains(up, {0.25, 0.0}));
  EXPECT_TRUE(rect.contains(up, {0.05, 0.25}));

  // In the robot's frame: the same distances, the point turned by the caller.
  EXPECT_NEAR(rect.signed_distance_in_frame({1.3, 0.0}), 1.0, 1e-12);
  EXPECT_NEAR(rect.signed_distance_in_frame({0.25, 0.0}), -0.05, 1e-12);
  EXPECT_NEAR(circle.signed_distance_in_frame({0.0, 1.0}), 0.5, 1e-15);
  for (const Footprint& fp : {circle, rect}) {
    EXPECT_THROW(fp.signed_distance_in_frame({std::nan(""), 0.0}), Error);
    EXPECT_THROW(fp.signed_distance_in_frame({0.0, std::numeric_limits<double>::infinity()}), Error);
  }
}

// Every point of the footprint lies in one of its cover discs, and no disc
// reaches farther past the outline than half its piece's diagonal.
// The bounding box holds every vertex and touches the outline on each side;
// a point's distance from it never exceeds its distance from the footprint.
TEST(Footprint, BoundingBoxIsTheVerticesExtremesAndBoundsTheDistance) {
  const Footprint triangle = Footprint::polygon({{-0.2, -0.3}, {0.5, 0.1}, {-0.1, 0.25}});
  EXPECT_EQ(triangle.box_min(), Vec2(-0.2, -0.3));
  EXPECT_EQ(triangle.box_max(), Vec2(0.5, 0.25));
  const Footprint circle = Footprint::circle(0.3);
  EXPECT_EQ(circle.box_min(), Vec2(-0.3, -0.3));
  EXPECT_EQ(circle.box_max(), Vec2(0.3, 0.3));
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) {
    const Vec2 q(u(rng), u(rng));
    for (const Footprint& fp : {triangle, circle}) {
      const Vec2 below = fp.box_min() - q, above = q - fp.box_max();
      EXPECT_LE(std::max({below.x(), below.y(), above.x(), above.y()}), fp.signed_distance_in_frame(q) + 1e-12);
    }
  }
}

TEST(Footprint, CoverDiscsCoverTheFootprint) {
  std::mt19937 rng(5);
  for (const Footprint& fp : {Footprint::circle(0.3),
                              Footprint::polygon({{0.21, 0.165}, {-0.21, 0.165}, {-0.21, -0.165}, {0.21, -0.165}}),
                              Footprint::polygon({{0.4, 0.0}, {0.0, 0.1}, {-0.1, 0.0}, {0.0, -0.1}}),
                              Footprint::polygon({{-0.2, -0.15}, {0.2, -0.15}, {0.05, 0.15}, {-0.05, 0.15}})}) {
    std::uniform_real_distribution<double> u(-fp.radius(), fp.radius());
    int inside = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      const Vec2 p(u(rng), u(rng));
      if (!fp.contains(Pose2{}, p)) continue;
      ++inside;
      bool covered = false;
      for (const Footprint::CoverDisc& d : fp.cover()) covered = covered || (p - d.centre).norm() <= d.radius;
      ASSERT_TRUE(covered) << p.transpose();
    }
    EXPECT_GT(inside, 1000);
    for (const Footprint::CoverDisc& d : fp.cover()) EXPECT_LE(d.radius, fp.radius() + 1e-12);
  }
  // The Jackal's 0.42 m x 0.33 m: pieces of at most half the short side.
  const Footprint jackal = Footprint::polygon({{0.21, 0.165}, {-0.21, 0.165}, {-0.21, -0.165}, {0.21, -0.165}});
  EXPECT_EQ(jackal.cover().size(), 6u);
  for (const Footprint::CoverDisc& d : jackal.cover()) EXPECT_NEAR(d.radius, 0.5 * std::hypot(0.14, 0.165), 1e-12);
}

TEST(Footprint, HeadingChordIsTheShortestChordAlongTheHeading) {
  EXPECT_EQ(Footprint::circle(0.3).heading_chord(), 0.0);
  EXPECT_NEAR(Footprint::polygon({{0.21, 0.165}, {-0.21, 0.165}, {-0.21, -0.165}, {0.21, -0.165}}).heading_chord(),
              0.42, 1e-12);
  // Narrowest at the top edge.
  EXPECT_NEAR(Footprint::polygon({{-0.2, -0.15}, {0.2, -0.15}, {0.05, 0.15}, {-0.05, 0.15}}).heading_chord(), 0.1,
              1e-12);
  // A vertex alone at the top.
  EXPECT_EQ(Footprint::polygon({{0.4, 0.0}, {0.0, 0.1}, {-0.1, 0.0}, {0.0, -0.1}}).heading_chord(), 0.0);
  // Turned a quarter: the long sides run across the heading.
  EXPECT_NEAR(Footprint::polygon({{0.165, 0.21}, {-0.165, 0.21}, {-0.165, -0.21}, {0.165, -0.21}}).heading_chord(),
              0.33, 1e-12);
}

// unicycle_step() turns first, then moves along the new heading.
TEST(Step, TurnsThenMovesAlongTheNewHeading) {
  const Pose2 start{1.0, 2.0, 0.3};
  const Twist twist{2.0, 0.5};
  const double dt = 0.1;
  const Pose2 next = unicycle_step(start, twist, dt);
  EXPECT_DOUBLE_EQ(next.theta, 0.35);
  EXPECT_DOUBLE_EQ(next.x, 1.0 + 2.0 * std::cos(0.35) * 0.1);
  EXPECT_DOUBLE_EQ(next.y, 2.0 + 2.0 * std::sin(0.35) * 0.1);
  // The other order (move along the old heading) would land measurably elsewhere.
  EXPECT_GT(std::abs(next.y - (2.0 + 2.0 * std::sin(0.3) * 0.1)), 1e-3);
}

TEST(Step, WrapsTheHeading) {
  const Pose2 next = unicycle_step(Pose2{0.0, 0.0, 3.1}, Twist{1.0, 1.0}, 0.1);
  EXPECT_NEAR(next.theta, 3.2 - 2 * M_PI, 1e-12);
  EXPECT_NEAR(next.x, 0.1 * std::cos(3.2), 1e-15);
  EXPECT_NEAR(next.y, 0.1 * std::sin(3.2), 1e-15);
}

// The discrete model in closed form:
// sum_{j=1..k} cos(a + j b) = sin(k b / 2) / sin(b / 2) cos(a + (k + 1) b / 2), likewise for sin.
TEST(Rollout, ConstantCommandMatchesTheDiscreteClosedForm) {
  std::mt19937 rng(20240601);
  std::uniform_real_distribution<double> pos(-10, 10), angle(-M_PI, M_PI), speed(0.0, 2.0), dts(0.01, 0.3);
  std::uniform_real_distribution<double> turn(0.05, 2.0);
  std::uniform_int_distribution<int> steps(1, 60);
  std::bernoulli_distribution sign;
  for (int trial = 0; trial < 500; ++trial) {
    const Pose2 start{pos(rng), pos(rng), angle(rng)};
    const Twist twist{speed(rng), (sign(rng) ? 1 : -1) * turn(rng)};
    const double dt = dts(rng);
    const int n = steps(rng);
    const Trajectory poses = rollout(start, twist, dt, n);
    ASSERT_EQ(poses.size(), static_cast<std::size_t>(n));
    const double a = start.theta, b = twist.omega * dt;
    for (int k = 1; k <= n; ++k) {
      const double gain = std::sin(k * b / 2) / std::sin(b / 2);
      const double mid = a + (k + 1) * b / 2;
      const Pose2& p = poses[static_cast<std::size_t>(k - 1)];
      ASSERT_NEAR(p.x, start.x + twist.v * dt * gain * std::cos(mid), 1e-9) << "trial " << trial << " k " << k;
      ASSERT_NEAR(p.y, start.y + twist.v * dt * gain * std::sin(mid), 1e-9) << "trial " << trial << " k " << k;
      ASSERT_NEAR(angle_difference(p.theta, a + k * b), 0.0, 1e-9);
      ASSERT_GT(p.theta, -M_PI);
      ASSERT_LE(p.theta, M_PI);
    }
  }
}

// Against the continuous arc of radius v / omega the discrete model is off by
// |sin(k b / 2)| v dt |e^{i b / 2} / sin(b / 2) - 2 / b| (b = omega dt): about one
// step length v dt, since it moves along the end-of-step heading.
TEST(Rollout, StaysWithinOneStepOfTheContinuousArc) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), speed(0.1, 2.0), dts(0.01, 0.3), turn(-2.0, 2.0);
  for (int trial = 0; trial < 300; ++trial) {
    const Pose2 start{0.5, -1.5, angle(rng)};
    const Twist twist{speed(rng), turn(rng)};
    if (std::abs(twist.omega) < 1e-3) continue;
    const double dt = dts(rng);
    const int n = 40;
    const Trajectory poses = rollout(start, twist, dt, n);
    const double radius = twist.v / twist.omega, b = twist.omega * dt;
    const double gap = std::abs(std::polar(1.0, b / 2) / std::sin(b / 2) - 2.0 / b);
    ASSERT_LE(gap, 1.01);  // |omega dt| <= 0.6 here: within 1 % of one step
    for (int k = 1; k <= n; ++k) {
      const double th = start.theta + twist.omega * k * dt;
      const Vec2 arc(start.x + radius * (std::sin(th) - std::sin(start.theta)),
                     start.y - radius * (std::cos(th) - std::cos(start.theta)));
      const double off = (poses[static_cast<std::size_t>(k - 1)].position() - arc).norm();
      ASSERT_NEAR(off, std::abs(std::sin(k * b / 2)) * twist.v * dt * gap, 1e-9) << "trial " << trial << " k " << k;
      ASSERT_LE(off, 1.01 * twist.v * dt);
    }
  }
}

TEST(Rollout, ZeroTurnRateIsAStraightLine) {
  const Pose2 start{1.0, -2.0, 2.5};
  const Trajectory poses = rollout(start, Twist{0.8, 0.0}, 0.15, 20);
  for (int k = 1; k <= 20; ++k) {
    const Pose2& p = poses[static_cast<std::size_t>(k - 1)];
    EXPECT_NEAR(p.x, 1.0 + 0.8 * 0.15 * k * std::cos(2.5), 1e-12);
    EXPECT_NEAR(p.y, -2.0 + 0.8 * 0.15 * k * std::sin(2.5), 1e-12);
    EXPECT_EQ(p.theta, 2.5);
  }
}

TEST(Rollout, EqualsRepeatedSteps) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> pos(-5, 5), angle(-4.0, 4.0), speed(0.0, 1.5), turn(-3.0, 3.0), dts(0.01, 0.3);
  Trajectory poses;  // reused: the overload resizes it
  for (int trial = 0; trial < 300; ++trial) {
    const Pose2 start{pos(rng), pos(rng), angle(rng)};  // unwrapped on purpose
    const Twist twist{speed(rng), trial % 5 == 0 ? 0.0 : turn(rng)};
    const double dt = dts(rng);
    const int n = 1 + trial % 50;
    rollout(start, twist, dt, n, poses);
    ASSERT_EQ(poses.size(), static_cast<std::size_t>(n));
    Pose2 p = start;
    for (int k = 0; k < n; ++k) {
      p = unicycle_step(p, twist, dt);
      const Pose2& q = poses[static_cast<std::size_t>(k)];
      ASSERT_NEAR(q.x, p.x, 1e-12) << "trial " << trial << " k " << k;
      ASSERT_NEAR(q.y, p.y, 1e-12) << "trial " << trial << " k " << k;
      ASSERT_NEAR(angle_difference(q.theta, p.theta), 0.0, 1e-12) << "trial " << trial << " k " << k;
    }
  }
  rollout(Pose2{}, Twist{1.0, 0.0}, 0.1, 0, poses);
  EXPECT_TRUE(poses.empty());
}

TEST(Geometry, WrapAngleRange) {
  EXPECT_DOUBLE_EQ(wrap_angle(M_PI), M_PI);
  EXPECT_DOUBLE_EQ(wrap_angle(-M_PI), M_PI);
  EXPECT_NEAR(wrap_angle(3 * M_PI + 0.1), -M_PI + 0.1, 1e-12);
  EXPECT_NEAR(angle_difference(0.1, 2 * M_PI - 0.1), 0.2, 1e-12);
}

// Wrapping is the IEEE remainder by 2 pi, moved from -pi to pi, to the bit:
// near the ends of each shortcut, across whole turns, and at random.
TEST(Geometry, WrapAngleIsTheRemainderToTheBit) {
  const auto reference = [](double angle) {
    double wrapped = std::remainder(angle, 2.0 * M_PI);
    if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
    return wrapped;
  };
  std::vector<double> angles;
  for (double edge : {M_PI, -M_PI, 3 * M_PI, -3 * M_PI, 7.0, -7.0, 2 * M_PI, -2 * M_PI, 0.0, 5 * M_PI})
    for (int ulps = -3; ulps <= 3; ++ulps) {
      double a = edge;
      for (int u = 0; u < std::abs(ulps); ++u) a = std::nextafter(a, ulps > 0 ? 100.0 : -100.0);
      angles.push_back(a);
    }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> turns(-20.0, 20.0);
  for (int i = 0; i < 100000; ++i) angles.push_back(turns(rng));
  for (double a : angles) {
    const double got = wrap_angle(a), want = reference(a);
    ASSERT_EQ(std::memcmp(&got, &want, sizeof got), 0) << std::hexfloat << a << " -> " << got << ", not " << want;
  }
}


TEST(Footprint, PaddedGrowsEverySideByTheMargin) {
  const Footprint box = Footprint::polygon({{0.21, 0.165}, {-0.21, 0.165}, {-0.21, -0.165}, {0.21, -0.165}});
  const Footprint grown = box.padded(0.05);
  ASSERT_EQ(grown.vertices().size(), 4u);
  for (const Vec2& v : grown.vertices()) {
    EXPECT_NEAR(std::abs(v.x()), 0.26, 1e-12);
    EXPECT_NEAR(std::abs(v.y()), 0.215, 1e-12);
  }
  // A triangle: every point of the grown outline lies `margin` off the original.
  const Footprint triangle = Footprint::polygon({{0.4, 0.0}, {-0.2, 0.25}, {-0.2, -0.25}});
  const Footprint wider = triangle.padded(0.1);
  for (std::size_t i = 0; i < 3; ++i) {
    const Vec2 a = wider.vertices()[i], b = wider.vertices()[(i + 1) % 3];
    EXPECT_NEAR(triangle.signed_distance(Pose2{}, 0.5 * (a + b)), 0.1, 1e-9);
  }
  EXPECT_DOUBLE_EQ(Footprint::circle(0.25).padded(0.05).radius(), 0.3);
  EXPECT_DOUBLE_EQ(box.padded(0.0).radius(), box.radius());
  expect_error_naming([&] { box.padded(-0.01); }, "footprint padding");
  expect_error_naming([&] { box.padded(std::nan("")); }, "footprint padding");
}

TEST(Presets, TheJackalIsPlannedAsBarnsBoxAndJudgedAsItsBody) {
  const RobotPreset jackal = robot_preset("jackal");
  EXPECT_NEAR(jackal.footprint.vertices()[0].norm(), std::hypot(0.21, 0.165), 1e-12);
  for (const Vec2& v : jackal.outline.vertices()) {
    EXPECT_NEAR(std::abs(v.x()), 0.254, 1e-12);
    EXPECT_NEAR(std::abs(v.y()), 0.215, 1e-12);
  }
  const RobotPreset plain = robot_preset("default");
  EXPECT_EQ(plain.outline.radius(), plain.footprint.radius());
}

}  // namespace
}  // namespace fgdwa
