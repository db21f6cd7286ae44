#pragma once
// Statistics for the analysis of sweeps (docs/design.md §5.8, paper "Quantitative comparison"
// and "Hierarchic disorder"): mean and standard error over seeds, power-law fits y ~ l^p with
// their standard errors (OLS and a bootstrap over seeds), lognormal fits and normalised
// histograms. Pure functions; NaN marks "not available".
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace wirepack::analysis {

inline constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

struct MeanSem {
  double mean = NaN;  // sample mean
  double sd = NaN;    // sample standard deviation (n - 1 in the denominator)
  double sem = NaN;   // standard error of the mean, sd / sqrt(n)
  std::size_t n = 0;  // number of non-NaN entries used
};
// Mean, standard deviation and standard error of the non-NaN entries of xs (an infinite entry is
// kept and propagates). n = 1 gives the mean with sd, sem NaN; n = 0 gives all NaN.
MeanSem mean_sem(std::span<const double> xs);

// Distinct outcomes among the non-NaN entries of xs (e.g. one statistic over the seeds of a grid
// point): sorted, a new outcome starts wherever two neighbours differ by more than gap. Ten seeds
// that follow one trajectory give 1, ten independent ones up to 10; 0 for no entries.
std::size_t distinct_outcomes(std::span<const double> xs, double gap = 0.01);

struct PowerLawFit {
  double exponent = NaN;              // p in y = exp(log_prefactor) l^p
  double stderr_ = NaN;               // standard error of p (OLS, n - 2 dof)
  double log_prefactor = NaN;         // ln a
  double log_prefactor_stderr = NaN;  // standard error of ln a
  double l_min = NaN, l_max = NaN;    // smallest and largest l actually used
  std::size_t n_points = 0;           // points used
  bool ok = false;                    // n_points >= 3 and at least two distinct l
};
// Ordinary least squares of ln y on ln l over the points with l_min <= l <= l_max, l > 0, y > 0,
// both finite (l and y of equal length; a longer one is cut to the shorter). Standard errors from
// the residual variance with n - 2 degrees of freedom.
PowerLawFit fit_power_law(std::span<const double> l, std::span<const double> y, double l_min,
                          double l_max);

// Seed bootstrap of the power-law exponent: series s is (l[s], y[s]), one per seed. Draws
// `resamples` sets of as many seeds as given, with replacement (std::mt19937_64 seeded with
// rng_seed: reproducible), pools the drawn seeds' points and fits; returns the standard deviation
// (n - 1) of the fitted exponents over the successful fits. NaN with fewer than 2 seeds or fewer
// than 2 successful fits.
double bootstrap_exponent_stderr(const std::vector<std::vector<double>>& l,
                                 const std::vector<std::vector<double>>& y, double l_min,
                                 double l_max, int resamples = 1000,
                                 std::uint64_t rng_seed = 20150101);

struct LognormalFit {
  double mu = NaN, sigma = NaN;                // ln x ~ N(mu, sigma^2), sigma the MLE (1/n)
  double mu_stderr = NaN, sigma_stderr = NaN;  // sigma / sqrt(n), sigma / sqrt(2 n)
  std::size_t n = 0;                           // samples used (finite, > 0)
  bool ok = false;                             // n >= 2
};
// Maximum-likelihood lognormal fit over the finite samples x > 0 (others skipped); standard errors
// from the Fisher information.
LognormalFit fit_lognormal(std::span<const double> samples);

// Bins i = 0..bins-1 cover [lo_i, hi_i) of equal width on [lo, hi). Only finite xs in [lo, hi)
// are counted; density_i = count_i / (n_in * (hi_i - lo_i)) with n_in the number counted, so
// sum density_i (hi_i - lo_i) = 1 (all densities 0 when n_in = 0). bins < 1 or !(lo < hi), or
// non-finite lo, hi: empty histogram.
struct Histogram {
  std::vector<double> lo, hi;      // bin edges (bins)
  std::vector<double> density;     // probability density (bins) [1/unit of x]
  std::vector<std::size_t> count;  // samples per bin (bins)
};
Histogram histogram(std::span<const double> xs, double lo, double hi, int bins);

// The paper's "best-fitting density" (Fig. 6): the normal density N(mu, sigma^2) fitted to a
// histogram by least squares, sum_i (density_i - p_i(mu, sigma))^2 over the bins, p_i the normal
// density averaged over bin i, (Phi((hi_i - mu) / sigma) - Phi((lo_i - mu) / sigma)) /
// (hi_i - lo_i), so that an exact histogram of a normal gives its parameters back whatever the
// bin width. Levenberg-Marquardt from the histogram's own mean and standard deviation. Unlike the
// maximum-likelihood fit it weights every bin alike, so the tails count as much as the peak; the
// two differ where the data are not normal. ok = false with fewer than 3 bins holding samples or
// when the iteration does not converge.
struct HistogramNormalFit {
  double mu = NaN, sigma = NaN;  // [unit of x]
  double rms = NaN;              // root mean square residual over the bins [1/unit of x]
  int iterations = 0;
  bool ok = false;
};
HistogramNormalFit fit_normal_to_histogram(const Histogram& h);

}  // namespace wirepack::analysis
