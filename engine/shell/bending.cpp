#include "engine/shell/bending.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace wirepack {

namespace {

// Cyclic successor and predecessor of a local vertex index: s_i uses q_{i+1}, q_{i+2}.
int next(int i) {
  return i == 2 ? 0 : i + 1;
}
int prev(int i) {
  return i == 0 ? 2 : i - 1;
}

// |N_f0 + N_f1| = 2 cos(theta / 2) for a fold theta is kept away from 0 (two faces folded flat
// onto each other, where the edge normal is undefined and its derivative ~ 1 / |m| diverges),
// so forces stay finite; such a state is far outside anything a step accepts.
constexpr double kMinNormalSum = 1e-8;

}  // namespace

BendingTerm::BendingTerm(const ShellMesh& m, const ShellMaterial& material)
    : faces_(m.faces),
      face_edges_(m.face_edges),
      edge_faces_(m.edge_faces),
      B_(material.B()),
      nu_(material.nu) {
  const int nf = m.num_faces();
  const int ne = static_cast<int>(m.edges.size());
  if (static_cast<int>(m.face_edges.size()) != nf || static_cast<int>(m.edge_faces.size()) != ne)
    throw std::invalid_argument("BendingTerm: mesh topology not built (build_topology)");
  face_normal_.resize(nf);
  face_dblarea_.resize(nf);
  grad_face_normal_.resize(nf);
  edge_normal_.resize(ne);
  edge_mnorm_.assign(ne, 1.0);
  grad_edge_normal_.resize(ne);

  // Rest metric abar_ij = e_i . e_j, area, smallest altitude.
  rest_area_.resize(nf);
  abar_inv_.resize(nf);
  h_min_ = std::numeric_limits<double>::infinity();
  for (int f = 0; f < nf; ++f) {
    const auto& v = m.faces[f];
    const Vec3 e1 = m.rest[v[1]] - m.rest[v[0]];
    const Vec3 e2 = m.rest[v[2]] - m.rest[v[0]];
    const double dblarea = e1.cross(e2).norm();
    if (!(dblarea > 0.0)) throw std::invalid_argument("BendingTerm: degenerate rest face");
    Eigen::Matrix2d abar;
    abar << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
    abar_inv_[f] = abar.inverse();
    rest_area_[f] = 0.5 * dblarea;
    const double lmax = std::max({e1.norm(), e2.norm(), (e2 - e1).norm()});
    h_min_ = std::min(h_min_, dblarea / lmax);
  }

  // Edge kinds: a boundary edge between two clamped vertices keeps its rest normal.
  edge_kind_.resize(ne);
  edge_fixed_normal_.assign(ne, Vec3::Zero());
  for (int e = 0; e < ne; ++e) {
    const auto& ef = m.edge_faces[e];
    if (ef[0] >= 0 && ef[1] >= 0) {
      edge_kind_[e] = EdgeKind::kInterior;
      continue;
    }
    const int f = ef[0] >= 0 ? ef[0] : ef[1];
    const bool clamped = !m.clamped.empty() && m.clamped[m.edges[e][0]] && m.clamped[m.edges[e][1]];
    edge_kind_[e] = clamped ? EdgeKind::kClamped : EdgeKind::kFree;
    if (clamped) {
      const auto& v = m.faces[f];
      edge_fixed_normal_[e] =
          (m.rest[v[1]] - m.rest[v[0]]).cross(m.rest[v[2]] - m.rest[v[0]]).normalized();
    }
  }

  // Assembly plans (targets: -1 where the serial loops add nothing).
  const int nv = static_cast<int>(m.rest.size());
  std::vector<int> fold_t(9 * nf), edge_t(3 * nf), face_t(3 * nf), normal_t(2 * ne, -1);
  for (int f = 0; f < nf; ++f) {
    const auto& v = m.faces[f];
    for (int i = 0; i < 3; ++i) {
      const EdgeKind kind = edge_kind_[m.face_edges[f][i]];
      const bool on = kind != EdgeKind::kFree;
      fold_t[9 * f + 3 * i] = on ? v[i] : -1;
      fold_t[9 * f + 3 * i + 1] = on ? v[next(i)] : -1;
      fold_t[9 * f + 3 * i + 2] = on ? v[prev(i)] : -1;
      edge_t[3 * f + i] = kind == EdgeKind::kInterior ? m.face_edges[f][i] : -1;
      face_t[3 * f + i] = v[i];
    }
  }
  for (int e = 0; e < ne; ++e) {
    if (edge_kind_[e] != EdgeKind::kInterior) continue;
    normal_t[2 * e] = m.edge_faces[e][0];
    normal_t[2 * e + 1] = m.edge_faces[e][1];
  }
  fold_plan_ = ScatterPlan(fold_t, 9, nv);
  edge_plan_ = ScatterPlan(edge_t, 3, ne);
  normal_plan_ = ScatterPlan(normal_t, 2, nf);
  face_plan_ = ScatterPlan(face_t, 3, nv);
  fold_force_.assign(9 * nf, Vec3::Zero());
  edge_term_.assign(3 * nf, Vec3::Zero());
  normal_term_.assign(2 * ne, Vec3::Zero());
  face_force_.assign(3 * nf, Vec3::Zero());
  face_U_.assign(nf, 0.0);

  // Rest second fundamental form with the same discretisation.
  compute_normals(m.rest);
  bbar_.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d s = edge_folds(m.rest, f);
    bbar_[f] << s[0] + s[1], s[0], s[0], s[0] + s[2];
  }
  lambda_rest_ = rest_power_iteration(m.rest);
}

