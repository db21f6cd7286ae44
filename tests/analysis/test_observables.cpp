// Tests for the centerline observables of docs/design.md §5: Voronoi lengths, discrete curvature,
// total curvature K (with its O(1/n^2) convergence on a circle), coil normal and turning axis, the
// order parameter S, D on coils, spirals, a figure-eight, helices and straight wires, invariance
// under rigid motions, degenerate inputs, and the scaled bending energy.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <Eigen/Geometry>

#include "analysis/observables.hpp"

namespace wirepack::analysis {
namespace {

using std::numbers::pi;

// Closed circle of radius a in the xy plane as an open chain of n + 2 nodes: nodes 0 and n
// coincide and node n + 1 repeats node 1, so nodes 1..n are the n interior nodes of one full turn,
// each turning by 2 pi / n. sense = +1 counterclockwise seen from +z, -1 clockwise.
std::vector<Vec3> circle(double a, int n, double sense = 1) {
  std::vector<Vec3> x;
  for (int j = 0; j <= n + 1; ++j) {
    const double t = sense * 2 * pi * j / n;
    x.emplace_back(a * std::cos(t), a * std::sin(t), 0);
  }
  return x;
}

// Helix about z: radius a, rise `pitch` per turn, `turns` turns, m nodes per turn.
std::vector<Vec3> helix(double a, double pitch, int turns, int m) {
  std::vector<Vec3> x;
  for (int j = 0; j <= turns * m; ++j) {
    const double t = 2 * pi * j / m;
    x.emplace_back(a * std::cos(t), a * std::sin(t), pitch * t / (2 * pi));
  }
  return x;
}

Eigen::Matrix3d some_rotation() {
  return (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()) *
          Eigen::AngleAxisd(-1.9, Vec3(-2, 0.5, 1).normalized()))
      .toRotationMatrix();
}

// ----------------------------------------------------------------------------------------------
// Voronoi lengths, curvature, total curvature

TEST(VoronoiLengths, StraightLineWithUnevenSpacing) {
  const std::vector<Vec3> x{{0, 0, 0}, {1, 0, 0}, {3, 0, 0}, {6, 0, 0}};
  const std::vector<double> ell = voronoi_lengths(x);
  ASSERT_EQ(ell.size(), 4u);
  EXPECT_DOUBLE_EQ(ell[0], 0.5);  // half of the first edge only
  EXPECT_DOUBLE_EQ(ell[1], 1.5);
  EXPECT_DOUBLE_EQ(ell[2], 2.5);
  EXPECT_DOUBLE_EQ(ell[3], 1.5);
  // Any direction: ell sums to the length.
  std::vector<Vec3> y;
  for (const Vec3& p : x) y.push_back(p.x() * Vec3(1, -2, 2) / 3);
  double L = 0;
  for (double e : voronoi_lengths(y)) L += e;
  EXPECT_NEAR(L, 6, 1e-14);
}

TEST(Curvatures, CircleOfRadiusA) {
  // Exactly kappa = 2 tan(phi/2) / (2 a sin(phi/2)) = 1 / (a cos(phi/2)) with phi = 2 pi / n:
  // 1/a up to the relative error phi^2 / 8 (2.5e-5 at n = 200).
  const double a = 0.37;
  const int n = 200;
  const auto x = circle(a, n);
  const std::vector<double> kappa = curvatures(x);
  ASSERT_EQ(kappa.size(), x.size());
  EXPECT_EQ(kappa.front(), 0.0);
  EXPECT_EQ(kappa.back(), 0.0);
  const double exact = 1 / (a * std::cos(pi / n));
  for (int i = 1; i <= n; ++i) {
    EXPECT_NEAR(kappa[i], exact, 1e-12 * exact);
    EXPECT_NEAR(kappa[i] * a, 1, std::pow(2 * pi / n, 2) / 8 * 1.01);
  }
}

TEST(Curvatures, NearReversalIsAccurateAndExactReversalFinite) {
  // phi = pi - delta: tan(phi / 2) = 1 / tan(delta / 2), to full relative precision although
  // 1 + cos(phi) ~ delta^2 / 2 cancels.
  for (double delta : {1e-2, 1e-5, 1e-7}) {
    const std::vector<Vec3> x{{0, 0, 0}, {1, 0, 0}, {1 - std::cos(delta), std::sin(delta), 0}};
    const double kappa = curvatures(x)[1];  // ell_1 = 1
    EXPECT_NEAR(kappa, 2 / std::tan(delta / 2), 1e-9 * kappa) << "delta " << delta;
  }
  const std::vector<Vec3> hairpin{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}};
  EXPECT_TRUE(std::isfinite(curvatures(hairpin)[1]));
  EXPECT_TRUE(std::isfinite(total_curvature(hairpin)));
}

