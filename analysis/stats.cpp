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

std::size_t distinct_outcomes(std::span<const double> xs, double gap) {
  std::vector<double> v;
  for (double x : xs)
    if (!std::isnan(x)) v.push_back(x);
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  std::size_t n = 1;
  for (std::size_t i = 1; i < v.size(); ++i)
    if (v[i] - v[i - 1] > gap) ++n;
  return n;
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

HistogramNormalFit fit_normal_to_histogram(const Histogram& h) {
  HistogramNormalFit f;
  const std::size_t nb = h.density.size();
  // Start: the histogram's mean and standard deviation (bin centres, weights density * width).
  double w = 0, m1 = 0, m2 = 0;
  int filled = 0;
  for (std::size_t i = 0; i < nb; ++i) {
    const double c = 0.5 * (h.lo[i] + h.hi[i]), mass = h.density[i] * (h.hi[i] - h.lo[i]);
    if (!(mass >= 0) || !std::isfinite(c)) return f;
    w += mass;
    m1 += mass * c;
    filled += mass > 0 ? 1 : 0;
  }
  if (filled < 3 || !(w > 0)) return f;
  m1 /= w;
  for (std::size_t i = 0; i < nb; ++i) {
    const double c = 0.5 * (h.lo[i] + h.hi[i]);
    m2 += h.density[i] * (h.hi[i] - h.lo[i]) * (c - m1) * (c - m1);
  }
  double mu = m1, sigma = std::sqrt(m2 / w);
  if (!(sigma > 0)) return f;
  // Bin-averaged normal density and its derivatives in (mu, sigma) (analytic, via the density).
  const auto model = [&](double m, double s, std::vector<double>& p, std::vector<double>& dm,
                         std::vector<double>& ds) {
    p.resize(nb);
    dm.resize(nb);
    ds.resize(nb);
    for (std::size_t i = 0; i < nb; ++i) {
      const double a = (h.lo[i] - m) / s, b = (h.hi[i] - m) / s, width = h.hi[i] - h.lo[i];
      const double Phi_a = 0.5 * std::erfc(-a / std::sqrt(2.0));
      const double Phi_b = 0.5 * std::erfc(-b / std::sqrt(2.0));
      const double phi_a = std::exp(-0.5 * a * a) / std::sqrt(2 * M_PI);
      const double phi_b = std::exp(-0.5 * b * b) / std::sqrt(2 * M_PI);
      p[i] = (Phi_b - Phi_a) / width;
      dm[i] = -(phi_b - phi_a) / (s * width);          // d/dmu of Phi((x - mu) / s) = -phi / s
      ds[i] = -(b * phi_b - a * phi_a) / (s * width);  // d/dsigma: -phi (x - mu) / s^2
    }
  };
  const auto rss_of = [&](const std::vector<double>& p) {
    double r = 0;
    for (std::size_t i = 0; i < nb; ++i) r += (h.density[i] - p[i]) * (h.density[i] - p[i]);
    return r;
  };
  std::vector<double> p, dm, ds, p_try, dm_try, ds_try;
  model(mu, sigma, p, dm, ds);
  double rss = rss_of(p), lambda = 1e-3;
  for (f.iterations = 0; f.iterations < 200; ++f.iterations) {
    // Normal equations J^T J d = J^T r of the two parameters, damped (Marquardt: diagonal).
    double a11 = 0, a12 = 0, a22 = 0, g1 = 0, g2 = 0;
    for (std::size_t i = 0; i < nb; ++i) {
      const double r = h.density[i] - p[i];
      a11 += dm[i] * dm[i];
      a12 += dm[i] * ds[i];
      a22 += ds[i] * ds[i];
      g1 += dm[i] * r;
      g2 += ds[i] * r;
    }
    bool improved = false;
    for (int tries = 0; tries < 30 && !improved; ++tries) {
      const double b11 = a11 * (1 + lambda), b22 = a22 * (1 + lambda);
      const double det = b11 * b22 - a12 * a12;
      if (!(det > 0)) {
        lambda *= 10;
        continue;
      }
      const double d_mu = (b22 * g1 - a12 * g2) / det, d_sigma = (b11 * g2 - a12 * g1) / det;
      const double mu_try = mu + d_mu, sigma_try = sigma + d_sigma;
      if (sigma_try > 0) {
        model(mu_try, sigma_try, p_try, dm_try, ds_try);
        const double rss_try = rss_of(p_try);
        if (rss_try <= rss) {
          const bool converged = rss - rss_try <= 1e-14 * rss + 1e-300 &&
                                 std::abs(d_mu) <= 1e-10 * sigma &&
                                 std::abs(d_sigma) <= 1e-10 * sigma;
          mu = mu_try;
          sigma = sigma_try;
          rss = rss_try;
          std::swap(p, p_try);
          std::swap(dm, dm_try);
          std::swap(ds, ds_try);
          lambda = std::max(lambda / 10, 1e-12);
          improved = true;
          if (converged) {
            f.mu = mu;
            f.sigma = sigma;
            f.rms = std::sqrt(rss / static_cast<double>(nb));
            f.ok = true;
            return f;
          }
          continue;
        }
      }
      lambda *= 10;
    }
    if (!improved) break;  // no step lowers the residual: at the minimum to round-off
  }
  if (std::isfinite(mu) && sigma > 0) {
    f.mu = mu;
    f.sigma = sigma;
    f.rms = std::sqrt(rss / static_cast<double>(nb));
    f.ok = f.iterations < 200;
  }
  return f;
}

}  // namespace wirepack::analysis
