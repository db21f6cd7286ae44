// SelfContactTerm: capsules of radius r around the edges of one rod. Hertz's law for crossing
// edges (E* = E / (2 (1 - nu^2)), R* = r), action = reaction and the split of the force to the
// nodes by the closest-point parameters, an FD gradient check on dense random states, the
// neighbour exclusion along the wire, the Verlet list against a brute-force all-pairs search,
// and the dashpot.
#include "engine/contact/self_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>
#include <vector>

#include "engine/contact/segment_distance.hpp"
#include "engine/fd_harness.hpp"
#include "engine/rod_builders.hpp"

namespace wirepack {
namespace {

const RodMaterial kMat = testing::default_material();
const double kNu = WireParams{}.poisson_ratio;

SelfContactParams params(double element_length, double zeta = 0.0) {
  SelfContactParams p;
  p.r = kMat.r;
  p.E_star = effective_modulus(kMat.E, kNu, kMat.E, kNu);
  p.element_length = element_length;
  p.skin = 0.5 * kMat.r;  // the scene's SceneConstants::kSkin
  p.damping_ratio = zeta;
  p.node_mass = 1e-6;
  return p;
}

// One rod whose edge a = 4 (along x, at z = 0) and edge b = 35 (along y, at height
// h = 2 r - delta) cross at right angles over the origin, joined by a loop far from the
// crossing. Edge length l = 2 r. The last leg (9 edges, b the fifth) is shifted along y by
// `joint_shift` l; unshifted, the crossing point is at parameter s = 0.4 on edge a and t = 0.3 on
// edge b. With delta <= 0.06 r the neighbours of a and b stay > 2 r from the other edge (the
// nearest is sqrt((0.3 l)^2 + h^2) > l), so (a, b) is the only contact.
constexpr int kEdgeA = 4, kEdgeB = 35;
State crossing_rod(double delta, double joint_shift = 0.0) {
  const double l = 2.0 * kMat.r;
  const double h = (2.0 * kMat.r - delta) / l;
  const double y0 = -4.3 + joint_shift;
  const Vec3List way = {Vec3(-4.4, 0, 0), Vec3(4.6, 0, 0), Vec3(4.6, 0, 6),   Vec3(4.6, -4.3, 6),
                        Vec3(0, -4.3, 6), Vec3(0, y0, h),  Vec3(0, y0 + 9, h)};
  Vec3List pts;
  for (const Vec3& p : way) pts.push_back(l * p);
  return testing::rod_through(testing::polyline(pts, l * (1 + 1e-9)));
}

TEST(SelfContact, EffectiveModulusOfTwoWires) {
  EXPECT_NEAR(effective_modulus(kMat.E, kNu, kMat.E, kNu) / (kMat.E / (2.0 * (1.0 - kNu * kNu))),
              1.0, 1e-15);
}

// Crossing capsules: F = 4/3 E* sqrt(r) delta^{3/2} along the common normal (from b to a: -z),
// split to the nodes as (1 - s, s) F on edge a and -(1 - t, t) F on edge b; the forces sum to
// zero and have zero moment (the force acts along the line joining the closest points).
// Tolerances: s, t, delta from closed-form closest points of exactly perpendicular segments,
// round-off eps l / delta <= 1e-13 relative in delta (1e-12 on s, t; 1e-10 on F and U); sums
// 1e-12 of F.
TEST(SelfContact, CrossingEdgesHertzForceAndSplit) {
  const double r = kMat.r;
  const double E_star = kMat.E / (2.0 * (1.0 - kNu * kNu));
  const double k = 4.0 / 3.0 * E_star * std::sqrt(r);
  for (double d : {0.01, 0.03, 0.06}) {
    const double delta = d * r;
    const State s = crossing_rod(delta);
    ASSERT_EQ(s.num_edges(), kEdgeB + 5);
    SelfContactTerm term(params(2.0 * r));
    double U = 0;
    const Forces f = testing::forces_of(term, s, &U);
    ASSERT_EQ(term.contacts(), 1) << d;
    const WireContact& c = term.contact_list()[0];
    EXPECT_EQ(c.a, kEdgeA);
    EXPECT_EQ(c.b, kEdgeB);
    EXPECT_NEAR(c.s, 0.4, 1e-12);
    EXPECT_NEAR(c.t, 0.3, 1e-12);
    EXPECT_NEAR(c.delta / delta, 1.0, 1e-10);
    const double F = k * std::pow(delta, 1.5);
    EXPECT_NEAR(c.force / F, 1.0, 1e-10) << d;
    EXPECT_NEAR(U / (0.4 * k * std::pow(delta, 2.5)), 1.0, 1e-10) << d;
    EXPECT_NEAR(term.energy(s) / U, 1.0, 1e-14);
    EXPECT_LT((c.normal - Vec3(0, 0, -1)).norm(), 1e-12);
    const Vec3 Fa = -F * Vec3::UnitZ();  // on edge a
    EXPECT_LT((f.f[kEdgeA] - 0.6 * Fa).norm(), 1e-10 * F);
    EXPECT_LT((f.f[kEdgeA + 1] - 0.4 * Fa).norm(), 1e-10 * F);
    EXPECT_LT((f.f[kEdgeB] + 0.7 * Fa).norm(), 1e-10 * F);
    EXPECT_LT((f.f[kEdgeB + 1] + 0.3 * Fa).norm(), 1e-10 * F);
    for (int i = 0; i < s.num_nodes(); ++i) {
      if (i != kEdgeA && i != kEdgeA + 1 && i != kEdgeB && i != kEdgeB + 1) {
        EXPECT_EQ(f.f[i], Vec3::Zero()) << i;
      }
    }
    EXPECT_LT(testing::sum_of(f.f).norm(), 1e-12 * F);
    EXPECT_LT(testing::moment_of(s, f).norm(), 1e-12 * F * 10.0 * s.rest_length[0]);
  }
}

// Dense random state: a random walk of edge length ~l = r confined to a ball of radius 3 l, so
// the wire crosses itself many times at generic angles (closest points unique).
State dense_rod(int n, unsigned seed) {
  const double l = kMat.r;
  const double Rb = 3.0 * l;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec3List x{Vec3::Zero()};
  Vec3 dir = Vec3::UnitX();
  while (static_cast<int>(x.size()) < n) {
    dir = (dir + 0.9 * Vec3(g(rng), g(rng), g(rng))).normalized();
    const Vec3 next = x.back() + l * (1.0 + 0.1 * u(rng)) * dir;
    if (next.norm() > Rb) {
      dir = (dir - 2.0 * dir.dot(x.back().normalized()) * x.back().normalized()).normalized();
      continue;  // reflect off the confining ball and retry
    }
    x.push_back(next);
  }
  return testing::rod_through(x);
}

// Brute-force set of touching pairs: every pair of active edges (at least one dynamic node)
// more than the exclusion apart whose axes are closer than 2 r.
std::vector<std::pair<int, int>> brute_force_contacts(const State& s, int exclusion) {
  std::vector<std::pair<int, int>> out;
  const int ne = std::min(s.n_free, s.num_edges());
  for (int a = 0; a < ne; ++a) {
    for (int b = a + exclusion + 1; b < ne; ++b) {
      const auto c = segment_segment_closest(s.x[a], s.x[a + 1], s.x[b], s.x[b + 1]);
      if (c.dist2 < 4.0 * kMat.r * kMat.r) out.emplace_back(a, b);
    }
  }
  return out;
}

std::vector<std::pair<int, int>> term_contacts(const SelfContactTerm& term) {
  std::vector<std::pair<int, int>> out;
  for (const auto& c : term.contact_list()) out.emplace_back(c.a, c.b);
  std::sort(out.begin(), out.end());
  return out;
}

// The term's contact list at s (after its accumulate) equals the brute-force set of touching
// edge pairs, contacts() = N is its size, and a fresh term (full rebuild) finds the same set.
void expect_matches_brute_force(const SelfContactTerm& term, const State& s) {
  const auto got = term_contacts(term);
  const auto all = brute_force_contacts(s, term.exclusion());
  EXPECT_EQ(got, all);
  EXPECT_EQ(term.contacts(), static_cast<int>(got.size()));
  SelfContactTerm fresh(params(kMat.r));
  testing::forces_of(fresh, s);
  EXPECT_EQ(term_contacts(fresh), got);
}

// FD check on dense random states with several contacts (velocities zero: no dashpot).
// Criterion as for the rod terms: best of the ladder below 1e-6 relative and O(h^2) trend.
TEST(SelfContact, GradientMatchesFiniteDifferences) {
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const State s = dense_rod(40, seed);
    SelfContactTerm term(params(kMat.r, 0.5));
    testing::forces_of(term, s);
    std::printf("  dense rod seed %u: %d contacts\n", seed, term.contacts());
    ASSERT_GE(term.contacts(), 5);
    const auto rep = testing::fd_check(term, s, kMat.r, testing::default_fd_steps());
    testing::print_report(rep);
    EXPECT_LT(rep.best(), 1e-6);
    EXPECT_LT(rep.err[1], 0.1 * rep.err[0] + 1e-9);
  }
}

// The exclusion: pairs whose arc-length gap (|a - b| - 1) l is shorter than pi r (a hairpin of
// radius r) never interact, i.e. exclusion() = ceil(pi r / l).
TEST(SelfContact, ExclusionCoversAHairpinOfRadiusR) {
  for (double l_over_r : {0.25, 0.5, 1.0, 1.5, 2.0, 4.0}) {
    SelfContactTerm term(params(l_over_r * kMat.r));
    const int e = term.exclusion();
    EXPECT_GE(e * l_over_r, M_PI) << l_over_r;
    if (e > 1) {
      EXPECT_LT((e - 1) * l_over_r, M_PI) << l_over_r;
    }
  }
}

// A tight hairpin (legs 0.8 r apart, overlapping by 1.2 r) whose edges are all within the
// exclusion of each other has no contact at all; one more edge on a leg brings exactly the one
// pair beyond the exclusion into contact.
TEST(SelfContact, NeighboursWithinExclusionNeverInteract) {
  const double l = kMat.r;
  SelfContactTerm term(params(l));
  ASSERT_EQ(term.exclusion(), 4);
  Vec3List x;
  for (Vec3 p : {Vec3(-2, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 0), Vec3(0, 0.8, 0), Vec3(-1, 0.8, 0),
                 Vec3(-2, 0.8, 0)}) {
    x.push_back(l * p);
  }
  State s = testing::rod_through(x);  // edges 0 .. 4
  // Geometric overlap of the legs, e.g. edges 0 and 4 (0.8 r apart).
  EXPECT_LT(segment_segment_closest(s.x[0], s.x[1], s.x[4], s.x[5]).dist2, 4 * l * l);
  double U = 1;
  Forces f = testing::forces_of(term, s, &U);
  EXPECT_EQ(term.contacts(), 0);
  EXPECT_EQ(U, 0.0);
  EXPECT_EQ(term.energy(s), 0.0);
  for (const Vec3& v : f.f) EXPECT_EQ(v, Vec3::Zero());

  x.push_back(l * Vec3(-3, 0.8, 0));  // edge 5: (0, 5) is beyond the exclusion, (1, 5) is not
  SelfContactTerm term2(params(l));
  s = testing::rod_through(x);
  f = testing::forces_of(term2, s, &U);
  ASSERT_EQ(term2.contacts(), 1);
  EXPECT_EQ(term2.contact_list()[0].a, 0);
  EXPECT_EQ(term2.contact_list()[0].b, 5);
  expect_matches_brute_force(term2, s);
}

// Verlet list: displacements below skin / 2 per node (measured from the positions at the last
// build) keep the list and still find every contact (two nodes closing by < skin cannot bring a
// pair from beyond 2 r + skin into contact); a node moved farther triggers a rebuild. After every
// accumulate the contact set matches the brute-force all-pairs search (see above).
TEST(SelfContact, VerletListRebuildsOnlyWhenNeeded) {
  const double skin = params(kMat.r).skin;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const State s0 = dense_rod(60, seed + 10);
    SelfContactTerm term(params(kMat.r));
    testing::forces_of(term, s0);
    EXPECT_EQ(term.rebuilds(), 1);
    expect_matches_brute_force(term, s0);
    const auto set0 = brute_force_contacts(s0, term.exclusion());

    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g(0.0, 1.0);
    int changed = 0;
    // Moves of every size below skin / 2: the list also skips pairs whose slack at the build
    // exceeds what their nodes moved since, so small moves exercise that skip; forces must be
    // bitwise those of a fresh term (which evaluates every pair).
    for (double move : {0.05, 0.15, 0.3, 0.4, 0.49}) {
      State s = s0;
      for (auto& p : s.x) p += move * skin * Vec3(g(rng), g(rng), g(rng)).normalized();
      double U = 0;
      const Forces f = testing::forces_of(term, s, &U);
      EXPECT_EQ(term.rebuilds(), 1) << "no rebuild below skin / 2";
      expect_matches_brute_force(term, s);
      EXPECT_EQ(term.energy(s), U);
      SelfContactTerm fresh(params(kMat.r));
      double U_fresh = 0;
      const Forces f_fresh = testing::forces_of(fresh, s, &U_fresh);
      EXPECT_EQ(U, U_fresh);
      for (size_t i = 0; i < f.f.size(); ++i) EXPECT_EQ(f.f[i], f_fresh.f[i]) << i;
      changed += brute_force_contacts(s, term.exclusion()) != set0;
    }
    EXPECT_GT(changed, 0) << "the perturbations should change the contact set";

    State s = s0;
    s.x[17] += 0.51 * skin * Vec3(1, 1, 0).normalized();
    testing::forces_of(term, s);
    EXPECT_EQ(term.rebuilds(), 2) << "a node moved beyond skin / 2 rebuilds";
    expect_matches_brute_force(term, s);

    // Fewer dynamic nodes: edges made only of guide nodes drop out (a rebuild, as the active
    // edge count changed).
    s.n_free = s.num_nodes() - 20;
    testing::forces_of(term, s);
    EXPECT_EQ(term.rebuilds(), 3);
    expect_matches_brute_force(term, s);
  }
}

