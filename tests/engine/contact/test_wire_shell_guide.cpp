// The guide as a contact body (wire_shell.hpp): the kinematic wire outside the hole is a rigid
// capsule of radius r on the feed axis, from the first guide node down to guide_bottom_z, and
// the shell cannot wrap it. Analytic values (one Hertz contact at the capsule's end anywhere
// over a flat mesh, a face beside it), finite differences of the shell forces and of the
// reaction on the guide's top node, the Verlet list and a checkpoint bitwise, a fast triangle
// thrown at the guide held off (and passing through without the guide), and the scenes' rims
// clear of it at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/contact/wire_shell.hpp"
#include "engine/contact/wire_shell_fixtures.hpp"
#include "engine/elastic_runs.hpp"
#include "engine/fd_harness.hpp"
#include "engine/feeder.hpp"
#include "engine/scene.hpp"
#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/shell_fixtures.hpp"

namespace wirepack {
namespace {

constexpr double kR = 0.5e-3;   // wire radius [m]
constexpr double kH = 0.25e-3;  // shell half-thickness [m]
constexpr double kDc = kR + kH;

WireShellParams params(double bottom_z) {
  WireShellParams p = testing::wire_shell_params();  // r = kR, t/2 = kH
  p.guide = true;
  p.guide_bottom_z = bottom_z;
  return p;
}

double hertz_energy(double delta) {
  return Hertz::from(params(0).E_star, kR).energy(delta);
}

// A wire of one free node above the guide's top (0, 0, top) and one more guide node below it
// (n_free = 1), over the shell `mesh` at rest. The free edge ends at the top.
State wire_into_guide(const ShellMesh& mesh, double top) {
  State s = testing::wire_over(mesh, Vec3(0.2 * kR, 0, top + 2 * kR), Vec3(0, 0, top), 2);
  s.x.push_back(Vec3(0, 0, top - kR));
  s.v.assign(3, Vec3::Zero());
  s.rest_length.push_back(kR);
  s.n_free = 1;
  return s;
}

// The capsule's lower end above a flat mesh (z = 0) at overlap delta: one Hertz contact
// wherever the axis meets the mesh, in a face, on an edge or at a vertex (1e-9 relative).
TEST(WireShellGuide, OneContactAtTheEndAnywhereOnAFlatMesh) {
  const double delta = 0.03 * kR, bottom = kDc - delta;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-4 * kR, 4 * kR);
  for (int trial = 0; trial < 40; ++trial) {
    ShellMesh mesh = flat_square(20 * kR, 10);        // 2 r squares, a vertex at the origin
    const Vec3 shift = trial == 0   ? Vec3::Zero()    // over a vertex
                       : trial == 1 ? Vec3(kR, 0, 0)  // over an edge's midpoint
                                    : Vec3(u(rng), u(rng), 0.0);  // anywhere
    for (auto& p : mesh.rest) p += shift;
    const State s = wire_into_guide(mesh, bottom + 6 * kR);
    WireShellTerm term(mesh, params(bottom));
    EXPECT_NEAR(term.energy(s) / hertz_energy(delta), 1.0, 1e-9) << "trial " << trial;
    EXPECT_GT(term.guide_contacts(), 0);
    EXPECT_EQ(term.contacts(), 0) << "the free wire is far from the mesh";
  }
}

// One triangle parallel to the axis at distance d: Hertz at overlap r + t/2 - d; the same
// triangle clamped takes no part.
TEST(WireShellGuide, FaceBesideTheAxisAndClampedFacesTakeNoPart) {
  const double bottom = 0.0, top = 8 * kR, d = kDc - 0.05 * kR;
  ShellMesh mesh;
  mesh.rest = {Vec3(d, -6 * kR, bottom), Vec3(d, 6 * kR, bottom), Vec3(d, 0, top - 2 * kR)};
  mesh.faces = {{0, 1, 2}};
  mesh.clamped = {0, 0, 1};
  mesh.build_topology();
  const State s = wire_into_guide(mesh, top);
  WireShellTerm term(mesh, params(bottom));
  EXPECT_NEAR(term.energy(s) / hertz_energy(kDc - d), 1.0, 1e-12);
  EXPECT_EQ(term.guide_contacts(), 1);
  EXPECT_EQ(term.contacts(), 0);
  mesh.clamped = {1, 1, 1};
  WireShellTerm clamped(mesh, params(bottom));
  EXPECT_EQ(clamped.energy(s), 0.0);
  EXPECT_EQ(clamped.guide_contacts(), 0);
  WireShellParams off = params(bottom);
  off.guide = false;
  mesh.clamped = {0, 0, 0};
  WireShellTerm no_guide(mesh, off);
  EXPECT_EQ(no_guide.energy(s), 0.0);
}

// A bumpy patch curved around the axis (closest near the capsule's middle), pressed into it:
// shell forces and the reaction on the guide's top node are central differences of the energy
// (error O(h^2) until round-off; the other guide node feels nothing).
ShellMesh curved_patch(double d, std::mt19937_64& rng) {
  ShellMesh mesh = flat_square(12 * kR, 6);
  std::normal_distribution<double> g(0.0, 1.0);
  for (auto& p : mesh.rest) {
    const double y = p[1], z = p[0] + 5 * kR;  // the square's x becomes the height
    p = Vec3(d + 0.03 * (z - 4.5 * kR) * (z - 4.5 * kR) / kR + 0.05 * kR * g(rng), y, z);
  }
  return mesh;
}

TEST(WireShellGuide, ForcesAndReactionMatchFiniteDifferences) {
  std::mt19937_64 rng(9);
  const ShellMesh mesh = curved_patch(kDc - 0.08 * kR, rng);
  const State s = wire_into_guide(mesh, 9 * kR);
  WireShellTerm term(mesh, params(0.0));
  Forces f;
  f.reset(s);
  term.accumulate(s, f);
  ASSERT_GT(term.guide_contacts(), 2);
  EXPECT_GT(f.f[1].norm(), 0.0) << "the top takes its share of the reaction";
  EXPECT_EQ(f.f[2], Vec3::Zero());
  const testing::FdReport r = testing::fd_check(term, s, kR, {1e-3, 1e-4, 1e-5, 1e-6});
  testing::print_report(r);
  EXPECT_LT(r.best(), 1e-6);
  EXPECT_LT(r.err[1], 0.1 * r.err[0] + 1e-9);
}

// Moves below skin / 2 of the shell and of the guide's top keep the guide's list and give the
// fresh term's energy and forces bitwise; a term restored from a checkpoint does too.
TEST(WireShellGuide, VerletListAndCheckpointGiveTheFreshTermsForces) {
  std::mt19937_64 rng(13);
  std::normal_distribution<double> g(0.0, 1.0);
  const ShellMesh mesh = curved_patch(kDc - 0.02 * kR, rng);
  const State s0 = wire_into_guide(mesh, 9 * kR);
  const double skin = params(0.0).skin;
  WireShellTerm term(mesh, params(0.0));
  Forces f;
  f.reset(s0);
  term.accumulate(s0, f);
  StateWriter out;
  term.save(out);
  WireShellTerm restored(mesh, params(0.0));
  StateReader in(out.bytes());
  restored.load(in);
  const int contacts0 = term.guide_contacts();
  int changed = 0;
  for (double move : {0.02, 0.1, 0.3, 0.49}) {
    State s = s0;
    s.x[1] += move * skin * Vec3(g(rng), g(rng), g(rng)).normalized();
    for (auto& p : s.shell_x) p += move * skin * Vec3(g(rng), g(rng), g(rng)).normalized();
    WireShellTerm fresh(mesh, params(0.0));
    Forces f1, f2, f3;
    for (Forces* ff : {&f1, &f2, &f3}) ff->reset(s);
    const double U1 = term.accumulate(s, f1);
    const double U2 = restored.accumulate(s, f2);
    const double U3 = fresh.accumulate(s, f3);
    EXPECT_EQ(U1, U3) << move;
    EXPECT_EQ(U2, U3) << move;
    for (size_t i = 0; i < f1.f.size(); ++i) {
      EXPECT_EQ(f1.f[i], f3.f[i]) << move;
      EXPECT_EQ(f2.f[i], f3.f[i]) << move;
    }
    for (size_t k = 0; k < f1.shell_f.size(); ++k) {
      EXPECT_EQ(f1.shell_f[k], f3.shell_f[k]) << move << " vertex " << k;
      EXPECT_EQ(f2.shell_f[k], f3.shell_f[k]) << move << " vertex " << k;
    }
    changed += term.guide_contacts() != contacts0;
  }
  EXPECT_EQ(term.rebuilds(), 1) << "moves below skin / 2 keep the list";
  EXPECT_GT(changed, 0) << "the moves should change the contacts";
}

// A triangle moving as a rigid body (three unclamped vertices, translation only) thrown
// sideways at the guide with five times the kinetic energy Hertz alone could absorb before the
// axis reaches its mid-surface: held off by the barrier, it turns back with its speed (no
// damping; 1 % for the explicit integration), the axis never reaching it. Without the guide
// the same triangle passes through the axis.
TEST(WireShellGuide, AFastTriangleIsHeldOffTheGuide) {
  const double bottom = 0.0, top = 8 * kR;
  ShellMesh mesh;
  const double x0 = kDc + 0.5 * kR;
  mesh.rest = {Vec3(x0, -3 * kR, 2 * kR), Vec3(x0, 3 * kR, 2.5 * kR), Vec3(x0, 0.5 * kR, 6 * kR)};
  mesh.faces = {{0, 1, 2}};
  mesh.clamped = {0, 0, 0};
  mesh.build_topology();
  const WireShellParams p = params(bottom);
  const double M = 3.0 * p.vertex_mass;  // the triangle's mass [kg]
  const Hertz hertz = Hertz::from(p.E_star, kR);
  const double V = std::sqrt(2.0 * 5.0 * hertz.energy(kDc) / M);  // [m/s]
  auto throw_triangle = [&](bool guide, double& min_dist, Vec3& final_v) {
    WireShellParams q = p;
    q.guide = guide;
    WireShellTerm term(mesh, q);
    State s = wire_into_guide(mesh, top);
    Vec3 v(-V, 0, 0);
    min_dist = HUGE_VAL;
    Forces f;
    for (int step = 0; step < 200000; ++step) {
      s.shell_v.assign(3, v);
      f.reset(s);
      term.accumulate(s, f);
      ASSERT_TRUE(term.failure().empty()) << term.failure();
      // Symplectic Euler at a fifth of the stability limit (and at most the time to cross
      // 1e-3 r at V), the guide held.
      const double w2 = term.omega_max_sq(RodInertia{p.node_mass, 0.0});
      const double dt = std::min(w2 > 0 ? 0.4 / std::sqrt(w2) : HUGE_VAL, 1e-3 * kR / V);
      v += dt / M * (f.shell_f[0] + f.shell_f[1] + f.shell_f[2]);
      for (auto& x : s.shell_x) x += dt * v;
      ASSERT_TRUE(v.allFinite());
      const TriangleClosest tc = segment_triangle_closest(s.x[1], Vec3(0, 0, bottom), s.shell_x[0],
                                                          s.shell_x[1], s.shell_x[2]);
      min_dist = std::min(min_dist, std::sqrt(tc.dist2));
      if ((s.shell_x[0][0] > x0 && v[0] > 0) || s.shell_x[0][0] < -x0) break;
    }
    final_v = v;
  };
  double min_dist = 0;
  Vec3 v;
  throw_triangle(true, min_dist, v);
  EXPECT_GT(min_dist, 0.05 * kDc) << "the axis stays off the mid-surface";
  EXPECT_LT(min_dist, 0.5 * kDc) << "beyond Hertz alone: the barrier held it";
  EXPECT_NEAR(v[0] / V, 1.0, 0.01) << "elastic rebound";
  EXPECT_LT(std::hypot(v[1], v[2]), 1e-9 * V) << "pushed along the normal";
  throw_triangle(false, min_dist, v);
  EXPECT_LT(min_dist, 1e-2 * kR) << "without the guide it passes through the axis";
  EXPECT_EQ(v, Vec3(-V, 0, 0));
}

// The scenes: the guide is on, ten radii long below the rim's plane, and at rest no face of
// the shell (the clamped rim included) touches it, thin, thick, soft and stiff.
TEST(WireShellGuide, ScenesHaveTheGuideClearOfTheRimAtRest) {
  for (double rho : {10.0, 20.0, 40.0}) {
    for (double xi : {10.0, 200.0}) {
      const SceneParams sp = testing::elastic_scene(rho, xi, 1e4, 0.5, 1.0);
      Assembly a = assemble(sp);
      ASSERT_NE(a.wire_shell, nullptr);
      const WireShellParams& ws = a.wire_shell_params;
      EXPECT_TRUE(ws.guide);
      const Feeder feeder(a.feeder);
      EXPECT_NEAR(ws.guide_bottom_z, feeder.z_hole() - 10.0 * sp.R(), 1e-12 * sp.R());
      State s = feeder.initial_state();
      s.shell_x = a.mesh->rest;
      s.shell_v.assign(s.shell_x.size(), Vec3::Zero());
      ASSERT_LT(s.n_free, s.num_nodes());
      a.wire_shell->energy(s);
      EXPECT_EQ(a.wire_shell->guide_contacts(), 0) << "rho " << rho << " xi " << xi;
      EXPECT_EQ(a.wire_shell->failure(), "");
    }
  }
}

}  // namespace
}  // namespace wirepack
