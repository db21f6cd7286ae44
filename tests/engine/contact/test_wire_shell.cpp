// Wire-shell contact: one contact per wire edge wherever it lies on the mesh (inclusion-
// exclusion over faces, edges and vertices), finite-difference gradient, action = reaction.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Dense>

#include "engine/contact/wire_shell.hpp"
#include "engine/contact/wire_shell_fixtures.hpp"
#include "engine/fd_harness.hpp"
#include "engine/shell/mesh_builders.hpp"
#include "engine/shell/shell_fixtures.hpp"

namespace wirepack {
namespace {

constexpr double kR = 0.5e-3;   // wire radius [m]
constexpr double kH = 0.25e-3;  // shell half-thickness [m]

WireShellParams params() {
  return testing::wire_shell_params();  // r = kR, t/2 = kH
}

double hertz_energy(double delta) {
  const Hertz h = Hertz::from(params().E_star, kR);
  return h.energy(delta);
}

using testing::wire_over;

// A flat square of side 12 r (6 x 6 squares) with vertex heights jittered by 0.1 r.
ShellMesh bumpy_square(std::mt19937_64& rng) {
  ShellMesh mesh = flat_square(12 * kR, 6);
  std::normal_distribution<double> g(0.0, 1.0);
  for (auto& p : mesh.rest) p[2] += 0.1 * kR * g(rng);
  return mesh;
}

// n wire nodes one r apart along x, centred on x = 0, y jittered by 0.4 r, at heights
// z0 + dz g (g standard normal), over the mesh at rest.
State wire_across(const ShellMesh& mesh, int n, double z0, double dz, std::mt19937_64& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3List pts;
  for (int i = 0; i < n; ++i) {
    const double y = 0.4 * kR * g(rng);
    const double z = z0 + dz * g(rng);
    pts.push_back(Vec3((i - 0.5 * (n - 1)) * kR, y, z));
  }
  State s = wire_over(mesh, pts.front(), pts.back(), n);
  s.x = pts;
  return s;
}

// A straight wire edge lying parallel to a flat shell at overlap delta is one Hertz contact,
// wherever it lies: over a face, along or across mesh edges, over vertices (1e-9 relative).
TEST(WireShell, OneContactPerEdgeAnywhereOnAFlatMesh) {
  const ShellMesh mesh = flat_square(20 * kR, 10);  // 2 r squares, split in two triangles
  const double delta = 0.02 * kR, z = kR + kH - delta;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-4 * kR, 4 * kR), ang(0, M_PI);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 c(u(rng), u(rng), z);
    const double t = trial < 3 ? trial * M_PI / 4 : ang(rng);  // incl. along the mesh lines
    const Vec3 d = kR * Vec3(std::cos(t), std::sin(t), 0);
    const Vec3 c0 = trial == 1 ? Vec3(0, 0, z) : c;  // exactly over a vertex
    State s = wire_over(mesh, c0 - d, c0 + d, 2);
    WireShellTerm term(mesh, params());
    const double U = term.energy(s);
    EXPECT_NEAR(U / hertz_energy(delta), 1.0, 1e-9) << "trial " << trial;
  }
  // Two edges: two contacts (the wire side is per edge).
  State s = wire_over(mesh, Vec3(-1.3 * kR, 0.2 * kR, z), Vec3(1.1 * kR, 0.3 * kR, z), 3);
  WireShellTerm term(mesh, params());
  EXPECT_NEAR(term.energy(s) / hertz_energy(delta), 2.0, 1e-9);
}

// The rim of a hole: a wire edge touching a boundary edge from the side is a contact too
// (boundary pieces are not subtracted).
TEST(WireShell, BoundaryEdgeOfTheMeshIsAContact) {
  const ShellMesh mesh = flat_square(20 * kR, 10);
  const double L = 10 * kR, delta = 0.02 * kR;
  // Vertical wire beside the boundary x = L, at distance r + h - delta from it.
  const double x = L + kR + kH - delta;
  State s = wire_over(mesh, Vec3(x, 0.3 * kR, -kR), Vec3(x, 0.3 * kR, kR), 2);
  WireShellTerm term(mesh, params());
  EXPECT_NEAR(term.energy(s) / hertz_energy(delta), 1.0, 1e-9);
}

