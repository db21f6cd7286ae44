// Critical-point fits of D(x) with bootstrap intervals, and refinement proposals (critical.hpp).
#include "analysis/critical.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>

namespace wirepack::analysis {

double continuous_model(double u, const ContinuousFit& f) {
  const double d = f.side * (u - f.u_c);
  return f.D0 + (d > 0 ? f.A * std::pow(d, f.b) : 0.0);
}

double smooth_model(double u, const SmoothFit& f) {
  return f.D_lo + (f.D_hi - f.D_lo) / (1 + std::exp(-(u - f.u_c) / f.w));
}

namespace {

constexpr double kBMin = 0.1, kBMax = 5;  // range of the exponent b
constexpr double kWMinFrac = 1e-3;        // smooth width w in [kWMinFrac, 1] x span of u

// Grid values with finite D, sorted by u: weights n (seeds), means m, and the resampling pool.
struct Data {
  std::vector<double> u, n, m;
  std::vector<std::vector<double>> values;  // finite D per point
  double N = 0;                             // all finite values
  double ssw = 0;                           // within-point sum of squares
};

Data aggregate(const std::vector<CriticalSample>& samples, bool log_x) {
  std::vector<std::pair<double, std::vector<double>>> pts;
  for (const auto& s : samples) {
    if (!std::isfinite(s.x) || (log_x && s.x <= 0)) continue;
    std::vector<double> v;
    for (double d : s.D)
      if (std::isfinite(d)) v.push_back(d);
    if (v.empty()) continue;
    pts.emplace_back(log_x ? std::log10(s.x) : s.x, std::move(v));
  }
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  Data d;
  for (auto& [u, v] : pts) {
    // Equal x given twice: one point.
    if (!d.u.empty() && d.u.back() == u) {
      d.values.back().insert(d.values.back().end(), v.begin(), v.end());
    } else {
      d.u.push_back(u);
      d.values.push_back(std::move(v));
    }
  }
  for (const auto& v : d.values) {
    const auto ms = mean_sem(v);
    d.n.push_back(static_cast<double>(v.size()));
    d.m.push_back(ms.mean);
    d.N += static_cast<double>(v.size());
    if (v.size() > 1) d.ssw += ms.sd * ms.sd * static_cast<double>(v.size() - 1);
  }
  return d;
}

// Weighted least squares m ~ c0 + c1 g (weights n); ss = sum n (m - fit)^2.
struct Lin {
  double c0 = NaN, c1 = 0, ss = NaN;
};
Lin wls(const Data& d, const std::vector<double>& g) {
  double sw = 0, sg = 0, sm = 0;
  for (std::size_t i = 0; i < d.u.size(); ++i) {
    sw += d.n[i];
    sg += d.n[i] * g[i];
    sm += d.n[i] * d.m[i];
  }
  const double gbar = sg / sw, mbar = sm / sw;
  double sgg = 0, sgm = 0, smm = 0;
  for (std::size_t i = 0; i < d.u.size(); ++i) {
    const double dg = g[i] - gbar, dm = d.m[i] - mbar;
    sgg += d.n[i] * dg * dg;
    sgm += d.n[i] * dg * dm;
    smm += d.n[i] * dm * dm;
  }
  Lin r;
  if (!(sgg > 1e-300)) {
    r.c0 = mbar;
    r.ss = smm;
    return r;
  }
  r.c1 = sgm / sgg;
  r.c0 = mbar - r.c1 * gbar;
  r.ss = std::max(0.0, smm - r.c1 * sgm);
  return r;
}

// Minimises f(p0, p1) over a box: the best of an n0 x n1 grid (and `start`, when finite), then
// Nelder-Mead from there with the parameters clamped to the box. Returns (p0, p1, f).
template <class F>
std::array<double, 3> minimize2(const F& f, double lo0, double hi0, int n0, double lo1, double hi1,
                                int n1, std::array<double, 2> start = {NaN, NaN}) {
  const auto clamp = [&](std::array<double, 2> p) {
    return std::array<double, 2>{std::clamp(p[0], lo0, hi0), std::clamp(p[1], lo1, hi1)};
  };
  const auto eval = [&](const std::array<double, 2>& p) { return f(p[0], p[1]); };
  std::array<double, 2> best{lo0, lo1};
  double fbest = INFINITY;
  for (int i = 0; i < n0; ++i)
    for (int j = 0; j < n1; ++j) {
      const std::array<double, 2> p{lo0 + (hi0 - lo0) * i / (n0 - 1),
                                    lo1 + (hi1 - lo1) * j / (n1 - 1)};
      if (const double v = eval(p); v < fbest) fbest = v, best = p;
    }
  if (std::isfinite(start[0]) && std::isfinite(start[1])) {
    const auto p = clamp(start);
    if (const double v = eval(p); v < fbest) fbest = v, best = p;
  }
  const double s0 = (hi0 - lo0) / (n0 - 1), s1 = (hi1 - lo1) / (n1 - 1);
  std::array<std::array<double, 2>, 3> x = {best, clamp({best[0] + s0 / 2, best[1]}),
                                            clamp({best[0], best[1] + s1 / 2})};
  if (x[1] == best) x[1] = clamp({best[0] - s0 / 2, best[1]});
  if (x[2] == best) x[2] = clamp({best[0], best[1] - s1 / 2});
  std::array<double, 3> fx = {fbest, eval(x[1]), eval(x[2])};
  for (int it = 0; it < 200; ++it) {
    std::array<int, 3> o = {0, 1, 2};
    std::sort(o.begin(), o.end(), [&](int a, int b) { return fx[a] < fx[b]; });
    const auto& xb = x[o[0]];
    const auto& xw = x[o[2]];
    // Simplex size in grid steps.
    const double size = (std::abs(x[o[1]][0] - xb[0]) + std::abs(xw[0] - xb[0])) / s0 +
                        (std::abs(x[o[1]][1] - xb[1]) + std::abs(xw[1] - xb[1])) / s1;
    if (size < 1e-6) break;
    const std::array<double, 2> c = {(xb[0] + x[o[1]][0]) / 2, (xb[1] + x[o[1]][1]) / 2};
    const auto along = [&](double t) {
      return clamp({c[0] + t * (xw[0] - c[0]), c[1] + t * (xw[1] - c[1])});
    };
    const auto xr = along(-1);
    const double fr = eval(xr);
    if (fr < fx[o[0]]) {
      const auto xe = along(-2);
      const double fe = eval(xe);
      if (fe < fr)
        x[o[2]] = xe, fx[o[2]] = fe;
      else
        x[o[2]] = xr, fx[o[2]] = fr;
    } else if (fr < fx[o[1]]) {
      x[o[2]] = xr, fx[o[2]] = fr;
    } else {
      const auto xc = along(fr < fx[o[2]] ? -0.5 : 0.5);
      const double fc = eval(xc);
      if (fc < std::min(fr, fx[o[2]])) {
        x[o[2]] = xc, fx[o[2]] = fc;
      } else {  // shrink towards the best
        for (int k : {o[1], o[2]}) {
          x[k] = {(x[k][0] + xb[0]) / 2, (x[k][1] + xb[1]) / 2};
          fx[k] = eval(x[k]);
        }
      }
    }
  }
  const int b = static_cast<int>(std::min_element(fx.begin(), fx.end()) - fx.begin());
  return {x[b][0], x[b][1], fx[b]};
}

struct Fitter {
  const Data& d;
  std::vector<double> g;  // scratch
  explicit Fitter(const Data& data) : d(data), g(data.u.size()) {}

