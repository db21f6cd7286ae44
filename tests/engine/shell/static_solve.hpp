#pragma once
// Static solves of a shell for the analytic tests (pressurised sphere, plates, point loads):
// the stiffness K = d^2 U / dx^2 of any list of ShellTerms by central finite differences of
// their forces, several vertices perturbed at once (a vertex colouring: two vertices share a
// colour only when no force depends on both), assembled sparse; then K u = F on the free
// degrees of freedom (linear), or Newton steps on f(x) + F = 0 (nonlinear). Header-only,
// namespace wirepack::testing like the FD harness.
//
// DOF layout: entry 3 i + k is coordinate k of vertex i (nv vertices, 3 nv DOFs).
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "engine/shell/shell_term.hpp"

namespace wirepack::testing {

struct StiffnessOptions {
  double h_rel = 1e-5;  // FD step over the mean rest edge [-] (O(h^2) error ~1e-10 relative)
  // Reach of the terms' stencils in vertex rings: the force on a vertex depends only on the
  // vertices within this many edges of it (1: membrane; 2: midedge-normal bending, whose
  // stencil is a face and its three edge neighbours).
  int stencil_rings = 2;
};

// 1 for the DOFs of the mesh's clamped vertices (3 nv).
inline std::vector<char> clamped_dofs(const ShellMesh& mesh) {
  std::vector<char> fixed(3 * mesh.rest.size(), 0);
  for (size_t i = 0; i < mesh.rest.size(); ++i) {
    for (int k = 0; k < 3; ++k) fixed[3 * i + k] = mesh.clamped[i];
  }
  return fixed;
}

// Sum of the terms' forces -dU/dx at x into f (nv, overwritten); returns the total U [J].
inline double total_forces(const std::vector<ShellTerm*>& terms, const Vec3List& x, Vec3List& f) {
  f.assign(x.size(), Vec3::Zero());
  double U = 0.0;
  for (ShellTerm* t : terms) U += t->accumulate(x, f);
  return U;
}

inline double mean_rest_edge(const ShellMesh& mesh) {
  double s = 0.0;
  for (const auto& e : mesh.edges) s += (mesh.rest[e[1]] - mesh.rest[e[0]]).norm();
  return s / static_cast<double>(mesh.edges.size());
}

// Vertices within `rings` edges of each vertex, itself included (nv lists).
inline std::vector<std::vector<int>> vertex_rings(const ShellMesh& mesh, int rings) {
  const int nv = mesh.num_vertices();
  std::vector<std::vector<int>> nb(nv), out(nv);
  for (const auto& e : mesh.edges) {
    nb[e[0]].push_back(e[1]);
    nb[e[1]].push_back(e[0]);
  }
  std::vector<int> seen(nv, -1);
  for (int v = 0; v < nv; ++v) {
    std::vector<int>& ring = out[v];
    ring.push_back(v);
    seen[v] = v;
    size_t begin = 0;
    for (int r = 0; r < rings; ++r) {
      const size_t end = ring.size();
      for (size_t i = begin; i < end; ++i) {
        for (int w : nb[ring[i]]) {
          if (seen[w] != v) seen[w] = v, ring.push_back(w);
        }
      }
      begin = end;
    }
  }
  return out;
}

// Greedy colouring: u and v get different colours when some vertex is within `rings` of both
// (i.e. they are within 2 rings of each other). Returns the vertices of each colour.
inline std::vector<std::vector<int>> fd_colouring(const ShellMesh& mesh, int rings) {
  const auto near = vertex_rings(mesh, 2 * rings);
  const int nv = mesh.num_vertices();
  std::vector<int> colour(nv, -1);
  std::vector<std::vector<int>> classes;
  std::vector<int> used;
  for (int v = 0; v < nv; ++v) {
    used.assign(classes.size() + 1, 0);
    for (int w : near[v]) {
      if (colour[w] >= 0) used[colour[w]] = 1;
    }
    int c = 0;
    while (used[c]) ++c;
    if (c == static_cast<int>(classes.size())) classes.emplace_back();
    colour[v] = c;
    classes[c].push_back(v);
  }
  return classes;
}

// K = d^2 U / dx^2 at x (3 nv x 3 nv, symmetrised) by central differences of the forces:
// column (u, k) is -(f(x + h e_uk) - f(x - h e_uk)) / (2 h), read on the rows within
// stencil_rings of u; all vertices of one colour are perturbed together.
inline Eigen::SparseMatrix<double> fd_stiffness(const std::vector<ShellTerm*>& terms,
                                                const ShellMesh& mesh, const Vec3List& x,
                                                const StiffnessOptions& opt = {}) {
  const int nv = mesh.num_vertices();
  const double h = opt.h_rel * mean_rest_edge(mesh);
  const auto rings = vertex_rings(mesh, opt.stencil_rings);
  const auto classes = fd_colouring(mesh, opt.stencil_rings);
  std::vector<Eigen::Triplet<double>> trip;
  Vec3List xp, xm, fp, fm;
  for (const auto& cls : classes) {
    for (int k = 0; k < 3; ++k) {
      xp = x;
      xm = x;
      for (int u : cls) xp[u][k] += h, xm[u][k] -= h;
      total_forces(terms, xp, fp);
      total_forces(terms, xm, fm);
      for (int u : cls) {
        for (int r : rings[u]) {
          for (int l = 0; l < 3; ++l) {
            const double val = -(fp[r][l] - fm[r][l]) / (2 * h);
            if (val != 0.0) trip.emplace_back(3 * r + l, 3 * u + k, val);
          }
        }
      }
    }
  }
  Eigen::SparseMatrix<double> K(3 * nv, 3 * nv);
  K.setFromTriplets(trip.begin(), trip.end());
  Eigen::SparseMatrix<double> Kt = K.transpose();
  return 0.5 * (K + Kt);
}

// Solves K du = r on the DOFs with fixed = 0 (du = 0 on the others). SimplicialLDLT (K is
// symmetric; positive definite once the rigid motions are fixed), SparseLU if that fails.
inline Eigen::VectorXd solve_free(const Eigen::SparseMatrix<double>& K,
                                  const std::vector<char>& fixed, const Eigen::VectorXd& r) {
  const int n = static_cast<int>(fixed.size());
  std::vector<int> id(n, -1);
  int nf = 0;
  for (int i = 0; i < n; ++i) {
    if (!fixed[i]) id[i] = nf++;
  }
  std::vector<Eigen::Triplet<double>> trip;
  for (int c = 0; c < K.outerSize(); ++c) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, c); it; ++it) {
      if (id[it.row()] >= 0 && id[it.col()] >= 0) {
        trip.emplace_back(id[it.row()], id[it.col()], it.value());
      }
    }
  }
  Eigen::SparseMatrix<double> Kf(nf, nf);
  Kf.setFromTriplets(trip.begin(), trip.end());
  Eigen::VectorXd rf(nf);
  for (int i = 0; i < n; ++i) {
    if (id[i] >= 0) rf[id[i]] = r[i];
  }
  Eigen::VectorXd uf;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(Kf);
  if (ldlt.info() == Eigen::Success) uf = ldlt.solve(rf);
  if (ldlt.info() != Eigen::Success || !uf.allFinite()) {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(Kf);
    if (lu.info() != Eigen::Success) throw std::runtime_error("solve_free: singular stiffness");
    uf = lu.solve(rf);
  }
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n);
  for (int i = 0; i < n; ++i) {
    if (id[i] >= 0) u[i] = uf[id[i]];
  }
  return u;
}

