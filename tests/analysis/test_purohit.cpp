// Tests for the Purohit coil model (paper Eqs. 4-7): the closed forms for L, U_b and K against
// Gauss-Legendre quadrature of the model's integrals for p < 1, p = 1 and p > 1, the real form of
// Eq. (6) for p > 1, continuity across p = 1 and across the large-p series switch, and the
// invalid-input contract.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "analysis/purohit.hpp"

namespace wirepack::analysis {
namespace {

using std::numbers::pi;

// Composite 20-point Gauss-Legendre on 200 panels of a smooth (after y = R_t + R_y sin theta)
// integrand converges to round-off: the closed forms must agree to 1e-11 relative (a few hundred
// ulp of accumulated sums, far below any modelling question).
constexpr double kRelTol = 1e-11;

struct Case {
  double R_t, R_x, R_y;
};

// Radii of a coil of the paper's scale (R_x = 2.5 mm, R_y = 4 mm), with
// p = R_t / R_y = 0.05, 0.3, 1 (exactly), 3, sqrt(17) +- (series switch), 20, 1000.
std::vector<Case> cases() {
  const double R_y = 4e-3;
  std::vector<Case> c;
  for (double p : {0.05, 0.3, 1.0, 3.0, std::sqrt(17.0) * (1 - 1e-12),
                   std::sqrt(17.0) * (1 + 1e-12), 20.0, 1000.0}) {
    c.push_back({p * R_y, 2.5e-3, R_y});
  }
  return c;
}

TEST(Purohit, ClosedFormsMatchQuadrature) {
  const double L = 2.0, EI = 4.9e-5;  // r = 0.5 mm, E_w = 1 GPa: EI = E pi r^4 / 4
  for (const Case& k : cases()) {
    SCOPED_TRACE("p = " + std::to_string(k.R_t / k.R_y));
    const PurohitPrediction pr = purohit(L, k.R_t, k.R_x, k.R_y, EI);
    ASSERT_TRUE(pr.ok);
    EXPECT_DOUBLE_EQ(pr.p, k.R_t / k.R_y);
    EXPECT_DOUBLE_EQ(pr.c, 4.0 / 3.0 + pi * pr.p);
    // Eq. (4): the quadrature at the closed-form d gives back the injected length.
    EXPECT_NEAR(purohit_length_quadrature(pr.d, k.R_t, k.R_x, k.R_y) / L, 1.0, kRelTol);
    // Eqs. (5) -> (6) and (7).
    const double Ub = purohit_bending_quadrature(pr.d, k.R_t, k.R_x, k.R_y, EI);
    EXPECT_NEAR(pr.U_b / Ub, 1.0, kRelTol);
    const double K = purohit_curvature_quadrature(pr.d, k.R_t, k.R_x, k.R_y);
    EXPECT_NEAR(pr.K / K, 1.0, kRelTol);
  }
}

TEST(Purohit, BendingIntegralForms) {
  // p = 1: int_0^1 sqrt((1 - u)/(1 + u)) du = pi/2 - 1 exactly.
  EXPECT_DOUBLE_EQ(purohit_bending_integral(1.0), pi / 2 - 1);
  // p > 1: Eq. (6) with q ln((1+q)/p) -> -s atan(s), s = sqrt(p^2 - 1), written directly.
  for (double p : {1.5, 3.0, 10.0}) {
    const double s = std::sqrt(p * p - 1);
    EXPECT_NEAR(purohit_bending_integral(p), -s * std::atan(s) + pi / 2 * p - 1, 1e-14);
  }
  // p < 1: the paper's form literally.
  for (double p : {0.1, 0.5, 0.9}) {
    const double q = std::sqrt(1 - p * p);
    EXPECT_NEAR(purohit_bending_integral(p), q * std::log((1 + q) / p) + pi / 2 * p - 1, 1e-14);
  }
  // Continuous across p = 1: both branches have a finite slope there, so a step of 1e-9 in p
  // moves I by O(1e-9).
  const double I1 = purohit_bending_integral(1.0);
  EXPECT_NEAR(purohit_bending_integral(1 - 1e-9), I1, 1e-8);
  EXPECT_NEAR(purohit_bending_integral(1 + 1e-9), I1, 1e-8);
  // Large p: I ~ pi/(4p) - 1/(3p^2); relative to the leading term, next order O(1/p).
  const double p = 1e6;
  EXPECT_NEAR(purohit_bending_integral(p) / (pi / (4 * p) - 1 / (3 * p * p)), 1.0, 1e-9);
}

TEST(Purohit, BendingEnergyDecreasesWithP) {
  // Paper, below Eq. (6): at fixed L, R_x, R_y, U_b is monotonically decreasing in p = R_t / R_y.
  const double R_y = 4e-3;
  double prev = purohit(2.0, 0.01 * R_y, 2.5e-3, R_y, 4.9e-5).U_b;
  for (double p = 0.013; p < 100; p *= 1.3) {
    const double cur = purohit(2.0, p * R_y, 2.5e-3, R_y, 4.9e-5).U_b;
    EXPECT_LT(cur, prev) << "p = " << p;
    EXPECT_GT(cur, 0);
    prev = cur;
  }
}

TEST(Purohit, InvalidInputIsNotOk) {
  EXPECT_FALSE(purohit(1, 0, 1e-3, 1e-3, 1).ok);
  EXPECT_FALSE(purohit(1, 1e-3, -1e-3, 1e-3, 1).ok);
  EXPECT_FALSE(purohit(1, 1e-3, 1e-3, NaN, 1).ok);
  EXPECT_FALSE(purohit(1, 1e-3, 1e-3, std::numeric_limits<double>::infinity(), 1).ok);
  EXPECT_FALSE(purohit(0, 1e-3, 1e-3, 1e-3, 1).ok);
  EXPECT_TRUE(std::isnan(purohit(1, 0, 1e-3, 1e-3, 1).U_b));
}

}  // namespace
}  // namespace wirepack::analysis
