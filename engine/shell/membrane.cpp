#include "engine/shell/membrane.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace wirepack {
namespace {

// nu tr(A)^2 + (1 - nu) tr(A^2), A = abar^{-1} alpha: H^{ijkl} alpha_ij alpha_kl (paper Eq. 3).
double h_quadratic(const Eigen::Matrix2d& abar_inv, const Eigen::Matrix2d& alpha, double nu) {
  const Eigen::Matrix2d A = abar_inv * alpha;
  const double tr = A.trace();
  return nu * tr * tr + (1.0 - nu) * (A * A).trace();
}

}  // namespace

MembraneTerm::MembraneTerm(const ShellMesh& mesh, const ShellMaterial& material)
    : M_(material.M()),
      nu_(material.nu),
      neo_hookean_(material.law == ShellMaterialLaw::NeoHookean) {
  faces_.reserve(mesh.faces.size());
  std::vector<double> vertex_sum(mesh.rest.size(), 0.0);
  for (const auto& v : mesh.faces) {
    const Vec3 e1 = mesh.rest[v[1]] - mesh.rest[v[0]];
    const Vec3 e2 = mesh.rest[v[2]] - mesh.rest[v[0]];
    Face face;
    face.v = v;
    face.abar << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
    const double det = face.abar.determinant();
    if (!(det > 0)) throw std::invalid_argument("MembraneTerm: degenerate rest face");
    face.abar_inv = face.abar.inverse();
    face.area = 0.5 * std::sqrt(det);
    faces_.push_back(face);

    // Rest stiffness of the face: U = M/2 Abar q(alpha) with q(alpha(w)) = w^T C w for
    // w = (alpha_11, alpha_22, alpha_12) (C by polarisation of the quadratic form), and the
    // linearised strain w = L dx (3 x 9, dx = (dx_0, dx_1, dx_2)):
    //   d alpha_11 = e1 . de1, d alpha_22 = e2 . de2, d alpha_12 = (de1 . e2 + e1 . de2) / 2.
    std::array<Eigen::Matrix2d, 3> basis;
    basis[0] << 1, 0, 0, 0;
    basis[1] << 0, 0, 0, 1;
    basis[2] << 0, 1, 1, 0;
    Eigen::Matrix3d C;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        C(i, j) = 0.5 * (h_quadratic(face.abar_inv, basis[i] + basis[j], nu_) -
                         h_quadratic(face.abar_inv, basis[i], nu_) -
                         h_quadratic(face.abar_inv, basis[j], nu_));
      }
    }
    Eigen::Matrix<double, 3, 9> L = Eigen::Matrix<double, 3, 9>::Zero();
    L.block<1, 3>(0, 3) = e1.transpose();
    L.block<1, 3>(0, 0) = -e1.transpose();
    L.block<1, 3>(1, 6) = e2.transpose();
    L.block<1, 3>(1, 0) = -e2.transpose();
    L.block<1, 3>(2, 3) = 0.5 * e2.transpose();
    L.block<1, 3>(2, 6) = 0.5 * e1.transpose();
    L.block<1, 3>(2, 0) = -0.5 * (e1 + e2).transpose();
    const Eigen::Matrix<double, 9, 9> K = M_ * face.area * L.transpose() * C * L;
    const double lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>>(K, Eigen::EigenvaluesOnly)
            .eigenvalues()
            .maxCoeff();
    for (int k = 0; k < 3; ++k) vertex_sum[v[k]] += lambda;
    face_lambda_.push_back(lambda);
  }
  for (double s : vertex_sum) rest_bound_ = std::max(rest_bound_, s);
  std::vector<int> targets;
  for (const Face& face : faces_) targets.insert(targets.end(), face.v.begin(), face.v.end());
  plan_ = ScatterPlan(targets, 3, static_cast<int>(mesh.rest.size()));
  face_force_.assign(targets.size(), Vec3::Zero());
  face_energy_.assign(faces_.size(), 0.0);
  face_load_.assign(targets.size(), 0.0);
  vertex_load_.assign(mesh.rest.size(), 0.0);
  max_vertex_load_ = rest_bound_;
}

