// Fields of the simulation for output (issue 18): the wire-shell contact force on the shell's
// vertices, the clamped rim, the wire's self-contacts per node. Reading them leaves the
// trajectory bitwise unchanged.
#include <gtest/gtest.h>

#include <numeric>

#include "engine/simulation.hpp"

namespace wirepack {
namespace {

SceneParams elastic_scene(double l_max) {
  SceneParams p;
  p.shell = ShellKind::Elastic;
  p.rho = 10;
  p.xi = 10;
  p.eps = 1000;
  p.l_max = l_max;
  p.numerics.element_length = 2 * p.wire.radius;
  p.numerics.shell_mesh_size = 2 * p.wire.radius;
  return p;
}

// The wire meets the shell (the tip head-on at l ~ 2) and pushes it outwards: the contact
// forces on the shell have a positive outward component in all (sum of F . x / |x| over the
// vertices); probing them every 20 steps changes nothing of the run; the clamped vertices are
// the rim around the hole and never move.
TEST(SimulationFields, ContactForceOnTheShellIsReadOnlyAndPushesOutwards) {
  const SceneParams p = elastic_scene(2.6);
  Simulation probed(p), plain(p);
  int touching = 0;  // probes with a contact
  while (!probed.finished()) {
    probed.step();
    plain.step();
    if (probed.steps() % 20 != 0) continue;
    const Vec3List f = probed.shell_contact_forces();
    ASSERT_EQ(f.size(), probed.shell_vertices().size());
    double outward = 0, magnitude = 0;  // [N]
    for (std::size_t v = 0; v < f.size(); ++v) {
      outward += f[v].dot(probed.shell_vertices()[v].normalized());
      magnitude += f[v].norm();
    }
    if (magnitude == 0) continue;
    ++touching;
    EXPECT_GT(outward, 0.0) << "l = " << probed.l();
  }
  EXPECT_GT(touching, 3) << "the wire never touched the shell";
  ASSERT_EQ(probed.steps(), plain.steps());
  for (std::size_t i = 0; i < plain.all_nodes().size(); ++i)
    ASSERT_EQ(probed.all_nodes()[i], plain.all_nodes()[i]) << i;
  for (std::size_t v = 0; v < plain.shell_vertices().size(); ++v)
    ASSERT_EQ(probed.shell_vertices()[v], plain.shell_vertices()[v]) << v;

  const auto clamped = probed.shell_clamped();
  const auto rest = probed.shell_rest_vertices();
  const auto now = probed.shell_vertices();
  ASSERT_EQ(clamped.size(), rest.size());
  const double R = p.R();
  int n_clamped = 0, moved = 0;
  for (std::size_t v = 0; v < rest.size(); ++v) {
    if (clamped[v]) {
      ++n_clamped;
      EXPECT_EQ(now[v], rest[v]) << v;        // held
      EXPECT_LT(rest[v].z(), -0.7 * R) << v;  // at the south pole, around the hole
    }
    moved += now[v] != rest[v];
  }
  EXPECT_GT(n_clamped, 3);
  EXPECT_EQ(moved, static_cast<int>(rest.size()) - n_clamped);  // all the others are free
}

// Rigid shell: no shell fields; self-contacts per node add up to 2 N once the wire touches
// itself.
TEST(SimulationFields, WireContactsPerNodeSumToTwiceN) {
  SceneParams p;
  p.shell = ShellKind::Rigid;
  p.rho = 10;
  p.l_max = 20;
  Simulation sim(p);
  EXPECT_TRUE(sim.shell_contact_forces().empty());
  EXPECT_TRUE(sim.shell_clamped().empty());
  while (!sim.finished() && sim.wire_contacts() < 3) sim.advance_to(sim.l() + 0.5);
  ASSERT_GE(sim.wire_contacts(), 3);
  const std::vector<int> per_node = sim.wire_contacts_per_node();
  ASSERT_EQ(per_node.size(), sim.inside_nodes().size());
  EXPECT_EQ(std::accumulate(per_node.begin(), per_node.end(), 0), 2 * sim.wire_contacts());
  for (int c : per_node) EXPECT_GE(c, 0);
}

}  // namespace
}  // namespace wirepack
