// Tests for segment_segment_closest: closed-form cases, degenerate and parallel segments,
// symmetry, and a brute-force reference for random and nearly parallel segments.
#include "engine/contact/segment_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace wirepack {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// ---------------------------------------------------------------------------------------------
// Brute-force reference in long double (64-bit mantissa on x86-64): golden-section minimisation
// over s of h(s) = min_{t in [0,1]} |P(s) - Q(t)|^2, with t optimal in closed form (clamped
// projection). h is convex (partial minimum of a jointly convex function over a convex set), so
// golden section finds its global minimum; only the value is compared because for (nearly)
// parallel segments the minimiser is not unique (or ill conditioned).
struct Ref {
  long double s, t, dist2;
};

Ref brute_force(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  using LD = long double;
  LD r[3], d1[3], d2[3];
  for (int k = 0; k < 3; ++k) {
    r[k] = LD(p0[k]) - LD(q0[k]);
    d1[k] = LD(p1[k]) - LD(p0[k]);
    d2[k] = LD(q1[k]) - LD(q0[k]);
  }
  LD e = 0, b = 0, f = 0;
  for (int k = 0; k < 3; ++k) {
    e += d2[k] * d2[k];
    b += d1[k] * d2[k];
    f += d2[k] * r[k];
  }
  auto eval = [&](LD s) {
    LD t = e > 0 ? (b * s + f) / e : 0;
    t = std::min<LD>(1, std::max<LD>(0, t));
    LD d2sum = 0;
    for (int k = 0; k < 3; ++k) {
      const LD w = r[k] + s * d1[k] - t * d2[k];
      d2sum += w * w;
    }
    return Ref{s, t, d2sum};
  };
  const LD g = (std::sqrt(LD(5)) - 1) / 2;
  LD lo = 0, hi = 1;
  LD x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  Ref f1 = eval(x1), f2 = eval(x2);
  for (int it = 0; it < 200 && hi - lo > 1e-19L; ++it) {
    if (f1.dist2 <= f2.dist2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = eval(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = eval(x2);
    }
  }
  Ref best = f1.dist2 <= f2.dist2 ? f1 : f2;
  for (LD s : {LD(0), LD(1)}) {
    const Ref end = eval(s);
    if (end.dist2 < best.dist2) best = end;
  }
  return best;
}

// Squared distance at the returned (s, t), in long double, to check that the reported dist2
// belongs to the reported points [m^2].
long double dist2_at(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, double s,
                     double t) {
  long double sum = 0;
  for (int k = 0; k < 3; ++k) {
    const long double pk = p0[k] + s * ((long double)p1[k] - p0[k]);
    const long double qk = q0[k] + t * ((long double)q1[k] - q0[k]);
    sum += (pk - qk) * (pk - qk);
  }
  return sum;
}

// Distance tolerance [m]: 1e-12 relative, plus an absolute floor of 8 ulps of the problem's
// scale. The floor is unavoidable: the closest points are formed in double from r = p0 - q0,
// d1 and d2, so their difference carries a rounding error of a few eps * (|r| + |d1| + |d2|)
// however small the distance is (e.g. crossing segments). For distances above 1e-3 of the scale
// the relative term dominates. 1e-12 leaves room for the nearly parallel case, where the
// minimiser along the valley is ill conditioned but the distance is not (error ~ (D/e) ds^2).
double distance_tol(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1, double d_ref) {
  const double scale = (p0 - q0).norm() + (p1 - p0).norm() + (q1 - q0).norm();
  return 1e-12 * d_ref + 8 * kEps * scale;
}

// Checks the result against the brute-force reference: s, t in range, dist2 consistent with
// (s, t), distance within distance_tol of the reference.
void expect_matches_reference(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const SegmentClosest c = segment_segment_closest(p0, p1, q0, q1);
  const Ref ref = brute_force(p0, p1, q0, q1);
  ASSERT_GE(c.s, 0.0);
  ASSERT_LE(c.s, 1.0);
  ASSERT_GE(c.t, 0.0);
  ASSERT_LE(c.t, 1.0);
  const double d = std::sqrt(c.dist2);
  const double d_ref = std::sqrt(double(ref.dist2));
  const double d_at = std::sqrt(double(dist2_at(p0, p1, q0, q1, c.s, c.t)));
  const double tol = distance_tol(p0, p1, q0, q1, d_ref);
  EXPECT_NEAR(d, d_ref, tol) << "p0=" << p0.transpose() << " p1=" << p1.transpose()
                             << " q0=" << q0.transpose() << " q1=" << q1.transpose();
  EXPECT_NEAR(d, d_at, tol) << "reported dist2 does not belong to the reported (s, t)";
}

Vec3 random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v(n(rng), n(rng), n(rng));
  return v.normalized();
}

