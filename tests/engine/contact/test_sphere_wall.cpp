// SphereWallTerm: wire nodes against the inside of a rigid sphere with an entrance hole at the
// south pole. FD gradient, Hertz's law (paper; docs/design.md §2.5: F = 4/3 E* sqrt(R*) delta^{3/2}
// with R* = r R / (R - r)), the hole and its rim, guide nodes, the contact count and the dashpot.
#include "engine/contact/sphere_wall.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "engine/fd_harness.hpp"
#include "engine/rod_builders.hpp"

namespace wirepack {
namespace {

// Default wire in a sphere of rho = R / r = 20 with the scene's hole r_h = 1.1 r.
struct Wall {
  RodMaterial mat = testing::default_material();
  double r = mat.r;
  double R = 20.0 * mat.r;
  double r_h = 1.1 * mat.r;
  double z_rim = -std::sqrt(R * R - r_h * r_h);
  double E_star = effective_modulus(mat.E, WireParams{}.poisson_ratio,
                                    std::numeric_limits<double>::infinity(), 0.0);
  double R_star = r * R / (R - r);

  SphereWallParams params(double zeta = 0.0) const {
    SphereWallParams p;
    p.R = R;
    p.r = r;
    p.hole_radius = r_h;
    p.E_star = E_star;
    p.damping_ratio = zeta;
    p.node_mass = 1e-6;
    return p;
  }
  // Node whose capsule overlaps the wall by delta along the unit direction dir.
  Vec3 at_overlap(const Vec3& dir, double delta) const { return (R - r + delta) * dir; }
};

// A "rod" of loose nodes (the wall term looks at nodes only); all dynamic, at rest.
State nodes(const Vec3List& x) {
  return testing::rod_through(x);
}

// FD check: eight nodes overlapping the wall by random 0 .. 0.1 r in random directions away from
// the hole, two nodes clear of it, one node touching the hole's rim (rim branch, R* = r) and a
// guide node overlapping the wall (no force, no energy). Velocities zero: the dashpot is off and
// the forces are -grad U. Same criterion as the rod terms: best of the ladder below 1e-6
// relative, error falling >= 10x from h = 1e-2 r to 1e-3 r.
TEST(SphereWall, GradientMatchesFiniteDifferences) {
  const Wall w;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Vec3List x;
    while (x.size() < 8) {
      const Vec3 d = Vec3(g(rng), g(rng), g(rng)).normalized();
      if (d[2] < -0.9) continue;  // keep clear of the hole
      x.push_back(w.at_overlap(d, 0.1 * w.r * (1e-3 + u(rng))));
    }
    x.push_back(Vec3(0.2, 0.3, 0.1) * w.R);                              // inside, clear
    x.push_back(w.at_overlap(Vec3(1, -1, 1).normalized(), -0.3 * w.r));  // near, clear
    // Rim: 0.95 r from the rim circle (delta = 0.05 r), inside the hole cylinder, 0.3 r above.
    x.push_back(Vec3(w.r_h - std::sqrt(0.95 * 0.95 - 0.3 * 0.3) * w.r, 0.0, w.z_rim + 0.3 * w.r));
    x.push_back(w.at_overlap(Vec3(0, 1, 0), 0.05 * w.r));  // guide node
    State s = nodes(x);
    s.n_free = s.num_nodes() - 1;
    SphereWallTerm term(w.params(0.5));
    Forces f = testing::forces_of(term, s);
    EXPECT_EQ(term.contacts(), 9) << seed;  // eight on the wall, one on the rim
    EXPECT_EQ(f.f.back(), Vec3::Zero());
    const auto rep = testing::fd_check(term, s, w.r, testing::default_fd_steps());
    testing::print_report(rep);
    EXPECT_LT(rep.best(), 1e-6);
    EXPECT_LT(rep.err[1], 0.1 * rep.err[0] + 1e-9);
  }
}

// Hertz's law for a node pushed out by delta: F = 4/3 E* sqrt(R*) delta^{3/2} along -x/|x|,
// U = 8/15 E* sqrt(R*) delta^{5/2}, for delta = 0.01 .. 0.2 r, so the log-log slope is 3/2.
// Tolerance 1e-12 relative: delta = |x| + r - R is a difference of O(R) numbers, so its
// round-off is ~eps R / delta <= 2.2e-14 at delta >= 0.01 r (R = 20 r), times 3/2 in F; the
// reference delta is formed in long double from the same node position.
TEST(SphereWall, HertzForceOfOneNode) {
  const Wall w;
  const Vec3 dir = Vec3(0.3, -0.5, 0.8).normalized();
  const double k = 4.0 / 3.0 * w.E_star * std::sqrt(w.R_star);
  double prev_F = 0, prev_delta = 0;
  for (double d : {0.01, 0.02, 0.05, 0.1, 0.2}) {
    State s = nodes({w.at_overlap(dir, d * w.r)});
    SphereWallTerm term(w.params());
    double U = 0;
    const Forces f = testing::forces_of(term, s, &U);
    const Vec3& x = s.x[0];
    const long double norm_ld =
        std::sqrt((long double)x[0] * x[0] + (long double)x[1] * x[1] + (long double)x[2] * x[2]);
    const double delta = static_cast<double>(norm_ld + (long double)w.r - (long double)w.R);
    const double F = k * std::pow(delta, 1.5);
    EXPECT_NEAR(f.f[0].norm() / F, 1.0, 1e-12) << d;
    EXPECT_NEAR(U / (0.4 * k * std::pow(delta, 2.5)), 1.0, 1e-12) << d;
    EXPECT_LT((f.f[0].normalized() + x.normalized()).norm(), 1e-14);  // pushes towards the centre
    EXPECT_EQ(term.contacts(), 1);
    if (prev_F > 0) {
      const double slope = std::log(f.f[0].norm() / prev_F) / std::log(delta / prev_delta);
      EXPECT_NEAR(slope, 1.5, 1e-10);
    }
    prev_F = f.f[0].norm();
    prev_delta = delta;
  }
  // Just inside the contact distance: nothing.
  State s = nodes({w.at_overlap(dir, -1e-3 * w.r)});
  SphereWallTerm term(w.params());
  double U = 1;
  const Forces f = testing::forces_of(term, s, &U);
  EXPECT_EQ(U, 0.0);
  EXPECT_EQ(f.f[0], Vec3::Zero());
  EXPECT_EQ(term.contacts(), 0);
}

// The hole: nodes on the feed axis just above, in and below the hole plane feel nothing (the
// wall alone would give them overlaps of ~r); a node pushed sideways against the rim is pushed
// back towards the axis by the rim's Hertz force (edge contact, R* = r).
TEST(SphereWall, HoleAndRim) {
  const Wall w;
  SphereWallTerm term(w.params());
  for (double dz : {1.5, 0.5, 0.0, -0.5, -3.0}) {  // [r] relative to the rim plane
    State s = nodes({Vec3(0, 0, w.z_rim + dz * w.r)});
    double U = 1;
    const Forces f = testing::forces_of(term, s, &U);
    EXPECT_EQ(U, 0.0) << dz;
    EXPECT_EQ(f.f[0], Vec3::Zero()) << dz;
    EXPECT_EQ(term.contacts(), 0);
  }
  const double k_rim = 4.0 / 3.0 * w.E_star * std::sqrt(w.r);
  for (double beta : {0.0, 1.0, 2.5, -2.0}) {
    const Vec3 radial(std::cos(beta), std::sin(beta), 0.0);
    // In the rim plane, 0.8 r from the rim circle: delta = 0.2 r, force exactly towards the axis.
    State s = nodes({(w.r_h - 0.8 * w.r) * radial + Vec3(0, 0, w.z_rim)});
    const Forces f = testing::forces_of(term, s);
    EXPECT_EQ(term.contacts(), 1);
    // 1e-10: delta = r - dist with dist formed from O(R) coordinates (eps R / (0.2 r) ~ 1e-14).
    EXPECT_NEAR(f.f[0].norm() / (k_rim * std::pow(0.2 * w.r, 1.5)), 1.0, 1e-10) << beta;
    EXPECT_LT((f.f[0].normalized() + radial).norm(), 1e-10) << beta;
    // Above the rim plane the force also lifts the node into the sphere.
    State s2 = nodes({(w.r_h - 0.7 * w.r) * radial + Vec3(0, 0, w.z_rim + 0.3 * w.r)});
    const Forces f2 = testing::forces_of(term, s2);
    EXPECT_LT(f2.f[0].dot(radial), 0.0);
    EXPECT_GT(f2.f[0][2], 0.0);
  }
}

// Guide nodes (index >= n_free) are kinematic: no force, no energy, not counted, whatever their
// overlap; contacts() counts the dynamic nodes that touch.
TEST(SphereWall, GuideNodesAndContactCount) {
  const Wall w;
  Vec3List x;
  for (int i = 0; i < 6; ++i) {
    const double a = 0.7 * i;
    x.push_back(w.at_overlap(Vec3(std::cos(a), std::sin(a), 0.2).normalized(),
                             (i % 2 ? 0.05 : -0.05) * w.r));
  }
  State s = nodes(x);  // touching: nodes 1, 3, 5
  SphereWallTerm term(w.params());
  double U_all = 0;
  testing::forces_of(term, s, &U_all);
  EXPECT_EQ(term.contacts(), 3);
  s.n_free = 4;  // nodes 4, 5 are guide nodes
  double U = 0;
  const Forces f = testing::forces_of(term, s, &U);
  EXPECT_EQ(term.contacts(), 2);
  EXPECT_EQ(f.f[4], Vec3::Zero());
  EXPECT_EQ(f.f[5], Vec3::Zero());
  EXPECT_NEAR(U, 2.0 / 3.0 * U_all, 1e-12 * U_all);  // three equal contacts, one dropped
  EXPECT_EQ(term.energy(s), U);
}

// Dashpot: with approach speed u = v . n the normal force is F + 2 zeta sqrt(k_c m) u, k_c the
// Hertz stiffness 3/2 F / delta: an approaching node gets more than the elastic force, a
// receding one less, a fast receding one none (never attractive). Tangential motion does not
// count. energy() ignores velocities. Tolerance 1e-12 relative (same formula, round-off).
TEST(SphereWall, DashpotOnApproachOnly) {
  const Wall w;
  const double zeta = 0.5;
  SphereWallParams p = w.params(zeta);
  SphereWallTerm term(p);
  const Vec3 n = Vec3(0.6, 0.0, 0.8);
  const double delta = 0.05 * w.r;
  State s = nodes({w.at_overlap(n, delta)});
  const Forces f0 = testing::forces_of(term, s);
  const double F = f0.f[0].norm();
  const double k_c = 1.5 * F / delta;
  const double eta = 2.0 * zeta * std::sqrt(k_c * p.node_mass);
  const Vec3 tangential = Vec3(0.8, 0.0, -0.6);
  for (double u : {1e-3, 1e-2, -1e-3, -1e-2, -1.0, -100.0}) {
    s.v[0] = u * n + 0.3 * tangential;
    const Forces f = testing::forces_of(term, s);
    const double fn = -f.f[0].dot(n);  // push away from the wall, >= 0
    EXPECT_GE(fn, 0.0) << u;
    EXPECT_LT((f.f[0] + fn * n).norm(), 1e-12 * F);  // normal only
    EXPECT_NEAR(fn, std::max(0.0, F + eta * u), 1e-12 * F) << u;
    if (u > 0) {
      EXPECT_GT(fn, F);
    } else {
      EXPECT_LT(fn, F);
    }
    EXPECT_EQ(term.energy(s), term.energy(nodes({s.x[0]})));
  }
}

}  // namespace
}  // namespace wirepack
