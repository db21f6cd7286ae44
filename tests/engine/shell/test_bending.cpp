// Checks of the shell bending energy (BendingTerm; paper Eq. (2)-(3), midedge-normal shape
// operator): finite-difference gradient, rigid-motion invariance, a dilated sphere against the
// continuum energy, the Poisson coupling (cylinder vs spherical cap), consistency for every
// constant curvature (and the mesh dependence of the average-normal variant), and the
// stiffness estimate behind omega_max_sq.
#include "engine/fd_harness.hpp"
#include "engine/shell/bending.hpp"
#include "engine/shell/mesh_builders.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace wirepack {
namespace {

// ---------------------------------------------------------------------------------------------
// Meshes: the scene's builders (geodesic_sphere, sphere_with_hole, flat_square: checkerboard
// diagonals), and here a square with all diagonals along the same direction, whose zig-zag
// mode is the stiffest one seen (BendingOmega).

// Square [-L/2, L/2]^2 in the plane z = 0, n x n cells, each cut along its (i, j)-(i+1, j+1)
// diagonal; nothing clamped.
ShellMesh diagonal_square(double L, int n) {
  ShellMesh m;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      m.rest.emplace_back(L * (double(i) / n - 0.5), L * (double(j) / n - 0.5), 0.0);
    }
  }
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      m.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  m.clamped.assign(m.rest.size(), 0);
  m.build_topology();
  return m;
}

// flat_square with nothing clamped (free edges all around).
ShellMesh free_square(double L, int n) {
  ShellMesh m = flat_square(L, n);
  m.clamped.assign(m.rest.size(), 0);
  return m;
}

ShellMaterial material(double nu = 0.3) {
  ShellMaterial mat;
  mat.E = 1.0e6;  // [Pa]
  mat.nu = nu;
  mat.t = 1.0e-3;  // [m]
  return mat;
}

double mean_edge_length(const ShellMesh& m) {
  double s = 0.0;
  for (const auto& e : m.edges) s += (m.rest[e[0]] - m.rest[e[1]]).norm();
  return s / m.edges.size();
}

// ---------------------------------------------------------------------------------------------
// Finite-difference check (tests/engine/fd_harness.hpp): max over all coordinates of
// |f + dU/dx| relative to max |f| at steps h * length_scale, printed as a ladder.
std::vector<double> fd_ladder(ShellTerm& term, const Vec3List& x0, double length_scale,
                              const std::vector<double>& steps) {
  const testing::FdReport r = testing::fd_check(term, x0, length_scale, steps);
  testing::print_report(r);
  return r.err;
}

Vec3List perturbed(const Vec3List& x, double amp, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  Vec3List y = x;
  for (auto& p : y) p += amp * Vec3(g(rng), g(rng), g(rng));
  return y;
}

void expect_ladder(const std::vector<double>& err) {
  // steps 1e-2 .. 1e-5 of the edge length: central differences of a smooth energy drop 100x
  // per decade (O(h^2)) until round-off (~1e-16 U / (h |f|) ~ 1e-10 at h = 1e-5).
  EXPECT_LT(err[0], 1e-2);
  EXPECT_GT(err[0] / err[1], 50.0);  // O(h^2): 100x per decade
  EXPECT_LT(err[2], 1e-6);
  EXPECT_LT(*std::min_element(err.begin(), err.end()), 1e-7);
}

TEST(BendingFd, PerturbedSphere) {
  const ShellMesh m = geodesic_sphere(1.0, 0.5);  // 80 faces
  const double h = mean_edge_length(m);
  BendingTerm term(m, material());
  for (unsigned seed : {1u, 2u}) {
    const Vec3List x = perturbed(m.rest, 0.1 * h, seed);
    expect_ladder(fd_ladder(term, x, h, {1e-2, 1e-3, 1e-4, 1e-5}));
  }
}

