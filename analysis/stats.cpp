// Statistics for sweep analysis: mean/SEM, power-law OLS with its standard errors, the seed
// bootstrap of the exponent, the lognormal MLE and normalised histograms (see stats.hpp).
#include "analysis/stats.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace wirepack::analysis {

MeanSem mean_sem(std::span<const double> xs) {
  MeanSem r;
  // Two passes: the mean, then the sum of squared deviations (no cancellation of large means).
  double sum = 0;
  for (double x : xs) {
    if (std::isnan(x)) continue;
    sum += x;
    ++r.n;
  }
  if (r.n == 0) return r;
  r.mean = sum / static_cast<double>(r.n);
  if (r.n == 1) return r;
  double ss = 0;
  for (double x : xs) {
    if (!std::isnan(x)) ss += (x - r.mean) * (x - r.mean);
  }
  r.sd = std::sqrt(ss / static_cast<double>(r.n - 1));
  r.sem = r.sd / std::sqrt(static_cast<double>(r.n));
  return r;
}

namespace {

// Accepted point of a power-law fit: in the window, finite, and both coordinates positive.
bool usable(double l, double y, double l_min, double l_max) {
  return std::isfinite(l) && std::isfinite(y) && l > 0 && y > 0 && l >= l_min && l <= l_max;
}

// OLS of v = ln y on u = ln l for pre-logged points (u, v).
PowerLawFit ols_loglog(std::span<const double> u, std::span<const double> v) {
  PowerLawFit f;
  const std::size_t n = u.size();
  f.n_points = n;
  if (n == 0) return f;
  double u_bar = 0, v_bar = 0;
  for (std::size_t i = 0; i < n; ++i) {
    u_bar += u[i];
    v_bar += v[i];
  }
  u_bar /= static_cast<double>(n);
  v_bar /= static_cast<double>(n);
  double suu = 0, suv = 0;
  double u_lo = u[0], u_hi = u[0];
  for (std::size_t i = 0; i < n; ++i) {
    suu += (u[i] - u_bar) * (u[i] - u_bar);
    suv += (u[i] - u_bar) * (v[i] - v_bar);
    u_lo = std::min(u_lo, u[i]);
    u_hi = std::max(u_hi, u[i]);
  }
  f.l_min = std::exp(u_lo);
  f.l_max = std::exp(u_hi);
  if (n < 3 || !(suu > 0) || !(u_hi > u_lo)) return f;
  f.exponent = suv / suu;
  f.log_prefactor = v_bar - f.exponent * u_bar;
  // Residual variance with n - 2 degrees of freedom; Var(p) = s^2 / Suu,
  // Var(ln a) = s^2 (1/n + u_bar^2 / Suu).
  double ssr = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double e = v[i] - f.log_prefactor - f.exponent * u[i];
    ssr += e * e;
  }
  const double s2 = ssr / static_cast<double>(n - 2);
  f.stderr_ = std::sqrt(s2 / suu);
  f.log_prefactor_stderr = std::sqrt(s2 * (1.0 / static_cast<double>(n) + u_bar * u_bar / suu));
  f.ok = true;
  return f;
}

}  // namespace

PowerLawFit fit_power_law(std::span<const double> l, std::span<const double> y, double l_min,
                          double l_max) {
  std::vector<double> u, v;
  const std::size_t n = std::min(l.size(), y.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable(l[i], y[i], l_min, l_max)) continue;
    u.push_back(std::log(l[i]));
    v.push_back(std::log(y[i]));
  }
  PowerLawFit f = ols_loglog(u, v);
  // Report the extremes exactly as given rather than exp(ln l).
  if (f.n_points > 0) {
    f.l_min = std::numeric_limits<double>::infinity();
    f.l_max = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      if (!usable(l[i], y[i], l_min, l_max)) continue;
      f.l_min = std::min(f.l_min, l[i]);
      f.l_max = std::max(f.l_max, l[i]);
    }
  }
  return f;
}

