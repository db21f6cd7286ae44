#pragma once
// The fitting window of a scaling exponent, chosen by a stated rule instead of by eye
// (docs/design.md §5.8). A packing's series follow a power law only after a transient: the coil
// has to form (R_t, R_x, R_y, N), and the crumpled phase starts at a bifurcation, a jump in
// U_b_hat and K (paper, "Quantitative comparison"). The rule:
//  1. the series is resampled at log-spaced points: the geometric mean of l and of y in bins of
//     1 / points_per_decade decades (raw rows are evenly spaced in l, so a plain fit would weigh
//     the last decade ~10x the one before);
//  2. the local exponent at each resampled point is the OLS slope of ln y on ln l over the
//     resampled points within +-local_span / 2 decades of it (at least 3 points), with the
//     standard error the data's noise gives it (the noise per row estimated robustly from the
//     median second difference of the resampled series, so that a kink does not widen its own
//     tolerance);
//  3. the window starts at the first resampled point l_s from which the series is one power law:
//     every local exponent whose neighbourhood lies inside [l_s, l_end] is within
//     tolerance + z * (its standard error) of the exponent fitted over [l_s, l_end], and the
//     window spans at least min_decades. A transient, a crossover or a jump puts local exponents
//     outside that band, so the window starts after it.
// The exponent is then the least-squares fit over the resampled points in the window, each
// weighted by its rows (a bin of c rows has 1/c of a row's variance).
#include <span>
#include <vector>

#include "analysis/stats.hpp"

namespace wirepack::analysis {

struct ScalingWindowOptions {
  double points_per_decade = 20;  // resampling density [1/decade]
  double local_span = 0.3;        // width of a local exponent's neighbourhood [decades]
  double tolerance = 0.1;         // allowed deviation of a local exponent, beyond its noise [-]
  double z = 3;                   // standard errors of a local exponent allowed on top [-]
  double min_decades = 0.3;       // shortest acceptable window (factor 2 in l) [decades]
};

struct ScalingWindow {
  double l_start = NaN;  // first l of the window (a resampled point's geometric-mean l) [-]
  double l_end = NaN;    // last l of the window [-]
  PowerLawFit fit;       // weighted fit over the resampled points in [l_start, l_end]
  std::size_t resampled_points = 0;  // resampled points of the whole series up to l_end
  bool ok = false;                   // a window of at least min_decades was found
};

// Log-spaced resampling (step 1): bins [l0 10^(k/ppd), l0 10^((k+1)/ppd)) from the smallest
// usable l0 (points in any order) (l > 0, y > 0, both finite, l <= l_end); returns the bins'
// geometric-mean l and y (empty bins skipped), in increasing l, and, if counts is given, the rows
// in each bin.
void log_resample(std::span<const double> l, std::span<const double> y, double l_end,
                  double points_per_decade, std::vector<double>& l_out, std::vector<double>& y_out,
                  std::vector<int>* counts = nullptr);

// Least squares of ln y on ln l over the log-spaced resampling (step 1) of the points with
// l_min <= l <= l_max, weighted by rows per bin; standard errors from the weighted residuals.
PowerLawFit fit_power_law_log_spaced(std::span<const double> l, std::span<const double> y,
                                     double l_min, double l_max, double points_per_decade = 20);

// The window of the rule above for the series (l, y) (l increasing) cut at l_end.
ScalingWindow find_scaling_window(std::span<const double> l, std::span<const double> y,
                                  double l_end, const ScalingWindowOptions& options = {});

}  // namespace wirepack::analysis