TEST(TotalCurvature, CircleConvergesAtSecondOrder) {
  // K_n = 2 n tan(pi / n) = 2 pi (1 + pi^2 / (3 n^2) + O(n^-4)): each doubling of n divides the
  // error by 4 (within 1 % at these n, the O(n^-4) term being ~pi^2 / (5 n^2) relative to it).
  double err_prev = 0;
  for (int n : {32, 64, 128}) {
    const double K = total_curvature(circle(2.5, n));
    const double err = K - 2 * pi;
    EXPECT_NEAR(K, 2 * n * std::tan(pi / n), 1e-12);
    EXPECT_GT(err, 0);
    EXPECT_NEAR(err, 2 * std::pow(pi, 3) / (3.0 * n * n), 0.01 * err);
    if (err_prev > 0) {
      EXPECT_NEAR(err_prev / err, 4, 0.04);
    }
    err_prev = err;
  }
}

TEST(TotalCurvature, StraightLineIsZero) {
  std::vector<Vec3> x;
  for (int j = 0; j < 50; ++j) x.push_back((j + 0.1 * (j % 3)) * Vec3(0.3, -0.5, 0.7));
  EXPECT_NEAR(total_curvature(x), 0, 1e-12);
}

// ----------------------------------------------------------------------------------------------
// Axes

TEST(CoilNormal, PlanarCoilInXyPlaneIsPlusZ) {
  // Sign convention: the largest-magnitude component is positive, for either sense of rotation.
  for (double sense : {1.0, -1.0}) {
    const Vec3 n = coil_normal(circle(1.3, 100, sense));
    EXPECT_NEAR(n.z(), 1, 1e-12);
    const Vec3 w = turning_axis(circle(1.3, 100, sense));
    EXPECT_NEAR(w.z(), 1, 1e-12);
  }
}

TEST(CoilNormal, TallHelixTipsIntoThePlaneWhileTurningAxisStays) {
  // Documented limitation of the axis of docs/design.md §5.3: a helix taller than wide
  // (height^2 / 12 > a^2 / 2) has its smallest gyration eigenvalue in the plane, so n is
  // in-plane and D ~ 1 (the sign of n . b_i alternates every half turn). The turning axis is z
  // whatever the height.
  // Height 20, a = 1; n leans out of the plane by ~cov(y, z) / var(z) = 0.005 only.
  const auto x = helix(1.0, 1.0, 20, 64);
  EXPECT_LT(std::abs(coil_normal(x).z()), 0.02);
  EXPECT_GT(order_parameter(x).D, 0.9);
  EXPECT_NEAR(turning_axis(x).z(), 1, 1e-6);
}

// ----------------------------------------------------------------------------------------------
// Order parameter S, D

TEST(OrderParameter, PlanarCircleIsOrdered) {
  for (double sense : {1.0, -1.0}) {
    const Order o = order_parameter(circle(0.8, 120, sense));
    EXPECT_DOUBLE_EQ(o.S, sense);  // n = +z: counterclockwise S = +1, clockwise S = -1
    EXPECT_DOUBLE_EQ(o.D, 0);
    EXPECT_NEAR(o.n.z(), 1, 1e-12);
  }
}