// Forces: central differences of the energy in every wire and shell coordinate, on a randomly
// perturbed mesh with a crumpled wire pressed into it (error O(h^2) until round-off), and the
// total force is zero (action = reaction).
TEST(WireShell, GradientMatchesFiniteDifferencesAndBalances) {
  std::mt19937_64 rng(7);
  const ShellMesh mesh = bumpy_square(rng);
  State s = wire_across(mesh, 8, kR + kH - 0.05 * kR, -0.05 * kR, rng);
  WireShellTerm term(mesh, params());
  Forces f;
  f.reset(s);
  term.accumulate(s, f);
  ASSERT_GT(term.contacts(), 3);
  Vec3 total = Vec3::Zero();
  double fmax = 0;
  for (const auto& v : f.f) total += v, fmax = std::max(fmax, v.norm());
  for (const auto& v : f.shell_f) total += v, fmax = std::max(fmax, v.norm());
  EXPECT_LT(total.norm(), 1e-12 * fmax);
  // Wire nodes and shell vertices (tests/engine/fd_harness.hpp).
  const testing::FdReport r = testing::fd_check(term, s, kR, {1e-3, 1e-4, 1e-5, 1e-6});
  testing::print_report(r);
  const std::vector<double>& errs = r.err;
  EXPECT_LT(*std::min_element(errs.begin(), errs.end()), 1e-6);
  EXPECT_LT(errs[1], 0.1 * errs[0] + 1e-9);
}

// Verlet list: the term keeps its pair lists while every point moved less than skin / 2 and
// skips a pair while its points moved less than half its slack at the build (wire_shell.hpp). Moves
// of every size below skin / 2, of the wire and of the shell: energy and forces must be bitwise
// those of a fresh term (which evaluates every pair), and some moves must change the contacts.
TEST(WireShell, VerletSkipGivesTheFreshTermsForces) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  const ShellMesh mesh = bumpy_square(rng);
  // Heights from touching (overlap ~0.3 r) to clear of contact by ~0.3 r.
  const State s0 = wire_across(mesh, 10, kR + kH, 0.15 * kR, rng);
  const double skin = params().skin;
  WireShellTerm term(mesh, params());
  Forces f;
  f.reset(s0);
  term.accumulate(s0, f);
  const int contacts0 = term.contacts();
  int changed = 0;
  for (double move : {0.02, 0.1, 0.2, 0.3, 0.45, 0.49}) {
    State s = s0;
    for (auto& p : s.x) p += move * skin * Vec3(g(rng), g(rng), g(rng)).normalized();
    for (auto& p : s.shell_x) p += move * skin * Vec3(g(rng), g(rng), g(rng)).normalized();
    f.reset(s);
    const double U = term.accumulate(s, f);
    EXPECT_EQ(term.energy(s), U) << move;
    WireShellTerm fresh(mesh, params());
    Forces ff;
    ff.reset(s);
    const double U_fresh = fresh.accumulate(s, ff);
    EXPECT_EQ(U, U_fresh) << move;
    EXPECT_EQ(term.contacts(), fresh.contacts()) << move;
    for (size_t i = 0; i < f.f.size(); ++i) EXPECT_EQ(f.f[i], ff.f[i]) << move << " node " << i;
    for (size_t k = 0; k < f.shell_f.size(); ++k) {
      EXPECT_EQ(f.shell_f[k], ff.shell_f[k]) << move << " vertex " << k;
    }
    changed += term.contacts() != contacts0;
  }
  EXPECT_EQ(term.rebuilds(), 1) << "moves below skin / 2 keep the list";
  EXPECT_GT(changed, 0) << "the moves should change the contacts";
}

