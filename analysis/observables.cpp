// Observables of a wire centerline (docs/design.md §5): Voronoi lengths, discrete curvature, total
// curvature K, coil normal, turning axis, order parameter S, D, and the scaled bending energy.
// The coil cross-section fit (R_t, R_x, R_y) is in coil_radii.cpp.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "analysis/observables.hpp"
#include "core/section.hpp"

namespace wirepack::analysis {
namespace {

// tan(phi / 2) cap for an exact reversal t1 = -t0 (phi = pi, a zero-length hairpin): the true
// value is infinite; a finite cap keeps K and kappa finite for such degenerate input.
constexpr double kTanHalfMax = 1e8;

// A turning sine below this (n . (t0 x t1) or |t0 x t1| of unit vectors) is round-off of a
// straight wire (a few ulp of 1), not a sense of rotation: it counts as exact zero.
constexpr double kZeroTurn = 1e-12;

// The sense of a turning sine n . (t0 x t1): +1, -1, or 0 within round-off of straight.
int turning_sign(double kn) {
  return kn > kZeroTurn ? 1 : kn < -kZeroTurn ? -1 : 0;
}

// Unit tangent of edge e = (x_e, x_{e+1}); false for a zero-length edge.
bool edge_tangent(Centerline x, std::size_t e, Vec3& t) {
  const Vec3 d = x[e + 1] - x[e];
  const double len = d.norm();
  if (!(len > 0)) return false;
  t = d / len;
  return true;
}

// tan(phi / 2) of the angle phi between unit tangents t0, t1, in full relative precision:
// sin(phi) / (1 + cos(phi)) for phi <= pi/2, the equal (1 - cos(phi)) / sin(phi) beyond
// (avoids 0/0 cancellation as phi -> pi).
double tan_half_turn(const Vec3& t0, const Vec3& t1) {
  const double s = t0.cross(t1).norm();
  const double c = t0.dot(t1);
  if (c >= 0) return s / (1 + c);
  if (s * kTanHalfMax <= 1 - c) return kTanHalfMax;
  return (1 - c) / s;
}

// Deterministic sign of an eigenvector: its component of largest magnitude is made positive
// (the lowest index wins a tie). The sign can only flip where two components are nearly equal in
// magnitude; D = 1 - |S| never depends on it.
Vec3 canonical_sign(const Vec3& v) {
  Eigen::Index k = 0;
  v.cwiseAbs().maxCoeff(&k);
  return v[k] < 0 ? Vec3(-v) : v;
}

}  // namespace

// Voronoi lengths ell_i = (|e_{i-1}| + |e_i|) / 2 with missing edges counted as 0 (n) [m].
std::vector<double> voronoi_lengths(Centerline x) {
  std::vector<double> ell(x.size(), 0.0);
  for (std::size_t e = 0; e + 1 < x.size(); ++e) {
    const double half = 0.5 * (x[e + 1] - x[e]).norm();
    ell[e] += half;
    ell[e + 1] += half;
  }
  return ell;
}

// docs/design.md §5.1: kappa_i = 2 tan(phi_i / 2) / ell_i at interior nodes, 0 at the ends and
// wherever an adjacent edge has zero length (n) [1/m].
std::vector<double> curvatures(Centerline x) {
  std::vector<double> kappa(x.size(), 0.0);
  const std::vector<double> ell = voronoi_lengths(x);
  Vec3 t0, t1;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    if (!edge_tangent(x, i - 1, t0) || !edge_tangent(x, i, t1)) continue;
    kappa[i] = 2 * tan_half_turn(t0, t1) / ell[i];
  }
  return kappa;
}

// K = sum_i kappa_i ell_i = sum_i 2 tan(phi_i / 2) [-].
double total_curvature(Centerline x) {
  double K = 0;
  Vec3 t0, t1;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    if (!edge_tangent(x, i - 1, t0) || !edge_tangent(x, i, t1)) continue;
    K += 2 * tan_half_turn(t0, t1);
  }
  return K;
}

