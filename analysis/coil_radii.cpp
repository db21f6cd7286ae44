// Coil cross-section radii R_t, R_x, R_y (paper Fig. 1f, docs/design.md §5.4): extreme-value
// estimates of the bundle's outline, combined by a least-squares fit of the half-ellipse's
// support function.
//
// Coordinates: axis m = turning_axis over chords of ~1/8 turn (the turns' common binormal; unlike
// the coil normal it stays the coil axis for bundles taller than wide), through the
// turning-weighted centroid. Node i maps to the cross-section point (y_i, a_i): y = distance from
// the axis, a = axial coordinate; a turn of the coil is one point of that plane.
//
// Convention: the radii describe the material envelope M, the outline of the wire's surface that
// the paper's superposed half-ellipses follow: M = {y >= R_t, ((y - R_t) / R_y)^2 +
// ((a - a0) / R_x)^2 <= 1}. A wire of radius r lies inside M iff its centerline lies in the
// eroded set M_r = M (-) disk(r), so the outline of a bundle that fills M is the opening
// M_r (+) disk(r), whose support function h(u) = max_{q} u.q is closed form (model_support).
//
// Estimator:
// 1. Robust extremes: supports of the centerline points, h_k = max_i u_k.(y_i, a_i) + r, with the
//    top half mean turn of wire length trimmed, after a running mean of (y, a) over ~1/8 turn and
//    over coil-like nodes only (curvature radius ~ y), so that node noise, a stray turn or the
//    straight entering wire do not set the outline.
// 2. R_t = inner face: -h(-y), the innermost wire surface.
// 3. (R_x, R_y, a0): Levenberg-Marquardt on the support of M_r (+) disk(r) against h_k over K
//    directions from the axial face -a over the outer rim +y to the face +a. The support of a
//    set dilated by disk(r) is the centerline support + r exactly, so no shape bias from r.
// Accuracy on synthetic hexagonally packed bundles (tests/analysis/test_coil_radii.cpp): < 0.5 %
// at R_y = 32 r with 0.05 r node noise. A lattice that does not touch M everywhere has its own
// envelope inside M by up to one lattice gap (~r); the radii are those of the wire, not of M.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <numeric>

#include <Eigen/Dense>

#include "analysis/observables.hpp"

namespace wirepack::analysis {
namespace {

using std::numbers::pi;

constexpr std::size_t kMinNodes = 8;  // fewer nodes cannot make a turn worth fitting
constexpr int kDirections = 49;       // support directions over the outer half, 3.75 deg apart
constexpr int kMaxIterations = 100;   // Levenberg-Marquardt iterations (converges in ~10)
constexpr double kMinTurns = 1.0;     // |net winding about the axis| needed to call it a coil
constexpr double kTrimTurns = 0.5;    // length trimmed from each support, in mean turn lengths
constexpr double kChordsPerTurn = 8;  // turning-axis chords per mean turn (45 deg turning)
constexpr double kMaxRhoOverY = 2;    // coil-like node: curvature radius <= 2 x axis distance

// Shape parameters of the material half-ellipse [m].
struct Shape {
  double T, X, Y, a0;  // R_t, R_x, R_y, axial centre
};

// Trimmed maximum of a length-weighted point set: with values sorted in decreasing order, the
// first value at which the accumulated weight reaches `trim` (values v, weights w: n; idx is
// scratch). O(n) selection of the top values, then a sort of those only.
double trimmed_max(const std::vector<double>& v, const std::vector<double>& w, double total_w,
                   double trim, std::vector<std::size_t>& idx) {
  const std::size_t n = v.size();
  // Guess how many of the largest values hold `trim` of the weight; grow if it was too few.
  std::size_t m = std::min(n, static_cast<std::size_t>(2.0 * trim / total_w * n) + 16);
  for (;;) {
    idx.resize(n);
    std::iota(idx.begin(), idx.end(), std::size_t{0});
    auto larger = [&](std::size_t i, std::size_t j) { return v[i] > v[j]; };
    std::nth_element(idx.begin(), idx.begin() + (m - 1), idx.end(), larger);  // O(n)
    std::sort(idx.begin(), idx.begin() + m, larger);
    double acc = 0;
    for (std::size_t k = 0; k < m; ++k) {
      acc += w[idx[k]];
      if (acc >= trim) return v[idx[k]];
    }
    if (m == n) return v[idx[n - 1]];
    m = std::min(n, 4 * m);
  }
}

// Corner of the eroded set M_r: the inner parallel curve of the ellipse (at distance r) meets the
// line y = T + r at a = a0 +- returned value. Ellipse points (T + Y cos t, a0 + X sin t) with
// outward normal nu(t) = (X cos t, Y sin t) / N(t); solve (e - r nu)_y = T + r by bisection on
// t in [0, pi/2] (monotone when the ellipse's curvature radius exceeds r).
double eroded_corner(const Shape& s, double r) {
  auto N = [&](double t) { return std::hypot(s.X * std::cos(t), s.Y * std::sin(t)); };
  auto f = [&](double t) { return s.Y * std::cos(t) - r * s.X * std::cos(t) / N(t) - r; };
  if (f(0) <= 0) return 0.0;  // M_r degenerate (R_y <= 2 r): a single column of turns
  double lo = 0, hi = pi / 2;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) > 0 ? lo : hi) = mid;
  }
  const double t = 0.5 * (lo + hi);
  return std::max(0.0, s.X * std::sin(t) - r * s.Y * std::sin(t) / N(t));
}

