// Analytic checks of the twisting energy (TwistTerm, Bergou et al. 2010; paper Eq. (1)):
// uniform twist of a straight rod, torque balance, invariance under rigid rotations (the energy
// depends on the material frames only, not on how the reference frames were carried), and a
// finite-difference check on a helix with nonzero reference twist.
#include "engine/rod/twist.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "engine/fd_harness.hpp"
#include "engine/rod/frames.hpp"
#include "engine/rod_builders.hpp"

namespace wirepack {
namespace {

using testing::forces_of;

// Material director m1 of edge j: ref1 rotated by theta_j about the edge tangent.
Vec3 material_director(const State& s, int j) {
  const Vec3 t = (s.x[j + 1] - s.x[j]).normalized();
  return std::cos(s.theta[j]) * s.ref1[j] + std::sin(s.theta[j]) * t.cross(s.ref1[j]);
}

// Straight rod (generic direction) with theta_j = j k3 l: every interior vertex carries the
// twist m = k3 l over its Voronoi length l, so U_t = 1/2 G J k3^2 L exactly, where L = (N-1) l is
// the distance between the midpoints of the first and last edges (theta lives on edges). The
// only error is round-off of the reference twist of the straight rod (~1e-16 rad against
// m = k3 l >= 1e-4 rad): tolerance 1e-12 relative. The torques are those of a uniformly twisted
// shaft: +-G J k3 at the end edges, 0 inside; a straight rod feels no position forces.
TEST(Twist, UniformTwistOfStraightRod) {
  const auto mat = testing::default_material();
  const double l = 0.5e-3;
  const int N = 30;                        // edges
  for (double k3 : {0.2, 30.0, -150.0}) {  // [rad/m]; k3 l from 1e-4 to 0.075 rad
    State s = testing::straight_rod(N + 1, l, Vec3(2, -1, 0.5).normalized(), true);
    for (int j = 0; j < N; ++j) s.theta[j] = j * k3 * l;
    TwistTerm term(mat.GJ());
    double U = 0;
    const Forces f = forces_of(term, s, &U);
    const double U_exact = 0.5 * mat.GJ() * k3 * k3 * (N - 1) * l;
    EXPECT_NEAR(U / U_exact, 1.0, 1e-12) << "k3 = " << k3;
    EXPECT_NEAR(term.energy(s) / U_exact, 1.0, 1e-12);
    const double T = mat.GJ() * k3;  // shaft torque [N m]
    EXPECT_NEAR(f.torque[0] / T, 1.0, 1e-12);
    EXPECT_NEAR(f.torque[N - 1] / -T, 1.0, 1e-12);
    for (int j = 1; j + 1 < N; ++j) EXPECT_LT(std::abs(f.torque[j]), 1e-9 * std::abs(T));
    for (const Vec3& v : f.f) EXPECT_LT(v.norm(), 1e-9 * std::abs(T) / l);
  }
}

// Straight rod, reference frames transported along it, ends rotated against each other by Phi,
// random interior angles: the torques are internal (pairwise equal and opposite), so their sum
// vanishes (to round-off of the largest torque, 1e-12). Relaxing the interior angles (the
// interior torques vanish for theta linear in j) leaves the shaft torque +-G J Phi / L.
TEST(Twist, TorqueBalanceWithRotatedEnds) {
  const auto mat = testing::default_material();
  const double l = 0.5e-3;
  const int N = 20;
  const double Phi = 2.5;  // [rad]
  State s = testing::straight_rod(N + 1, l, Vec3::UnitZ(), true);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = 1; j + 1 < N; ++j) s.theta[j] = u(rng);
  s.theta[N - 1] = Phi;
  TwistTerm term(mat.GJ());
  Forces f = forces_of(term, s);
  double tsum = 0, tmax = 0;
  for (double t : f.torque) {
    tsum += t;
    tmax = std::max(tmax, std::abs(t));
  }
  EXPECT_LT(std::abs(tsum), 1e-12 * tmax);

  for (int j = 0; j < N; ++j) s.theta[j] = Phi * j / (N - 1);
  f = forces_of(term, s);
  const double T = mat.GJ() * Phi / ((N - 1) * l);
  EXPECT_NEAR(f.torque[0] / T, 1.0, 1e-12);
  EXPECT_NEAR(f.torque[N - 1] / -T, 1.0, 1e-12);
  for (int j = 1; j + 1 < N; ++j) EXPECT_LT(std::abs(f.torque[j]), 1e-12 * T) << j;
}

// A helix-shaped rod with frames carried in time from the straight state (nonzero reference
// twist) and random material angles.
State twisted_helix(unsigned seed) {
  const double l = 0.5e-3;
  const int n = 16;
  const Vec3List helix = testing::helix_points(2.0 * l, 0.5 * l, 0.45, n);
  State s = testing::straight_rod(n, l, Vec3::UnitZ(), true);
  // Morph the straight rod into the helix, transporting the reference frames in time.
  Vec3List straight = s.x;
  for (int k = 1; k <= 40; ++k) {
    const double w = k / 40.0;
    for (int i = 0; i < n; ++i) s.x[i] = (1 - w) * straight[i] + w * helix[i];
    update_reference_frames(s);
  }
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int j = 0; j + 1 < n; ++j) {
    s.rest_length[j] = (s.x[j + 1] - s.x[j]).norm() * (1.0 + 0.05 * u(rng));
    s.theta[j] = 0.8 * u(rng);
  }
  return s;
}

