#pragma once
// Bending energy of the Kirchhoff-Love shell (paper Eq. (2)-(3), docs/design.md §2.3): the change
// beta = bbar - b of a discrete second fundamental form per triangle,
//   U_sb = sum_f 1/2 Abar_f B H^{ijkl} beta_ij beta_kl
//        = sum_f B/2 Abar_f [nu tr(S)^2 + (1 - nu) tr(S^2)],   S = abar^{-1} (b - bbar),
// with B = M t^2 / 12 and the rest metric abar of the face (the same H as the membrane).
//
// Discrete b: midedge-normal shape operator (Grinspun et al. 2006; Chen et al. 2018), in the
// variant whose edge normal is the normalised average of the two adjacent face normals
// (libshell's "MidedgeAverage"), so there are no unknowns besides the vertex positions.
// For face (q0, q1, q2), edge i opposite to vertex i with edge normal n_i, the normal field
// interpolating n_i at the edge midpoints is linear in the barycentric coordinates lambda_i,
// n = sum_i (1 - 2 lambda_i) n_i. With (u, v) = (lambda_1, lambda_2) and the face basis
// e1 = q1 - q0, e2 = q2 - q0 (x = q0 + u e1 + v e2):
//   b_jk = e_j . d_k n,   d_u n = 2 (n0 - n1),  d_v n = 2 (n0 - n2).
// Each n_i is perpendicular to edge i (both face normals are), so n_i . q_{i+1} = n_i . q_{i+2},
// which makes b symmetric and
//   b = s0 [[1, 1], [1, 1]] + s1 [[1, 0], [0, 0]] + s2 [[0, 0], [0, 1]],
//   s_i = n_i . (q_{i+1} + q_{i+2} - 2 q_i) = 2 h_i sin(theta_i / 2)   [m],
// theta_i the fold (dihedral turning angle) across edge i, h_i the altitude from vertex i;
// positive for a convex surface with outward normals (a sphere of radius R: b ~ a / R). Each
// matrix is the dual-basis form of nu_i nu_i^T / h_i^2 (nu_i the in-plane unit normal of edge
// i), so S = sum_i (2 sin(theta_i / 2) / h_i) nu_i nu_i^T: a fold per edge, and the trace term
// of the energy couples the folds of the three edges (Poisson).
//
// Mesh dependence: the average of two face normals is the midedge normal to first order only
// where the two faces form a parallelogram. On three-direction (valence-6) lattices, like the
// geodesic sphere, b is exact for every constant curvature; on a checkerboard square
// (right triangles mirrored across a leg) twisting energy is 2.86x too high and a clamped
// plate converges to 0.77 of Kirchhoff's deflection (tests/engine/shell/test_bending.cpp,
// test_plate.cpp). Random jitter of a fraction j of the spacing costs ~2 j^2 of the energy.
//
// Boundary edges (one adjacent face): if both end vertices are clamped, the edge normal is
// held at the rest normal of its face (a clamped edge: zero slope, the rotation is held);
// otherwise it is the face's own current normal, so s_i = 0 (a free edge carries no moment).
//
// Gradient (accumulate): with sigma_i = dU/ds_i from P = dU/db = B Abar [nu tr(S) abar^{-1} +
// (1 - nu) abar^{-1} D abar^{-1}] (D = b - bbar), the chain rule runs through (1) the explicit
// q's in s_i, (2) the edge normal n = m / |m|, m = N_f + N_g: dU/dm = (I - n n^T) dU/dn / |m|,
// (3) the face normal N = c / |c|, c = e1 x e2: dU/dc = (I - N N^T) dU/dN / |c|,
// dU/dq1 = e2 x dU/dc, dU/dq2 = dU/dc x e1, dU/dq0 = -(dU/dq1 + dU/dq2).
#include <array>
#include <vector>

#include <Eigen/Core>

#include "engine/shell/scatter_plan.hpp"
#include "engine/shell/shell_term.hpp"

namespace wirepack {

class BendingTerm : public ShellTerm {
 public:
  // Copies what it needs of the mesh (topology, rest shape, clamped flags).
  BendingTerm(const ShellMesh& mesh, const ShellMaterial& material);
  std::string name() const override { return "shell_bending"; }
  TermType type() const override { return TermType::kShellBending; }
  double accumulate(const Vec3List& x, Vec3List& f) override;
  double energy(const Vec3List& x) override;
  // Highest mode: omega^2 = kOmegaMargin lambda_rest / m, lambda_rest the largest eigenvalue
  // of this mesh's rest stiffness (power iteration at construction), see bending.cpp.
  double omega_max_sq(double vertex_mass) const override;
  // lambda_rest [N/m] and the former closed-form estimate C_omega B / h_min^2 [N/m].
  double rest_stiffness_max() const { return lambda_rest_; }
  double closed_form_stiffness() const { return kOmegaConstant * B_ / (h_min_ * h_min_); }