// Support function of the opening M_r (+) disk(r) in direction u = (u_y, u_a) [m]: where the
// ellipse's support point, moved inwards by r, satisfies y >= T + r it is the ellipse's own
// support; otherwise the maximum of u.q over M_r is at a corner (T + r, a0 +- a_c), plus r.
double model_support(const Shape& s, double a_c, double r, double uy, double ua) {
  const double q = std::hypot(s.Y * uy, s.X * ua);
  if (q > 0) {
    const double ey = s.T + s.Y * s.Y * uy / q;  // ellipse support point, y coordinate
    if (ey - r * uy >= s.T + r) return s.T * uy + s.a0 * ua + q;
  }
  return uy * (s.T + r) + s.a0 * ua + a_c * std::abs(ua) + r;
}

}  // namespace

CoilRadii coil_radii(Centerline x, double wire_radius) {
  const double r = wire_radius;
  const std::size_t n = x.size();
  if (n < kMinNodes || !(r >= 0)) return {};
  const std::vector<double> ell = voronoi_lengths(x);
  double L = 0;
  Vec3 c = Vec3::Zero();  // length-weighted centroid, first guess of a point on the axis
  for (std::size_t i = 0; i < n; ++i) {
    L += ell[i];
    c += ell[i] * x[i];
  }
  if (!(L > 0)) return {};
  c /= L;

  // Cylindrical coordinates (y, a) about the axis m through c; net winding about m [turns].
  std::vector<double> y(n), a(n);
  auto cylindrical = [&](const Vec3& m) {
    const Vec3 e1 = m.unitOrthogonal(), e2 = m.cross(e1);
    double winding = 0, theta_prev = 0;  // sum of wrapped azimuth steps
    for (std::size_t i = 0; i < n; ++i) {
      const Vec3 d = x[i] - c;
      a[i] = m.dot(d);
      const double d1 = e1.dot(d), d2 = e2.dot(d);
      y[i] = std::hypot(d1, d2);
      const double theta = std::atan2(d2, d1);
      if (i > 0) winding += std::remainder(theta - theta_prev, 2 * pi);
      theta_prev = theta;
    }
    return std::abs(winding) / (2 * pi);
  };
  // Axis and centre in two passes. Pass 1 (node-scale turning axis, centroid) only counts the
  // turns. Pass 2 uses chords of ~1/8 turn (kChordsPerTurn), which average out node noise
  // (sigma / chord instead of sigma / edge), and centres on the turning-weighted centroid
  // sum w_i x_i / sum w_i, w_i = sin(chord turning at i): each turn of a coil weighs the same and
  // is uniform in azimuth, so the centre is on the axis, while straight stretches (the entering
  // wire, jumps between layers) weigh nothing.
  double turns = cylindrical(turning_axis(x));
  if (!(turns >= kMinTurns)) return {};
  const auto stride = static_cast<std::size_t>(std::max(1.0, n / (kChordsPerTurn * turns)));
  {
    Vec3 cw = Vec3::Zero();
    double sw = 0;
    for (std::size_t i = stride; i + stride < n; ++i) {
      const Vec3 d0 = x[i] - x[i - stride], d1 = x[i + stride] - x[i];
      const double l0 = d0.norm(), l1 = d1.norm();
      if (!(l0 > 0 && l1 > 0)) continue;
      const double w = d0.cross(d1).norm() / (l0 * l1);
      cw += w * x[i];
      sw += w;
    }
    if (sw > 0) c = cw / sw;
  }
  turns = cylindrical(turning_axis(x, stride));
  if (!(turns >= kMinTurns)) return {};
  const double trim = kTrimTurns * L / turns;

  // Coil-like nodes: radius of curvature over the chords, rho = chord / (2 sin(theta / 2)), at
  // most kMaxRhoOverY times the distance y from the axis (a turn about the axis has rho ~ y).
  // Straight or off-axis stretches (the entering wire, a loop sticking out) and the first and
  // last `stride` nodes are left out of the outline.
  std::vector<char> coil(n, 0);
  for (std::size_t i = stride; i + stride < n; ++i) {
    const Vec3 d0 = x[i] - x[i - stride], d1 = x[i + stride] - x[i];
    const double l0 = d0.norm(), l1 = d1.norm();
    if (!(l0 > 0 && l1 > 0)) continue;
    const double sin_half = std::sqrt(std::max(0.0, 0.5 * (1 - d0.dot(d1) / (l0 * l1))));
    coil[i] = 0.5 * (l0 + l1) <= 2 * kMaxRhoOverY * y[i] * sin_half;
  }

  // Length-weighted running mean of (y, a) over the same ~1/8 turn: a coil's turn is one point
  // of the cross-section, so this only averages node noise (and blends neighbouring turns where
  // the wire moves between them, which stays inside the convex cross-section). Then keep the
  // coil-like nodes: (yc, ac, wc) (m).
  std::vector<double> yc, ac, wc;
  {
    std::vector<double> Sw(n + 1, 0.0), Sy(n + 1, 0.0), Sa(n + 1, 0.0);  // prefix sums
    for (std::size_t i = 0; i < n; ++i) {
      Sw[i + 1] = Sw[i] + ell[i];
      Sy[i + 1] = Sy[i] + ell[i] * y[i];
      Sa[i + 1] = Sa[i] + ell[i] * a[i];
    }
    const std::size_t half = stride / 2;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t lo = i > half ? i - half : 0, hi = std::min(n, i + half + 1);
      const double w = Sw[hi] - Sw[lo];
      if (!coil[i] || !(w > 0)) continue;
      yc.push_back((Sy[hi] - Sy[lo]) / w);
      ac.push_back((Sa[hi] - Sa[lo]) / w);
      wc.push_back(ell[i]);
    }
  }
  const std::size_t nc = yc.size();
  const double Lc = std::accumulate(wc.begin(), wc.end(), 0.0);
  if (!(Lc > trim)) return {};

  // Inner face: R_t = trimmed min_i y_i - r (support in direction -y).
  std::vector<double> v(nc);
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < nc; ++i) v[i] = -yc[i];
  const double R_t = -trimmed_max(v, wc, Lc, trim, idx) - r;

  // Outer rim: trimmed support of the centerline points plus r along u_k = (cos psi_k,
  // sin psi_k), psi_k from -pi/2 (axial face -a) through 0 (outer rim +y) to pi/2 (face +a).
  std::array<double, kDirections> uy{}, ua{}, h{};
  for (int k = 0; k < kDirections; ++k) {
    const double psi = pi * (double(k) / (kDirections - 1) - 0.5);
    uy[k] = std::cos(psi);
    ua[k] = std::sin(psi);
    for (std::size_t i = 0; i < nc; ++i) v[i] = uy[k] * yc[i] + ua[k] * ac[i];
    h[k] = trimmed_max(v, wc, Lc, trim, idx) + r;
  }

  // Start from the extents: axial faces (k = 0, K - 1) and outer rim (k = (K - 1) / 2).
  constexpr int kRim = (kDirections - 1) / 2;
  Eigen::Vector3d p(0.5 * (h[0] + h[kDirections - 1]), h[kRim] - R_t,
                    0.5 * (h[kDirections - 1] - h[0]));  // (R_x, R_y, a0)
  const double scale = std::max({std::abs(R_t), p[0], p[1], r});
  auto residuals = [&](const Eigen::Vector3d& q) {
    const Shape s{R_t, q[0], q[1], q[2]};
    const double a_c = eroded_corner(s, r);
    Eigen::Matrix<double, kDirections, 1> res;
    for (int k = 0; k < kDirections; ++k) res[k] = model_support(s, a_c, r, uy[k], ua[k]) - h[k];
    return res;
  };

  // Levenberg-Marquardt on (R_x, R_y, a0), central-difference Jacobian [m].
  auto res = residuals(p);
  double cost = res.squaredNorm(), lambda = 1e-3;
  const double fd = 1e-7 * scale;
  bool converged = false;
  for (int it = 0; it < kMaxIterations && !converged; ++it) {
    Eigen::Matrix<double, kDirections, 3> J;
    for (int j = 0; j < 3; ++j) {
      Eigen::Vector3d qp = p, qm = p;
      qp[j] += fd;
      qm[j] -= fd;
      J.col(j) = (residuals(qp) - residuals(qm)) / (2 * fd);
    }
    const Eigen::Matrix3d JtJ = J.transpose() * J;
    const Eigen::Vector3d g = J.transpose() * res;
    bool improved = false;
    while (!improved && lambda < 1e12) {
      Eigen::Matrix3d A = JtJ;
      A.diagonal() += lambda * JtJ.diagonal().cwiseMax(1e-12 * scale * scale);
      const Eigen::Vector3d step = -A.ldlt().solve(g);
      const Eigen::Vector3d trial = p + step;
      if (trial[0] > 0 && trial[1] > 0) {
        const auto tres = residuals(trial);
        if (tres.squaredNorm() < cost) {
          converged = step.norm() < 1e-12 * scale;
          p = trial;
          res = tres;
          cost = res.squaredNorm();
          lambda = std::max(lambda / 10, 1e-12);
          improved = true;
        }
      }
      if (!improved) lambda *= 10;
    }
    if (!improved) converged = true;  // no descent step left: at the minimum
  }

  CoilRadii out{R_t, p[0], p[1], false};
  out.ok = std::isfinite(out.R_t) && std::isfinite(out.R_x) && std::isfinite(out.R_y) &&
           out.R_t >= 0 && out.R_x > 0 && out.R_y > 0;
  return out;
}

}  // namespace wirepack::analysis