// Two straight wires crossing. Away from the joints of the crossed wire it is one contact with
// the Hertz energy U(delta) (1e-9 relative: closed-form distance of perpendicular segments).
// Within sqrt((2 r)^2 - (2 r - delta)^2) of a joint the end cap of the next edge also touches
// (the per-element-pair model, see self_contact.hpp): the energy then lies between U(delta)
// and 2 U(delta), reaches 2 U(delta) with the joint exactly under the crossing, and changes
// continuously as the joint slides past (no jump: the steps below change it by O(1e-9)).
TEST(SelfContact, CrossingEnergyNearAndAwayFromJoints) {
  const double r = kMat.r, delta = 0.03 * r;
  const double U_hertz =
      0.4 * 4.0 / 3.0 * (kMat.E / (2.0 * (1.0 - kNu * kNu))) * std::sqrt(r) * std::pow(delta, 2.5);
  const double l = 2.0 * r;
  const double window = std::sqrt(4 * r * r - (2 * r - delta) * (2 * r - delta));
  // Shifts (in l) put the joint between edges b and b+1 at y = (0.7 + shift) l from the
  // crossing.
  for (double shift : {-0.9, -0.75, -0.7 - 1e-9, -0.7, -0.7 + 1e-9, -0.65, -0.5, -0.3, 0.0}) {
    const State s = crossing_rod(delta, shift);
    SelfContactTerm term(params(l));
    double U = 0;
    testing::forces_of(term, s, &U);
    const double joint = std::abs(0.7 + shift) * l;
    if (joint > window) {
      EXPECT_NEAR(U / U_hertz, 1.0, 1e-9) << "joint at " << joint / l << " l";
      EXPECT_EQ(term.contacts(), 1);
    } else {
      EXPECT_GE(U / U_hertz, 1.0 - 1e-9);
      EXPECT_LE(U / U_hertz, 2.0 + 1e-9);
      EXPECT_EQ(term.contacts(), 2);
    }
    if (joint == 0.0) {
      EXPECT_NEAR(U / U_hertz, 2.0, 1e-9);
    }
  }
  double U_minus = 0, U_plus = 0;
  SelfContactTerm term(params(l));
  testing::forces_of(term, crossing_rod(delta, -0.7 - 1e-9), &U_minus);
  testing::forces_of(term, crossing_rod(delta, -0.7 + 1e-9), &U_plus);
  EXPECT_NEAR(U_plus / U_minus, 1.0, 1e-6);
}