  double lo() const { return d.u.front(); }
  double hi() const { return d.u.back(); }

  Lin continuous_lin(double u_c, double b, int side) {
    for (std::size_t i = 0; i < d.u.size(); ++i) {
      const double x = side * (d.u[i] - u_c);
      g[i] = x > 0 ? std::pow(x, b) : 0.0;
    }
    return wls(d, g);
  }
  Lin smooth_lin(double u_c, double w) {
    for (std::size_t i = 0; i < d.u.size(); ++i) g[i] = 1 / (1 + std::exp(-(d.u[i] - u_c) / w));
    return wls(d, g);
  }

  // coarse: the bootstrap's grid; start: a previous optimum (u_c, log b).
  ContinuousFit continuous(int side, bool coarse, std::array<double, 2> start = {NaN, NaN}) {
    const auto f = [&](double u_c, double t) { return continuous_lin(u_c, std::exp(t), side).ss; };
    const auto p = minimize2(f, lo(), hi(), coarse ? 16 : 48, std::log(kBMin), std::log(kBMax),
                             coarse ? 8 : 16, start);
    ContinuousFit r;
    r.u_c = p[0];
    r.b = std::exp(p[1]);
    r.side = side;
    const Lin l = continuous_lin(r.u_c, r.b, side);
    r.D0 = l.c0;
    r.A = l.c1;
    r.sse = l.ss + d.ssw;
    return r;
  }

