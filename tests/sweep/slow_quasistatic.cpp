// The quasi-static regime (selective mass scaling, docs/reference.md "Quasi-static regime"), label
// "slow" (about 8 min on one core): on the paper's elastic scene (rho = 20, xi = 10, eps = 1e3,
// seed 1) the default numerics agree with a reference whose element-scale inertia is 11 times
// smaller (quasistatic_ratio 0.003 against 0.01: inertia goes as q^2) to l = 10, and the kinetic
// energy stays a small fraction of the wire's bending energy.
// Tolerances: the seed floor of the default. Coil (mu_s = 0): U_b_hat and K differ by < 1 %
// between seeds 1 and 3 at l = 8-10 and the radii by < 0.02 R; 3 % and 0.05 R allow for the
// reference's own discretisation differences. Crumpled (mu_s = 0.5): the seed floor measured
// over whole runs is 8 % in U_b_hat and 0.23 in D (docs/measurements.md "Tolerance over a whole
// run"); the mean over l in [8, 10] is compared with those bounds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "analysis/observables.hpp"
#include "engine/simulation.hpp"
#include "sweep/config/scene_config.hpp"

namespace wirepack::sweep {
namespace {

struct Late {
  double U_b_hat = 0, K = 0, D = 0, R_x = 0, R_y = 0;  // means over l in [8, 10]
  int radii = 0;                                       // samples with a coil fit
  double ekin_mean = 0, ekin_max = 0;                  // E_kin / U_b over l in [5, 10]
};

Late run(double mu_s, double q) {
  nlohmann::json j = {{"rho", 20}, {"xi", 10}, {"eps", 1000}, {"mu_s", mu_s}, {"l_max", 10}};
  if (q > 0) j["numerics"] = {{"quasistatic_ratio", q}};
  const Scene scene = parse_scene(j, "quasistatic");
  Simulation sim(scene.engine);
  const double r = scene.engine.wire.radius, R = scene.engine.R();
  Late out;
  int n_late = 0, n_ekin = 0;
  for (double l = 5.0; l <= 10.0 + 1e-9; l += 0.25) {
    sim.advance_to(l);
    const Energies e = sim.energies();
    const double ratio = e.E_kin / e.U_b;
    out.ekin_mean += ratio;
    out.ekin_max = std::max(out.ekin_max, ratio);
    ++n_ekin;
    if (l < 8.0 - 1e-9 || std::fmod(l, 0.5) > 1e-9) continue;
    const auto x = sim.inside_nodes();
    out.U_b_hat += analysis::bending_energy_hat(e.U_b, r, R, scene.engine.wire.youngs_modulus);
    out.K += analysis::total_curvature(x);
    out.D += analysis::order_parameter(x).D;
    const analysis::CoilRadii c = analysis::coil_radii(x, r);
    if (c.ok) {
      out.R_x += c.R_x / R;
      out.R_y += c.R_y / R;
      ++out.radii;
    }
    ++n_late;
  }
  out.U_b_hat /= n_late;
  out.K /= n_late;
  out.D /= n_late;
  if (out.radii > 0) {
    out.R_x /= out.radii;
    out.R_y /= out.radii;
  }
  out.ekin_mean /= n_ekin;
  std::printf(
      "  mu_s %.1f q %s: U_b_hat %.5f K %.2f D %.3f R_x %.3f R_y %.3f (%d fits), "
      "E_kin/U_b mean %.4f max %.4f\n",
      mu_s, q > 0 ? std::to_string(q).c_str() : "default", out.U_b_hat, out.K, out.D, out.R_x,
      out.R_y, out.radii, out.ekin_mean, out.ekin_max);
  return out;
}

TEST(QuasiStatic, CoilAgreesWithTheLowInertiaReference) {
  const Late d = run(0.0, 0.0), ref = run(0.0, 0.003);
  EXPECT_NEAR(d.U_b_hat / ref.U_b_hat, 1.0, 0.03);
  EXPECT_NEAR(d.K / ref.K, 1.0, 0.03);
  EXPECT_NEAR(d.D, ref.D, 0.1);
  ASSERT_GT(d.radii, 0);
  ASSERT_GT(ref.radii, 0);
  EXPECT_NEAR(d.R_x, ref.R_x, 0.05);
  EXPECT_NEAR(d.R_y, ref.R_y, 0.05);
  // E_kin / U_b: the target 1 % on average (the uniform scaling had 15-25 %); single samples
  // reach a few % in the transient after the first shell contact (measured 2.7 % here, up to
  // 4.5 % over [5, 10] in results/elastic), bounded by 5 %.
  EXPECT_LT(d.ekin_mean, 0.01);
  EXPECT_LT(d.ekin_max, 0.05);
}

TEST(QuasiStatic, CrumplingRunAgreesWithTheLowInertiaReference) {
  const Late d = run(0.5, 0.0), ref = run(0.5, 0.003);
  EXPECT_NEAR(d.U_b_hat / ref.U_b_hat, 1.0, 0.08);
  EXPECT_NEAR(d.K / ref.K, 1.0, 0.08);
  EXPECT_NEAR(d.D, ref.D, 0.23);
  EXPECT_LT(d.ekin_mean, 0.01);
}

}  // namespace
}  // namespace wirepack::sweep