TEST(BendingFd, PerturbedFlatWithFreeAndClampedEdges) {
  // Clamp the vertices of the side y = -L/2: its boundary edges keep their rest normal; the
  // other three sides are free (edge normal = own face normal).
  ShellMesh m = free_square(1.0, 4);
  for (int i = 0; i <= 4; ++i) m.clamped[i] = 1;
  const double h = mean_edge_length(m);
  BendingTerm term(m, material());
  for (unsigned seed : {3u, 4u}) {
    Vec3List x = perturbed(m.rest, 0.1 * h, seed);
    expect_ladder(fd_ladder(term, x, h, {1e-2, 1e-3, 1e-4, 1e-5}));
  }
}

// ---------------------------------------------------------------------------------------------
// Rigid motions of the rest sphere: b is built from dot products of normals and edge vectors,
// so it is invariant and the energy vanishes up to round-off.
TEST(Bending, RigidMotionOfRestSphereIsFree) {
  const double R = 1.0;
  const ShellMesh m = geodesic_sphere(R, 0.25 * R);
  const auto mat = material();
  BendingTerm term(m, mat);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.7, Vec3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Vec3 d(0.3, -1.2, 2.5);
  // Scales: the energy of a 1 % dilation (4 pi B (1 + nu) 1e-4) and the force B / R^2 * 1e-2.
  const double U_scale = 4.0 * M_PI * mat.B() * 1.3e-4;
  const double f_scale = mat.B() / (R * R) * 1e-2;
  for (int k = 0; k < 3; ++k) {
    Vec3List x = m.rest;
    for (auto& p : x) p = k == 0 ? Vec3(p + d) : k == 1 ? Vec3(Q * p) : Vec3(Q * p + d);
    Vec3List f(x.size(), Vec3::Zero());
    const double U = term.accumulate(x, f);
    double fmax = 0.0;
    for (const auto& v : f) fmax = std::max(fmax, v.norm());
    std::printf("  rigid motion %d: U / U_scale = %.1e, max |f| / f_scale = %.1e\n", k,
                std::abs(U) / U_scale, fmax / f_scale);
    // Round-off: b ~ h^2 / R with relative error 1e-16 |x| / h; the energy is quadratic in it.
    // Measured ~1e-25 and ~1e-11 of the scales.
    EXPECT_LT(std::abs(U), 1e-20 * U_scale) << "motion " << k;
    EXPECT_LT(fmax, 1e-9 * f_scale) << "motion " << k;
  }
}

// ---------------------------------------------------------------------------------------------
// Uniform dilation x -> s x of the sphere of radius R: a = s^2 abar, b = a / (s R) = s abar / R,
// beta = bbar - b = (1 - s) abar / R, S = abar^{-1} beta = (1 - s) / R I. Energy density
// B/2 [nu (2 (1-s)/R)^2 + (1 - nu) 2 (1-s)^2 / R^2] = B (1 + nu) (1 - s)^2 / R^2, total over the
// rest area 4 pi R^2: U = 4 pi B (1 + nu) (1 - s)^2.
TEST(Bending, DilatedSphereMatchesContinuum) {
  const double R = 0.5, s = 1.01;
  const auto mat = material();
  const double U_exact = 4.0 * M_PI * mat.B() * (1.0 + mat.nu) * (1.0 - s) * (1.0 - s);
  double err[3], worst_last = 0.0;
  const double edges[3] = {0.3, 0.15, 0.075};  // target edge / R
  for (int k = 0; k < 3; ++k) {
    const ShellMesh m = geodesic_sphere(R, edges[k] * R);
    BendingTerm term(m, mat);
    Vec3List x = m.rest;
    for (auto& p : x) p *= s;
    const double ratio = term.energy(x) / U_exact;
    err[k] = std::abs(ratio - 1.0);
    // Per face, the rest mean curvature tr(abar^{-1} bbar) / 2 against 1 / R.
    const auto bbar = term.second_fundamental_forms(m.rest);
    double worst = 0.0;
    for (int f = 0; f < m.num_faces(); ++f) {
      const auto& v = m.faces[f];
      const Vec3 e1 = m.rest[v[1]] - m.rest[v[0]], e2 = m.rest[v[2]] - m.rest[v[0]];
      Eigen::Matrix2d abar;
      abar << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
      worst = std::max(worst, std::abs(0.5 * (abar.inverse() * bbar[f]).trace() * R - 1.0));
    }
    std::printf(
        "  dilated sphere: %zu faces, h = %.3g R, U / U_cont = %.5f, "
        "max over faces |H R - 1| = %.4f\n",
        m.faces.size(), mean_edge_length(m) / R, ratio, worst);
  }
  // The discrete b scales exactly with s (normals unchanged, edge vectors times s), so the
  // ratio is the discrete rest curvature energy over the sphere's. Measured 1.00772, 1.00211,
  // 1.00058: second order (3.7x per halving of h). Bounds: > 3x per halving, 0.1 % at the
  // finest (h = 0.075 R, 5120 faces). Per face the curvature is off by up to 5.4 % at every
  // refinement, but only within ~2 edges of the 12 five-valent vertices (the faces over 3 %
  // at h = 0.075 R: 240 of 5120, all there), a region whose area shrinks like h^2.
  EXPECT_GT(err[0] / err[1], 3.0);
  EXPECT_GT(err[1] / err[2], 3.0);
  EXPECT_LT(err[2], 1e-3);
  EXPECT_LT(worst_last, 0.08);
}