  SmoothFit smooth(bool coarse, std::array<double, 2> start = {NaN, NaN}) {
    const double span = hi() - lo();
    const auto f = [&](double u_c, double t) { return smooth_lin(u_c, std::exp(t)).ss; };
    const auto p = minimize2(f, lo(), hi(), coarse ? 16 : 48, std::log(kWMinFrac * span),
                             std::log(span), coarse ? 8 : 16, start);
    SmoothFit r;
    r.u_c = p[0];
    r.w = std::exp(p[1]);
    const Lin l = smooth_lin(r.u_c, r.w);
    r.D_lo = l.c0;
    r.D_hi = l.c0 + l.c1;
    r.sse = l.ss + d.ssw;
    return r;
  }
};

double aic(double sse, double N, int k) {
  return N * std::log(std::max(sse, N * 1e-30) / N) + 2.0 * (k + 1);
}

// Percentile (linear interpolation between order statistics) of sorted xs.
double percentile(const std::vector<double>& xs, double q) {
  if (xs.empty()) return NaN;
  const double h = q * static_cast<double>(xs.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(h));
  if (i + 1 >= xs.size()) return xs.back();
  return xs[i] + (h - static_cast<double>(i)) * (xs[i + 1] - xs[i]);
}

std::string fmt(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.4g", x);
  return buf;
}

}  // namespace

CriticalResult fit_critical(const std::vector<CriticalSample>& samples,
                            const CriticalOptions& opt) {
  CriticalResult r;
  const Data d = aggregate(samples, opt.log_x);
  const auto to_x = [&](double u) { return opt.log_x ? std::pow(10.0, u) : u; };
  r.points = d.u.size();
  r.values = static_cast<std::size_t>(d.N);
  if (d.u.empty()) {
    r.status = "no data";
    r.note = "no grid value has a finite D (failed or missing runs)";
    return r;
  }
  r.x_min = to_x(d.u.front());
  r.x_max = to_x(d.u.back());
  if (d.u.size() < 4) {
    r.status = "too few points";
    r.note = std::to_string(d.u.size()) + " grid value(s) with a finite D; a fit needs >= 4";
    return r;
  }

  Fitter fit(d);
  r.aic_constant = aic(wls(d, std::vector<double>(d.u.size(), 0.0)).ss + d.ssw, d.N, 1);
  r.aic_line = aic(wls(d, d.u).ss + d.ssw, d.N, 2);
  const ContinuousFit up = fit.continuous(+1, false), down = fit.continuous(-1, false);
  r.continuous = up.sse <= down.sse ? up : down;
  r.smooth = fit.smooth(false);
  r.aic_continuous = aic(r.continuous.sse, d.N, 4);
  r.aic_smooth = aic(r.smooth.sse, d.N, 4);
  // The crossover counts only when both its plateaus are sampled, by two grid values each
  // beyond x_c -+ 2 w: a logistic with a plateau outside the range is just a curved rise, and its
  // midpoint no transition.
  std::size_t below = 0, above = 0;
  for (double u : d.u) {
    below += u <= r.smooth.u_c - 2 * r.smooth.w;
    above += u >= r.smooth.u_c + 2 * r.smooth.w;
  }
  const bool smooth_inside = below >= 2 && above >= 2;
  const bool smooth = smooth_inside && r.aic_smooth < r.aic_continuous;
  const double best = smooth ? r.aic_smooth : r.aic_continuous;
  const double null_aic = std::min(r.aic_constant, r.aic_line);
  if (!(best < null_aic - opt.min_aic_gain)) {
    r.status = "no transition in range";
    r.note = "neither transition model beats a " +
             std::string(r.aic_constant <= r.aic_line ? "constant" : "straight line") + " by AIC " +
             fmt(opt.min_aic_gain) + " (gain " + fmt(null_aic - best) + ")";
    return r;
  }

  // Inside the range: half a grid step from either end; the continuous model needs two grid
  // values on its rising side (for A and b).
  const std::size_t n = d.u.size();
  double lo_ok = d.u[0] + (d.u[1] - d.u[0]) / 2, hi_ok = d.u[n - 1] - (d.u[n - 1] - d.u[n - 2]) / 2;
  const double u_c = smooth ? r.smooth.u_c : r.continuous.u_c;
  if (!smooth) {
    if (r.continuous.side > 0)
      hi_ok = std::min(hi_ok, d.u[n - 2]);
    else
      lo_ok = std::max(lo_ok, d.u[1]);
  }
  if (!(u_c > lo_ok && u_c < hi_ok)) {
    r.status = "no transition in range";
    const bool low = u_c <= lo_ok;
    r.note = std::string(smooth ? "smooth" : "continuous") + " fit puts x_c = " + fmt(to_x(u_c)) +
             " at the " + (low ? "lower" : "upper") + " edge of the range [" + fmt(r.x_min) + ", " +
             fmt(r.x_max) + "]: add grid values " + (low ? "near or below " : "near or above ") +
             fmt(low ? r.x_min : r.x_max);
    return r;
  }

  r.model = smooth ? "smooth" : "continuous";
  r.x_c = to_x(u_c);
  if (smooth) {
    r.width = r.smooth.w;
    r.D0 = r.smooth.D_lo;
    r.D_plateau = r.smooth.D_hi;
  } else {
    r.side = r.continuous.side;
    r.b = r.continuous.b;
    r.D0 = r.continuous.D0;
    r.D_plateau = continuous_model(r.continuous.side > 0 ? d.u.back() : d.u.front(), r.continuous);
  }

  // Percentile bootstrap over the seeds: each point's values resampled with replacement, the
  // chosen model refitted (same side).
  std::size_t most = 0;
  for (const auto& v : d.values) most = std::max(most, v.size());
  if (most < 2 || opt.resamples < 2) {
    r.status = "no interval";
    r.note = most < 2 ? "one seed per grid value: no bootstrap interval"
                      : "bootstrap off (resamples < 2)";
    return r;
  }
  std::mt19937_64 rng(opt.rng_seed);
  Data boot = d;
  Fitter bfit(boot);
  std::vector<double> ucs, bs;
  for (int k = 0; k < opt.resamples; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      const auto& v = d.values[i];
      std::uniform_int_distribution<std::size_t> pick(0, v.size() - 1);
      double s = 0;
      for (std::size_t j = 0; j < v.size(); ++j) s += v[pick(rng)];
      // The resampled mean's spread is sqrt((n - 1) / n) of the mean's: rescaled about the
      // sample mean (the small-sample correction of the seed bootstrap).
      const double nv = static_cast<double>(v.size());
      const double inflate = v.size() > 1 ? std::sqrt(nv / (nv - 1)) : 1.0;
      boot.m[i] = d.m[i] + inflate * (s / nv - d.m[i]);
    }
    if (smooth) {
      const SmoothFit f = bfit.smooth(true, {r.smooth.u_c, std::log(r.smooth.w)});
      if (std::isfinite(f.u_c)) ucs.push_back(f.u_c);
    } else {
      const ContinuousFit f =
          bfit.continuous(r.continuous.side, true, {r.continuous.u_c, std::log(r.continuous.b)});
      if (std::isfinite(f.u_c)) ucs.push_back(f.u_c), bs.push_back(f.b);
    }
  }
  r.resamples = ucs.size();
  std::sort(ucs.begin(), ucs.end());
  std::sort(bs.begin(), bs.end());
  const double a = (1 - opt.level) / 2;
  r.x_c_lo = to_x(percentile(ucs, a));
  r.x_c_hi = to_x(percentile(ucs, 1 - a));
  if (!smooth) {
    r.b_lo = percentile(bs, a);
    r.b_hi = percentile(bs, 1 - a);
  }
  r.status = "ok";
  r.note = smooth ? "smooth crossover preferred by AIC (no exponent)"
                  : "continuous transition preferred by AIC";
  if (smooth) {
    // A crossover no grid value sees (none within u_c -+ 2 w): the data place x_c only between
    // the two grid values around it, wherever the logistic's midpoint fell, and the bootstrap
    // over the seeds cannot know that; the interval covers that whole step of the grid.
    bool seen = false;
    for (double u : d.u) seen = seen || std::abs(u - u_c) <= 2 * r.smooth.w;
    if (!seen) {
      const auto above_it = std::upper_bound(d.u.begin(), d.u.end(), u_c);
      const double a = to_x(*(above_it - 1)), b = to_x(*above_it);  // u_c is inside the range
      r.x_c_lo = std::min(r.x_c_lo, a);
      r.x_c_hi = std::max(r.x_c_hi, b);
      r.note +=
          "; the crossover is sharper than the grid (no grid value within x_c -+ 2 width): "
          "x_c lies between the grid values " +
          fmt(a) + " and " + fmt(b) +
          ", the interval is widened to them; values between them resolve it";
    }
  }
  return r;
}