template <bool kForces>
double MembraneTerm::evaluate(const Vec3List& x, Vec3List* f) {
  double max_stretch_sq = 1.0;
  const int nf = static_cast<int>(faces_.size());
  int collapsed = nf;  // the lowest neo-Hookean face of zero area (nf: none)
#pragma omp parallel for schedule(static) reduction(max : max_stretch_sq) reduction(min : collapsed)
  for (int k = 0; k < nf; ++k) {
    const Face& face = faces_[k];
    const Vec3 e1 = x[face.v[1]] - x[face.v[0]];
    const Vec3 e2 = x[face.v[2]] - x[face.v[0]];
    const double a11 = e1.dot(e1), a12 = e1.dot(e2), a22 = e2.dot(e2);
    if (neo_hookean_) {  // works on the metric itself, not the Green strain
      face_energy_[k] =
          neo_hookean_face<kForces>(k, e1, e2, a11, a12, a22, max_stretch_sq, collapsed);
      continue;
    }
    Eigen::Matrix2d alpha;  // Green strain alpha_ij = (a_ij - abar_ij) / 2 [m^2]
    alpha << a11 - face.abar(0, 0), a12 - face.abar(0, 1), a12 - face.abar(1, 0),
        a22 - face.abar(1, 1);
    alpha *= 0.5;
    const Eigen::Matrix2d A = face.abar_inv * alpha;  // mixed strain A^i_j [-]
    const double tr = A.trace();
    face_energy_[k] = 0.5 * M_ * face.area * (nu_ * tr * tr + (1.0 - nu_) * (A * A).trace());
    if constexpr (kForces) {
      // S^{ij} = dU/d alpha_ij = M Abar [nu tr(A) abar^{ij} + (1 - nu) (abar^{-1} alpha
      // abar^{-1})^{ij}] (symmetric); d alpha_ij = (de_i . e_j + e_i . de_j) / 2 gives
      // dU/de_i = S^{ij} e_j, and e_i = x_i - x_0.
      const Eigen::Matrix2d S =
          M_ * face.area * (nu_ * tr * face.abar_inv + (1.0 - nu_) * A * face.abar_inv);
      const Vec3 g1 = S(0, 0) * e1 + S(0, 1) * e2;
      const Vec3 g2 = S(1, 0) * e1 + S(1, 1) * e2;
      face_force_[3 * k] = g1 + g2;
      face_force_[3 * k + 1] = -g1;
      face_force_[3 * k + 2] = -g2;
      // Largest eigenvalue of abar^{-1} a = squared largest principal stretch.
      const double t = 0.5 * (face.abar_inv(0, 0) * a11 + 2 * face.abar_inv(0, 1) * a12 +
                              face.abar_inv(1, 1) * a22);
      const double d = (a11 * a22 - a12 * a12) * face.abar_inv.determinant();
      const double lambda2 = t + std::sqrt(std::max(0.0, t * t - d));
      max_stretch_sq = std::max(max_stretch_sq, lambda2);
      const double load = std::max(1.0, 0.5 * (3.0 * lambda2 - 1.0)) * face_lambda_[k];
      face_load_[3 * k] = face_load_[3 * k + 1] = face_load_[3 * k + 2] = load;
    }
  }
  if (collapsed < nf) {  // the run cannot go on: say which face, and how far it went
    const Face& face = faces_[collapsed];
    const Vec3 e1 = x[face.v[1]] - x[face.v[0]], e2 = x[face.v[2]] - x[face.v[0]];
    const double ratio = e1.cross(e2).norm() / (2.0 * face.area);  // |current / rest area| [-]
    throw SimulationError("neo-Hookean shell face " + std::to_string(collapsed) + " (vertices " +
                          std::to_string(face.v[0]) + ", " + std::to_string(face.v[1]) + ", " +
                          std::to_string(face.v[2]) + ") has collapsed (area " +
                          std::to_string(ratio) +
                          " of its rest area): the law has no energy there");
  }
  if constexpr (kForces) {
    plan_.gather_add(face_force_, *f);
    max_stretch_sq_ = max_stretch_sq;
    plan_.gather_set(face_load_, vertex_load_);
    max_vertex_load_ = 0.0;
    for (double w : vertex_load_) max_vertex_load_ = std::max(max_vertex_load_, w);
  }
  return ordered_sum(face_energy_);
}