  // Energy of each face at x (nf) [J]; sums to energy(x). For tests and diagnostics.
  std::vector<double> face_energies(const Vec3List& x);
  // Discrete second fundamental form of every face at x, covariant in the face's basis
  // (q1 - q0, q2 - q0) [m] (nf, each 2 x 2 symmetric). For tests and diagnostics.
  std::vector<Eigen::Matrix2d> second_fundamental_forms(const Vec3List& x);

  // Dimensionless constant of omega_max_sq (calibrated against the largest eigenvalue of the
  // finite-difference stiffness, tests/engine/shell/test_bending.cpp).
  static constexpr double kOmegaConstant = 40.0;
  // Margin of omega_max^2 over the measured rest eigenvalue (the power iteration's Rayleigh
  // quotient approaches lambda_max from below; geometric stiffening is not included).
  static constexpr double kOmegaMargin = 1.25;

 private:
  // Edge normal rule: interior (average of the two face normals), free boundary (own face
  // normal, s = 0), clamped boundary (fixed rest normal of the face).
  enum class EdgeKind : char { kInterior, kFree, kClamped };

  // Face and edge normals at x, into the work arrays below.
  void compute_normals(const Vec3List& x);
  // s_i of face f from the current normals (3).
  Eigen::Vector3d edge_folds(const Vec3List& x, int f) const;
  // Largest eigenvalue of the stiffness at `rest` by power iteration [N/m] (constructor).
  double rest_power_iteration(const Vec3List& rest);
  // Energy of face f and dU/ds_i (3) from its folds s (3).
  double face_energy(int f, const Eigen::Vector3d& s, Eigen::Vector3d* dU_ds) const;

  std::vector<std::array<int, 3>> faces_;       // vertex indices (nf)
  std::vector<std::array<int, 3>> face_edges_;  // edge i opposite to vertex i (nf)
  std::vector<std::array<int, 2>> edge_faces_;  // adjacent faces, -1 on a boundary (ne)
  double B_;                                    // bending rigidity M t^2 / 12 [N m]
  double nu_;                                   // Poisson ratio [-]
  std::vector<EdgeKind> edge_kind_;             // (ne)
  std::vector<Vec3> edge_fixed_normal_;         // rest face normal on clamped boundary edges (ne)
  std::vector<double> rest_area_;               // Abar (nf) [m^2]
  std::vector<Eigen::Matrix2d> abar_inv_;       // inverse rest metric, contravariant (nf) [1/m^2]
  std::vector<Eigen::Matrix2d> bbar_;           // rest second fundamental form (nf) [m]
  double h_min_ = 0.0;                          // smallest rest altitude of any face [m]
  double lambda_rest_ = 0.0;                    // largest rest stiffness eigenvalue [N/m]

  // Work arrays (per-run state, reused across calls).
  std::vector<Vec3> face_normal_;       // unit normal N_f (nf)
  std::vector<double> face_dblarea_;    // |(q1 - q0) x (q2 - q0)| (nf) [m^2]
  std::vector<Vec3> edge_normal_;       // unit n_e (ne)
  std::vector<double> edge_mnorm_;      // |N_f0 + N_f1| on interior edges (ne)
  std::vector<Vec3> grad_edge_normal_;  // dU/dn_e (ne) [J]
  std::vector<Vec3> grad_face_normal_;  // dU/dN_f (nf) [J]

  // Parallel assembly (threads over faces and edges; the sums are bitwise those of serial
  // loops over faces, then edges, then faces, see scatter_plan.hpp):
  ScatterPlan fold_plan_;       // 9 slots per face: fold i's three vertex terms (i, i+1, i+2)
  ScatterPlan edge_plan_;       // 3 slots per face: sigma_i w_i into dU/dn of edge i
  ScatterPlan normal_plan_;     // 2 slots per edge: dU/dm into its two faces' dU/dN
  ScatterPlan face_plan_;       // 3 slots per face: the face normal's vertex terms
  Vec3List fold_force_;         // (9 nf) [N]
  Vec3List edge_term_;          // (3 nf) [J]
  Vec3List normal_term_;        // (2 ne) [J]
  Vec3List face_force_;         // (3 nf) [N]
  std::vector<double> face_U_;  // (nf) [J]
};

}  // namespace wirepack