double max_abs_ref_twist(const State& s) {
  double m = 0;
  for (double t : s.ref_twist) m = std::max(m, std::abs(t));
  return m;
}

// The twist energy depends only on the material frames: rotating the rod rigidly by R (positions
// R x, material directors R m1) leaves it unchanged, whether the reference frames are rotated
// with it or carried by update_reference_frames (parallel transport from the old tangents, as a
// time step does) with theta re-expressed against the transported frames. Tolerance 1e-9
// relative: angles are recovered through atan2 (round-off ~1e-16 rad per edge against twists
// m ~ 0.1 - 1 rad) and the transport of each frame is exact to round-off.
TEST(Twist, EnergyInvariantUnderRigidRotation) {
  const auto mat = testing::default_material();
  TwistTerm term(mat.GJ());
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const State s0 = twisted_helix(seed);
    const double U0 = term.energy(s0);
    ASSERT_GT(U0, 0.0);
    for (double angle : {0.3, 1.3, 2.5}) {
      const Eigen::Matrix3d R =
          Eigen::AngleAxisd(angle, Vec3(1.0, 1.0, 0.5 * seed).normalized()).toRotationMatrix();
      // (a) Frames rotated rigidly with the rod, theta unchanged.
      State a = s0;
      for (auto& p : a.x) p = R * p;
      for (auto& d : a.ref1) d = R * d;
      for (auto& t : a.ref_tangent) t = R * t;
      EXPECT_NEAR(term.energy(a) / U0, 1.0, 1e-9) << "rigid frames, angle " << angle;

      // (b) Positions rotated, frames re-transported from the old tangents, theta adjusted so
      // that the material frame is the rotated one.
      State b = s0;
      for (auto& p : b.x) p = R * p;
      update_reference_frames(b);
      for (int j = 0; j < b.num_edges(); ++j) {
        const Vec3 target = R * material_director(s0, j);
        b.theta[j] = signed_angle(b.ref1[j], target, b.ref_tangent[j]);
      }
      // Consistency of the construction: the material directors are the rotated ones.
      for (int j = 0; j < b.num_edges(); ++j) {
        EXPECT_LT((material_director(b, j) - R * material_director(s0, j)).norm(), 1e-12);
      }
      EXPECT_NEAR(term.energy(b) / U0, 1.0, 1e-9) << "transported frames, angle " << angle;
      double Ub = 0;
      forces_of(term, b, &Ub);
      EXPECT_NEAR(Ub / U0, 1.0, 1e-9);
    }
  }
}

// Infinitesimal form of the rotation invariance: with theta following the material frame
// (d theta_j = omega . t_j, see frames.hpp: transport adds no spin about t), the forces and
// torques satisfy sum_i x_i x f_i + sum_j tau_j t_j = 0, and translation invariance gives
// sum_i f_i = 0. Tolerance: round-off relative to |x| |f| and |f|, 1e-12.
TEST(Twist, ForcesAndTorquesBalanceMoments) {
  const auto mat = testing::default_material();
  TwistTerm term(mat.GJ());
  for (unsigned seed = 1; seed <= 3; ++seed) {
    State s = twisted_helix(seed);
    for (auto& p : s.x) p += Vec3(1e-3, -2e-3, 0.5e-3);  // off-origin, so the moment is nontrivial
    update_reference_frames(s);
    const Forces f = forces_of(term, s);
    double fmax = 0, lever = 0;
    for (int i = 0; i < s.num_nodes(); ++i) {
      fmax = std::max(fmax, f.f[i].norm());
      lever = std::max(lever, s.x[i].norm());
    }
    double tmax = 0;
    for (double t : f.torque) tmax = std::max(tmax, std::abs(t));
    ASSERT_GT(fmax, 0.0);
    EXPECT_LT(testing::sum_of(f.f).norm(), 1e-12 * fmax);
    EXPECT_LT(testing::moment_of(s, f).norm(), 1e-12 * (fmax * lever + tmax));
  }
}

// FD check of forces and torques on the helix (non-planar, nonzero reference twist from the
// frames' history). Same criterion as test_stretch_bend_twist_fd.cpp: the best of the step
// ladder below 1e-6 relative and the O(h^2) trend between h = 1e-2 and 1e-3.
TEST(Twist, GradientMatchesFiniteDifferencesOnHelix) {
  const auto mat = testing::default_material();
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const State s = twisted_helix(seed);
    const double rt = max_abs_ref_twist(s);
    std::printf("  helix seed %u: max |reference twist| = %.3f rad\n", seed, rt);
    ASSERT_GT(rt, 0.01);
    TwistTerm term(mat.GJ());
    const auto rep = testing::fd_check(term, s, 0.5e-3, testing::default_fd_steps());
    testing::print_report(rep);
    EXPECT_LT(rep.best(), 1e-6);
    EXPECT_LT(rep.err[1], 0.1 * rep.err[0] + 1e-9);
  }
}

}  // namespace
}  // namespace wirepack