inline Eigen::VectorXd flatten(const Vec3List& v) {
  Eigen::VectorXd out(3 * v.size());
  for (size_t i = 0; i < v.size(); ++i) out.segment<3>(3 * i) = v[i];
  return out;
}

inline Vec3List unflatten(const Eigen::VectorXd& v) {
  Vec3List out(v.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = v.segment<3>(3 * i);
  return out;
}

// Linear static response to external forces F (nv) [N] about the rest state: K(rest) u = F
// on the free DOFs (fixed: 3 nv, 1 = held at zero). Returns the displacements u (nv) [m].
inline Vec3List solve_linear(const std::vector<ShellTerm*>& terms, const ShellMesh& mesh,
                             const std::vector<char>& fixed, const Vec3List& F,
                             const StiffnessOptions& opt = {}) {
  const auto K = fd_stiffness(terms, mesh, mesh.rest, opt);
  return unflatten(solve_free(K, fixed, flatten(F)));
}

struct NonlinearResult {
  Vec3List u;             // displacements from the rest state (nv) [m]
  int iterations = 0;     // Newton steps taken
  double residual = 0.0;  // max |f + F| over free DOFs at the end, over max |F| [-]
};

// Equilibrium f(x) + F = 0 by Newton's method with the FD stiffness re-assembled at every
// step, starting from the rest state; stops when the relative residual is below tol.
inline NonlinearResult solve_nonlinear(const std::vector<ShellTerm*>& terms, const ShellMesh& mesh,
                                       const std::vector<char>& fixed, const Vec3List& F,
                                       int max_iter = 20, double tol = 1e-10,
                                       const StiffnessOptions& opt = {}) {
  Vec3List x = mesh.rest, f;
  const Eigen::VectorXd Fv = flatten(F);
  const double scale = std::max(Fv.cwiseAbs().maxCoeff(), 1e-300);
  NonlinearResult res;
  for (;;) {
    total_forces(terms, x, f);
    Eigen::VectorXd r = flatten(f) + Fv;
    for (size_t i = 0; i < fixed.size(); ++i) {
      if (fixed[i]) r[i] = 0.0;
    }
    res.residual = r.cwiseAbs().maxCoeff() / scale;
    if (res.residual < tol || res.iterations >= max_iter) break;
    const auto K = fd_stiffness(terms, mesh, x, opt);
    const Vec3List dx = unflatten(solve_free(K, fixed, r));
    for (size_t i = 0; i < x.size(); ++i) x[i] += dx[i];
    ++res.iterations;
  }
  res.u.resize(x.size());
  for (size_t i = 0; i < x.size(); ++i) res.u[i] = x[i] - mesh.rest[i];
  return res;
}

// The explicit step's bound of a one-ring term at state x against the truth: after
// term.accumulate(x), omega_max_sq(1) (a stiffness at unit mass) and the largest eigenvalue of
// the FD stiffness there [N/m].
struct StepBound {
  double lambda_max, bound;
};
inline StepBound step_bound(ShellTerm& term, const ShellMesh& mesh, const Vec3List& x) {
  Vec3List f(x.size(), Vec3::Zero());
  term.accumulate(x, f);
  StiffnessOptions opt;
  opt.stencil_rings = 1;
  const Eigen::MatrixXd K = Eigen::MatrixXd(fd_stiffness({&term}, mesh, x, opt));
  const double lmax = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K, Eigen::EigenvaluesOnly)
                          .eigenvalues()
                          .maxCoeff();
  return {lmax, term.omega_max_sq(1.0)};
}

}  // namespace wirepack::testing