// A wire passing through the inside of a concave joint (a "V" of two edges of the other
// wire, slope k = 0.3, in the plane z = 0; the passing wire runs along z through
// (x_p, 0.75 l)): the distance to the left edge's line has its foot inside that edge for
// x_p < k y_p and clamped at the joint beyond, while the right edge keeps its own interior
// minimum. Moving x_p across k y_p by +-1e-9 l changes the geometry by 1e-9 l, so the energy
// must change by O(1e-9) relative at most (bound 1e-6): a jump is an impulsive force.
TEST(SelfContact, EnergyContinuousAtAConcaveJoint) {
  const double r = kMat.r, l = 2.0 * r, k = 0.3, yp = 0.75;
  double U_side[2];
  for (int side = 0; side < 2; ++side) {
    const double xp = k * yp + (side ? 1e-9 : -1e-9);
    const Vec3List way = {Vec3(-4, 4 * k, 0),  Vec3(0, 0, 0),     Vec3(4, 4 * k, 0),
                          Vec3(4, 4 * k, 6.5), Vec3(xp, yp, 6.5), Vec3(xp, yp, -3.5)};
    Vec3List pts;
    for (const Vec3& p : way) pts.push_back(l * p);
    const State s = testing::rod_through(testing::polyline(pts, 1.05 * l));
    SelfContactTerm term(params(l));
    testing::forces_of(term, s, &U_side[side]);
    std::printf("  concave joint, x_p = k y_p %+.0e l: U = %.9e J, %d contacts\n",
                side ? 1e-9 : -1e-9, U_side[side], term.contacts());
    ASSERT_GT(term.contacts(), 0);
  }
  EXPECT_NEAR(U_side[1] / U_side[0], 1.0, 1e-6);
}

