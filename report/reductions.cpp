#include "report/reductions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>

#include "analysis/purohit.hpp"
#include "analysis/scaling_window.hpp"
#include "core/section.hpp"
#include "report/csv_table.hpp"
#include "sweep/config/sweep_config.hpp"

namespace wirepack::report {

using json = nlohmann::json;

namespace {

// A run's snapshot is "at" l when it lies within this distance in l (snapshots are taken at the
// first step past each multiple of output.snapshots_every_l, so they overshoot by a step).
constexpr double kSnapshotTolerance = 0.05;

// The reported standard error is the seed bootstrap's from 3 seeds on (with 2 it has only three
// distinct resamples), else the OLS one, which ignores that neighbouring points of a series are
// correlated.
constexpr std::size_t kBootstrapMinSeeds = 3;

double last_of(const std::vector<double>* v) {
  return v && !v->empty() ? v->back() : NaN;
}

}  // namespace

std::vector<std::string> kept_series(const sweep::SeriesList& list) {
  return sweep::analysis_series(list);
}

void check_named_series(const sweep::SeriesList& list) {
  std::vector<std::string> named = {"D", "U_b_hat", "K", "N", "R_t", "R_x", "R_y"};
  for (const auto& e : exponent_specs()) named.push_back(e.series);
  const auto kept = kept_series(list);
  std::set<std::string> missing;
  for (const auto& name : named)
    if (std::find(kept.begin(), kept.end(), name) == kept.end()) missing.insert(name);
  if (missing.empty()) return;
  std::string names;
  for (const auto& name : missing) names += (names.empty() ? "" : ", ") + name;
  throw std::logic_error("series named by the analysis but not kept by the series list: " + names);
}

const std::vector<std::string>& predicted_series() {
  static const std::vector<std::string> names = {"U_b_hat_purohit", "K_purohit"};
  return names;
}

std::vector<double> values_in_window(const std::vector<double>& l, const std::vector<double>& y,
                                     const LWindow& w) {
  std::vector<double> out;
  for (std::size_t i = 0; i < l.size() && i < y.size(); ++i)
    if (l[i] >= w.l_min && l[i] <= w.l_max && std::isfinite(y[i])) out.push_back(y[i]);
  return out;
}

double number_at(const json& config, const char* pointer) {
  const json::json_pointer p(pointer);
  if (!config.is_object() || !config.contains(p) || !config[p].is_number()) return NaN;
  return config[p].get<double>();
}

void set_run_config(RunData& r, const json& config) {
  if (!config.is_object()) return;
  r.config = config;
  r.seed = config.contains("seed") ? config["seed"] : json();
  r.key = sweep::point_key(config);
}

void summarize_run(RunData& r, const AnalysisSettings& settings) {
  if (r.status != "complete") return;
  const std::size_t rows = r.series["l"].size();
  // D over the D window: its maximum (the paper's D) and its mean.
  const auto& L = r.series["l"];
  const std::vector<double> in_window = values_in_window(L, r.series["D"], settings.D_window);
  if (!in_window.empty()) {
    r.D = *std::max_element(in_window.begin(), in_window.end());
    r.D_avg = analysis::mean_sem(in_window).mean;
  }
  // A variant's maximum over the window; NaN when its series is absent or all NaN there.
  const auto window_max = [&](const std::vector<double>& y) {
    const std::vector<double> v = values_in_window(L, y, settings.D_window);
    return v.empty() ? NaN : *std::max_element(v.begin(), v.end());
  };
  if (const auto it = r.series.find("D_chord"); it != r.series.end())
    r.D_chord = window_max(it->second);
  if (const auto it = r.series.find("S_kappa"); it != r.series.end()) {
    std::vector<double> D_kappa;
    for (const double S : it->second) D_kappa.push_back(1 - std::abs(S));
    r.D_kappa = window_max(D_kappa);
  }
  r.U_b_hat = last_of(&r.series["U_b_hat"]);
  r.K = last_of(&r.series["K"]);
  r.N = last_of(&r.series["N"]);

  // Purohit model (paper Eqs. 4-7) from this run's radii at each l: L = l R, radii R_* R,
  // EI = E_w pi r^4 / 4, U_b_hat = U_b r^2 / (R EI).
  const double wire_r = number_at(r.config, "/wire/radius");
  const double R = number_at(r.config, "/rho") * wire_r;
  const double EI = number_at(r.config, "/wire/youngs_modulus") * section_second_moment(wire_r);
  auto& Ub = r.series["U_b_hat_purohit"];
  auto& Kp = r.series["K_purohit"];
  Ub.assign(rows, NaN);
  Kp.assign(rows, NaN);
  const auto& Rt = r.series["R_t"];
  const auto& Rx = r.series["R_x"];
  const auto& Ry = r.series["R_y"];
  for (std::size_t i = 0; i < rows; ++i) {
    const auto p = analysis::purohit(L[i] * R, Rt[i] * R, Rx[i] * R, Ry[i] * R, EI);
    if (!p.ok) continue;
    Ub[i] = p.U_b * wire_r * wire_r / (R * EI);
    Kp[i] = p.K;
  }
}

std::optional<std::size_t> snapshot_near(const std::vector<double>& ls, double l) {
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < ls.size(); ++k)
    if (std::abs(ls[k] - l) <= kSnapshotTolerance &&
        (!best || std::abs(ls[k] - l) < std::abs(ls[*best] - l)))
      best = k;
  return best;
}

