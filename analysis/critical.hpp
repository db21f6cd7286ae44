#pragma once
// Critical points of the coiling-to-crumpling transition (issue 16): fits of D(x) along one
// swept parameter x to the per-seed D values, a continuous-transition model against a smooth
// crossover (model choice by AIC), x_c and the exponent with percentile-bootstrap confidence
// intervals over the seeds, and the refinement proposal (where new grid values shrink the
// interval of x_c). Pure functions on in-memory data; NaN marks "not available".
//
// The fit coordinate u is x, or log10(x) with log_x (e.g. eps). Models in u:
//   continuous: D = D0 + A max(0, s (u - u_c))^b, s = +1 (D departs from D0 above u_c) or -1
//               (below); b in [0.1, 5]
//   smooth:     D = D_lo + (D_hi - D_lo) / (1 + exp(-(u - u_c) / w)), w in [span/1000, span]
//   nulls:      D = c (constant) and D = c0 + c1 u (line)
// Least squares on every finite per-seed value; AIC = N ln(SSE / N) + 2 (k + 1), k the model's
// parameters. A transition is claimed only when the better of the two transition models beats
// the better null by min_aic_gain, and x_c lies inside the sampled range with a grid value on
// either side (continuous: >= 1 on the flat side, >= 2 on the other).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "analysis/stats.hpp"

namespace wirepack::analysis {

// One grid value of the swept parameter with the D of each seed (NaN: that run gave no D).
struct CriticalSample {
  double x = NaN;
  std::vector<double> D;
};

struct CriticalOptions {
  bool log_x = false;       // fit in u = log10(x) (every x must be > 0)
  int resamples = 1000;     // bootstrap resamples of the seeds; < 2: no interval
  double level = 0.95;      // confidence level of the percentile intervals
  double min_aic_gain = 6;  // AIC margin of a transition model over the nulls (e^3 ~ 20:1)
  std::uint64_t rng_seed = 20150101;
};

// Continuous-transition fit in u.
struct ContinuousFit {
  double u_c = NaN, b = NaN, D0 = NaN, A = NaN;
  int side = 1;  // s: +1 D departs from D0 above u_c, -1 below
  double sse = NaN;
};
// Logistic crossover in u.
struct SmoothFit {
  double u_c = NaN, w = NaN, D_lo = NaN, D_hi = NaN;
  double sse = NaN;
};

double continuous_model(double u, const ContinuousFit& f);
double smooth_model(double u, const SmoothFit& f);

struct CriticalResult {
  // "ok" (x_c with its interval), "no interval" (x_c but fewer than 2 seeds anywhere, or
  // resamples < 2), "no transition in range", "too few points", "no data".
  std::string status;
  std::string note;   // why, in words; what to do
  std::string model;  // "continuous" | "smooth" | "" (no transition)
  int side = 0;       // continuous: +1 / -1 as ContinuousFit::side; 0 otherwise
  double x_c = NaN, x_c_lo = NaN, x_c_hi = NaN;  // in x (not u)
  double b = NaN, b_lo = NaN, b_hi = NaN;        // continuous only
  double width = NaN;                            // smooth only: w in u
  double D0 = NaN;         // continuous: the flat side; smooth: the asymptote below x_c
  double D_plateau = NaN;  // continuous: the model at the far end of the range; smooth: the
                           // asymptote above x_c
  double aic_continuous = NaN, aic_smooth = NaN, aic_constant = NaN, aic_line = NaN;
  std::size_t points = 0;           // grid values with at least one finite D
  std::size_t values = 0;           // finite D values (all seeds)
  std::size_t resamples = 0;        // bootstrap resamples that gave a fit
  double x_min = NaN, x_max = NaN;  // range of the grid values used
  ContinuousFit continuous;         // best fits on the full data (u coordinate)
  SmoothFit smooth;
};

// Fits D(x). Non-finite D are skipped (a point with none is left out), so are points with a
// non-finite x (or x <= 0 with log_x). Deterministic for a given rng_seed.
CriticalResult fit_critical(const std::vector<CriticalSample>& data, const CriticalOptions& opt);

// Where to add `count` new grid values (in x, sorted, distinct from the data and each other):
// with an interval of x_c (status "ok"), each new value bisects the largest gap between the
// grid values inside the interval and its ends (the data around the kink are what pin x_c);
// otherwise each bisects the gap between neighbours with the largest |difference of mean D|
// (a bisected gap passes half its difference to each half). Values are rounded to 4 significant
// digits of the range (of x itself with log_x). Fewer than two usable points: none.
std::vector<double> propose_refinement(const std::vector<CriticalSample>& data,
                                       const CriticalResult& fit, int count,
                                       const CriticalOptions& opt);

// Seeds per grid value around x_c below which refinement adds seeds before values. Measured on
// synthetic continuous transitions (noise 0.1, 11 values): with 2 / 3 / 5 / 10 seeds a value
// the fit claims a transition in 37 / 52 / 85 / 99 % of data sets and its 95 % bootstrap
// interval covers the truth in 65 / 81 / 86 / 87 % of them; beyond that, at equal runs, new
// values narrow the interval as much as new seeds (docs/measurements.md, "Refinement").
inline constexpr std::size_t kMinSeedsNearCritical = 5;

// Seeds to add: at the grid values `x` (the data's own values, sorted), `seeds` more at each.
struct SeedProposal {
  std::vector<double> x;
  std::size_t seeds = 0;  // to bring the least-seeded of them to kMinSeedsNearCritical (>= 1
                          // with force)
};

// Where the interval of x_c wants seeds before values: with an interval ("ok"), the grid values
// inside it and the nearest one outside on either side (the two around it when none is inside),
// when the least-seeded of them has fewer than kMinSeedsNearCritical finite D; otherwise none
// (propose_refinement's values are then the better spend). With `force`, those values whatever
// their seeds, and without an interval the two values of the gap with the largest |difference
// of mean D| and the next value beyond each.
SeedProposal propose_seeds(const std::vector<CriticalSample>& data, const CriticalResult& fit,
                           const CriticalOptions& opt, bool force = false);

}  // namespace wirepack::analysis
