// Twin-run separation modulo the rotation about the feed axis (analysis/twin.hpp) on synthetic
// centerlines with known answers.
#include "analysis/twin.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

namespace wirepack::analysis {
namespace {

using V = Eigen::Vector3d;

// A helix-like wire (nodes from the hole), not symmetric about z.
std::vector<V> wire(int n) {
  std::vector<V> x;
  for (int i = 0; i < n; ++i) {
    const double s = 0.1 * i;
    x.emplace_back(0.3 * std::sin(s) + 0.05 * s, 0.2 * (1 - std::cos(s)), -1 + 0.02 * s);
  }
  return x;
}

std::vector<V> rotated(const std::vector<V>& a, double phi) {
  std::vector<V> b;
  for (const auto& p : a)
    b.emplace_back(std::cos(phi) * p.x() - std::sin(phi) * p.y(),
                   std::sin(phi) * p.x() + std::cos(phi) * p.y(), p.z());
  return b;
}

TEST(TwinSeparation, ARotatedCopyAboutTheFeedAxisIsTheSameTrajectory) {
  // Seeds that pick another azimuth of one path: separation 0 (to rounding) at any angle.
  const auto a = wire(200);
  for (double phi : {0.0, 0.3, 2.0, -3.0, std::numbers::pi})
    EXPECT_NEAR(twin_separation(a, rotated(a, phi)).max, 0.0, 1e-12) << phi;
}

TEST(TwinSeparation, ALocalDepartureIsMeasuredInFull) {
  // One node moved by 0.25 along z (rotation about z cannot absorb it): largest distance 0.25,
  // rms 0.25 / sqrt(200).
  const auto a = wire(200);
  auto b = rotated(a, 1.1);
  b[150].z() += 0.25;
  EXPECT_NEAR(twin_separation(a, b).max, 0.25, 1e-9);
  EXPECT_NEAR(twin_separation(a, b).rms, 0.25 / std::sqrt(200.0), 1e-9);
  // A mirror image (the other coiling sense) is not a rotation: it parts by O(size).
  auto m = a;
  for (auto& p : m) p.y() = -p.y();
  EXPECT_GT(twin_separation(a, m).max, 0.1);
  EXPECT_GT(twin_separation(a, m).rms, 0.05);
}

TEST(TwinSeparation, ComparesTheCommonNodesFromTheHole) {
  const auto a = wire(200);
  auto b = a;
  b.resize(150);  // b one node row shorter: only its 150 nodes count
  EXPECT_NEAR(twin_separation(a, b).max, 0.0, 1e-15);
  EXPECT_EQ(twin_separation(std::vector<V>{}, a).rms, 0.0);
}

TEST(TwinPartingL, FirstRowAboveTheThreshold) {
  const std::vector<double> l{1, 2, 3, 4, 5};
  const std::vector<double> sep{0.0, 0.2, 0.9, 1.5, 0.4};
  EXPECT_EQ(twin_parting_l(l, sep, 1.0), 4.0);
  EXPECT_EQ(twin_parting_l(l, sep, 0.1), 2.0);
  EXPECT_TRUE(std::isnan(twin_parting_l(l, sep, 2.0)));  // never parts
}

}  // namespace
}  // namespace wirepack::analysis
