#pragma once
// Shared by the elastic-shell whole-run tests: runs a scene to l_max and checks it stays sane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/simulation.hpp"

namespace wirepack::testing {

inline SceneParams elastic_scene(double rho, double xi, double eps, double mu_s, double l_max) {
  SceneParams p;
  p.shell = ShellKind::Elastic;
  p.rho = rho;
  p.xi = xi;
  p.eps = eps;
  p.mu_s = mu_s;
  p.mu_d = 0.9 * mu_s;
  p.l_max = l_max;
  return p;
}

// No NaN, every released node inside the deformed shell (the run itself checks it with the
// winding number and would throw), and bounded energy: the elastic energy stays below the
// work a feed force of 10 N (two orders of magnitude above the wire's Euler load) could have
// done over the injected length.
inline void run_and_check(const SceneParams& p) {
  Simulation sim(p);
  double peak_U = 0;
  while (!sim.finished()) {
    ASSERT_NO_THROW(sim.step()) << "at l = " << sim.l();
    if (sim.steps() % 500 == 0) {
      const Energies e = sim.energies();
      ASSERT_TRUE(std::isfinite(e.U_b + e.U_m + e.U_sb + e.E_kin + e.U_contact));
      peak_U = std::max(peak_U, e.U_b + e.U_m + e.U_sb + e.U_contact);
    }
  }
  for (const Vec3& v : sim.shell_vertices()) ASSERT_TRUE(v.allFinite());
  const Energies e = sim.energies();
  std::printf("  rho=%g xi=%g eps=%g mu_s=%g: l=%.1f, %ld steps, U_b=%.2e U_m=%.2e U_sb=%.2e J\n",
              p.rho, p.xi, p.eps, p.mu_s, sim.l(), sim.steps(), e.U_b, e.U_m, e.U_sb);
  EXPECT_LT(peak_U, 10.0 * sim.L());
}

}  // namespace wirepack::testing
