// Whole-run behaviour of the rigid-sphere engine: hard cases stay stable, runs are
// deterministic, the scene assembles only the effects it needs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "engine/contact/segment_distance.hpp"
#include "engine/simulation.hpp"
#include "sanitizers.hpp"

namespace wirepack {
namespace {

SceneParams rigid_scene(double rho, double l_max) {
  SceneParams p;
  p.shell = ShellKind::Rigid;
  p.rho = rho;
  p.mu_s = 0.0;
  p.l_max = l_max;
  return p;
}

// Largest Hertz overlap |x| + r - R of a node's capsule with the wall, in units of r
// (negative: none); a node centre is outside the sphere when this exceeds 1. Nodes in the
// entrance hole region are skipped (they pass through the wall by design).
double wall_overlap(const Simulation& sim) {
  const double r = sim.params().wire.radius, R = sim.params().R();
  double worst = -1.0;
  for (const Vec3& x : sim.inside_nodes()) {
    if (x[2] < -R + 3 * r) continue;
    worst = std::max(worst, (x.norm() + r - R) / r);
  }
  return worst;
}

// The criterion: no wire node (centre) more than 0.05 r outside the sphere. The Hertz
// overlap itself is bounded tighter than that: at the default quasistatic_ratio q = 0.01 the
// wire pushed head-on into the pole compresses by a few percent before it buckles (the buckling
// mode's inertia is mass-scaled, the feed is not), which gives overlaps up to ~0.21 r (measured);
// 0.3 r bounds that with margin and still means "no tunnelling" by a factor of three.
constexpr double kMaxWallOverlap = 0.3;
void expect_inside(double overlap) {
  EXPECT_LT(overlap - 1.0, 0.05);
  EXPECT_LT(overlap, kMaxWallOverlap);
}

// Largest overlap 2r - d of two capsules more than the neighbour exclusion apart (units of r),
// brute force over all pairs.
double wire_overlap(const Simulation& sim) {
  const auto x = sim.inside_nodes();
  const double r = sim.params().wire.radius;
  const double ell = sim.params().numerics.element_length;
  const int excl = static_cast<int>(std::ceil(1.0 + M_PI * r / ell)) - 1;
  double worst = -2.0;
  const int ne = static_cast<int>(x.size()) - 1;
  for (int a = 0; a < ne; ++a) {
    for (int b = a + excl + 1; b < ne; ++b) {
      const auto c = segment_segment_closest(x[a], x[a + 1], x[b], x[b + 1]);
      worst = std::max(worst, (2 * r - std::sqrt(c.dist2)) / r);
    }
  }
  return worst;
}

bool all_finite(const Simulation& sim) {
  for (const Vec3& x : sim.all_nodes()) {
    if (!x.allFinite()) return false;
  }
  const Energies e = sim.energies();
  return std::isfinite(e.U_b) && std::isfinite(e.U_s) && std::isfinite(e.E_kin);
}

// Wire-wire overlap bound of the hard cases. Quasi-static contact forces in these packings
// give overlaps ~0.02 r; the peaks come from loops snapping through and hitting the packing
// at several times the feed speed, an inertia effect of the mass scaling: sampled every 20
// steps, the largest overlap at rho = 10, l <= 20 was 0.12 r at q = 0.01 (default) and
// 0.085 r at q = 0.003. The 0.1 r holds from q ~ 0.003 towards the physical q ~ 5e-4;
// 0.15 r bounds the default and still means no pass-through (that would need 2 r).
constexpr double kMaxWireOverlap = 0.15;

// Bounds: wall and wire-wire overlaps as above; the bending energy
// stays below that of the whole wire bent on a radius of 2 r, far above anything a packing in a
// sphere of radius >= 10 r stores.
void expect_sane(const Simulation& sim) {
  ASSERT_TRUE(all_finite(sim));
  expect_inside(wall_overlap(sim));
  EXPECT_LT(wire_overlap(sim), kMaxWireOverlap);
  const double r = sim.params().wire.radius;
  const double EI = sim.params().wire.youngs_modulus * M_PI * std::pow(r, 4) / 4;
  EXPECT_LT(sim.energies().U_b, EI * sim.L() / (2 * 4 * r * r));
}

TEST(Simulation, HeadOnTipIntoTheWallStaysStable) {
  // A straight wire reaches the north pole at l ~ 2 and pushes head-on into the wall.
  Simulation sim(rigid_scene(20, 3.0));
  double worst_wall = -1;
  while (!sim.finished()) {
    for (int k = 0; k < 200 && !sim.finished(); ++k) sim.step();
    worst_wall = std::max(worst_wall, wall_overlap(sim));
    ASSERT_TRUE(all_finite(sim));
  }
  std::printf("  head-on: max wall overlap %.4f r\n", worst_wall);
  expect_inside(worst_wall);
  expect_sane(sim);
}

TEST(Simulation, DensePackingAtRho10StaysStable) {
  Simulation sim(rigid_scene(10, 20.0));
  double worst_wall = -1, worst_wire = -2;
  while (!sim.finished()) {
    sim.step();
    if (sim.steps() % 20 != 0) continue;
    worst_wall = std::max(worst_wall, wall_overlap(sim));
    worst_wire = std::max(worst_wire, wire_overlap(sim));
    ASSERT_TRUE(all_finite(sim));
  }
  std::printf("  rho=10, l=20: max wall overlap %.4f r, max wire overlap %.4f r, N=%d\n",
              worst_wall, worst_wire, sim.wire_contacts());
  expect_inside(worst_wall);
  EXPECT_LT(worst_wire, kMaxWireOverlap);
  EXPECT_GT(sim.wire_contacts(), 0);
  expect_sane(sim);
}

// Engine II hard case: strong friction (mu_s = 1.2) in the rigid sphere, packed to l = 20
// (11 s in Release; to l = 10 under the sanitizers).
TEST(Simulation, HighFrictionPackingStaysStable) {
  const double l_max = testing::kUnderSanitizers ? 10.0 : 20.0;
  SceneParams p = rigid_scene(20, l_max);
  p.mu_s = 1.2;
  p.mu_d = 0.9 * p.mu_s;
  Simulation sim(p);
  double worst_wall = -1, worst_wire = -2;
  for (double l = 2; l <= l_max; l += 2) {
    sim.advance_to(l);
    worst_wall = std::max(worst_wall, wall_overlap(sim));
    worst_wire = std::max(worst_wire, wire_overlap(sim));
    ASSERT_TRUE(all_finite(sim));
  }
  std::printf("  mu_s=1.2, l=%g: max wall overlap %.4f r, max wire overlap %.4f r, N=%d\n", l_max,
              worst_wall, worst_wire, sim.wire_contacts());
  expect_inside(worst_wall);
  EXPECT_LT(worst_wire, kMaxWireOverlap);
  expect_sane(sim);
}

TEST(Simulation, VeryShortElementsStayStable) {
  SceneParams p = rigid_scene(20, 2.5);
  p.numerics.element_length = 0.25 * p.wire.radius;
  Simulation sim(p);
  sim.advance_to(p.l_max);
  expect_sane(sim);
}

TEST(Simulation, SameSeedGivesBitwiseIdenticalRuns) {
  SceneParams p = rigid_scene(10, 3.0);
  Simulation a(p), b(p);
  a.advance_to(3.0);
  b.advance_to(3.0);
  ASSERT_EQ(a.steps(), b.steps());
  const auto xa = a.all_nodes(), xb = b.all_nodes();
  ASSERT_EQ(xa.size(), xb.size());
  for (size_t i = 0; i < xa.size(); ++i) EXPECT_EQ(xa[i], xb[i]);
}

// A frictional rigid scene (rho = 10, mu_s = 0.8) to l = 4 with one option changed by `change`:
// the packing stays in the sphere and finite, two runs of it are bitwise identical, and the
// option acts (the run differs from the unchanged one).
void expect_option_stable_deterministic_and_acting(void (*change)(SceneParams&)) {
  SceneParams p = rigid_scene(10, 4.0);
  p.mu_s = 0.8;
  p.mu_d = 0.9 * p.mu_s;
  const SceneParams before = p;
  change(p);
  Simulation a(p), b(p), c(before);
  double worst_wall = -1;
  for (double l = 1; l <= 4; l += 1) {
    a.advance_to(l);
    worst_wall = std::max(worst_wall, wall_overlap(a));
    ASSERT_TRUE(all_finite(a));
  }
  b.advance_to(4.0);
  c.advance_to(4.0);
  expect_inside(worst_wall);
  expect_sane(a);
  ASSERT_EQ(a.steps(), b.steps());
  const auto xa = a.all_nodes(), xb = b.all_nodes();
  ASSERT_EQ(xa.size(), xb.size());
  for (size_t i = 0; i < xa.size(); ++i) EXPECT_EQ(xa[i], xb[i]);
  EXPECT_NE(a.inside_nodes()[0], c.inside_nodes()[0]);
}

// A swivel at the hole (FeederSpin::Free) with friction, hence twist, against the held feeder.
TEST(Simulation, SwivelFeederRunsAreStableDeterministicAndDiffer) {
  expect_option_stable_deterministic_and_acting(
      [](SceneParams& p) { p.feeder_spin = FeederSpin::Free; });
}

// A stick 4x stiffer than Mindlin's (scene key friction_stiffness_ratio; the step bound takes
// k_n (1 + ratio)) against Mindlin's.
TEST(Simulation, StiffStickRunsAreStableDeterministicAndDiffer) {
  expect_option_stable_deterministic_and_acting(
      [](SceneParams& p) { p.friction_stiffness_ratio = 3.2; });
}

TEST(Simulation, DifferentSeedsGiveDifferentRuns) {
  SceneParams p = rigid_scene(10, 3.0);
  SceneParams q = p;
  q.seed = 2;
  Simulation a(p), b(q);
  a.advance_to(3.0);
  b.advance_to(3.0);
  EXPECT_NE(a.inside_nodes()[0], b.inside_nodes()[0]);
}

TEST(Simulation, RigidFrictionlessSceneAssemblesOnlyItsTerms) {
  Simulation sim(rigid_scene(20, 1.0));
  const auto names = sim.term_names();
  EXPECT_EQ(names, (std::vector<std::string>{"stretch", "bend", "wall", "self_contact"}));
  EXPECT_TRUE(sim.shell_vertices().empty());  // no mesh is built
  {
    SceneParams on = rigid_scene(20, 1.0);
    on.numerics.shell_self_contact = EffectMode::On;  // a rigid sphere cannot fold: still none
    EXPECT_EQ(Simulation(on).term_names(), names);
  }
  SceneParams p = rigid_scene(20, 1.0);
  p.numerics.twist = EffectMode::On;
  Simulation twisted(p);
  const auto n2 = twisted.term_names();
  EXPECT_NE(std::find(n2.begin(), n2.end(), "twist"), n2.end());
}

TEST(Simulation, InjectedLengthGrowsAtTheFeedSpeed) {
  SceneParams p = rigid_scene(20, 1.0);
  Simulation sim(p);
  const double L0 = sim.L();
  sim.advance_to(1.0);
  EXPECT_NEAR(sim.L() - L0, p.injection_speed * sim.time(), 1e-12);
  // Released nodes = injected length / element length, within one element.
  const double expected = sim.L() / p.numerics.element_length;
  EXPECT_NEAR(static_cast<double>(sim.inside_nodes().size()), expected, 1.5);
}

}  // namespace
}  // namespace wirepack