// The axis of docs/design.md §5.3: smallest-eigenvalue eigenvector of
// G = sum ell_i (x_i - xbar)(x_i - xbar)^T, xbar the length-weighted centroid. +z when the wire
// has no length (n < 2 or all nodes equal).
Vec3 coil_normal(Centerline x) {
  const std::vector<double> ell = voronoi_lengths(x);
  double L = 0;
  Vec3 xbar = Vec3::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    L += ell[i];
    xbar += ell[i] * x[i];
  }
  if (!(L > 0)) return Vec3::UnitZ();
  xbar /= L;
  Eigen::Matrix3d G = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < x.size(); ++i) {
    const Vec3 d = x[i] - xbar;
    G += ell[i] * d * d.transpose();
  }
  // Eigenvalues come in increasing order: column 0 is the coil normal.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(G / L);
  return canonical_sign(eig.eigenvectors().col(0).normalized());
}

// Turning axis: largest-eigenvalue eigenvector of B = sum_i |b_i| bhat_i bhat_i^T over nodes
// k <= i < n - k, b_i = u_{i-k,i} x u_{i,i+k} with u_{j,l} the unit chord from x_j to x_l
// (|b_i| = sin of the turning over the chords): the common binormal of a coil's turns. +z when the
// wire never turns.
Vec3 turning_axis(Centerline x, std::size_t stride) {
  const std::size_t k = std::max<std::size_t>(stride, 1);
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
  double w = 0;
  for (std::size_t i = k; i + k < x.size(); ++i) {
    const Vec3 d0 = x[i] - x[i - k], d1 = x[i + k] - x[i];
    const double l0 = d0.norm(), l1 = d1.norm();
    if (!(l0 > 0 && l1 > 0)) continue;
    const Vec3 b = (d0 / l0).cross(d1 / l1);
    const double s = b.norm();
    if (!(s > kZeroTurn)) continue;
    B += b * b.transpose() / s;
    w += s;
  }
  if (!(w > 0)) return Vec3::UnitZ();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(B / w);
  return canonical_sign(eig.eigenvectors().col(2).normalized());
}

// Paper "Order-disorder transition" with the axis of docs/design.md §5.3, n = coil_normal:
// S = (1/L) sum_i ell_i sgn(n . (t_{i-1} x t_i)) over interior nodes, L = sum of those ell_i.
// A node with (numerically) zero turning, or a zero-length adjacent edge, contributes 0 to the sum
// but its ell_i to L. Fewer than 3 nodes, or no length, give S = 0, D = 1 (no turning at all).
Order order_parameter(Centerline x) {
  Order o;
  if (x.size() < 3) return o;
  o.n = coil_normal(x);
  const std::vector<double> ell = voronoi_lengths(x);
  double L = 0, sum = 0;
  Vec3 t0, t1;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    L += ell[i];
    if (!edge_tangent(x, i - 1, t0) || !edge_tangent(x, i, t1)) continue;
    sum += turning_sign(o.n.dot(t0.cross(t1))) * ell[i];
  }
  o.S = L > 0 ? sum / L : 0.0;
  o.D = 1 - std::abs(o.S);
  return o;
}

std::vector<double> signed_turning(Centerline x, const Vec3& n) {
  std::vector<double> turn(x.size(), 0.0);
  Vec3 t0, t1;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    if (!edge_tangent(x, i - 1, t0) || !edge_tangent(x, i, t1)) continue;
    const double c = t0.dot(t1);
    if (!(c > -1)) continue;                      // a complete fold-back: curvature undefined
    turn[i] = 2 * n.dot(t0.cross(t1)) / (1 + c);  // kappa_n,i ell_i [-]
  }
  return turn;
}

Order curvature_weighted_order(Centerline x) {
  Order o;
  if (x.size() < 3) return o;
  o.n = coil_normal(x);
  double signed_sum = 0, abs_sum = 0;
  for (const double turn : signed_turning(x, o.n)) {
    signed_sum += turn;
    abs_sum += std::abs(turn);
  }
  o.S = abs_sum > 0 ? signed_sum / abs_sum : 0.0;
  o.D = 1 - std::abs(o.S);
  return o;
}