const std::vector<std::string>& fixed_parameters() {
  static const std::vector<std::string> p = sweep::keys_with(&sweep::KeySpec::Roles::column);
  return p;
}

std::vector<std::string> swept_parameters(const std::vector<GridPoint>& points,
                                          const std::optional<sweep::Sweep>& sweep) {
  std::set<std::string> all;
  for (const auto& p : points)
    for (const auto& [ptr, v] : p.leaves) all.insert(ptr);
  const auto value = [](const GridPoint& p, const std::string& ptr) {
    const auto it = p.leaves.find(ptr);
    return it == p.leaves.end() ? std::string("-") : sweep::canonical_json(it->second);
  };
  std::vector<std::string> candidates;
  const auto add = [&](const std::string& ptr) {
    if (all.contains(ptr) &&
        std::find(candidates.begin(), candidates.end(), ptr) == candidates.end())
      candidates.push_back(ptr);
  };
  if (sweep)
    for (const auto& axis : sweep->axes) add(axis.pointer);
  for (const auto& ptr : fixed_parameters()) add(ptr);
  for (const auto& ptr : sweep::keys_with(&sweep::KeySpec::Roles::physical)) add(ptr);
  for (const auto& ptr : all) add(ptr);

  std::vector<std::string> kept;
  for (const auto& ptr : candidates) {
    std::set<std::string> values;
    for (const auto& p : points) values.insert(value(p, ptr));
    if (values.size() < 2) continue;
    // Is ptr a function of the kept parameters over the points?
    std::map<std::string, std::string> seen;
    bool determined = !kept.empty();
    for (const auto& p : points) {
      if (!determined) break;
      std::string tuple;
      for (const auto& k : kept) tuple += value(p, k) + "\x1f";
      const auto [it, fresh] = seen.emplace(tuple, value(p, ptr));
      if (!fresh && it->second != value(p, ptr)) determined = false;
    }
    if (!determined) kept.push_back(ptr);
  }
  return kept;
}

json leaf(const GridPoint& p, const std::string& ptr) {
  const auto it = p.leaves.find(ptr);
  return it == p.leaves.end() ? json() : it->second;
}

void group(Analysis& a, const std::optional<sweep::Sweep>& sweep) {
  std::map<std::string, GridPoint> by_key;
  for (const auto& r : a.runs) {
    if (r.key.empty()) continue;
    GridPoint& p = by_key[r.key];
    if (p.key.empty()) {
      p.key = r.key;
      flatten(sweep::point_scene(r.config), "", p.leaves);
    }
  }
  std::vector<GridPoint> points;
  for (auto& [key, p] : by_key) points.push_back(std::move(p));
  // A key resolved only where it acts, present at some points: the others get its meaning.
  for (const auto& [key_ptr, absent] : sweep::values_where_not_resolved()) {
    // A named copy: clang before 16 cannot capture a structured binding in a lambda.
    const std::string& ptr = key_ptr;
    const bool somewhere = std::any_of(points.begin(), points.end(),
                                       [&](const GridPoint& p) { return p.leaves.contains(ptr); });
    if (!somewhere) continue;
    for (auto& p : points) p.leaves.emplace(ptr, absent);
  }
  a.axes = swept_parameters(points, sweep);
  // Points ordered by the swept parameters (the first slowest), ties by their scene.
  std::sort(points.begin(), points.end(), [&](const GridPoint& x, const GridPoint& y) {
    for (const auto& ptr : a.axes)
      if (const int c = compare_values(leaf(x, ptr), leaf(y, ptr)); c != 0) return c < 0;
    return x.key < y.key;
  });
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < points.size(); ++i) index[points[i].key] = static_cast<int>(i);
  for (auto& r : a.runs) r.point = r.key.empty() ? -1 : index.at(r.key);
  // runs.csv order: point (unknown last), seed, file.
  std::sort(a.runs.begin(), a.runs.end(), [](const RunData& x, const RunData& y) {
    const auto px = x.point < 0 ? std::numeric_limits<int>::max() : x.point;
    const auto py = y.point < 0 ? std::numeric_limits<int>::max() : y.point;
    if (px != py) return px < py;
    if (const int c = compare_values(x.seed, y.seed); c != 0) return c < 0;
    return x.file < y.file;
  });
  for (const auto& r : a.runs) {
    if (r.point < 0) continue;
    GridPoint& p = points[r.point];
    if (r.status == "complete")
      p.complete.push_back(&r);
    else if (r.status == "failed")
      ++p.failed;
    else
      ++p.missing;
  }
  a.points = std::move(points);
  a.params = fixed_parameters();
  for (const auto& ptr : a.axes)
    if (std::find(a.params.begin(), a.params.end(), ptr) == a.params.end()) a.params.push_back(ptr);
  for (const auto& ptr : a.params) a.param_names.push_back(column_name(ptr));
}

