// Thin shells carry the inertia of thickness t_m = max(t, min(c r, t rho_w / rho_s))
// (numerics.shell_inertia_thickness = c, scene.cpp): the vertex masses against their closed
// form, the drag per vertex unchanged, the contacts' step bounds fed the heavier vertices, the
// cap at the physical inertia, and no change at all where the rule does not act.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "engine/scene.hpp"
#include "engine/simulation.hpp"

namespace wirepack {
namespace {

SceneParams shell_scene(double rho, double xi, double eps, double c) {
  SceneParams p;
  p.shell = ShellKind::Elastic;
  p.rho = rho;
  p.xi = xi;
  p.eps = eps;
  p.numerics.shell_mesh_size = 4 * p.wire.radius;  // a coarse mesh: the rule is per area
  p.numerics.shell_inertia_factor = c;
  return p;
}

double total(const std::vector<double>& m) {
  return std::accumulate(m.begin(), m.end(), 0.0);
}

// Lumped mass of a vertex: rho_s t_m A_v / 3 summed over its faces, rho_s = E_s q^2 / v^2
// (40 kg/m^3 at eps = 1e4, below the cap rho_w = 1140). The mesh's total is rho_s t_m times its
// area; here t_m = c r, so each vertex is c r / t = c xi / rho times heavier than with t. Tolerance
// 1e-12 relative: the two assemblies sum the same face areas in the same order, only the factor
// differs.
TEST(ShellInertia, ThinShellVertexMassesMatchTheClosedForm) {
  const double rho = 20, xi = 200, eps = 1e4, c = 1.0;
  const Assembly own = assemble(shell_scene(rho, xi, eps, 0.0));
  const Assembly thin = assemble(shell_scene(rho, xi, eps, c));
  const SceneParams p = shell_scene(rho, xi, eps, c);
  const double r = p.wire.radius, R = p.R(), t = R / xi;
  EXPECT_DOUBLE_EQ(shell_mass_thickness(p), c * r);
  const double q = p.numerics.quasistatic_ratio, v = p.injection_speed;
  const double rho_s = p.wire.youngs_modulus / eps * q * q / (v * v);
  // Mesh area from the faces, independently of the assembly's loop.
  const ShellMesh& mesh = *thin.mesh;
  double area = 0.0;
  for (const auto& f : mesh.faces)
    area +=
        0.5 * (mesh.rest[f[1]] - mesh.rest[f[0]]).cross(mesh.rest[f[2]] - mesh.rest[f[0]]).norm();
  EXPECT_NEAR(total(thin.vertex_mass), rho_s * c * r * area, 1e-12 * rho_s * c * r * area);
  EXPECT_NEAR(total(own.vertex_mass), rho_s * t * area, 1e-12 * rho_s * t * area);
  const double factor = c * xi / rho;  // t_m / t = 10
  ASSERT_EQ(thin.vertex_mass.size(), own.vertex_mass.size());
  for (size_t k = 0; k < own.vertex_mass.size(); ++k)
    EXPECT_NEAR(thin.vertex_mass[k], factor * own.vertex_mass[k], 1e-12 * thin.vertex_mass[k]);
  // Drag per vertex (rate x mass) is that of thickness t: the extra inertia adds no drag.
  EXPECT_NEAR(thin.shell_damping_rate * thin.vertex_mass[0],
              own.shell_damping_rate * own.vertex_mass[0],
              1e-12 * own.shell_damping_rate * own.vertex_mass[0]);
  // The contacts' step bounds see the lightest free vertex of the heavier shell.
  EXPECT_NEAR(thin.wire_shell_params.vertex_mass, factor * own.wire_shell_params.vertex_mass,
              1e-12 * thin.wire_shell_params.vertex_mass);
}

// The cap: never heavier than a physical shell at the wire's density rho_w = 1140 kg/m^3. At
// eps = 1e3 (rho_s = 400 kg/m^3) the thin shell's factor is rho_w / rho_s = 2.85, not 10.
TEST(ShellInertia, ThinShellNeverHeavierThanThePhysicalShell) {
  const Assembly own = assemble(shell_scene(20, 200, 1e3, 0.0));
  const Assembly capped = assemble(shell_scene(20, 200, 1e3, 1.0));
  const double factor = 1140.0 / 400.0;
  for (size_t k = 0; k < own.vertex_mass.size(); ++k)
    EXPECT_NEAR(capped.vertex_mass[k], factor * own.vertex_mass[k], 1e-12 * capped.vertex_mass[k]);
}

// Where the rule does not act the assembly is bitwise that of the shell's own thickness: the
// paper's thick shells (xi = 10: t = 2 r at rho = 20) and a thin shell whose scaled density
// is already above the physical one (eps = 100: rho_s = 4000 kg/m^3).
TEST(ShellInertia, UnchangedWhereTheRuleDoesNotAct) {
  struct Case {
    double rho, xi, eps;
  };
  for (const Case& c :
       {Case{10, 10, 1e3}, Case{20, 10, 1e3}, Case{20, 10, 1e4}, Case{20, 200, 100}}) {
    const Assembly own = assemble(shell_scene(c.rho, c.xi, c.eps, 0.0));
    const Assembly def = assemble(shell_scene(c.rho, c.xi, c.eps, 1.0));
    const std::string at = "rho = " + std::to_string(c.rho) + ", xi = " + std::to_string(c.xi) +
                           ", eps = " + std::to_string(c.eps);
    EXPECT_EQ(own.vertex_mass, def.vertex_mass) << at;
    EXPECT_EQ(own.shell_damping_rate, def.shell_damping_rate) << at;
    EXPECT_EQ(own.wire_shell_params.vertex_mass, def.wire_shell_params.vertex_mass) << at;
  }
}

// The hard case at test size (rho = 10, xi = 200, eps = 1e4, mu_s = 1, elements and mesh 2 r;
// t = r / 20, so the vertices are 20x heavier). Steps as 1.8 / omega: with the shell's own
// thickness the membrane's rest bound (10.0 us) was below the wire's three terms together
// (14.1 us) and set the step (omega^2 2.0x the wire's); with the thin shell's inertia the wire
// sets it (membrane 44.7 us, omega^2 0.10x the wire's; contact 28.6 us, 0.24x). The test's
// limits 1.5x, 0.2x and 0.5x leave a factor of 1.3-2 to each. Steps to l = 2.5 (the first contact):
// 4017 with the shell's own inertia, 1668 with the rule (2026-12-02); the budget 2500 sits 1.5x
// above the new count and 1.6x below the old one, so the test cannot pass on the former masses.
SceneParams coarse_thin_scene(double c) {
  SceneParams p = shell_scene(10, 200, 1e4, c);
  p.mu_s = 1.0;
  p.mu_d = 0.9;
  p.numerics.element_length = 2 * p.wire.radius;
  p.numerics.shell_mesh_size = 2 * p.wire.radius;
  p.l_max = 2.5;
  return p;
}

double omega_sq_of(const Simulation& sim, const std::vector<std::string>& names) {
  const auto all = sim.term_names();
  const auto w2 = sim.term_omega_sq();
  double sum = 0.0;
  for (size_t k = 0; k < w2.size(); ++k) {
    for (const auto& n : names) sum += all[k] == n ? w2[k] : 0.0;
  }
  return sum;
}

TEST(ShellInertia, ThinShellLeavesTheStepToTheWire) {
  for (double c : {0.0, 1.0}) {
    Simulation sim(coarse_thin_scene(c));
    sim.step();
    const double wire = omega_sq_of(sim, {"stretch", "bend", "twist"});
    const double shell = omega_sq_of(sim, {"membrane", "shell_bending"});
    const double contact = omega_sq_of(sim, {"wire_shell"});
    if (c == 0.0) {
      EXPECT_GT(shell, 1.5 * wire) << "the former masses: the membrane sets the step";
    } else {
      EXPECT_LT(shell, 0.2 * wire);
      EXPECT_LT(contact, 0.5 * wire);
    }
  }
  Simulation sim(coarse_thin_scene(1.0));
  while (!sim.finished()) ASSERT_NO_THROW(sim.step()) << "at l = " << sim.l();
  std::printf("  thin shell, rule on: %ld steps to l = 2.5 (4017 with the shell's own inertia)\n",
              sim.steps());
  EXPECT_LT(sim.steps(), 2500);
}

}  // namespace
}  // namespace wirepack