SenseBlocks sense_blocks(std::span<const double> ell, std::span<const int> sign, double min_block) {
  SenseBlocks out;
  const std::size_t n = std::min(ell.size(), sign.size());
  // Maximal runs of one sign: lengths b [m] and signs, alternating once merged.
  std::vector<double> b;
  std::vector<int> sg;
  for (std::size_t i = 0; i < n; ++i) {
    out.length += ell[i];
    const int s = sign[i] > 0 ? 1 : sign[i] < 0 ? -1 : 0;
    if (b.empty()) {
      b.push_back(ell[i]);
      sg.push_back(s);
    } else if (s == 0 || s == sg.back() || sg.back() == 0) {
      b.back() += ell[i];
      if (sg.back() == 0) sg.back() = s;  // leading non-turning nodes join the first block
    } else {
      b.push_back(ell[i]);
      sg.push_back(s);
    }
  }
  // Merge the shortest block below min_block with its neighbours until none is left.
  while (b.size() > 1) {
    std::size_t k = 0;
    for (std::size_t j = 1; j < b.size(); ++j)
      if (b[j] < b[k]) k = j;
    if (!(b[k] < min_block)) break;
    const std::size_t lo = k > 0 ? k - 1 : k, hi = k + 1 < b.size() ? k + 1 : k;
    double merged = 0;
    for (std::size_t j = lo; j <= hi; ++j) merged += b[j];
    const int s = k > 0 ? sg[k - 1] : sg[k + 1];  // the neighbours' sense
    b.erase(b.begin() + static_cast<std::ptrdiff_t>(lo) + 1,
            b.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
    sg.erase(sg.begin() + static_cast<std::ptrdiff_t>(lo) + 1,
             sg.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
    b[lo] = merged;
    sg[lo] = s;
  }
  if (b.empty() || !(out.length > 0)) return out;
  out.reversals = b.size() - 1;
  double sum2 = 0;
  for (const double len : b) sum2 += len * len;
  out.order_length = sum2 / out.length;
  return out;
}

SenseBlocks sense_blocks(Centerline x, const Vec3& n, double min_block) {
  if (x.size() < 3) return {};
  const std::vector<double> all = voronoi_lengths(x);
  std::vector<double> ell;
  std::vector<int> sign;
  Vec3 t0, t1;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    ell.push_back(all[i]);
    int s = 0;
    if (edge_tangent(x, i - 1, t0) && edge_tangent(x, i, t1)) s = turning_sign(n.dot(t0.cross(t1)));
    sign.push_back(s);
  }
  return sense_blocks(ell, sign, min_block);
}

std::size_t entry_chord_start(Centerline x, double r, double slack, std::size_t exclude,
                              double hole_zone,
                              const std::function<double(const Vec3&)>& distance_to_shell) {
  const std::size_t n = x.size();
  if (n == 0) return 0;
  const Vec3& hole = x[n - 1];
  const double wire2 = (2 * r + slack) * (2 * r + slack);
  for (std::size_t i = n; i-- > 0;) {
    if ((x[i] - hole).norm() < hole_zone) continue;
    bool touches = distance_to_shell(x[i]) < r + slack;
    for (std::size_t j = 0; j < n && !touches; ++j) {
      const std::size_t gap = i > j ? i - j : j - i;
      touches = gap >= exclude && (x[i] - x[j]).squaredNorm() < wire2;
    }
    if (touches) return i + 1;
  }
  return 0;
}

// Paper: U_b_hat = U_b r^2 / (R E_w I), I = pi r^4 / 4 [-]; U_b [J], r, R [m], E_w [Pa].
double bending_energy_hat(double U_b, double r, double R, double E_w) {
  return U_b * r * r / (R * E_w * section_second_moment(r));
}

}  // namespace wirepack::analysis