double bootstrap_exponent_stderr(const std::vector<std::vector<double>>& l,
                                 const std::vector<std::vector<double>>& y, double l_min,
                                 double l_max, int resamples, std::uint64_t rng_seed) {
  const std::size_t seeds = std::min(l.size(), y.size());
  if (seeds < 2 || resamples < 2) return NaN;
  // Pre-log each seed's usable points once.
  std::vector<std::vector<double>> u(seeds), v(seeds);
  for (std::size_t s = 0; s < seeds; ++s) {
    const std::size_t n = std::min(l[s].size(), y[s].size());
    for (std::size_t i = 0; i < n; ++i) {
      if (!usable(l[s][i], y[s][i], l_min, l_max)) continue;
      u[s].push_back(std::log(l[s][i]));
      v[s].push_back(std::log(y[s][i]));
    }
  }
  std::mt19937_64 rng(rng_seed);
  std::uniform_int_distribution<std::size_t> pick(0, seeds - 1);
  std::vector<double> exponents;
  std::vector<double> pu, pv;
  for (int b = 0; b < resamples; ++b) {
    pu.clear();
    pv.clear();
    for (std::size_t k = 0; k < seeds; ++k) {
      const std::size_t s = pick(rng);
      pu.insert(pu.end(), u[s].begin(), u[s].end());
      pv.insert(pv.end(), v[s].begin(), v[s].end());
    }
    const PowerLawFit f = ols_loglog(pu, pv);
    if (f.ok) exponents.push_back(f.exponent);
  }
  if (exponents.size() < 2) return NaN;
  return mean_sem(exponents).sd;
}

LognormalFit fit_lognormal(std::span<const double> samples) {
  LognormalFit f;
  std::vector<double> z;
  for (double x : samples) {
    if (std::isfinite(x) && x > 0) z.push_back(std::log(x));
  }
  f.n = z.size();
  if (f.n < 2) return f;
  // MLE: mu the mean of ln x, sigma^2 the mean squared deviation (1/n, not 1/(n-1)).
  const double n = static_cast<double>(f.n);
  double sum = 0;
  for (double zi : z) sum += zi;
  f.mu = sum / n;
  double ss = 0;
  for (double zi : z) ss += (zi - f.mu) * (zi - f.mu);
  f.sigma = std::sqrt(ss / n);
  // Inverse Fisher information of (mu, sigma): diag(sigma^2 / n, sigma^2 / (2 n)).
  f.mu_stderr = f.sigma / std::sqrt(n);
  f.sigma_stderr = f.sigma / std::sqrt(2 * n);
  f.ok = true;
  return f;
}

Histogram histogram(std::span<const double> xs, double lo, double hi, int bins) {
  Histogram h;
  if (bins < 1 || !std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) return h;
  const auto nb = static_cast<std::size_t>(bins);
  const double width = (hi - lo) / bins;
  h.lo.resize(nb);
  h.hi.resize(nb);
  h.density.assign(nb, 0.0);
  h.count.assign(nb, 0);
  for (std::size_t i = 0; i < nb; ++i) {
    h.lo[i] = lo + width * static_cast<double>(i);
    h.hi[i] = i + 1 == nb ? hi : lo + width * static_cast<double>(i + 1);
  }
  std::size_t n_in = 0;
  for (double x : xs) {
    if (!std::isfinite(x) || x < lo || x >= hi) continue;
    auto i = static_cast<std::size_t>((x - lo) / width);
    // Round-off at a bin edge: move to the bin whose [lo_i, hi_i) holds x.
    i = std::min(i, nb - 1);
    while (i > 0 && x < h.lo[i]) --i;
    while (i + 1 < nb && x >= h.hi[i]) ++i;
    ++h.count[i];
    ++n_in;
  }
  if (n_in == 0) return h;
  for (std::size_t i = 0; i < nb; ++i) {
    h.density[i] =
        static_cast<double>(h.count[i]) / (static_cast<double>(n_in) * (h.hi[i] - h.lo[i]));
  }
  return h;
}

}  // namespace wirepack::analysis