namespace {

// x rounded to 4 significant digits of `scale` (the decimal text's nearest double, so it prints
// short).
double round_to(double x, double scale) {
  const int digits = std::max(0, 3 - static_cast<int>(std::floor(std::log10(std::abs(scale)))));
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return std::strtod(buf, nullptr);
}

}  // namespace

std::vector<double> propose_refinement(const std::vector<CriticalSample>& samples,
                                       const CriticalResult& fit, int count,
                                       const CriticalOptions& opt) {
  const Data d = aggregate(samples, opt.log_x);
  if (d.u.size() < 2 || count < 1) return {};
  const auto to_u = [&](double x) { return opt.log_x ? std::log10(x) : x; };
  const auto to_x = [&](double u) { return opt.log_x ? std::pow(10.0, u) : u; };

  const double scale = opt.log_x ? NaN : to_x(d.u.back()) - to_x(d.u.front());
  const auto rounded = [&](double x) { return round_to(x, opt.log_x ? x : scale); };
  std::vector<double> taken;
  for (double u : d.u) taken.push_back(rounded(to_x(u)));
  std::vector<double> out;

  // Gaps (a, b) with a score; each step bisects the best one.
  struct Gap {
    double a, b, score;
  };
  const auto bisect = [&](std::vector<Gap> gaps, bool by_width) {
    for (int step = 0; step < 1000 && static_cast<int>(out.size()) < count && !gaps.empty();
         ++step) {
      const auto it = std::max_element(gaps.begin(), gaps.end(), [](const Gap& a, const Gap& b) {
        return a.score < b.score || (a.score == b.score && a.a > b.a);
      });
      const Gap g = *it;
      gaps.erase(it);
      const double mid = (g.a + g.b) / 2;
      const double x = rounded(to_x(mid));
      // A gap below the rounding is dropped.
      if (!std::isfinite(x) || (opt.log_x && x <= 0)) continue;
      if (std::find(taken.begin(), taken.end(), x) != taken.end()) continue;
      gaps.push_back({g.a, mid, by_width ? mid - g.a : g.score / 2});
      gaps.push_back({mid, g.b, by_width ? g.b - mid : g.score / 2});
      taken.push_back(x);
      out.push_back(x);
    }
  };

  const bool have_ci = fit.status == "ok" && std::isfinite(fit.x_c_lo) &&
                       std::isfinite(fit.x_c_hi) && (!opt.log_x || fit.x_c_lo > 0);
  if (have_ci) {
    double lo = to_u(fit.x_c_lo), hi = to_u(fit.x_c_hi);
    if (!(hi > lo)) {  // a zero-width interval: a quarter of the smallest grid step around x_c
      double step = INFINITY;
      for (std::size_t i = 1; i < d.u.size(); ++i) step = std::min(step, d.u[i] - d.u[i - 1]);
      lo -= step / 4;
      hi += step / 4;
    }
    // An interval already sampled below the rounding is widened (x 2 about its centre, within
    // the range) until the values fit.
    for (int widen = 0; widen < 64 && static_cast<int>(out.size()) < count; ++widen) {
      std::vector<double> cuts = {lo, hi};
      for (double u : d.u)
        if (u > lo && u < hi) cuts.push_back(u);
      for (double x : out)
        if (to_u(x) > lo && to_u(x) < hi) cuts.push_back(to_u(x));
      std::sort(cuts.begin(), cuts.end());
      std::vector<Gap> gaps;
      for (std::size_t i = 1; i < cuts.size(); ++i)
        gaps.push_back({cuts[i - 1], cuts[i], cuts[i] - cuts[i - 1]});
      bisect(gaps, true);
      if (lo <= d.u.front() && hi >= d.u.back()) break;  // the whole range is sampled finely
      const double c = (lo + hi) / 2, h = hi - lo;
      lo = std::max(d.u.front(), c - h);
      hi = std::min(d.u.back(), c + h);
    }
  } else {
    std::vector<Gap> gaps;
    for (std::size_t i = 1; i < d.u.size(); ++i)
      gaps.push_back({d.u[i - 1], d.u[i], std::abs(d.m[i] - d.m[i - 1])});
    bisect(gaps, false);
  }
  std::sort(out.begin(), out.end());
  return out;
}