double BendingTerm::rest_power_iteration(const Vec3List& rest) {
  // Power iteration on the rest stiffness K (all vertices, clamped ones included: by
  // interlacing an upper bound of the free vertices' K), K v by central differences of the
  // forces, -(f(x + h v) - f(x - h v)) / (2 h) with |v| = 1 and h = 1e-6 of the mesh's scale.
  // The Rayleigh quotient v.Kv rises towards lambda_max; after k iterations the eigenvalues
  // 3 % below it keep a weight ~0.97^(2k) (k = 120: 1e-3).
  const int nv = static_cast<int>(rest.size());
  if (nv == 0 || faces_.empty()) return 0.0;
  double scale = 0.0;
  for (const Vec3& p : rest) scale = std::max(scale, p.cwiseAbs().maxCoeff());
  const double h = 1e-6 * std::max(scale, h_min_);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec3List v(nv);
  for (Vec3& p : v) p = Vec3(u(rng), u(rng), u(rng));
  const auto normalise = [](Vec3List& w) {
    double n2 = 0.0;
    for (const Vec3& p : w) n2 += p.squaredNorm();
    const double n = std::sqrt(n2);
    if (n > 0.0) {
      for (Vec3& p : w) p /= n;
    }
    return n;
  };
  normalise(v);
  Vec3List xp(nv), xm(nv), fp(nv), fm(nv), Kv(nv);
  double lambda = 0.0;
  for (int it = 0; it < 120; ++it) {
    for (int i = 0; i < nv; ++i) {
      xp[i] = rest[i] + h * v[i];
      xm[i] = rest[i] - h * v[i];
    }
    std::fill(fp.begin(), fp.end(), Vec3::Zero());
    std::fill(fm.begin(), fm.end(), Vec3::Zero());
    accumulate(xp, fp);
    accumulate(xm, fm);
    double vKv = 0.0;
    for (int i = 0; i < nv; ++i) {
      Kv[i] = -(fp[i] - fm[i]) / (2.0 * h);
      vKv += v[i].dot(Kv[i]);
    }
    lambda = std::max(lambda, vKv);
    if (!(normalise(Kv) > 0.0)) break;
    v.swap(Kv);
  }
  return lambda;
}

void BendingTerm::compute_normals(const Vec3List& x) {
  const int nf = static_cast<int>(faces_.size());
#pragma omp parallel for schedule(static)
  for (int f = 0; f < nf; ++f) {
    const auto& v = faces_[f];
    const Vec3 c = (x[v[1]] - x[v[0]]).cross(x[v[2]] - x[v[0]]);
    face_dblarea_[f] = c.norm();
    face_normal_[f] = c / face_dblarea_[f];
  }
  const int ne = static_cast<int>(edge_faces_.size());
#pragma omp parallel for schedule(static)
  for (int e = 0; e < ne; ++e) {
    const auto& ef = edge_faces_[e];
    switch (edge_kind_[e]) {
      case EdgeKind::kInterior: {
        const Vec3 mv = face_normal_[ef[0]] + face_normal_[ef[1]];
        edge_mnorm_[e] = std::max(mv.norm(), kMinNormalSum);
        edge_normal_[e] = mv / edge_mnorm_[e];
        break;
      }
      case EdgeKind::kFree:
        edge_normal_[e] = face_normal_[ef[0] >= 0 ? ef[0] : ef[1]];
        break;
      case EdgeKind::kClamped:
        edge_normal_[e] = edge_fixed_normal_[e];
        break;
    }
  }
}