double RunData::*order_parameter_field(const std::string& name) {
  if (name == "D_chord") return &RunData::D_chord;
  if (name == "D_kappa") return &RunData::D_kappa;
  return &RunData::D;
}

std::vector<double> values(const GridPoint& p, double RunData::*field) {
  std::vector<double> v;
  for (const RunData* r : p.complete) v.push_back(r->*field);
  return v;
}

View make_view(const Analysis& a, const std::string& ptr) {
  View v;
  v.name = column_name(ptr);
  v.pointer = ptr;
  for (const auto& o : a.axes)
    if (o != ptr) v.others.push_back(o);
  for (std::size_t i = 0; i < a.points.size(); ++i) v.order.push_back(i);
  std::stable_sort(v.order.begin(), v.order.end(), [&](std::size_t x, std::size_t y) {
    for (const auto& o : v.others)
      if (const int c = compare_values(leaf(a.points[x], o), leaf(a.points[y], o)); c != 0)
        return c < 0;
    return compare_values(leaf(a.points[x], ptr), leaf(a.points[y], ptr)) < 0;
  });
  return v;
}

ExponentFit fit_exponent(const GridPoint& p, const std::string& series, const LWindow& w,
                         int resamples, bool auto_window) {
  std::vector<std::vector<double>> ls, ys;
  std::vector<double> pooled_l, pooled_y;
  for (const RunData* r : p.complete) {
    const auto& l = r->series.at("l");
    const auto& y = r->series.at(series);
    ls.push_back(l);
    ys.push_back(y);
    pooled_l.insert(pooled_l.end(), l.begin(), l.end());
    pooled_y.insert(pooled_y.end(), y.begin(), y.end());
  }
  ExponentFit f;
  f.seeds = p.complete.size();
  if (!auto_window) {
    f.fit = analysis::fit_power_law(pooled_l, pooled_y, w.l_min, w.l_max);
    if (f.fit.ok && f.seeds >= 2 && resamples >= 2)
      f.stderr_bootstrap = analysis::bootstrap_exponent_stderr(ls, ys, w.l_min, w.l_max, resamples);
    return f;
  }
  f.auto_window = true;
  std::vector<double> in_l, in_y;
  for (std::size_t i = 0; i < pooled_l.size(); ++i)
    if (pooled_l[i] >= w.l_min) {
      in_l.push_back(pooled_l[i]);
      in_y.push_back(pooled_y[i]);
    }
  const analysis::ScalingWindow sw = analysis::find_scaling_window(in_l, in_y, w.l_max);
  if (!sw.ok) return f;  // no scaling window: fit.ok = false
  f.fit = analysis::fit_power_law_log_spaced(pooled_l, pooled_y, sw.l_start, w.l_max);
  if (!f.fit.ok || f.seeds < 2 || resamples < 2) return f;
  // Seed bootstrap of the same window (fixed RNG seed, as bootstrap_exponent_stderr).
  std::mt19937_64 rng(20150101);
  std::uniform_int_distribution<std::size_t> pick(0, f.seeds - 1);
  std::vector<double> exponents;
  for (int b = 0; b < resamples; ++b) {
    std::vector<double> bl, by;
    for (std::size_t k = 0; k < f.seeds; ++k) {
      const std::size_t s = pick(rng);
      bl.insert(bl.end(), ls[s].begin(), ls[s].end());
      by.insert(by.end(), ys[s].begin(), ys[s].end());
    }
    const auto g = analysis::fit_power_law_log_spaced(bl, by, sw.l_start, w.l_max);
    if (g.ok) exponents.push_back(g.exponent);
  }
  if (exponents.size() >= 2) f.stderr_bootstrap = analysis::mean_sem(exponents).sd;
  return f;
}

