#include "analysis/scaling_window.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace wirepack::analysis {

namespace {

bool usable(double l, double y, double l_end) {
  return std::isfinite(l) && std::isfinite(y) && l > 0 && y > 0 && l <= l_end;
}

// One resampled point's neighbourhood [lo, hi] (indices) and the local exponent over it.
struct Local {
  std::size_t lo = 0, hi = 0;
  double slope = NaN, se = NaN;
};

// Noise of ln y per raw row, s1: robust (median) estimate from the second differences of the
// resampled ln y, d_i = v_{i-1} - 2 v_i + v_{i+1} over ln l spacing corrections; for bins of c
// rows each v carries variance s1^2 / c, so d_i / sqrt(1/c_{i-1} + 4/c_i + 1/c_{i+1}) ~ N(0,
// s1^2) where the series is smooth. A kink or a jump touches only a few d_i: the median ignores
// them. The second difference of a pure power law in ln l is zero for equal spacing; unequal
// spacing is corrected by interpolating v_i linearly in u = ln l.
double unit_noise(const std::vector<double>& L, const std::vector<double>& Y,
                  const std::vector<int>& C) {
  std::vector<double> d;
  for (std::size_t i = 1; i + 1 < L.size(); ++i) {
    const double u0 = std::log(L[i - 1]), u1 = std::log(L[i]), u2 = std::log(L[i + 1]);
    const double a = (u2 - u1) / (u2 - u0);  // weight of v_{i-1} in the interpolant at u1
    const double b = 1 - a;
    const double r = std::log(Y[i]) - a * std::log(Y[i - 1]) - b * std::log(Y[i + 1]);
    const double var = 1.0 / C[i] + a * a / C[i - 1] + b * b / C[i + 1];
    d.push_back(std::abs(r) / std::sqrt(var));
  }
  if (d.empty()) return 0.0;
  std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
  return 1.4826 * d[d.size() / 2];  // median |N(0, s^2)| = 0.6745 s
}

// Weighted least squares of ln y on ln l over the resampled points [s, e], weights = rows per
// bin (a bin's ln y has variance s1^2 / count); standard errors from the weighted residuals
// with n - 2 degrees of freedom.
PowerLawFit wls_fit(const std::vector<double>& L, const std::vector<double>& Y,
                    const std::vector<int>& C, std::size_t s, std::size_t e) {
  PowerLawFit f;
  double sw = 0, su = 0, sv = 0;
  for (std::size_t i = s; i <= e; ++i) {
    sw += C[i];
    su += C[i] * std::log(L[i]);
    sv += C[i] * std::log(Y[i]);
  }
  f.n_points = e - s + 1;
  f.l_min = L[s];
  f.l_max = L[e];
  const double u_bar = su / sw, v_bar = sv / sw;
  double suu = 0, suv = 0;
  for (std::size_t i = s; i <= e; ++i) {
    const double du = std::log(L[i]) - u_bar;
    suu += C[i] * du * du;
    suv += C[i] * du * (std::log(Y[i]) - v_bar);
  }
  if (f.n_points < 3 || !(suu > 0)) return f;
  f.exponent = suv / suu;
  f.log_prefactor = v_bar - f.exponent * u_bar;
  double ssr = 0;
  for (std::size_t i = s; i <= e; ++i) {
    const double r = std::log(Y[i]) - f.log_prefactor - f.exponent * std::log(L[i]);
    ssr += C[i] * r * r;
  }
  const double s2 = ssr / static_cast<double>(f.n_points - 2);
  f.stderr_ = std::sqrt(s2 / suu);
  f.log_prefactor_stderr = std::sqrt(s2 * (1.0 / sw + u_bar * u_bar / suu));
  f.ok = true;
  return f;
}

}  // namespace

void log_resample(std::span<const double> l, std::span<const double> y, double l_end,
                  double points_per_decade, std::vector<double>& l_out, std::vector<double>& y_out,
                  std::vector<int>* counts) {
  l_out.clear();
  y_out.clear();
  if (counts) counts->clear();
  const std::size_t n = std::min(l.size(), y.size());
  double l0 = NaN;  // the smallest usable l (points may come in any order, e.g. pooled seeds)
  for (std::size_t i = 0; i < n; ++i)
    if (usable(l[i], y[i], l_end) && !(l[i] >= l0)) l0 = l[i];
  if (std::isnan(l0) || !(points_per_decade > 0)) return;
  // Bin k holds log10(l / l0) in [k, k + 1) / points_per_decade; sums of ln l, ln y per bin.
  std::vector<double> su, sv;
  std::vector<int> count;
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable(l[i], y[i], l_end) || l[i] < l0) continue;
    const auto k = static_cast<std::size_t>(std::floor(points_per_decade * std::log10(l[i] / l0)));
    if (k >= count.size()) {
      su.resize(k + 1, 0.0);
      sv.resize(k + 1, 0.0);
      count.resize(k + 1, 0);
    }
    su[k] += std::log(l[i]);
    sv[k] += std::log(y[i]);
    ++count[k];
  }
  for (std::size_t k = 0; k < count.size(); ++k) {
    if (count[k] == 0) continue;
    l_out.push_back(std::exp(su[k] / count[k]));
    y_out.push_back(std::exp(sv[k] / count[k]));
    if (counts) counts->push_back(count[k]);
  }
}