TEST(OrderParameter, ArchimedeanSpiralIsOrdered) {
  // rho = b theta over 6 turns, about constant arclength spacing: one sense of turning throughout.
  std::vector<Vec3> x;
  const double b = 0.05;
  for (double t = 2 * pi; t < 14 * pi; t += 0.05 / (b * t)) {
    x.emplace_back(b * t * std::cos(t), b * t * std::sin(t), 0);
  }
  const Order o = order_parameter(x);
  EXPECT_DOUBLE_EQ(o.D, 0);
  EXPECT_DOUBLE_EQ(std::abs(o.S), 1);
}

TEST(OrderParameter, FigureEightIsDisordered) {
  // Lemniscate of Gerono (cos t, sin t cos t, 0), n nodes over one closed loop. t -> t + pi
  // mirrors x -> -x, which maps each lobe onto the other with the opposite sense, so left and
  // right turning balance: S = 0 up to the two inflection nodes at the crossing and the
  // non-uniform ell of the sampling, |S| <= 4 / n here.
  const int n = 2000;
  std::vector<Vec3> x;
  for (int j = 0; j <= n + 1; ++j) {
    const double t = 2 * pi * (j + 0.25) / n;
    x.emplace_back(std::cos(t), std::sin(t) * std::cos(t), 0);
  }
  const Order o = order_parameter(x);
  EXPECT_NEAR(o.n.z(), 1, 1e-12);
  EXPECT_LT(std::abs(o.S), 4.0 / n);
  EXPECT_GT(o.D, 1 - 4.0 / n);
}

TEST(OrderParameter, FlatHelixWithManyTurnsIsOrdered) {
  // 30 turns of radius 1 rising 0.01 per turn (height 0.3): a tight coil, n = axis up to a lean
  // of cov(y, z) / var(y) ~ 0.0032, and every node turns the same way about it.
  const auto x = helix(1.0, 0.01, 30, 48);
  const Order o = order_parameter(x);
  EXPECT_GT(std::abs(o.n.z()), 0.9999);
  EXPECT_LT(o.D, 1e-12);
}

TEST(OrderParameter, StraightLineHasNoSense) {
  // Documented value: a straight wire never turns (round-off turning |t0 x t1| <= 1e-12 counts as
  // zero), so S = 0 and D = 1.
  std::vector<Vec3> x;
  for (int j = 0; j < 40; ++j) x.push_back(Vec3(0.1, 0.2, -0.3) + (j * j * 0.01) * Vec3(1, 2, 3));
  const Order o = order_parameter(x);
  EXPECT_EQ(o.S, 0.0);
  EXPECT_EQ(o.D, 1.0);
}

TEST(OrderParameter, InvariantUnderRigidMotion) {
  // A wavy, slightly non-planar coil rho(t) = 1 + 0.5 sin(4.3 t) whose in-plane curvature
  // changes sign near the minima of rho: both senses of turning, 0 < D < 1. D must not change
  // under rotation plus translation (S may flip sign with the axis convention).
  std::vector<Vec3> x;
  for (int j = 0; j < 3000; ++j) {
    const double t = 0.01 * j, rho = 1 + 0.5 * std::sin(4.3 * t);
    x.emplace_back(rho * std::cos(t), rho * std::sin(t), 0.2 * std::sin(0.37 * t));
  }
  const Order o = order_parameter(x);
  ASSERT_GT(o.D, 0.05);
  ASSERT_LT(o.D, 0.95);
  const Eigen::Matrix3d Q = some_rotation();
  const Vec3 shift(3.0, -7.5, 12.25);
  std::vector<Vec3> y;
  for (const Vec3& p : x) y.push_back(Q * p + shift);
  const Order oy = order_parameter(y);
  EXPECT_NEAR(oy.D, o.D, 1e-9);
  EXPECT_NEAR(std::abs(oy.n.dot(Q * o.n)), 1, 1e-9);
  EXPECT_NEAR(total_curvature(y), total_curvature(x), 1e-9 * total_curvature(x));
}