// ---------------------------------------------------------------------------------------------
// Poisson coupling. A flat plate bent onto a cylinder of radius rho (x -> arc) has one nonzero
// curvature kappa = 1/rho: tr(S)^2 = tr(S^2) = kappa^2 and the density is B/2 kappa^2. Onto a
// sphere of radius rho (both curvatures kappa): tr(S)^2 = 4 kappa^2, tr(S^2) = 2 kappa^2, density
// B/2 kappa^2 2 (1 + nu). The ratio 2 (1 + nu) needs the trace term; a hinge (sum of squared
// dihedral angles) model gives 2 for every nu. Interior faces only: a free edge carries no
// curvature (s = 0), which would bias the faces along the boundary.
struct PlateBend {
  double cyl, cap;  // energy per area / (B/2 kappa^2) on interior faces
};

PlateBend bent_plate(double nu, int n, bool checkerboard) {
  const double L = 1.0, rho = 5.0;
  const ShellMesh m = checkerboard ? free_square(L, n) : diagonal_square(L, n);
  const auto mat = material(nu);
  BendingTerm term(m, mat);
  Vec3List cyl = m.rest, cap = m.rest;
  for (size_t i = 0; i < m.rest.size(); ++i) {
    const Vec3& p = m.rest[i];
    cyl[i] = Vec3(rho * std::sin(p.x() / rho), p.y(), rho * (1.0 - std::cos(p.x() / rho)));
    // Cap: geodesic polar coordinates (the distance r from the centre is kept).
    const double r = std::hypot(p.x(), p.y());
    const double c = r > 0 ? rho * std::sin(r / rho) / r : 1.0;
    cap[i] = Vec3(c * p.x(), c * p.y(), rho * (1.0 - std::cos(r / rho)));
  }
  const auto Ucyl = term.face_energies(cyl);
  const auto Ucap = term.face_energies(cap);
  double area = 0.0, sum_cyl = 0.0, sum_cap = 0.0;
  for (int f = 0; f < m.num_faces(); ++f) {
    bool interior = true;
    for (int e : m.face_edges[f]) interior &= m.edge_faces[e][1] >= 0;
    if (!interior) continue;
    const auto& v = m.faces[f];
    area += 0.5 * (m.rest[v[1]] - m.rest[v[0]]).cross(m.rest[v[2]] - m.rest[v[0]]).norm();
    sum_cyl += Ucyl[f];
    sum_cap += Ucap[f];
  }
  const double unit = 0.5 * mat.B() / (rho * rho) * area;
  return {sum_cyl / unit, sum_cap / unit};
}

