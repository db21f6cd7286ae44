// Full-size elastic-shell hard cases (label "slow", not in CI): rho = 20 with the default
// numerics, to l = 5 (past the head-on contact at l ~ 2 and the first loops). Same checks as
// test_simulation_elastic.cpp: no NaN, every released node inside the deformed shell (the
// run checks it with the winding number), bounded energy.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/simulation.hpp"

namespace wirepack {
namespace {

SceneParams full_scene(double xi, double eps, double mu_s) {
  SceneParams p;
  p.shell = ShellKind::Elastic;
  p.rho = 20;
  p.xi = xi;
  p.eps = eps;
  p.mu_s = mu_s;
  p.mu_d = 0.9 * mu_s;
  p.l_max = 5;
  return p;
}

void run_and_check(const SceneParams& p) {
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
  std::printf("  xi=%g eps=%g mu_s=%g: %ld steps, peak elastic energy %.3e J\n", p.xi, p.eps,
              p.mu_s, sim.steps(), peak_U);
  EXPECT_LT(peak_U, 10.0 * sim.L());  // below 10 N of feed force over the injected length
}

TEST(ElasticSimulationFullSize, SoftThinShellStrongFriction) {
  run_and_check(full_scene(200, 1e4, 1.0));
}
TEST(ElasticSimulationFullSize, StiffThickShell) {
  run_and_check(full_scene(10, 1, 0));
}
TEST(ElasticSimulationFullSize, HeadOnIntoAVerySoftShell) {
  run_and_check(full_scene(10, 1e4, 0));
}

}  // namespace
}  // namespace wirepack