// ----------------------------------------------------------------------------------------------
// Degenerate inputs and the scaled bending energy

// The curvature-weighted order parameter: +-1 on a circle, ~0 on the figure-eight, and an
// entry chord that is straight weighs nothing in it (the paper's S counts its length).
TEST(SignedTurning, CircleTurnsByTwoTanHalfTheAngleAtEveryNode) {
  // A regular polygon of n sides turns by phi = 2 pi / n at each vertex: kappa_n ell =
  // 2 sin(phi) / (1 + cos(phi)) = 2 tan(phi / 2), signed by the sense about +z; ends carry 0.
  const int n = 40;
  for (double sense : {1.0, -1.0}) {
    const auto x = circle(1.3, n, sense);
    const auto turn = signed_turning(x, Vec3::UnitZ());
    ASSERT_EQ(turn.size(), x.size());
    EXPECT_EQ(turn.front(), 0.0);
    EXPECT_EQ(turn.back(), 0.0);
    for (std::size_t i = 1; i + 1 < x.size(); ++i)
      EXPECT_NEAR(turn[i], sense * 2 * std::tan(pi / n), 1e-12);
    // About an axis in the circle's plane nothing turns.
    for (double t : signed_turning(x, Vec3::UnitX())) EXPECT_NEAR(t, 0.0, 1e-12);
  }
}

TEST(CurvatureWeightedOrder, CircleFigureEightAndStraightEntryChord) {
  for (double sense : {1.0, -1.0}) {
    const Order o = curvature_weighted_order(circle(0.8, 120, sense));
    EXPECT_NEAR(o.S, sense, 1e-12);
    EXPECT_NEAR(o.D, 0, 1e-12);
  }
  const int n = 2000;
  std::vector<Vec3> eight;
  for (int j = 0; j <= n + 1; ++j) {
    const double t = 2 * pi * (j + 0.25) / n;
    eight.emplace_back(std::cos(t), std::sin(t) * std::cos(t), 0);
  }
  EXPECT_LT(std::abs(curvature_weighted_order(eight).S), 4.0 / n);
  // Three turns of radius a = 1 (120 nodes per turn), then a straight chord of 3 a along the
  // last tangent: the paper's S = L_coil / L, S_kappa = 1.
  std::vector<Vec3> x;
  const int per_turn = 120;
  for (int j = 0; j <= 3 * per_turn; ++j) {
    const double t = 2 * pi * j / per_turn;
    x.emplace_back(std::cos(t), std::sin(t), 0);
  }
  const double h = 2 * std::sin(pi / per_turn);  // chord of the coil's nodes
  for (int k = 1; k <= 3.0 / h; ++k) x.push_back(Vec3(1, 0, 0) + k * h * Vec3(0, 1, 0));
  EXPECT_LT(order_parameter(x).S, 0.97);  // 3 a of 6 pi a + 3 a is straight
  EXPECT_NEAR(curvature_weighted_order(x).S, 1, 1e-12);
}

// A chord that turns against the coil (as the entry chord of coiling runs does): the paper's S
// loses twice the chord's share of the length, S_kappa twice its share of the turning, here
// (2 pi N - theta_c) / (2 pi N + theta_c) with the chord's angle theta_c = L_c / (5 a).
TEST(CurvatureWeightedOrder, ReversedChordCountsByItsTurning) {
  std::vector<Vec3> x;
  const int per_turn = 200, turns = 3;
  for (int j = 0; j <= turns * per_turn; ++j) {
    const double t = 2 * pi * j / per_turn;
    x.emplace_back(std::cos(t), std::sin(t), 0);
  }
  // At (1, 0) heading +y, continue on a circle of radius 5 turning clockwise (centre (6, 0)),
  // through the same arc length per node, for theta_c = 0.6 (arc length 3).
  const double ds = 2 * pi / per_turn, dtheta = ds / 5, theta_c = 0.6;
  const int m = static_cast<int>(std::round(theta_c / dtheta));
  for (int k = 1; k <= m; ++k) {
    const double phi = pi - k * dtheta;  // angle about (6, 0), starting at (1, 0)
    x.emplace_back(6 + 5 * std::cos(phi), 5 * std::sin(phi), 0);
  }
  const double turning = 2 * pi * turns, chord = m * dtheta;
  const double L = turning * 1 + chord * 5;
  EXPECT_NEAR(curvature_weighted_order(x).S, (turning - chord) / (turning + chord), 2e-3);
  // The paper's S to a node's share of the length (ell / L ~ 1.5e-3; the end nodes do not count).
  EXPECT_NEAR(order_parameter(x).S, (turning - 5 * chord) / L, 5e-3);
}