SeedProposal propose_seeds(const std::vector<CriticalSample>& samples, const CriticalResult& fit,
                           const CriticalOptions& opt, bool force) {
  // The grid values with a finite D, sorted, as given (they name the points of the sweep):
  // x -> (finite D values, their sum).
  std::map<double, std::pair<std::size_t, double>> by_x;
  for (const auto& s : samples) {
    if (!std::isfinite(s.x) || (opt.log_x && s.x <= 0)) continue;
    for (double d : s.D)
      if (std::isfinite(d)) {
        ++by_x[s.x].first;
        by_x[s.x].second += d;
      }
  }
  std::vector<double> x, n, m;  // value, finite D, mean D
  for (const auto& [xi, c] : by_x) {
    x.push_back(xi);
    n.push_back(static_cast<double>(c.first));
    m.push_back(c.second / static_cast<double>(c.first));
  }
  if (x.size() < 2) return {};
  std::size_t lo = 0, hi = 0;  // the chosen values x[lo..hi]
  const bool have_ci = fit.status == "ok" && std::isfinite(fit.x_c_lo) && std::isfinite(fit.x_c_hi);
  if (have_ci) {
    // The first value above the interval's top, and the last below its bottom.
    std::size_t above = 0;
    while (above < x.size() && x[above] <= fit.x_c_hi) ++above;
    std::size_t below = above;
    while (below > 0 && x[below - 1] >= fit.x_c_lo) --below;
    lo = below > 0 ? below - 1 : 0;
    hi = std::min(above, x.size() - 1);
    if (hi == lo) {  // an interval beyond the range: the two values at that end
      hi = std::min(lo + 1, x.size() - 1);
      lo = hi - 1;
    }
  } else {
    if (!force) return {};
    std::size_t best = 1;
    for (std::size_t i = 2; i < x.size(); ++i)
      if (std::abs(m[i] - m[i - 1]) > std::abs(m[best] - m[best - 1])) best = i;
    lo = best >= 2 ? best - 2 : 0;
    hi = std::min(best + 1, x.size() - 1);
  }
  const double fewest = *std::min_element(n.begin() + static_cast<std::ptrdiff_t>(lo),
                                          n.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
  SeedProposal out;
  const double lack = static_cast<double>(kMinSeedsNearCritical) - fewest;
  if (lack <= 0 && !force) return out;
  out.seeds = lack > 0 ? static_cast<std::size_t>(lack) : 1;
  out.x.assign(x.begin() + static_cast<std::ptrdiff_t>(lo),
               x.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
  return out;
}

}  // namespace wirepack::analysis