namespace wirepack {
namespace {

// The wire at the start moves as a rigid body at the feed speed (free nodes and guide alike), so
// its kinetic energy is 1/2 n m v^2 with m the physical node mass under selective scaling (the
// Laplacian part sees no relative motion) and the scaled one under uniform scaling: the mass
// model is wired into the simulation's accelerations and energies as intended.
TEST(Simulation, InitialRigidFeedCarriesTheModelsMass) {
  for (const MassScaling ms : {MassScaling::Selective, MassScaling::Uniform}) {
    for (const double mu : {0.0, 0.5}) {  // with friction the twist angles exist (omega = 0)
      SceneParams p = rigid_scene(20, 1.0);
      p.mu_s = mu;
      p.mu_d = 0.9 * mu;
      p.numerics.mass_scaling = ms;
      const Simulation sim(p);
      const int n = static_cast<int>(sim.inside_nodes().size());
      const double A = M_PI * p.wire.radius * p.wire.radius, ell = p.numerics.element_length;
      const double v = p.injection_speed, q = p.numerics.quasistatic_ratio;
      const double rho =
          ms == MassScaling::Selective ? p.wire.density : p.wire.youngs_modulus * q * q / (v * v);
      const double expected = 0.5 * n * rho * A * ell * v * v;
      EXPECT_NEAR(sim.energies().E_kin, expected, 1e-12 * expected)
          << (ms == MassScaling::Selective ? "selective" : "uniform") << " mu " << mu;
    }
  }
}

}  // namespace
}  // namespace wirepack
