#pragma once
// Membrane energy of the shell (paper Eqs. (2)-(3), the M term): constant-strain triangles,
// St. Venant-Kirchhoff on the Green strain alpha_ij = (a_ij - abar_ij) / 2 in covariant
// components of each face's edge basis e_1 = x_1 - x_0, e_2 = x_2 - x_0:
//   U_m = sum_f 1/2 Abar_f M H^{ijkl} alpha_ij alpha_kl
//       = sum_f M/2 Abar_f [nu tr(A)^2 + (1 - nu) tr(A^2)],   A = abar^{-1} alpha (2 x 2).
// With ShellMaterialLaw::NeoHookean (beyond the paper, its open question of material
// nonlinearity), a compressible neo-Hookean membrane in C = abar^{-1} a = I + 2 A (2 x 2):
//   U_m = sum_f Abar_f [mu/2 (tr C - 2 - ln det C) + lambda/8 (ln det C)^2],
// mu = M (1 - nu) / 2 and lambda = M nu the 2-D Lame moduli of the linear law, so that the two
// agree to second order in the strain; it softens in tension (a sphere inflated by a pressure
// has a limit point) and stiffens without bound as a face collapses (ln det C -> -inf).
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/shell/scatter_plan.hpp"
#include "engine/shell/shell_term.hpp"

namespace wirepack {

class MembraneTerm : public ShellTerm {
 public:
  MembraneTerm(const ShellMesh& mesh, const ShellMaterial& material);
  std::string name() const override { return "membrane"; }
  TermType type() const override { return TermType::kMembrane; }
  double accumulate(const Vec3List& x, Vec3List& f) override;
  double energy(const Vec3List& x) override;
  // omega_max^2 <= s * max_v sum_{f at v} lambda_f / m (see rest_stiffness_bound) with the
  // stretch factor s = max(1, (3 lambda^2 - 1) / 2) of the largest principal stretch lambda
  // seen at the last accumulate() (StVK stiffens in tension; at rest s = 1). Neo-Hookean:
  // s = max(1, (1 + nu - 2 ln lambda_min) / ((1 + nu) lambda_min^2)) of the smallest principal
  // stretch, its principal-stretch Hessian over the rest one's largest eigenvalue M (1 + nu)
  // (it softens in tension and stiffens in compression). Against the
  // largest eigenvalue of the FD stiffness (test_membrane): 1.6x at rest and at 10 %
  // dilation, 2.4x at random +-20 % strains.
  // Per vertex (Engine V): omega_max^2 <= max_v sum_{f at v} s_f lambda_f / m with each face's
  // own stretch factor s_f (the same Rayleigh-quotient argument face by face), so one
  // over-stretched face raises the bound at its vertices only, not everywhere.
  double omega_max_sq(double vertex_mass) const override;

  // max over vertices of sum over the faces at the vertex of lambda_f, the largest eigenvalue
  // of the face's 9 x 9 rest stiffness Abar M L^T H L (L: nodal displacements -> alpha) [N/m].
  // Bounds the largest eigenvalue of the assembled rest stiffness (Rayleigh quotient).
  double rest_stiffness_bound() const { return rest_bound_; }
  // Largest squared principal stretch lambda^2 = max eig(abar^{-1} a) over the faces at the
  // last accumulate() [-] (1 before any).
  double max_stretch_sq() const { return max_stretch_sq_; }

 private:
  struct Face {
    std::array<int, 3> v;      // vertex indices
    Eigen::Matrix2d abar;      // rest metric abar_ij = ebar_i . ebar_j [m^2]
    Eigen::Matrix2d abar_inv;  // inverse rest metric abar^{ij} [1/m^2]
    double area;               // rest area Abar [m^2]
  };
  template <bool kForces>
  double evaluate(const Vec3List& x, Vec3List* f);
  // The neo-Hookean energy of face k with edges e1, e2 and metric a11, a12, a22 [J]; with
  // kForces its slot forces and load, and its largest squared stretch into max_stretch_sq. A
  // face of zero area (det C = 0: the law has no energy) lowers `collapsed` to k and gives 0.
  template <bool kForces>
  double neo_hookean_face(int k, const Vec3& e1, const Vec3& e2, double a11, double a12, double a22,
                          double& max_stretch_sq, int& collapsed);

  std::vector<Face> faces_;
  double M_, nu_;                // membrane rigidity [N/m], Poisson ratio [-]
  bool neo_hookean_;             // ShellMaterialLaw::NeoHookean
  double rest_bound_ = 0.0;      // [N/m]
  double max_stretch_sq_ = 1.0;  // [-]
  // Parallel assembly (threads over faces, bitwise the serial sums): slot j of face k is
  // vertex v[j]; per-face forces (3 nf) [N] and energies (nf) [J].
  ScatterPlan plan_;
  Vec3List face_force_;
  std::vector<double> face_energy_;
  std::vector<double> face_lambda_;  // lambda_f, largest eigenvalue of the face's rest stiffness
  std::vector<double> face_load_;    // (3 nf) s_f lambda_f per slot at the last accumulate [N/m]
  std::vector<double> vertex_load_;  // (nv) sum over the faces at each vertex [N/m]
  double max_vertex_load_ = 0.0;     // [N/m]
};

}  // namespace wirepack
