// Point-triangle and segment-triangle closest points against sampling and closed forms.
#include <gtest/gtest.h>

#include <random>

#include "engine/contact/triangle_distance.hpp"

namespace wirepack {
namespace {

Vec3 on_triangle(const TriangleClosest& c, const Vec3& a, const Vec3& b, const Vec3& c3) {
  return c.w[0] * a + c.w[1] * b + c.w[2] * c3;
}

void expect_valid_weights(const TriangleClosest& c) {
  for (double w : c.w) EXPECT_GE(w, -1e-12);
  EXPECT_NEAR(c.w[0] + c.w[1] + c.w[2], 1.0, 1e-12);
}

TEST(TriangleDistance, PointRegionsClosedForm) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // Above the face interior: the foot of the perpendicular.
  auto r = point_triangle_closest(Vec3(0.2, 0.3, 0.7), a, b, c);
  EXPECT_NEAR(r.dist2, 0.49, 1e-14);
  EXPECT_TRUE(on_triangle(r, a, b, c).isApprox(Vec3(0.2, 0.3, 0), 1e-14));
  // Beyond vertex b, beyond edge ab, beyond the hypotenuse.
  r = point_triangle_closest(Vec3(2, -1, 0), a, b, c);
  EXPECT_NEAR(r.dist2, 2.0, 1e-14);
  r = point_triangle_closest(Vec3(0.5, -1, 1), a, b, c);
  EXPECT_NEAR(r.dist2, 2.0, 1e-14);
  r = point_triangle_closest(Vec3(1, 1, 0), a, b, c);
  EXPECT_NEAR(r.dist2, 0.5, 1e-14);
  expect_valid_weights(r);
}

// Random queries: no sampled point of the triangle (a 200 x 200 barycentric grid) is closer
// than the answer, and the answer is attained (the grid spacing bounds how much closer a
// sampled point could be found: none may beat the answer at all).
TEST(TriangleDistance, PointMatchesSampling) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a(g(rng), g(rng), g(rng)), b(g(rng), g(rng), g(rng)), c(g(rng), g(rng), g(rng));
    const Vec3 p = 2.0 * Vec3(g(rng), g(rng), g(rng));
    const auto r = point_triangle_closest(p, a, b, c);
    expect_valid_weights(r);
    EXPECT_NEAR((p - on_triangle(r, a, b, c)).squaredNorm(), r.dist2, 1e-12);
    const int n = 200;
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; i + j <= n; ++j) {
        const Vec3 q = a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a);
        ASSERT_GE((p - q).squaredNorm(), r.dist2 - 1e-12) << trial;
      }
    }
  }
}

TEST(TriangleDistance, SegmentCrossingTheTriangleHasZeroDistance) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto r = segment_triangle_closest(Vec3(0.2, 0.2, -1), Vec3(0.2, 0.2, 1), a, b, c);
  EXPECT_EQ(r.dist2, 0.0);
  EXPECT_NEAR(r.s, 0.5, 1e-14);
  EXPECT_TRUE(on_triangle(r, a, b, c).isApprox(Vec3(0.2, 0.2, 0), 1e-14));
}

TEST(TriangleDistance, SegmentParallelAboveTheFace) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  const auto r = segment_triangle_closest(Vec3(0.1, 0.1, 0.3), Vec3(0.3, 0.2, 0.3), a, b, c);
  EXPECT_NEAR(r.dist2, 0.09, 1e-14);
}

TEST(TriangleDistance, SegmentMatchesSampling) {
  std::mt19937_64 rng(9);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Vec3 a(g(rng), g(rng), g(rng)), b(g(rng), g(rng), g(rng)), c(g(rng), g(rng), g(rng));
    const Vec3 p0 = 1.5 * Vec3(g(rng), g(rng), g(rng)), p1 = 1.5 * Vec3(g(rng), g(rng), g(rng));
    const auto r = segment_triangle_closest(p0, p1, a, b, c);
    expect_valid_weights(r);
    const Vec3 ps = p0 + r.s * (p1 - p0);
    EXPECT_NEAR((ps - on_triangle(r, a, b, c)).squaredNorm(), r.dist2, 1e-12);
    // For each sampled segment point, the exact point-triangle distance may not beat it.
    for (int k = 0; k <= 400; ++k) {
      const Vec3 p = p0 + (k / 400.0) * (p1 - p0);
      ASSERT_GE(point_triangle_closest(p, a, b, c).dist2, r.dist2 - 1e-12) << trial;
    }
  }
}

}  // namespace
}  // namespace wirepack