// Uniform point in [-1, 1]^3 [m].
Vec3 random_point(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return Vec3(u(rng), u(rng), u(rng));
}

// Unit vector perpendicular to u.
Vec3 random_perp(const Vec3& u, std::mt19937_64& rng) {
  Vec3 v = random_unit(rng);
  v -= v.dot(u) * u;
  return v.normalized();
}

// ---------------------------------------------------------------------------------------------
// Closed-form cases.

TEST(SegmentDistance, ParallelDisjoint) {
  const auto c = segment_segment_closest({0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 2.0);
  EXPECT_DOUBLE_EQ(c.s, 1.0);
  EXPECT_DOUBLE_EQ(c.t, 0.0);
}

TEST(SegmentDistance, ParallelOverlappingTakesMidpointOfOverlap) {
  // Overlap x in [1, 2], midpoint x = 1.5.
  auto c = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 1.0);
  EXPECT_DOUBLE_EQ(c.s, 0.75);
  EXPECT_DOUBLE_EQ(c.t, 0.25);
  // Antiparallel: same overlap, t runs the other way.
  c = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 1, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 1.0);
  EXPECT_DOUBLE_EQ(c.s, 0.75);
  EXPECT_DOUBLE_EQ(c.t, 0.75);
  // Under rigid motions the segments stay parallel to rounding level: still the midpoint.
  std::mt19937_64 rng(9);
  for (int k = 0; k < 100; ++k) {
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(6 * random_point(rng).x(), random_unit(rng)).toRotationMatrix();
    const Vec3 T = random_point(rng);  // translation [m]
    c = segment_segment_closest(R * Vec3(0, 0, 0) + T, R * Vec3(2, 0, 0) + T, R * Vec3(1, 1, 0) + T,
                                R * Vec3(3, 1, 0) + T);
    EXPECT_NEAR(c.dist2, 1.0, 1e-14);
    EXPECT_NEAR(c.s, 0.75, 1e-12);
    EXPECT_NEAR(c.t, 0.25, 1e-12);
  }
  // Contained: overlap x in [0.5, 1].
  c = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {0.5, 0, 3}, {1, 0, 3});
  EXPECT_DOUBLE_EQ(c.dist2, 9.0);
  EXPECT_DOUBLE_EQ(c.s, 0.375);
  EXPECT_DOUBLE_EQ(c.t, 0.5);
}

TEST(SegmentDistance, ParallelOverlapIsContinuousInTheShift) {
  // Sliding one segment along the other: the overlap midpoint moves continuously, the distance
  // stays exact.
  for (int k = 0; k <= 40; ++k) {
    const double x = -1.0 + 0.075 * k;  // shift of the second segment [m]
    const auto c = segment_segment_closest({0, 0, 0}, {1, 0, 0}, {x, 0.5, 0}, {x + 1, 0.5, 0});
    const double lo = std::max(0.0, x), hi = std::min(1.0, x + 1);
    if (lo <= hi) {
      EXPECT_DOUBLE_EQ(c.dist2, 0.25);
      EXPECT_NEAR(c.s, 0.5 * (lo + hi), 1e-15);
      EXPECT_NEAR(c.t, 0.5 * (lo + hi) - x, 1e-15);
    } else {
      const double gap = x > 1 ? x - 1 : -x - 1;
      EXPECT_NEAR(c.dist2, 0.25 + gap * gap, 1e-15);
    }
  }
}

