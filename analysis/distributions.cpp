// Hierarchic-disorder distributions (paper section "Hierarchic disorder"): normalised squared
// curvature and the loop detector documented in distributions.hpp.
#include "analysis/distributions.hpp"

#include <algorithm>
#include <cmath>

namespace wirepack::analysis {
namespace {

// Gaussian kernel cut-off, in standard deviations (weight e^-8 ~ 3e-4 at the cut).
constexpr double kCutSigmas = 4.0;

// Arc length s_i of node i from node 0 along the polyline (n) [m].
std::vector<double> arc_lengths(Centerline x) {
  std::vector<double> s(x.size(), 0.0);
  for (std::size_t i = 1; i < x.size(); ++i) s[i] = s[i - 1] + (x[i] - x[i - 1]).norm();
  return s;
}

// Indices of the local maxima of g over the interior nodes 1..n-2 (g[0], g[n-1] unused), each
// with two interior neighbours: above the left neighbour and above the right one after any flat
// top (a plateau counts once, at its first node).
std::vector<std::size_t> local_maxima(const std::vector<double>& g) {
  std::vector<std::size_t> peaks;
  const std::size_t last = g.size() - 2;  // last interior node
  for (std::size_t i = 2; i < last; ++i) {
    if (!(g[i] > g[i - 1])) continue;
    std::size_t j = i;
    while (j + 1 < last && g[j + 1] == g[i]) ++j;
    if (g[j + 1] < g[i]) peaks.push_back(i);
    i = j;
  }
  return peaks;
}

// Topographic prominence of the maximum at i over g[lo..hi]: the peak height minus the higher of
// the minima on the way to the first strictly higher value on either side (or to the end).
double prominence(const std::vector<double>& g, std::size_t i, std::size_t lo, std::size_t hi) {
  double left = g[i];
  for (std::size_t j = i; j > lo;) {
    --j;
    if (g[j] > g[i]) break;
    left = std::min(left, g[j]);
  }
  double right = g[i];
  for (std::size_t j = i + 1; j <= hi; ++j) {
    if (g[j] > g[i]) break;
    right = std::min(right, g[j]);
  }
  return g[i] - std::max(left, right);
}

// Arc position of the vertex of the parabola through (s, g) at i - 1, i, i + 1, clamped to that
// span; s_i when the points are collinear.
double parabola_vertex(const std::vector<double>& s, const std::vector<double>& g, std::size_t i) {
  const double s0 = s[i - 1], s1 = s[i], s2 = s[i + 1];
  const double g0 = g[i - 1], g1 = g[i], g2 = g[i + 1];
  // Newton form g(t) = g0 + d01 (t - s0) + a (t - s0)(t - s1) with divided differences.
  const double d01 = (g1 - g0) / (s1 - s0);
  const double d12 = (g2 - g1) / (s2 - s1);
  const double a = (d12 - d01) / (s2 - s0);  // curvature coefficient of the parabola
  if (!(a < 0)) return s1;
  // g'(t) = d01 + a (2 t - s0 - s1) = 0.
  const double t = 0.5 * (s0 + s1) - d01 / (2 * a);
  return std::clamp(t, s0, s2);
}

}  // namespace

std::vector<double> normalized_squared_curvature(Centerline x) {
  if (x.size() < 3) return {};
  const std::vector<double> kappa = curvatures(x);
  const std::vector<double> ell = voronoi_lengths(x);
  double num = 0, den = 0;
  for (std::size_t i = 1; i + 1 < x.size(); ++i) {
    num += ell[i] * kappa[i] * kappa[i];
    den += ell[i];
  }
  if (!(num > 0) || !(den > 0)) return {};
  const double mean = num / den;
  std::vector<double> out;
  out.reserve(x.size() - 2);
  for (std::size_t i = 1; i + 1 < x.size(); ++i) out.push_back(kappa[i] * kappa[i] / mean);
  return out;
}

std::vector<Vec3> coarse_grained_centerline(Centerline x, double sigma) {
  const std::size_t n = x.size();
  if (n < 3 || !(sigma > 0)) return {x.begin(), x.end()};
  const std::vector<double> s = arc_lengths(x);
  const double cut = kCutSigmas * sigma;
  // Extended chain: point reflections of nodes 1..n-1 about node 0 (before) and of nodes
  // n-2..0 about node n-1 (after), as far as the kernel reaches.
  std::vector<Vec3> xe;
  std::vector<double> se;
  for (std::size_t k = n - 1; k >= 1; --k) {
    if (s[k] > cut + s[1]) continue;  // keep one beyond the cut for the Voronoi weight
    xe.push_back(2 * x[0] - x[k]);
    se.push_back(-s[k]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    xe.push_back(x[i]);
    se.push_back(s[i]);
  }
  for (std::size_t k = n - 1; k-- > 0;) {
    if (s[n - 1] - s[k] > cut + (s[n - 1] - s[n - 2])) break;
    xe.push_back(2 * x[n - 1] - x[k]);
    se.push_back(2 * s[n - 1] - s[k]);
  }
  // Voronoi weights of the extended chain (half the adjacent spacings).
  const std::size_t m = xe.size();
  std::vector<double> w(m, 0.0);
  for (std::size_t j = 0; j + 1 < m; ++j) {
    const double half = 0.5 * (se[j + 1] - se[j]);
    w[j] += half;
    w[j + 1] += half;
  }
  // Gaussian-weighted mean position; a sliding window [lo, hi] over the sorted se.
  std::vector<Vec3> out(n);
  const double inv2s2 = 1 / (2 * sigma * sigma);
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double si = s[i];
    while (lo < m && se[lo] < si - cut) ++lo;
    while (hi < m && se[hi] <= si + cut) ++hi;
    Vec3 acc = Vec3::Zero();
    double wsum = 0;
    for (std::size_t j = lo; j < hi; ++j) {
      const double ds = se[j] - si;
      const double wj = w[j] * std::exp(-ds * ds * inv2s2);
      // Relative to x_i: no loss of precision far from the origin.
      acc += wj * (xe[j] - x[i]);
      wsum += wj;
    }
    out[i] = wsum > 0 ? Vec3(x[i] + acc / wsum) : x[i];
  }
  return out;
}

std::vector<double> loop_lengths(Centerline x, double wire_radius,
                                 const LoopDetectorOptions& options) {
  const std::size_t n = x.size();
  if (n < 5 || !(wire_radius > 0) || !std::isfinite(wire_radius)) return {};
  const std::vector<double> s = arc_lengths(x);
  // 1. Coarse-grain the centerline over sigma = smoothing_r * r.
  const std::vector<Vec3> xs = coarse_grained_centerline(x, options.smoothing_r * wire_radius);
  // 2. Squared curvature of the coarse-grained curve at the interior nodes (g[0], g[n-1] = 0).
  const std::vector<double> kappa = curvatures(xs);
  const std::vector<double> ell = voronoi_lengths(xs);
  std::vector<double> g(n, 0.0);
  double num = 0, den = 0;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    g[i] = kappa[i] * kappa[i];
    num += ell[i] * g[i];
    den += ell[i];
  }
  if (!(num > 0) || !(den > 0)) return {};
  const double mean = num / den;
  // 3. Maxima with enough prominence (over the interior nodes 1..n-2).
  std::vector<double> positions;
  for (std::size_t i : local_maxima(g)) {
    const double prom = prominence(g, i, 1, n - 2);
    if (prom >= options.min_prominence * std::max(g[i], mean)) {
      // 4. Sub-element position of the maximum, on the original arc length.
      positions.push_back(parabola_vertex(s, g, i));
    }
  }
  std::vector<double> Lambda;
  for (std::size_t k = 1; k < positions.size(); ++k) {
    Lambda.push_back(positions[k] - positions[k - 1]);
  }
  return Lambda;
}

std::vector<double> loop_lengths(Centerline x, double wire_radius) {
  return loop_lengths(x, wire_radius, LoopDetectorOptions{});
}

std::vector<LoopSensitivityRow> loop_sensitivity(const std::vector<std::vector<Vec3>>& wires,
                                                 double wire_radius,
                                                 std::span<const double> smoothings,
                                                 std::span<const double> prominences) {
  std::vector<LoopSensitivityRow> rows;
  for (const double smoothing : smoothings) {
    for (const double prominence : prominences) {
      LoopSensitivityRow row;
      row.smoothing_r = smoothing;
      row.min_prominence = prominence;
      std::vector<double> over_r;
      for (const auto& x : wires)
        for (const double Lambda : loop_lengths(x, wire_radius, {smoothing, prominence}))
          over_r.push_back(Lambda / wire_radius);
      row.loops = over_r.size();
      row.fit = fit_lognormal(over_r);
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace wirepack::analysis