Eigen::Vector3d BendingTerm::edge_folds(const Vec3List& x, int f) const {
  const auto& v = faces_[f];
  const auto& fe = face_edges_[f];
  Eigen::Vector3d s;
  for (int i = 0; i < 3; ++i) {
    // s_i = n_i . (q_{i+1} + q_{i+2} - 2 q_i); identically 0 on a free edge (n_i = N_f).
    if (edge_kind_[fe[i]] == EdgeKind::kFree) {
      s[i] = 0.0;
      continue;
    }
    const Vec3 w = x[v[next(i)]] + x[v[prev(i)]] - 2.0 * x[v[i]];
    s[i] = edge_normal_[fe[i]].dot(w);
  }
  return s;
}

double BendingTerm::face_energy(int f, const Eigen::Vector3d& s, Eigen::Vector3d* dU_ds) const {
  Eigen::Matrix2d D;  // b - bbar [m]
  D << s[0] + s[1], s[0], s[0], s[0] + s[2];
  D -= bbar_[f];
  const Eigen::Matrix2d& Ai = abar_inv_[f];
  const Eigen::Matrix2d S = Ai * D;  // shape-operator change, mixed components [1/m]
  const double trS = S.trace();
  const double trS2 = (S * S).trace();
  const double k = B_ * rest_area_[f];  // [N m^3]
  if (dU_ds) {
    // P_jk = dU/dD_jk = B Abar [nu tr(S) abar^{jk} + (1 - nu) (abar^{-1} D abar^{-1})^{jk}];
    // b_00 = s0 + s1, b_01 = b_10 = s0, b_11 = s0 + s2.
    const Eigen::Matrix2d P = k * (nu_ * trS * Ai + (1.0 - nu_) * S * Ai);
    (*dU_ds)[0] = P(0, 0) + P(1, 1) + P(0, 1) + P(1, 0);
    (*dU_ds)[1] = P(0, 0);
    (*dU_ds)[2] = P(1, 1);
  }
  return 0.5 * k * (nu_ * trS * trS + (1.0 - nu_) * trS2);
}