TEST(SegmentDistance, Collinear) {
  // Overlapping: distance 0 on the overlap [1, 2].
  auto c = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {3, 0, 0});
  EXPECT_EQ(c.dist2, 0.0);
  EXPECT_DOUBLE_EQ(c.s, 0.75);
  EXPECT_DOUBLE_EQ(c.t, 0.25);
  // Disjoint: end to end, gap 2.
  c = segment_segment_closest({0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {4, 0, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 4.0);
  EXPECT_DOUBLE_EQ(c.s, 1.0);
  EXPECT_DOUBLE_EQ(c.t, 0.0);
  // Disjoint, reversed second segment: closest end is q1.
  c = segment_segment_closest({0, 0, 0}, {1, 0, 0}, {4, 0, 0}, {3, 0, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 4.0);
  EXPECT_DOUBLE_EQ(c.s, 1.0);
  EXPECT_DOUBLE_EQ(c.t, 1.0);
}

TEST(SegmentDistance, Touching) {
  // Collinear, end to end.
  auto c = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {2, 0, 0}, {3, 0, 0});
  EXPECT_EQ(c.dist2, 0.0);
  EXPECT_EQ(c.s, 1.0);
  EXPECT_EQ(c.t, 0.0);
  // Parallel, overlap reduced to one abscissa.
  c = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {3, 1, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 1.0);
  EXPECT_EQ(c.s, 1.0);
  EXPECT_EQ(c.t, 0.0);
  // T-junction: an end point on the interior of the other segment.
  c = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0});
  EXPECT_EQ(c.dist2, 0.0);
  EXPECT_DOUBLE_EQ(c.s, 0.25);
  EXPECT_EQ(c.t, 0.0);
}

TEST(SegmentDistance, Crossing) {
  auto c = segment_segment_closest({-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0});
  EXPECT_EQ(c.dist2, 0.0);
  EXPECT_DOUBLE_EQ(c.s, 0.5);
  EXPECT_DOUBLE_EQ(c.t, 0.5);
  // Random crossings: segments through a common point c at random parameters.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 1000; ++k) {
    const Vec3 x = random_point(rng);
    const Vec3 d1 = random_unit(rng) * (0.1 + u(rng)), d2 = random_unit(rng) * (0.1 + u(rng));
    const double s = u(rng), t = u(rng);
    const Vec3 p0 = x - s * d1, q0 = x - t * d2;
    c = segment_segment_closest(p0, p0 + d1, q0, q0 + d2);
    // Rounding p0, q0, p0 + d1, q0 + d2 (coordinates up to ~2) moves the segments off the
    // common point by a few ulps: distance below 16 eps * 4 [m].
    EXPECT_LT(std::sqrt(c.dist2), 64 * kEps);
  }
}

TEST(SegmentDistance, SkewClosedForm) {
  // Perpendicular skew: x axis and a y-parallel line at height h; closest at x = 0, y = 0.
  const double h = 0.3;
  auto c = segment_segment_closest({-1, 0, 0}, {3, 0, 0}, {0, -2, h}, {0, 2, h});
  EXPECT_NEAR(c.dist2, h * h, 1e-16);
  EXPECT_NEAR(c.s, 0.25, 1e-15);
  EXPECT_NEAR(c.t, 0.5, 1e-15);
  // Oblique skew: the second segment along (1, 1, 0) at height h passes over (x0, 0, h) at
  // t = 1/4; the common perpendicular is along z, so the distance is h.
  const double x0 = 0.7;
  c = segment_segment_closest({-1, 0, 0}, {3, 0, 0}, {x0 - 1, -1, h}, {x0 + 3, 3, h});
  EXPECT_NEAR(c.dist2, h * h, 1e-15);
  EXPECT_NEAR(c.s, (x0 + 1) / 4, 1e-15);
  EXPECT_NEAR(c.t, 0.25, 1e-15);
  // Same configuration under a rigid motion: distance unchanged.
  std::mt19937_64 rng(3);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(1.234, random_unit(rng)).toRotationMatrix();  // rotation
  const Vec3 T(5, -2, 7);                                             // translation [m]
  auto move = [&](const Vec3& x) -> Vec3 { return R * x + T; };
  c = segment_segment_closest(move({-1, 0, 0}), move({3, 0, 0}), move({x0 - 1, -1, h}),
                              move({x0 + 3, 3, h}));
  EXPECT_NEAR(c.dist2, h * h, 1e-14);
  EXPECT_NEAR(c.s, (x0 + 1) / 4, 1e-14);
  EXPECT_NEAR(c.t, 0.25, 1e-14);
}