template <bool kForces>
double MembraneTerm::neo_hookean_face(int k, const Vec3& e1, const Vec3& e2, double a11, double a12,
                                      double a22, double& max_stretch_sq, int& collapsed) {
  const Face& face = faces_[k];
  const Eigen::Matrix2d& bi = face.abar_inv;
  const double mu = 0.5 * M_ * (1.0 - nu_), lambda = M_ * nu_;  // 2-D Lame moduli [N/m]
  const double det_a = a11 * a22 - a12 * a12;                   // [m^4]
  const double det_c = det_a * bi.determinant();                // det C = J^2 [-]
  const double tr_c = bi(0, 0) * a11 + 2.0 * bi(0, 1) * a12 + bi(1, 1) * a22;
  // det C = |e1 x e2|^2 / |ebar1 x ebar2|^2 >= 0: zero only for a face of zero area (a face
  // turned over keeps its area; the membrane does not see it), where ln det C has no value.
  if (!(det_c > 0.0)) {
    collapsed = std::min(collapsed, k);
    return 0.0;
  }
  const double ln_det = std::log(det_c);
  const double energy =
      face.area * (0.5 * mu * (tr_c - 2.0 - ln_det) + 0.125 * lambda * ln_det * ln_det);
  if constexpr (kForces) {
    // S^{ij} = dU/d alpha_ij = 2 dU/da_ij = Abar [mu (abar^{ij} - a^{ij}) + lambda/2 ln det C
    // a^{ij}] (d tr C / da_ij = abar^{ij}, d ln det C / da_ij = a^{ij}); dU/de_i = S^{ij} e_j.
    Eigen::Matrix2d a_inv;
    a_inv << a22, -a12, -a12, a11;
    a_inv /= det_a;
    const Eigen::Matrix2d S = face.area * (mu * (bi - a_inv) + 0.5 * lambda * ln_det * a_inv);
    const Vec3 g1 = S(0, 0) * e1 + S(0, 1) * e2;
    const Vec3 g2 = S(1, 0) * e1 + S(1, 1) * e2;
    face_force_[3 * k] = g1 + g2;
    face_force_[3 * k + 1] = -g1;
    face_force_[3 * k + 2] = -g2;
    // Principal stretches squared: the eigenvalues of C, t +- sqrt(t^2 - det C).
    const double t = 0.5 * tr_c;
    const double root = std::sqrt(std::max(0.0, t * t - det_c));
    max_stretch_sq = std::max(max_stretch_sq, t + root);
    const double min_sq = det_c / (t + root);  // the smaller eigenvalue, without cancellation
    const double s =
        std::max(1.0, (1.0 + nu_ - std::min(0.0, std::log(min_sq))) / ((1.0 + nu_) * min_sq));
    face_load_[3 * k] = face_load_[3 * k + 1] = face_load_[3 * k + 2] = s * face_lambda_[k];
  }
  return energy;
}

double MembraneTerm::accumulate(const Vec3List& x, Vec3List& f) {
  return evaluate<true>(x, &f);
}

double MembraneTerm::energy(const Vec3List& x) {
  return evaluate<false>(x, nullptr);
}

double MembraneTerm::omega_max_sq(double vertex_mass) const {
  // Neo-Hookean: the per-vertex loads carry each face's own factor (header).
  if (neo_hookean_) return max_vertex_load_ / vertex_mass;
  // Rest bound, scaled by the StVK tangent stiffness ratio at stretch lambda:
  // d^2/d lambda^2 of (lambda^2 - 1)^2 / 8 is (3 lambda^2 - 1) / 2 (1 at rest).
  const double s = std::max(1.0, 0.5 * (3.0 * max_stretch_sq_ - 1.0));
  // Per-vertex loads (see the header); never above the global s * rest_bound_.
  return std::min(s * rest_bound_, max_vertex_load_) / vertex_mass;
}

}  // namespace wirepack