double BendingTerm::accumulate(const Vec3List& x, Vec3List& out) {
  const int nf = static_cast<int>(faces_.size());
  const int ne = static_cast<int>(edge_faces_.size());
  compute_normals(x);
  // -0.0 in the slots a serial loop skips: x + (-0.0) is x for every x.
  const Vec3 none = Vec3::Constant(-0.0);

  // 1. Per face: U_f(s) and the explicit dependence of s_i = n_i . w_i on the positions
  //    (w_i = q_{i+1} + q_{i+2} - 2 q_i); dU/dn_e collects sigma_i w_i from both faces.
#pragma omp parallel for schedule(static)
  for (int f = 0; f < nf; ++f) {
    const auto& v = faces_[f];
    const auto& fe = face_edges_[f];
    const Eigen::Vector3d s = edge_folds(x, f);
    Eigen::Vector3d sigma;  // dU/ds_i [N]
    face_U_[f] = face_energy(f, s, &sigma);
    for (int i = 0; i < 3; ++i) {
      const int e = fe[i];
      Vec3* slot = &fold_force_[9 * f + 3 * i];
      if (edge_kind_[e] == EdgeKind::kFree) {
        slot[0] = slot[1] = slot[2] = none;
        edge_term_[3 * f + i] = none;
        continue;
      }
      const Vec3 gn = sigma[i] * edge_normal_[e];  // dU/dw_i
      slot[0] = 2.0 * gn;
      slot[1] = -gn;
      slot[2] = -gn;
      edge_term_[3 * f + i] = sigma[i] * (x[v[next(i)]] + x[v[prev(i)]] - 2.0 * x[v[i]]);
    }
  }
  fold_plan_.gather_add(fold_force_, out);
  edge_plan_.gather_set(edge_term_, grad_edge_normal_);

  // 2. Edge normal n = m / |m|, m = N_f0 + N_f1: dU/dm = (I - n n^T) dU/dn / |m|, and dU/dm
  //    goes to both face normals.
#pragma omp parallel for schedule(static)
  for (int e = 0; e < ne; ++e) {
    if (edge_kind_[e] != EdgeKind::kInterior) continue;
    const Vec3& n = edge_normal_[e];
    const Vec3& g = grad_edge_normal_[e];
    const Vec3 gm = (g - n * n.dot(g)) / edge_mnorm_[e];
    normal_term_[2 * e] = gm;
    normal_term_[2 * e + 1] = gm;
  }
  normal_plan_.gather_set(normal_term_, grad_face_normal_);

  // 3. Face normal N = c / |c|, c = e1 x e2 (e1 = q1 - q0, e2 = q2 - q0):
  //    dU/dc = (I - N N^T) dU/dN / |c|;  dU/dq1 = e2 x dU/dc, dU/dq2 = dU/dc x e1,
  //    dU/dq0 = -(dU/dq1 + dU/dq2).
#pragma omp parallel for schedule(static)
  for (int f = 0; f < nf; ++f) {
    const Vec3& g = grad_face_normal_[f];
    Vec3* slot = &face_force_[3 * f];
    if (g.isZero(0.0)) {
      slot[0] = slot[1] = slot[2] = none;
      continue;
    }
    const auto& v = faces_[f];
    const Vec3& N = face_normal_[f];
    const Vec3 gc = (g - N * N.dot(g)) / face_dblarea_[f];
    const Vec3 e1 = x[v[1]] - x[v[0]];
    const Vec3 e2 = x[v[2]] - x[v[0]];
    const Vec3 g1 = e2.cross(gc);
    const Vec3 g2 = gc.cross(e1);
    slot[0] = g1 + g2;
    slot[1] = -g1;
    slot[2] = -g2;
  }
  face_plan_.gather_add(face_force_, out);
  return ordered_sum(face_U_);
}

double BendingTerm::energy(const Vec3List& x) {
  compute_normals(x);
  double U = 0.0;
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
    U += face_energy(f, edge_folds(x, f), nullptr);
  return U;
}

std::vector<double> BendingTerm::face_energies(const Vec3List& x) {
  compute_normals(x);
  std::vector<double> U(faces_.size());
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
    U[f] = face_energy(f, edge_folds(x, f), nullptr);
  return U;
}

std::vector<Eigen::Matrix2d> BendingTerm::second_fundamental_forms(const Vec3List& x) {
  compute_normals(x);
  std::vector<Eigen::Matrix2d> b(faces_.size());
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
    const Eigen::Vector3d s = edge_folds(x, f);
    b[f] << s[0] + s[1], s[0], s[0], s[0] + s[2];
  }
  return b;
}

double BendingTerm::omega_max_sq(double vertex_mass) const {
  // Highest mode: a transverse zig-zag of amplitude w over the smallest altitude h. The folds
  // are s ~ w, the curvature |S| ~ w / h^2 and the energy ~ B h^2 (w / h^2)^2 per face, so the
  // stiffness per vertex is k ~ B / h^2 and omega^2 = C_omega B / (m h^2) (i.e. B / (rho t h^4)
  // per unit areal mass). The largest eigenvalue of the rest stiffness measured in units of
  // B / h_min^2 (test_bending.cpp: BendingOmega; nu = 0 .. 0.45 alike): ~32 on a uniform
  // one-diagonal square grid (the stiffest seen: 29.9 at 8 x 8, 31.4 at 16 x 16), 14.5 on the
  // geodesic spheres, 13 on the checkerboard square, 4 - 8 on jittered meshes (h_min of a thin
  // triangle is pessimistic). C_omega = 40 leaves a margin of 1.25 on the worst case; it is a
  // rest-state estimate (geometric stiffening under large stretch is not included).
  // Engine V: the measured rest eigenvalue of this mesh with a margin, never above the
  // closed-form estimate (the spheres of the scenes: 2.8x below it, i.e. 1.7x in the step).
  const double measured =
      lambda_rest_ > 0.0 ? kOmegaMargin * lambda_rest_ : closed_form_stiffness();
  return std::min(measured, closed_form_stiffness()) / vertex_mass;
}

}  // namespace wirepack