// The stability bound of the coupling (wire_shell.cpp, omega_max_sq): omega^2 <= k (1 / m_min +
// 1 / sqrt(m_n m_v)) must cover the largest eigenvalue of M^-1 K of the contact, K the Hessian of
// the contact energy over every wire and shell coordinate (central differences of the forces),
// M the node and vertex masses (a light vertex against the wire, m_v / m_n = 0.07 as at xi = 10).
TEST(WireShell, CouplingBoundCoversTheContactsLargestMode) {
  WireShellParams p = params();
  p.vertex_mass = 0.07 * p.node_mass;
  const ShellMesh mesh = flat_square(12 * kR, 6);  // 2 r squares, vertex at the origin
  const double delta = 0.02 * kR, z = kR + kH - delta;
  struct Case {
    Vec3 a, b;  // wire ends
    double max_ratio;
  };
  // Tilted wires whose lower end touches (a wire parallel to the mesh has a kink in its energy,
  // the closest point jumping between its ends): above the vertex at the origin (exactly k (1 /
  // m_n + 1 / m_v), the bound 1.18 times it), above an edge's midpoint (k (1 / m_n + 1 / (2
  // m_v)), 2.2 times) and above a face's interior (3.1 times at its centroid).
  const Vec3 up(0.3 * kR, 0.2 * kR, 0.9 * kR);
  const Case cases[] = {
      {Vec3(0, 0, z), Vec3(0, 0, z) + up, 1.19},
      {Vec3(kR, 0, z), Vec3(kR, 0, z) + up, 2.3},
      {Vec3(1.3 * kR, 0.6 * kR, z), Vec3(1.3 * kR, 0.6 * kR, z) + up, 4.0},
  };
  for (const Case& c : cases) {
    State s = wire_over(mesh, c.a, c.b, 2);
    WireShellTerm term(mesh, p);
    Forces f;
    f.reset(s);
    term.accumulate(s, f);
    ASSERT_GT(term.contacts(), 0);
    const double bound = term.omega_max_sq(RodInertia{p.node_mass, 0.0});
    // Coordinates: 6 of the wire, then 3 per shell vertex; mass-weighted Hessian by central
    // differences of the forces (h = 1e-6 r: the Hertz law is smooth at this overlap).
    const int nw = 6, n = nw + 3 * static_cast<int>(s.shell_x.size());
    auto coord = [&](int i) -> double& {
      return i < nw ? s.x[i / 3][i % 3] : s.shell_x[(i - nw) / 3][(i - nw) % 3];
    };
    auto forces = [&](Eigen::VectorXd& g) {
      WireShellTerm fresh(mesh, p);
      Forces ff;
      ff.reset(s);
      fresh.accumulate(s, ff);
      g.resize(n);
      for (int i = 0; i < n; ++i) {
        g[i] = i < nw ? ff.f[i / 3][i % 3] : ff.shell_f[(i - nw) / 3][(i - nw) % 3];
      }
    };
    const double h = 1e-6 * kR;
    Eigen::MatrixXd A(n, n);
    Eigen::VectorXd up, dn;
    for (int j = 0; j < n; ++j) {
      const double keep = coord(j);
      coord(j) = keep + h;
      forces(up);
      coord(j) = keep - h;
      forces(dn);
      coord(j) = keep;
      A.col(j) = -(up - dn) / (2 * h);  // K = -dF/dx
    }
    Eigen::VectorXd inv_sqrt_m(n);
    for (int i = 0; i < n; ++i)
      inv_sqrt_m[i] = 1.0 / std::sqrt(i < nw ? p.node_mass : p.vertex_mass);
    A = inv_sqrt_m.asDiagonal() * (0.5 * (A + A.transpose())) * inv_sqrt_m.asDiagonal();
    const double lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff();
    std::printf("  bound / largest eigenvalue: %.3f\n", bound / lambda);
    EXPECT_GE(bound, lambda * (1 - 1e-4)) << "wire from " << c.a.transpose();
    EXPECT_LE(bound, c.max_ratio * lambda) << "wire from " << c.a.transpose();
  }
}

}  // namespace
}  // namespace wirepack
