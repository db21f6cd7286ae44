// The read-only probe of the wire-shell contact (engine/contact/wire_shell_probe.hpp): on a
// flat patch at a known overlap its vertex forces add up to Hertz's force per wire edge, and
// they balance the force on the wire (action = reaction).
#include "engine/contact/wire_shell_probe.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/shell_fixtures.hpp"

namespace wirepack {
namespace {

constexpr double kR = 0.5e-3;                            // wire radius [m]
constexpr double kH = 0.25e-3;                           // shell half-thickness [m]
constexpr double kEw = 1e9, kEs = 1e6, kNu = 1.0 / 3.0;  // moduli [Pa], Poisson ratio

WireShellParams params() {
  WireShellParams p;
  p.r = kR;
  p.half_thickness = kH;
  p.E_star = 1.0 / ((1 - kNu * kNu) / kEw + (1 - kNu * kNu) / kEs);
  p.skin = 0.5 * kR;
  p.damping_ratio = 0.5;  // no effect at rest
  p.node_mass = 1e-4;
  p.vertex_mass = 1e-4;
  p.friction.mu_s = 0.5;  // left out by the probe
  p.friction.mu_d = 0.4;
  p.friction.stiffness_ratio = 0.8;
  return p;
}

using testing::wire_over;

Vec3 sum(const Vec3List& f) {
  Vec3 t = Vec3::Zero();
  for (const Vec3& v : f) t += v;
  return t;
}

// A wire of 4 edges lying on a flat patch (z = 0, normal +z) at overlap delta, across the
// mesh's lines: 4 Hertz contacts, F = 4/3 E* sqrt(r) delta^{3/2} each, pressing the patch
// down; the wire takes the opposite total.
TEST(WireShellProbe, FlatPatchGivesHertzForcePerEdge) {
  const ShellMesh mesh = flat_square(20 * kR, 10);  // 2 r squares, split in two triangles
  for (double delta : {0.01 * kR, 0.05 * kR, 0.2 * kR}) {
    const double z = kR + kH - delta;
    const State s = wire_over(mesh, Vec3(-3.1 * kR, 0.7 * kR, z), Vec3(2.9 * kR, 1.3 * kR, z), 5);
    const Vec3List shell_f = wire_shell_vertex_forces(mesh, params(), s);
    ASSERT_EQ(shell_f.size(), mesh.rest.size());
    const double hertz = 4.0 / 3.0 * params().E_star * std::sqrt(kR) * std::pow(delta, 1.5);
    const Vec3 total = sum(shell_f);
    EXPECT_NEAR(total.z() / (-4 * hertz), 1.0, 1e-9) << delta;
    EXPECT_NEAR(total.head<2>().norm(), 0.0, 1e-9 * hertz) << delta;
    // Only vertices of faces under the wire are loaded. (Not each one downwards: the
    // inclusion-exclusion corrections of the shell's edges and vertices can leave a vertex
    // a small upward share; the sum is exact.)
    int loaded = 0;
    for (std::size_t v = 0; v < shell_f.size(); ++v) {
      if (shell_f[v] == Vec3::Zero()) continue;
      ++loaded;
      EXPECT_LT(std::abs(mesh.rest[v].y() - (1.0 + 0.1 * mesh.rest[v].x() / kR) * kR), 5 * kR) << v;
    }
    EXPECT_GT(loaded, 4);
    EXPECT_LT(loaded, 60);

    // The term itself (without friction) puts the same forces on the shell and the opposite
    // total on the wire.
    WireShellParams p = params();
    p.friction = FrictionParams{};
    WireShellTerm term(mesh, p);
    Forces f;
    f.reset(s);
    term.accumulate(s, f);
    for (std::size_t v = 0; v < shell_f.size(); ++v) EXPECT_EQ(f.shell_f[v], shell_f[v]) << v;
    EXPECT_NEAR((sum(f.f) + total).norm(), 0.0, 1e-12 * hertz) << delta;
  }
}

// Far from the patch: no force anywhere.
TEST(WireShellProbe, NoContactNoForce) {
  const ShellMesh mesh = flat_square(20 * kR, 10);
  const double z = 1.01 * (kR + kH);
  const State s = wire_over(mesh, Vec3(-3 * kR, 0, z), Vec3(3 * kR, 0, z), 4);
  for (const Vec3& f : wire_shell_vertex_forces(mesh, params(), s)) EXPECT_EQ(f, Vec3::Zero());
}

}  // namespace
}  // namespace wirepack
