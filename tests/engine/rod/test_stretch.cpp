// Analytic checks of the stretching energy (StretchTerm, paper Eq. (1) last term): a uniformly
// strained rod stores 1/2 E A e^2 L and pulls on its ends with E A e (Hooke's law).
#include "engine/rod/stretch.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/fd_harness.hpp"
#include "engine/rod_builders.hpp"

namespace wirepack {
namespace {

// Uniform strain e of a straight rod of n nodes along a generic direction, with rest lengths
// varying along the rod (each edge stretched to lbar_j (1 + e)): U = 1/2 E A e^2 L with
// L = sum lbar_j, the end forces are -+ E A e along the axis, interior nodes are in balance.
// Tolerance 1e-10 relative: the strain is formed as |e_j| / lbar_j - 1, whose round-off is
// ~1e-16 / |e| relative to e (1e-13 at |e| = 1e-3); 1e-10 leaves room and still catches any
// factor or sign slip.
TEST(Stretch, UniformExtensionObeysHooke) {
  const auto mat = testing::default_material();
  const Vec3 dir = Vec3(0.3, -0.5, 0.8).normalized();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0.8, 1.2);
  for (double e : {1e-3, 2e-2, -5e-3, 0.3}) {
    const int n = 15;
    std::vector<double> lbar(n - 1);
    for (auto& v : lbar) v = 0.5e-3 * u(rng);
    State s;
    s.x.push_back(Vec3(1e-3, 2e-3, -1e-3));
    double L = 0;
    for (int j = 0; j + 1 < n; ++j) {
      s.x.push_back(s.x.back() + lbar[j] * (1.0 + e) * dir);
      L += lbar[j];
    }
    s.v.assign(n, Vec3::Zero());
    s.rest_length = lbar;
    s.n_free = n;

    StretchTerm term(mat.EA());
    double U = 0;
    const Forces f = testing::forces_of(term, s, &U);
    const double U_exact = 0.5 * mat.EA() * e * e * L;
    EXPECT_NEAR(U / U_exact, 1.0, 1e-10) << "e = " << e;
    EXPECT_NEAR(term.energy(s) / U_exact, 1.0, 1e-10);
    // Hooke: the tension E A e pulls the last node back (-dir) and the first one forward.
    const double F = mat.EA() * e;
    EXPECT_NEAR(f.f[n - 1].dot(dir) / -F, 1.0, 1e-10);
    EXPECT_NEAR(f.f[0].dot(dir) / F, 1.0, 1e-10);
    // Axial only, and interior nodes in balance (round-off of differences of O(F) forces).
    EXPECT_LT((f.f[n - 1] - f.f[n - 1].dot(dir) * dir).norm(), 1e-10 * std::abs(F));
    for (int i = 1; i + 1 < n; ++i) EXPECT_LT(f.f[i].norm(), 1e-10 * std::abs(F)) << i;
  }
}

// A stress-free rod (edges at rest length, any shape) has zero stretching energy and forces.
TEST(Stretch, RestStateIsStressFree) {
  const auto mat = testing::default_material();
  StretchTerm term(mat.EA());
  State s = testing::random_rod(20, 0.5e-3, false, 5);
  for (int j = 0; j + 1 < s.num_nodes(); ++j) s.rest_length[j] = (s.x[j + 1] - s.x[j]).norm();
  double U = 1.0;
  const Forces f = testing::forces_of(term, s, &U);
  // Round-off: strain ~1e-16, U ~ E A 1e-32 l, forces ~ E A 1e-16 (bound 1e-13 E A).
  EXPECT_LT(U, 1e-25 * mat.EA() * 0.5e-3);
  for (const Vec3& v : f.f) EXPECT_LT(v.norm(), 1e-13 * mat.EA());
}

// Two edges in series with different strains: each edge's tension E A eps_j acts on its own
// nodes, so the middle node feels the difference E A (eps_1 - eps_0).
TEST(Stretch, SeriesEdgesCarryTheirOwnTension) {
  const auto mat = testing::default_material();
  StretchTerm term(mat.EA());
  const double l = 0.5e-3;
  State s = testing::straight_rod(3, l);
  s.x[1][0] = l * 1.01;             // edge 0: eps_0 = +0.01
  s.x[2][0] = l * 1.01 + l * 0.98;  // edge 1: eps_1 = -0.02
  const Forces f = testing::forces_of(term, s);
  // Tolerance 1e-10 relative, as above.
  EXPECT_NEAR(f.f[0][0] / (mat.EA() * 0.01), 1.0, 1e-10);
  EXPECT_NEAR(f.f[1][0] / (mat.EA() * (-0.02 - 0.01)), 1.0, 1e-10);
  EXPECT_NEAR(f.f[2][0] / (mat.EA() * 0.02), 1.0, 1e-10);
}

}  // namespace
}  // namespace wirepack