// The entry chord in a sphere of radius R = 20 r: a coil against the wall (two turns at the
// equator, radius R - r) reached from the hole at the pole by a chord that turns against it.
// The chord starts after the coil's last node; without it the paper's D of the coil is 0, with
// it D > 0. A chord that touches the coil halfway (another part of the wire) ends there.
TEST(EntryChord, CoilAgainstTheWallAndAChordFromThePole) {
  const double r = 1, R = 20 * r;
  const auto to_sphere = [R](const Vec3& p) { return R - p.norm(); };
  std::vector<Vec3> x;
  const int per_turn = 126;  // ~1 r spacing at radius 19 r
  for (int j = 0; j <= 2 * per_turn; ++j) {
    const double t = 2 * pi * j / per_turn;
    x.emplace_back((R - r) * std::cos(t), (R - r) * std::sin(t), 0);
  }
  const std::size_t coil = x.size();
  // From the coil's end (R - r, 0, 0) up to the hole (0, 0, R): an arc through the interior,
  // bulging against the coil's sense (towards -y), 40 nodes.
  const Vec3 a = x.back(), b(0, 0, R);
  for (int k = 1; k <= 40; ++k) {
    const double s = k / 40.0;
    x.push_back((1 - s) * a + s * b + Vec3(0, -6 * r * std::sin(pi * s), 0));
  }
  // The chord leaves the wall and the coil's end gradually: its first nodes (up to 4 here)
  // still touch, so D without the chord is at most a few nodes' share (0.016) instead of 0.
  const std::size_t k = entry_chord_start(x, r, 0.1 * r, 4, 3 * r, to_sphere);
  EXPECT_GE(k, coil);
  EXPECT_LE(k, coil + 4);
  EXPECT_LT(order_parameter(std::span(x).first(k)).D, 0.02);
  EXPECT_GT(order_parameter(x).D, 0.1);
  // Nothing touches: k = 0 (a straight wire from the centre up to the hole at the pole).
  std::vector<Vec3> straight;
  for (int j = 0; j <= 20; ++j) straight.emplace_back(0, 0, j * r);
  EXPECT_EQ(entry_chord_start(straight, r, 0.1 * r, 4, 3 * r, to_sphere), 0u);
  // A chord that starts 2 r inside the coil at t = pi and runs straight to the pole: its first
  // node touches the coil, so the chord is what follows it.
  std::vector<Vec3> y(x.begin(), x.begin() + coil);
  const Vec3 c = y[per_turn / 2] + Vec3(2 * r, 0, 0);
  for (int k2 = 0; k2 <= 26; ++k2) y.push_back(c + (k2 / 26.0) * (b - c));
  EXPECT_EQ(entry_chord_start(y, r, 0.1 * r, 4, 3 * r, to_sphere), coil + 1);
}

// ----------------------------------------------------------------------------------------------
// Sense blocks

