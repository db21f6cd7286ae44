#pragma once
// Distributions of the paper's section "Hierarchic disorder" (docs/design.md §5.6): the normalised
// local squared curvature kappa^2 / <kappa^2> and the loop lengths Lambda between neighbouring
// maxima of kappa^2 along the wire; both are fitted by lognormals (stats.hpp: fit_lognormal).
#include <span>
#include <vector>

#include "analysis/observables.hpp"
#include "analysis/stats.hpp"

namespace wirepack::analysis {

// kappa_i^2 / <kappa^2> at the interior nodes i = 1..n-2 (n - 2 values, in order; [-]), with
// kappa_i the discrete curvature of observables.hpp and <kappa^2> = sum ell_i kappa_i^2 /
// sum ell_i over the interior nodes (Voronoi lengths ell_i). The end nodes (kappa = 0 by
// definition) are dropped; interior nodes of a straight stretch give 0 (ln -> -inf: fit_lognormal
// skips them). Empty when n < 3 or <kappa^2> = 0.
std::vector<double> normalized_squared_curvature(Centerline x);

// Loop detector. Raw discrete kappa_i^2 has a local maximum every few nodes wherever the nodes
// carry element-scale noise (node displacements delta give curvature noise ~ delta / ell^2,
// growing as the element length ell shrinks), so raw maxima neither mean loops nor converge.
// The detector therefore:
//  1. coarse-grains the centerline: each node is replaced by the Gaussian-weighted (over arc
//     length, standard deviation sigma = smoothing_r * r, cut at 4 sigma, weights = kernel *
//     Voronoi length) mean of the nodes' positions; at the two ends the wire is continued by
//     point reflection (x_{-k} = 2 x_0 - x_k), which keeps straight ends straight. Smoothing
//     positions (linear) rather than kappa^2 (quadratic) removes node noise instead of
//     rectifying it into a bias: the residual curvature noise scales as
//     delta sqrt(ell / sigma^5) and vanishes as ell -> 0, while the smoothed curve converges to
//     the Gaussian-smoothed continuous wire;
//  2. takes kappa^2 of the coarse-grained curve at the interior nodes, and its local maxima;
//  3. keeps a maximum only if its topographic prominence (height above the higher of the two
//     lowest points that separate it from higher ground or the wire's ends) is at least
//     min_prominence * max(its height, <kappa^2>), <.> the length-weighted mean of the smoothed
//     kappa^2: the curvature must drop by a fraction of the peak between two loops, and wiggles on
//     a nearly straight stretch do not count;
//  4. places each kept maximum at the vertex of the parabola through it and its two neighbours
//     (sub-element resolution) and returns the arc lengths of the original centerline between
//     neighbouring kept maxima (the partial segments before the first and after the last maximum
//     are not loops).
// Default sigma = 2 r (one wire diameter): two curvature peaks narrower than sigma stay resolved
// (prominence >= 0.25) down to a separation of ~2.8 sigma = 5.6 r, below the paper's loop lengths
// (ln(Lambda/r) ~ N(3.0, 0.48^2): 5.6 r is 2.7 standard deviations below the mean), while
// node noise of 0.05 r at ell = r leaves curvature noise ~0.004/r, far below loop curvatures.
struct LoopDetectorOptions {
  double smoothing_r = 2.0;      // sigma of the Gaussian coarse-graining, in wire radii [-]
  double min_prominence = 0.25;  // relative prominence a maximum needs to delimit a loop [-]
};
// Loop lengths Lambda [m] (one per pair of neighbouring kept maxima, in order along the wire);
// wire_radius r [m] > 0. Empty when fewer than two maxima are kept or r is not positive.
std::vector<double> loop_lengths(Centerline x, double wire_radius,
                                 const LoopDetectorOptions& options);
std::vector<double> loop_lengths(Centerline x, double wire_radius);

// How the loop parameters move with the detector's two settings (paper Fig. 6b; issue of the
// reproduction): for every (smoothing_r, min_prominence) pair, the loops of all `wires` pooled
// (each a centerline [m], e.g. one per seed) and their maximum-likelihood lognormal fit of
// Lambda / r. Rows in the order smoothings x prominences (prominence varying fastest).
struct LoopSensitivityRow {
  double smoothing_r = 0;     // [-]
  double min_prominence = 0;  // [-]
  std::size_t loops = 0;      // loops found, all wires
  LognormalFit fit;           // ln(Lambda / r) ~ N(mu, sigma^2)
};
std::vector<LoopSensitivityRow> loop_sensitivity(const std::vector<std::vector<Vec3>>& wires,
                                                 double wire_radius,
                                                 std::span<const double> smoothings,
                                                 std::span<const double> prominences);

// Step 1 above, exposed for inspection and tests: the coarse-grained centerline (n) [m].
std::vector<Vec3> coarse_grained_centerline(Centerline x, double sigma);

}  // namespace wirepack::analysis