// Dashpot on the approach speed of the closest points: closing adds 2 zeta sqrt(k_c m / 2) u,
// opening subtracts it, and the force is never attractive. 1e-10 relative (delta as above).
TEST(SelfContact, DashpotOnApproachNeverAttractive) {
  const double r = kMat.r, zeta = 0.5;
  const SelfContactParams p = params(2.0 * r, zeta);
  State s = crossing_rod(0.03 * r);
  SelfContactTerm term(p);
  testing::forces_of(term, s);
  ASSERT_EQ(term.contacts(), 1);
  const double F = term.contact_list()[0].force;
  const double eta = 2.0 * zeta * std::sqrt(1.5 * F / (0.03 * r) * 0.5 * p.node_mass);
  for (double u : {1e-3, -1e-3, -10.0}) {
    // Edge a moves towards b (+z) at speed u; edge b is at rest.
    s.v[kEdgeA] = s.v[kEdgeA + 1] = u * Vec3::UnitZ();
    testing::forces_of(term, s);
    ASSERT_EQ(term.contacts(), 1);
    const double fn = term.contact_list()[0].force;
    EXPECT_GE(fn, 0.0);
    EXPECT_NEAR(fn, std::max(0.0, F + eta * u), 1e-10 * F) << u;
  }
}

}  // namespace
}  // namespace wirepack