bool use_bootstrap(const ExponentFit& f) {
  return f.seeds >= kBootstrapMinSeeds && std::isfinite(f.stderr_bootstrap);
}
double reported_stderr(const ExponentFit& f) {
  return use_bootstrap(f) ? f.stderr_bootstrap : f.fit.stderr_;
}

Fits fit_all(const Analysis& a) {
  Fits fits(a.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (const auto& e : exponent_specs())
      fits[i].push_back(fit_exponent(a.points[i], e.series, a.settings.fit_windows.at(e.name),
                                     a.settings.bootstrap_resamples,
                                     a.settings.fit_auto.count(e.name) > 0));
  return fits;
}

MeanSeries mean_series(const GridPoint& p, const std::vector<std::string>& kept) {
  MeanSeries m;
  if (p.complete.empty()) return m;
  const double every = p.complete.front()->every_l;
  // Each run's row per nominal index k = round(l / every_l) (the last row wins a repeated k).
  std::vector<std::map<long long, std::size_t>> rows(p.complete.size());
  std::set<long long> ks;
  for (std::size_t s = 0; s < p.complete.size(); ++s) {
    const auto& l = p.complete[s]->series.at("l");
    for (std::size_t i = 0; i < l.size(); ++i) {
      if (!std::isfinite(l[i])) continue;
      const long long k = std::llround(l[i] / every);
      rows[s][k] = i;
      ks.insert(k);
    }
  }
  const auto names = cat(kept, predicted_series());
  for (const long long k : ks) {
    // Nominal l, rounded to 1e-9 so that 3 x 0.1 reads 0.3.
    m.l.push_back(std::round(static_cast<double>(k) * every * 1e9) / 1e9);
    std::size_t n = 0;
    for (const auto& r : rows) n += r.contains(k);
    m.n.push_back(n);
    for (const auto& name : names) {
      std::vector<double> xs;
      for (std::size_t s = 0; s < p.complete.size(); ++s)
        if (const auto it = rows[s].find(k); it != rows[s].end())
          xs.push_back(p.complete[s]->series.at(name)[it->second]);
      m.q[name].push_back(analysis::mean_sem(xs));
    }
  }
  return m;
}

double common_snapshot_l(const Analysis& a) {
  const RunData* first = nullptr;
  for (const auto& r : a.runs)
    if (r.status == "complete") {
      first = &r;
      break;
    }
  if (!first) return NaN;
  std::vector<double> candidates = first->snapshot_l;
  std::sort(candidates.rbegin(), candidates.rend());
  for (const double c : candidates) {
    const double l = std::round(c * 1000) / 1000;
    bool everywhere = true;
    for (const auto& r : a.runs)
      if (r.status == "complete" && !snapshot_near(r.snapshot_l, l)) everywhere = false;
    if (everywhere) return l;
  }
  return NaN;
}

double normal_pdf(double x, double mu, double sigma) {
  const double z = (x - mu) / sigma;
  return std::exp(-z * z / 2) / (sigma * std::sqrt(2 * std::numbers::pi));
}

Distribution distribution(const std::string& quantity, const std::vector<double>& xs, int bins) {
  Distribution d;
  d.quantity = quantity;
  d.fit = analysis::fit_lognormal(xs);
  if (!d.fit.ok || !(d.fit.sigma > 0)) return d;
  std::vector<double> logs;
  for (const double x : xs)
    if (std::isfinite(x) && x > 0) logs.push_back(std::log(x));
  d.hist = analysis::histogram(logs, d.fit.mu - 4 * d.fit.sigma, d.fit.mu + 4 * d.fit.sigma, bins);
  for (std::size_t b = 0; b < d.hist.lo.size(); ++b)
    d.fit_density.push_back(normal_pdf((d.hist.lo[b] + d.hist.hi[b]) / 2, d.fit.mu, d.fit.sigma));
  d.ls_fit = analysis::fit_normal_to_histogram(d.hist);
  return d;
}

std::vector<CriticalPoint> critical_points(const Analysis& a) {
  // Every transition parameter, swept or not (the four-dimensional table, phase_4d.hpp).
  const auto transition = sweep::keys_with(&sweep::KeySpec::Roles::transition);
  std::vector<CriticalPoint> out;
  for (const auto& p : a.points) {
    CriticalPoint c;
    for (const auto& ptr : a.axes) c.params[ptr] = leaf(p, ptr);
    for (const auto& ptr : transition) c.params.emplace(ptr, leaf(p, ptr));
    c.D = values(p, order_parameter_field(a.settings.order_parameter));
    c.failed = p.failed;
    c.missing = p.missing;
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace wirepack::report
