// Whole runs with the elastic shell (Engine III): the hard cases of the issue at a reduced
// size that fits the test suite (rho = 10, coarse elements; the full-size runs are in
// slow_simulation_elastic.cpp): no NaN, every released node inside the deformed shell (the
// run itself checks it with the winding number and fails otherwise), bounded energy.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/winding.hpp"
#include "engine/simulation.hpp"

namespace wirepack {
namespace {

SceneParams elastic_scene(double xi, double eps, double mu_s, double l_max) {
  SceneParams p;
  p.shell = ShellKind::Elastic;
  p.rho = 10;
  p.xi = xi;
  p.eps = eps;
  p.mu_s = mu_s;
  p.mu_d = 0.9 * mu_s;
  p.l_max = l_max;
  p.numerics.element_length = 2 * p.wire.radius;
  p.numerics.shell_mesh_size = 2 * p.wire.radius;
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
  for (const Vec3& v : sim.shell_vertices()) ASSERT_TRUE(v.allFinite());
  const Energies e = sim.energies();
  std::printf("  xi=%g eps=%g mu_s=%g: l=%.1f, %ld steps, U_b=%.2e U_m=%.2e U_sb=%.2e J\n", p.xi,
              p.eps, p.mu_s, sim.l(), sim.steps(), e.U_b, e.U_m, e.U_sb);
  // Bounded: the elastic energy stays below the work a feed force of 10 N (two orders of
  // magnitude above the wire's Euler load) could have done over the injected length.
  EXPECT_LT(peak_U, 10.0 * sim.L());
}

TEST(ElasticSimulation, StiffThickShellHeadOn) {
  run_and_check(elastic_scene(10, 1, 0, 3));
}

TEST(ElasticSimulation, VerySoftThinShellWithStrongFriction) {
  run_and_check(elastic_scene(200, 1e4, 1.0, 3));
}

TEST(ElasticSimulation, HeadOnTipIntoAVerySoftShell) {
  run_and_check(elastic_scene(10, 1e4, 0, 3));
}

TEST(ElasticSimulation, SceneAssemblesShellTermsAndNoWall) {
  Simulation sim(elastic_scene(10, 1000, 0.5, 1));
  const auto names = sim.term_names();
  for (const char* want : {"membrane", "shell_bending", "wire_shell", "friction", "twist"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  }
  EXPECT_EQ(std::find(names.begin(), names.end(), "wall"), names.end());
  EXPECT_FALSE(sim.shell_vertices().empty());
  EXPECT_FALSE(sim.shell_triangles().empty());
}

}  // namespace
}  // namespace wirepack