PowerLawFit fit_power_law_log_spaced(std::span<const double> l, std::span<const double> y,
                                     double l_min, double l_max, double points_per_decade) {
  std::vector<double> lw, yw;
  for (std::size_t i = 0; i < std::min(l.size(), y.size()); ++i)
    if (l[i] >= l_min) {
      lw.push_back(l[i]);
      yw.push_back(y[i]);
    }
  std::vector<double> L, Y;
  std::vector<int> C;
  log_resample(lw, yw, l_max, points_per_decade, L, Y, &C);
  if (L.size() < 3) return PowerLawFit{};
  return wls_fit(L, Y, C, 0, L.size() - 1);
}

ScalingWindow find_scaling_window(std::span<const double> l, std::span<const double> y,
                                  double l_end, const ScalingWindowOptions& o) {
  ScalingWindow w;
  std::vector<double> L, Y;
  std::vector<int> C;
  log_resample(l, y, l_end, o.points_per_decade, L, Y, &C);
  const std::size_t m = L.size();
  w.resampled_points = m;
  if (m < 3) return w;
  const double inf = std::numeric_limits<double>::infinity();
  const double s1 = unit_noise(L, Y, C);
  // Step 2: local exponents over +-local_span / 2 decades.
  std::vector<Local> local(m);
  for (std::size_t i = 0; i < m; ++i) {
    Local& c = local[i];
    c.lo = i;
    c.hi = i;
    while (c.lo > 0 && std::log10(L[i] / L[c.lo - 1]) <= 0.5 * o.local_span + 1e-12) --c.lo;
    while (c.hi + 1 < m && std::log10(L[c.hi + 1] / L[i]) <= 0.5 * o.local_span + 1e-12) ++c.hi;
    if (c.hi - c.lo + 1 < 3) continue;
    const std::span<const double> lw(L.data() + c.lo, c.hi - c.lo + 1);
    const std::span<const double> yw(Y.data() + c.lo, c.hi - c.lo + 1);
    const PowerLawFit f = fit_power_law(lw, yw, 0.0, inf);
    if (!f.ok) continue;
    c.slope = f.exponent;
    // Var(p) = sum (u_j - u_bar)^2 sigma_j^2 / Suu^2 with sigma_j = s1 / sqrt(count_j): the
    // noise of the data, not the misfit of a kink inside the neighbourhood.
    double u_bar = 0;
    for (std::size_t j = c.lo; j <= c.hi; ++j) u_bar += std::log(L[j]);
    u_bar /= static_cast<double>(c.hi - c.lo + 1);
    double suu = 0, var = 0;
    for (std::size_t j = c.lo; j <= c.hi; ++j) {
      const double du = std::log(L[j]) - u_bar;
      suu += du * du;
      var += du * du * s1 * s1 / C[j];
    }
    c.se = std::sqrt(var) / suu;
  }
  // Step 3: the first start from which every enclosed local exponent agrees with the window's.
  for (std::size_t s = 0; s + 2 < m; ++s) {
    if (std::log10(L[m - 1] / L[s]) < o.min_decades - 1e-12) break;
    const PowerLawFit f = wls_fit(L, Y, C, s, m - 1);
    if (!f.ok) continue;
    bool agree = true;
    int checked = 0;
    for (std::size_t i = s; i < m && agree; ++i) {
      const Local& c = local[i];
      if (c.lo < s || std::isnan(c.slope)) continue;
      ++checked;
      agree = std::abs(c.slope - f.exponent) <= o.tolerance + o.z * c.se;
    }
    if (!agree || checked == 0) continue;
    w.l_start = L[s];
    w.l_end = L[m - 1];
    w.fit = f;
    w.ok = true;
    return w;
  }
  return w;
}

}  // namespace wirepack::analysis