TEST(Bending, PoissonCouplingCylinderVsCap) {
  for (bool checkerboard : {false, true}) {
    for (double nu : {0.0, 0.3, 0.45}) {
      const PlateBend r = bent_plate(nu, 16, checkerboard);
      std::printf("  %s nu=%.2f: cylinder %.5f (1), cap %.5f (%.3f), ratio %.4f (%.3f)\n",
                  checkerboard ? "checkerboard" : "diagonal", nu, r.cyl, r.cap, 2 * (1 + nu),
                  r.cap / r.cyl, 2 * (1 + nu));
      // kappa h = 1/80: the discretisation error of b is O((kappa h)^2) plus the metric change
      // of the cap (a = abar (1 + O((L/rho)^2))); 1 % covers both.
      EXPECT_NEAR(r.cyl, 1.0, 0.01);
      EXPECT_NEAR(r.cap / (2.0 * (1.0 + nu)), 1.0, 0.01);
      EXPECT_NEAR(r.cap / r.cyl, 2.0 * (1.0 + nu), 0.01 * 2.0 * (1.0 + nu));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Consistency for every constant curvature: w = kappa/2 x^2, kappa/2 y^2, kappa x y (twist) and
// kappa/2 ((x + y)/sqrt 2)^2 on a flat plate, energy on the interior faces against the
// continuum densities B/2 kappa^2 (cylinders) and B (1 - nu) kappa^2 (twist: S = [[0, k], [k, 0]],
// tr S = 0, tr S^2 = 2 kappa^2). The average of two face normals is the normal at the edge
// midpoint to first order (hence b to zeroth order) only where the two faces form a
// parallelogram, as on a three-direction (valence-6) lattice, where all four are exact. On
// flat_square's checkerboard the right triangles across a leg are mirror images instead, and
// the twist and the diagonal cylinder come out 2.86x and 1.65x too stiff: the average-normal
// variant is mesh-dependent (test_plate.cpp uses the diagonal mesh for this reason). Random
// in-plane jitter of the lattice by a fraction j of the spacing costs ~2 j^2 of the energy
// (measured +2.0 % at j = 0.1 on a 32 x 32 grid).
std::array<double, 4> quadratic_mode_ratios(const ShellMesh& m) {
  const auto mat = material();
  BendingTerm term(m, mat);
  const double k = 1e-3;  // kappa L = 1e-3: linear regime
  std::array<double, 4> out;
  for (int mode = 0; mode < 4; ++mode) {
    Vec3List x = m.rest;
    for (auto& p : x) {
      const double X = p.x(), Y = p.y(), D = (X + Y) / std::sqrt(2.0);
      p.z() = mode == 0   ? 0.5 * k * X * X
              : mode == 1 ? 0.5 * k * Y * Y
              : mode == 2 ? k * X * Y
                          : 0.5 * k * D * D;
    }
    const auto U = term.face_energies(x);
    double area = 0.0, sum = 0.0;
    for (int f = 0; f < m.num_faces(); ++f) {
      bool interior = true;
      for (int e : m.face_edges[f]) interior &= m.edge_faces[e][1] >= 0;
      if (!interior) continue;
      const auto& v = m.faces[f];
      area += 0.5 * (m.rest[v[1]] - m.rest[v[0]]).cross(m.rest[v[2]] - m.rest[v[0]]).norm();
      sum += U[f];
    }
    const double density = mode == 2 ? mat.B() * (1.0 - mat.nu) * k * k : 0.5 * mat.B() * k * k;
    out[mode] = sum / (density * area);
  }
  return out;
}

TEST(Bending, QuadraticModes) {
  const auto lattice = quadratic_mode_ratios(diagonal_square(1.0, 16));
  const auto checker = quadratic_mode_ratios(free_square(1.0, 16));
  std::printf(
      "  U / U_cont  xx, yy, twist, diagonal: three-direction %.5f %.5f %.5f %.5f, "
      "checkerboard %.5f %.5f %.5f %.5f\n",
      lattice[0], lattice[1], lattice[2], lattice[3], checker[0], checker[1], checker[2],
      checker[3]);
  // Exact up to the O(kappa^2 h^2) geometric nonlinearity (1e-6 here): 1e-4.
  for (double r : lattice) EXPECT_NEAR(r, 1.0, 1e-4);
  // The documented limitation (if this changes, the operator changed: revisit test_plate.cpp).
  EXPECT_NEAR(checker[0], 1.0, 1e-4);
  EXPECT_NEAR(checker[2], 20.0 / 7.0, 1e-3);
  EXPECT_NEAR(checker[3], 1.65, 1e-3);
}

// ---------------------------------------------------------------------------------------------
// omega_max_sq against the largest eigenvalue of the stiffness K = d^2 U/dx^2 at rest (central
// differences of the analytic forces, symmetrised), divided by the vertex mass.
double lambda_max_fd(BendingTerm& term, const Vec3List& x0, double h) {
  const int n = 3 * static_cast<int>(x0.size());
  Eigen::MatrixXd K(n, n);
  Vec3List x = x0;
  for (int j = 0; j < n; ++j) {
    Vec3List fp(x0.size(), Vec3::Zero()), fm(x0.size(), Vec3::Zero());
    x[j / 3][j % 3] = x0[j / 3][j % 3] + h;
    term.accumulate(x, fp);
    x[j / 3][j % 3] = x0[j / 3][j % 3] - h;
    term.accumulate(x, fm);
    x[j / 3][j % 3] = x0[j / 3][j % 3];
    for (int i = 0; i < n; ++i) K(i, j) = -(fp[i / 3][i % 3] - fm[i / 3][i % 3]) / (2 * h);
  }
  const Eigen::MatrixXd Ks = 0.5 * (K + K.transpose());
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Ks, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

TEST(BendingOmega, BoundsFdStiffness) {
  const double mass = 1e-3;
  struct Case {
    const char* name;
    ShellMesh mesh;
  };
  std::vector<Case> cases;
  cases.push_back({"flat diagonal", diagonal_square(1.0, 8)});
  cases.push_back({"flat checkerboard, free", free_square(1.0, 8)});
  cases.push_back({"flat checkerboard, clamped", flat_square(1.0, 8)});
  cases.push_back({"geodesic sphere", geodesic_sphere(1.0, 0.3)});
  cases.push_back({"sphere with hole", sphere_with_hole(1.0, 0.3, 0.3, 0.2)});
  {
    // Interior vertices jittered in-plane by up to 0.3 cells: a few thin triangles.
    ShellMesh m = free_square(1.0, 6);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-0.3, 0.3);
    for (int i = 0; i < m.num_vertices(); ++i) {
      const int ix = i % 7, iy = i / 7;
      if (ix > 0 && ix < 6 && iy > 0 && iy < 6) m.rest[i] += Vec3(u(rng), u(rng), 0.0) / 6.0;
    }
    cases.push_back({"flat jittered", m});
  }
  for (auto& c : cases) {
    BendingTerm term(c.mesh, material());
    const double lam = lambda_max_fd(term, c.mesh.rest, 1e-6 * mean_edge_length(c.mesh));
    const double est = term.omega_max_sq(mass);
    std::printf("  omega bound %s: estimate / (lambda_max / m) = %.2f\n", c.name, est * mass / lam);
    // Engine V: the bound is the mesh's own rest eigenvalue (power iteration) times the margin
    // 1.25, so the ratio is 1.25 on every mesh (measured: 1.25 on all six to two decimals; the
    // closed form C_omega B / h_min^2 it replaced gave 1.29 on the diagonal square, ~2.8 on the
    // geodesic spheres and ~7 on the jittered square). Safe (>= 1) and tight (< 1.3).
    EXPECT_GE(est * mass / lam, 1.0) << c.name;
    EXPECT_LT(est * mass / lam, 1.3) << c.name;
    EXPECT_LE(term.rest_stiffness_max() * BendingTerm::kOmegaMargin,
              term.closed_form_stiffness() * (1 + 1e-12))
        << c.name;
  }
}

}  // namespace
}  // namespace wirepack