// n nodes of weight h with sign +1 for the first `a` nodes, then alternating blocks of `b`.
std::vector<int> signs(std::size_t n, std::size_t a, std::size_t b) {
  std::vector<int> s(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = i < a ? 1 : ((i - a) / b) % 2 == 0 ? -1 : 1;
  return s;
}

TEST(SenseBlocks, OneSenseIsOneBlockOfTheWholeLength) {
  const std::vector<double> ell(500, 0.1);
  const SenseBlocks o = sense_blocks(ell, std::vector<int>(500, -1), 1.0);
  EXPECT_EQ(o.reversals, 0u);
  EXPECT_NEAR(o.length, 50.0, 1e-9);
  EXPECT_NEAR(o.order_length, 50.0, 1e-9);
}

TEST(SenseBlocks, OneReversalGivesTwoBlocksWhateverTheirLengths) {
  // 30 then 20 (ell 0.1): sum b^2 / sum b = (900 + 400) / 50 = 26, whereas the paper's D of this
  // sign sequence is 1 - |30 - 20| / 50 = 0.8.
  const std::vector<double> ell(500, 0.1);
  const SenseBlocks o = sense_blocks(ell, signs(500, 300, 1000), 1.0);
  EXPECT_EQ(o.reversals, 1u);
  EXPECT_NEAR(o.order_length, 26.0, 1e-9);
}

TEST(SenseBlocks, BlipsShorterThanTheMinimumAreMerged) {
  // A 0.5-long blip of the other sense in the middle of a 50-long block, and one of 0.3 at the
  // start: one block. With min_block 0.2 both count: three reversals.
  const std::vector<double> ell(500, 0.1);
  std::vector<int> s(500, 1);
  for (int i = 200; i < 205; ++i) s[i] = -1;
  for (int i = 0; i < 3; ++i) s[i] = -1;
  const SenseBlocks merged = sense_blocks(ell, s, 1.0);
  EXPECT_EQ(merged.reversals, 0u);
  EXPECT_NEAR(merged.order_length, 50.0, 1e-9);
  const SenseBlocks resolved = sense_blocks(ell, s, 0.2);
  EXPECT_EQ(resolved.reversals, 3u);
  // Blocks 0.3, 19.7, 0.5, 29.5.
  EXPECT_NEAR(resolved.order_length, (0.09 + 19.7 * 19.7 + 0.25 + 29.5 * 29.5) / 50, 1e-9);
}

TEST(SenseBlocks, AlternatingLoopsGiveBlocksOfTheirLength) {
  // 20 blocks of 2.5 alternating (a disordered packing's loops): 19 reversals, blocks of 2.5;
  // the paper's D of the same sequence is 1.
  const std::vector<double> ell(500, 0.1);
  const SenseBlocks o = sense_blocks(ell, signs(500, 25, 25), 1.0);
  EXPECT_EQ(o.reversals, 19u);
  EXPECT_NEAR(o.order_length, 2.5, 1e-9);
  // Unequal weights: the length, not the node count, decides.
  std::vector<double> uneven(500, 0.1);
  for (std::size_t i = 0; i < 25; ++i) uneven[i] = 0.01;  // the first block is 0.25 long
  const SenseBlocks u = sense_blocks(uneven, signs(500, 25, 25), 1.0);
  EXPECT_EQ(u.reversals, 18u);  // merged into the second block (now 2.75 long)
  EXPECT_NEAR(u.length, 47.75, 1e-9);
}

TEST(SenseBlocks, NonTurningNodesJoinTheBlockBeforeThem) {
  const std::vector<double> ell(6, 1.0);
  const SenseBlocks o = sense_blocks(ell, std::vector<int>{0, 0, 1, 0, -1, -1}, 0.5);
  EXPECT_EQ(o.reversals, 1u);  // blocks {0, 0, 1, 0} and {-1, -1}
  EXPECT_NEAR(o.order_length, (16.0 + 4.0) / 6, 1e-12);
  EXPECT_EQ(sense_blocks(ell, std::vector<int>(6, 0), 0.5).reversals, 0u);
  EXPECT_EQ(sense_blocks(std::vector<double>{}, std::vector<int>{}, 0.5).order_length, 0.0);
}

TEST(SenseBlocks, CoilWoundOneWayThenTheOtherOnACenterline) {
  // Three turns counter-clockwise about z, then three clockwise (the circle continued with the
  // opposite sense from the same point, a little higher): one reversal, two blocks of three turns;
  // the paper's D is 1 (S = 0) although both halves are perfect coils.
  const double a = 0.8;
  const int m = 120;
  std::vector<Vec3> x;
  for (int j = 0; j <= 3 * m; ++j) {
    const double t = 2 * pi * j / m;
    x.emplace_back(a * std::cos(t), a * std::sin(t), 0.0005 * j);
  }
  for (int j = 1; j <= 3 * m; ++j) {
    const double t = -2 * pi * j / m;
    x.emplace_back(a * std::cos(t), a * std::sin(t), 0.0005 * (3 * m + j));
  }
  const Vec3 n(0, 0, 1);
  const SenseBlocks o = sense_blocks(x, n, 0.5);
  EXPECT_EQ(o.reversals, 1u);
  const double turn = 2 * pi * a * std::sqrt(1 + std::pow(0.0005 * m / (2 * pi * a), 2));
  EXPECT_NEAR(o.length, 6 * turn, 0.01 * turn);
  EXPECT_NEAR(o.order_length, 3 * turn, 0.02 * turn);
  EXPECT_GT(order_parameter(x).D, 0.95);
  // The same wire rotated and moved: the same blocks about the moved axis.
  const Eigen::Matrix3d Q = some_rotation();
  std::vector<Vec3> y;
  for (const auto& p : x) y.push_back(Q * p + Vec3(3, -1, 2));
  const SenseBlocks q = sense_blocks(y, Q * n, 0.5);
  EXPECT_EQ(q.reversals, 1u);
  EXPECT_NEAR(q.order_length, o.order_length, 1e-9);
}

TEST(Observables, EmptyOneAndTwoNodeInputsGiveDocumentedZeros) {
  const std::vector<Vec3> none;
  const std::vector<Vec3> one{Vec3(1, 2, 3)};
  const std::vector<Vec3> two{Vec3(1, 2, 3), Vec3(2, 2, 3)};
  const std::vector<Vec3> same{Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)};
  EXPECT_TRUE(voronoi_lengths(none).empty());
  EXPECT_TRUE(curvatures(none).empty());
  EXPECT_EQ(voronoi_lengths(one), std::vector<double>{0.0});
  EXPECT_EQ(curvatures(one), std::vector<double>{0.0});
  EXPECT_EQ(curvatures(two), (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(curvatures(same), (std::vector<double>{0.0, 0.0, 0.0}));
  for (const auto* x : {&none, &one, &two, &same}) {
    EXPECT_EQ(total_curvature(*x), 0.0);
    const Order o = order_parameter(*x);
    EXPECT_EQ(o.S, 0.0);
    EXPECT_EQ(o.D, 1.0);
    EXPECT_TRUE(coil_normal(*x).allFinite());
    EXPECT_TRUE(turning_axis(*x).allFinite());
    EXPECT_FALSE(coil_radii(*x, 0.01).ok);
  }
  EXPECT_EQ(coil_normal(none), Vec3::UnitZ());
}

TEST(BendingEnergyHat, Definition) {
  // U_b_hat = U_b r^2 / (R E_w I) with I = pi r^4 / 4: U_b = R E_w I / r^2 gives exactly 1, and
  // a ring of radius R (U_b = pi E_w I / R) gives pi r^2 / R^2.
  const double r = 5e-4, R = 0.02, E_w = 2e11, I = pi * std::pow(r, 4) / 4;
  EXPECT_NEAR(bending_energy_hat(R * E_w * I / (r * r), r, R, E_w), 1, 1e-14);
  EXPECT_NEAR(bending_energy_hat(pi * E_w * I / R, r, R, E_w), pi * r * r / (R * R), 1e-16);
}

}  // namespace
}  // namespace wirepack::analysis