TEST(SegmentDistance, PerpendicularOffset) {
  // Perpendicular, not crossing in projection: closest is p1 to the middle of [q0, q1].
  auto c = segment_segment_closest({0, 0, 0}, {1, 0, 0}, {2, -1, 0}, {2, 1, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 1.0);
  EXPECT_DOUBLE_EQ(c.s, 1.0);
  EXPECT_DOUBLE_EQ(c.t, 0.5);
  // Perpendicular and out of plane: closest corners p1 and q0.
  c = segment_segment_closest({0, 0, 0}, {1, 0, 0}, {2, 1, 1}, {2, 2, 1});
  EXPECT_DOUBLE_EQ(c.dist2, 3.0);
  EXPECT_DOUBLE_EQ(c.s, 1.0);
  EXPECT_DOUBLE_EQ(c.t, 0.0);
}

TEST(SegmentDistance, DegeneratePointSegment) {
  // First segment a point above the interior of the second.
  auto c = segment_segment_closest({0.5, 1, 0}, {0.5, 1, 0}, {0, 0, 0}, {1, 0, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 1.0);
  EXPECT_EQ(c.s, 0.0);
  EXPECT_DOUBLE_EQ(c.t, 0.5);
  // Point beyond the end: projection clamps to q1.
  c = segment_segment_closest({2, 1, 0}, {2, 1, 0}, {0, 0, 0}, {1, 0, 0});
  EXPECT_DOUBLE_EQ(c.dist2, 2.0);
  EXPECT_EQ(c.t, 1.0);
  // Second segment a point.
  c = segment_segment_closest({0, 0, 0}, {4, 0, 0}, {1, 0, 2}, {1, 0, 2});
  EXPECT_DOUBLE_EQ(c.dist2, 4.0);
  EXPECT_DOUBLE_EQ(c.s, 0.25);
  EXPECT_EQ(c.t, 0.0);
  // Point on the segment.
  c = segment_segment_closest({0, 0, 0}, {4, 0, 0}, {3, 0, 0}, {3, 0, 0});
  EXPECT_EQ(c.dist2, 0.0);
  EXPECT_DOUBLE_EQ(c.s, 0.75);
}

TEST(SegmentDistance, DegeneratePointPoint) {
  auto c = segment_segment_closest({1, 2, 3}, {1, 2, 3}, {1, 2, 5}, {1, 2, 5});
  EXPECT_DOUBLE_EQ(c.dist2, 4.0);
  EXPECT_EQ(c.s, 0.0);
  EXPECT_EQ(c.t, 0.0);
  c = segment_segment_closest({1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3});
  EXPECT_EQ(c.dist2, 0.0);
}

TEST(SegmentDistance, SymmetricUnderSwap) {
  // Swapping the segments swaps s and t and keeps the distance; reversing a segment maps its
  // parameter to 1 - parameter.
  std::mt19937_64 rng(5);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 p0 = random_point(rng), p1 = random_point(rng), q0 = random_point(rng),
               q1 = random_point(rng);
    const auto a = segment_segment_closest(p0, p1, q0, q1);
    const auto b = segment_segment_closest(q0, q1, p0, p1);
    const auto r = segment_segment_closest(p1, p0, q0, q1);
    EXPECT_NEAR(a.dist2, b.dist2, 1e-14);
    EXPECT_NEAR(a.dist2, r.dist2, 1e-14);
    // Random segments have a unique, well separated minimiser.
    EXPECT_NEAR(a.s, b.t, 1e-9);
    EXPECT_NEAR(a.t, b.s, 1e-9);
    EXPECT_NEAR(a.s, 1 - r.s, 1e-9);
    EXPECT_NEAR(a.t, r.t, 1e-9);
  }
  // Parallel overlap: the midpoint choice is symmetric too.
  const auto a = segment_segment_closest({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0});
  const auto b = segment_segment_closest({1, 1, 0}, {3, 1, 0}, {0, 0, 0}, {2, 0, 0});
  EXPECT_DOUBLE_EQ(a.s, b.t);
  EXPECT_DOUBLE_EQ(a.t, b.s);
  EXPECT_DOUBLE_EQ(a.dist2, b.dist2);
}

// ---------------------------------------------------------------------------------------------
// Brute-force comparisons.

// Nearly parallel pairs at angle theta: random direction u, second direction rotated by theta
// towards w. Offsets: along u (overlap, partial overlap or none), in the rotation plane (either
// ~theta L so that the lines really cross inside the segments, or larger), and out of the plane
// (h, the line-line distance, 0 or 1e-3..1).
void nearly_parallel(double theta, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  std::uniform_real_distribution<double> sym(-1.0, 1.0);
  for (int k = 0; k < 2000; ++k) {
    const Vec3 u = random_unit(rng);
    const Vec3 w = random_perp(u, rng);
    const Vec3 v = u.cross(w);
    const Vec3 dir2 = std::cos(theta) * u + std::sin(theta) * w;
    const double L1 = 0.5 + 1.5 * u01(rng), L2 = 0.5 + 1.5 * u01(rng);  // lengths [m]
    const double along = 2.5 * sym(rng);
    const double in_plane =
        (k % 2 == 0) ? theta * 2 * sym(rng) : sym(rng) * std::pow(10.0, -3 * u01(rng));
    const double h = (k % 3 == 0) ? 0.0 : std::pow(10.0, -3 * u01(rng));
    const Vec3 p0 = random_point(rng);
    const Vec3 p1 = p0 + L1 * u;
    const Vec3 q0 = p0 + along * u + in_plane * w + h * v;
    const Vec3 q1 = q0 + L2 * dir2;
    expect_matches_reference(p0, p1, q0, q1);
    expect_matches_reference(p0, p1, q1, q0);
    if (::testing::Test::HasFailure()) return;
  }
}

// Either side of the fast-path threshold (sin^2 = 1e-4) in segment_distance.cpp.
TEST(SegmentDistance, NearFastPathThresholdMatchesBruteForce) {
  nearly_parallel(0.0099, 19);
  nearly_parallel(0.0101, 20);
}
TEST(SegmentDistance, NearlyParallel1e6MatchesBruteForce) {
  nearly_parallel(1e-6, 21);
}
TEST(SegmentDistance, NearlyParallel1e9MatchesBruteForce) {
  nearly_parallel(1e-9, 22);
}
TEST(SegmentDistance, NearlyParallel1e12MatchesBruteForce) {
  nearly_parallel(1e-12, 23);
}
TEST(SegmentDistance, NearlyParallel1e14MatchesBruteForce) {
  nearly_parallel(1e-14, 24);
}
// Angle at rounding level: about half of these take the overlap-midpoint (parallel) branch.
TEST(SegmentDistance, NearlyParallel1e16MatchesBruteForce) {
  nearly_parallel(1e-16, 25);
}

TEST(SegmentDistance, RandomPairsMatchBruteForce) {
  // 10000 random pairs in the unit cube, lengths spread over three decades, a tenth of them
  // with one degenerate segment.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  for (int k = 0; k < 10000; ++k) {
    const Vec3 p0 = random_point(rng);
    const Vec3 q0 = random_point(rng);
    const Vec3 p1 = p0 + random_unit(rng) * std::pow(10.0, -2 * u01(rng));
    const Vec3 q1 =
        (k % 10 == 0) ? q0 : Vec3(q0 + random_unit(rng) * std::pow(10.0, -2 * u01(rng)));
    expect_matches_reference(p0, p1, q0, q1);
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace wirepack
