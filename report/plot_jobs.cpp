#include "report/plot_jobs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "analysis/critical.hpp"
#include "analysis/stats.hpp"
#include "report/csv_table.hpp"
#include "report/plots.hpp"

namespace wirepack::report {

using json = nlohmann::json;
using analysis::NaN;

namespace {

// "mu_s = 0.5, eps = 1000" for the given parameters of a point.
std::string describe(const GridPoint& p, const std::vector<std::string>& pointers) {
  std::string s;
  for (const auto& ptr : pointers)
    s += (s.empty() ? "" : ", ") + column_name(ptr) + " = " + text_of(leaf(p, ptr));
  return s;
}

std::string point_tag(std::size_t i, std::size_t points) {
  const std::size_t width = std::to_string(points > 0 ? points - 1 : 0).size();
  std::string n = std::to_string(i);
  return "p" + std::string(width - std::min(width, n.size()), '0') + n;
}

std::string window_text(const LWindow& w) {
  return "[" + sweep::csv_number(w.l_min) + ", " + sweep::csv_number(w.l_max) + "]";
}

// The same with 3 significant digits, for plot keys.
std::string rounded_window_text(const LWindow& w) {
  char text[64];
  std::snprintf(text, sizeof(text), "[%.3g, %.3g]", w.l_min, w.l_max);
  return text;
}

}  // namespace

namespace {

// The fitted transition of a slice as a curve over its range, in x (200 points, log-spaced when
// the fit is in log10 x); empty without a transition model.
std::vector<plots::Row> model_rows(const CriticalSlice& slice) {
  const analysis::CriticalResult& f = slice.fit;
  std::vector<plots::Row> rows;
  if (f.model.empty() || !std::isfinite(f.x_min) || !std::isfinite(f.x_max)) return rows;
  const bool log_x = slice.options.log_x;
  const double u0 = log_x ? std::log10(f.x_min) : f.x_min;
  const double u1 = log_x ? std::log10(f.x_max) : f.x_max;
  for (int k = 0; k <= 200; ++k) {
    const double u = u0 + (u1 - u0) * k / 200;
    const double D = f.model == "continuous" ? analysis::continuous_model(u, f.continuous)
                                             : analysis::smooth_model(u, f.smooth);
    rows.push_back({log_x ? std::pow(10.0, u) : u, D, NaN, NaN});
  }
  return rows;
}

// Width of the main panel of D against a parameter, as a fraction of the canvas; the inset
// about x_c takes the rest, beside it.
constexpr double kMainWidth = 0.66;

// x range of the inset: from the second grid value below x_c to the second above (or the ends),
// widened to hold x_c's interval.
std::array<double, 2> inset_range(std::vector<double> xs, const analysis::CriticalResult& f) {
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  const auto above = std::upper_bound(xs.begin(), xs.end(), f.x_c);
  const std::size_t i = static_cast<std::size_t>(above - xs.begin());  // first grid value > x_c
  double lo = xs[i >= 2 ? i - 2 : 0];
  double hi = xs[std::min(xs.size() - 1, i + 1)];
  if (std::isfinite(f.x_c_lo)) lo = std::min(lo, f.x_c_lo);
  if (std::isfinite(f.x_c_hi)) hi = std::max(hi, f.x_c_hi);
  return {lo, hi};
}

}  // namespace

std::optional<PlotJob> view_plot(const Analysis& a, const View& v,
                                 const std::vector<CriticalSlice>& slices) {
  using plots::Curve;
  std::vector<double> xs;
  for (const auto& p : a.points) {
    const json x = leaf(p, v.pointer);
    if (!x.is_number()) return {};  // only numeric parameters are drawn
    xs.push_back(x.get<double>());
  }
  const std::string op = a.settings.order_parameter;  // D, D_chord or D_kappa
  const bool literal_too = op != "D";
  plots::Panel panel;
  panel.title = op + " = max of " + op + "(l) over l in " + window_text(a.settings.D_window) +
                ": mean and SEM over seeds";
  panel.xlabel = v.name;
  panel.ylabel = op;
  panel.y_from_zero = true;
  const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
  panel.logx = *lo > 0 && *hi >= 100 * *lo;
  // One curve per combination of the other swept parameters (rows are sorted by them); with
  // another order parameter, the literal D of each combination after them.
  std::vector<Curve> literal;
  std::string current = "\x01";
  for (const std::size_t i : v.order) {
    const GridPoint& p = a.points[i];
    const std::string title = describe(p, v.others);
    if (title != current) {
      // Named in the key when the literal D is beside it.
      const std::string named = !literal_too ? title : title.empty() ? op : title + ", " + op;
      panel.curves.push_back({named, Curve::Style::ErrorLines, {}});
      literal.push_back(
          {title.empty() ? "literal D" : title + ", literal D", Curve::Style::ErrorLines, {}});
      current = title;
    }
    const double x = leaf(p, v.pointer).get<double>();
    const auto m = analysis::mean_sem(values(p, order_parameter_field(op)));
    panel.curves.back().rows.push_back({x, m.mean, m.sem});
    const auto d = analysis::mean_sem(values(p, &RunData::D));
    literal.back().rows.push_back({x, d.mean, d.sem});
  }
  if (literal_too) panel.curves.insert(panel.curves.end(), literal.begin(), literal.end());

  // The fitted transition along this parameter, when it is the only one swept.
  std::vector<plots::Panel> panels;
  const CriticalSlice* slice = nullptr;
  for (const auto& s : slices)
    if (v.others.empty() && s.axis == v.pointer && s.at.empty()) slice = &s;
  const auto model = slice ? model_rows(*slice) : std::vector<plots::Row>{};
  if (!model.empty() && std::isfinite(slice->fit.x_c)) {
    const analysis::CriticalResult& f = slice->fit;
    // 3 significant digits: a key entry wider than the panel hides the whole key.
    const auto g3 = [](double x) {
      char text[32];
      std::snprintf(text, sizeof(text), "%.3g", x);
      return std::string(text);
    };
    std::string fit_title = "fit: " + v.name + "_c = " + g3(f.x_c);
    if (std::isfinite(f.x_c_lo) && std::isfinite(f.x_c_hi))
      fit_title += " [" + g3(f.x_c_lo) + ", " + g3(f.x_c_hi) + "]";
    const Curve fit{fit_title, Curve::Style::Lines, model};
    panel.curves.insert(panel.curves.begin() + 1, fit);
    panel.vlines = {f.x_c};
    if (std::isfinite(f.x_c_lo) && std::isfinite(f.x_c_hi)) panel.bands = {{f.x_c_lo, f.x_c_hi}};
    // The inset: the order parameter and the fit about x_c, x_c's interval shaded.
    plots::Panel inset;
    inset.title = "about " + v.name + "_c (" + f.model + ")";  // a longer one ran off the page
    inset.key = "off";
    inset.logx = panel.logx;
    inset.curves = {panel.curves[0], fit};
    inset.vlines = panel.vlines;
    inset.bands = panel.bands;
    inset.xrange = inset_range(xs, f);
    // The inset goes beside the main panel, not over it: over it, it hid data on either side
    // once the curve came back down at its far end (Fig. 5b at mu_s = 1) or had points just
    // past x_c. The key below the main panel.
    panel.key = "outside bottom center horizontal";
    panel.place = std::array<double, 4>{0, 0, kMainWidth, 1};
    inset.place = std::array<double, 4>{kMainWidth, 0.3, 1 - kMainWidth, 0.45};
    panels = {panel, inset};
  } else {
    panels = {panel};
  }
  PlotJob job;
  job.name = "D_vs_" + v.name;
  job.script = plots::script(op + " against " + v.name + " (paper Fig. 5); data: ../" + job.name +
                                 ".csv" + (model.empty() ? "" : ", ../critical.csv"),
                             "", panels, 1, 1, job.name + ".png", 800, 600);
  return job;
}

PlotJob scaling_plot(const Analysis& a, std::size_t i, const MeanSeries& m,
                     const std::vector<ExponentFit>& fits) {
  using plots::Curve;
  std::vector<plots::Panel> panels;
  for (std::size_t k = 0; k < exponent_specs().size(); ++k) {
    const auto& spec = exponent_specs()[k];
    const auto& f = fits[k].fit;
    plots::Panel panel;
    panel.logx = panel.logy = true;
    panel.xlabel = "l";
    panel.ylabel = spec.series;
    panel.key = "bottom right";
    Curve data{"seed mean", Curve::Style::Points, {}};
    for (std::size_t j = 0; j < m.l.size(); ++j)
      data.rows.push_back({m.l[j], m.q.at(spec.series)[j].mean, NaN});
    panel.curves.push_back(data);
    if (f.ok) {
      const double se = reported_stderr(fits[k]);
      char title[96];
      std::snprintf(title, sizeof(title), "%s = %.3f +/- %.2g (%s)", spec.name.c_str(), f.exponent,
                    se, use_bootstrap(fits[k]) ? "bootstrap" : "OLS");
      panel.title = title;
      const auto y = [&](double l) { return std::exp(f.log_prefactor) * std::pow(l, f.exponent); };
      panel.curves.push_back({"fit on " + rounded_window_text({f.l_min, f.l_max}),
                              Curve::Style::Lines,
                              {{f.l_min, y(f.l_min), NaN}, {f.l_max, y(f.l_max), NaN}}});
    } else {
      panel.title = spec.name + ": no fit";
    }
    panels.push_back(std::move(panel));
  }
  PlotJob job;
  job.name = "scaling_" + point_tag(i, a.points.size());
  job.script = plots::script("Scaling with l of grid point " + std::to_string(i) +
                                 " (log-log, fitted power laws); data: ../series.csv, "
                                 "../exponents.csv",
                             "point " + std::to_string(i) + ": " +
                                 describe(a.points[i], a.axes.empty() ? a.params : a.axes),
                             panels, 2, 3, job.name + ".png", 1500, 900);
  return job;
}

PlotJob distribution_plot(const Analysis& a, std::size_t i, const std::array<Distribution, 2>& ds) {
  using plots::Curve;
  std::vector<plots::Panel> panels;
  for (const Distribution& d : ds) {
    plots::Panel panel;
    panel.xlabel = d.quantity == "kappa2" ? "ln(kappa^2 / <kappa^2>)" : "ln(Lambda / r)";
    panel.ylabel = "probability density";
    panel.y_from_zero = true;
    Curve bars{"histogram (n = " + std::to_string(d.fit.n) + ")", Curve::Style::Boxes, {}};
    for (std::size_t b = 0; b < d.hist.lo.size(); ++b)
      bars.rows.push_back(
          {(d.hist.lo[b] + d.hist.hi[b]) / 2, d.hist.density[b], d.hist.hi[b] - d.hist.lo[b]});
    panel.curves.push_back(bars);
    if (!d.hist.lo.empty()) {
      Curve fit{"lognormal fit", Curve::Style::Lines, {}};
      const double lo = d.hist.lo.front(), hi = d.hist.hi.back();
      for (int s = 0; s <= 200; ++s) {
        const double x = lo + (hi - lo) * s / 200;
        fit.rows.push_back({x, normal_pdf(x, d.fit.mu, d.fit.sigma), NaN});
      }
      panel.curves.push_back(fit);
      panel.title = "mu = " + sweep::csv_number(std::round(d.fit.mu * 1000) / 1000) +
                    ", sigma = " + sweep::csv_number(std::round(d.fit.sigma * 1000) / 1000);
    } else {
      panel.title = "no fit";
    }
    panels.push_back(std::move(panel));
  }
  PlotJob job;
  job.name = "distributions_" + point_tag(i, a.points.size());
  job.script = plots::script(
      "Distributions at l = " + sweep::csv_number(a.distribution_l) + " of grid point " +
          std::to_string(i) + " with lognormal fits; data: ../distributions.csv",
      "point " + std::to_string(i) + " at l = " + sweep::csv_number(a.distribution_l) + ": " +
          describe(a.points[i], a.axes.empty() ? a.params : a.axes),
      panels, 1, 2, job.name + ".png", 1200, 500);
  return job;
}

std::optional<PlotJob> packing_plot(const Analysis& a, std::size_t i, const Samples& s) {
  using plots::Curve;
  if (s.wire.empty() || !(s.R > 0)) return std::nullopt;
  std::vector<plots::Panel> panels;
  for (const int k : {1, 2}) {
    plots::Panel panel;
    panel.title = k == 1 ? "from the north pole" : "from the side (the hole at the bottom)";
    panel.xlabel = "x / R";
    panel.ylabel = k == 1 ? "y / R" : "z / R";
    panel.key = "off";
    panel.equal_axes = true;
    Curve cavity{"", s.shell.empty() ? Curve::Style::Lines : Curve::Style::Dots, {}};
    for (const auto& p : s.shell) cavity.rows.push_back({p[0] / s.R, p[k] / s.R, NaN});
    for (int t = 0; s.shell.empty() && t <= 120; ++t) {
      const double phi = 2.0 * std::numbers::pi * t / 120;
      cavity.rows.push_back({std::cos(phi), std::sin(phi), NaN});
    }
    Curve wire{"", Curve::Style::Lines, {}};
    for (const auto& p : s.wire) wire.rows.push_back({p[0] / s.R, p[k] / s.R, NaN});
    panel.curves = {cavity, wire};
    panels.push_back(std::move(panel));
  }
  PlotJob job;
  job.name = "packing_" + point_tag(i, a.points.size());
  job.script = plots::script(
      "The packing of grid point " + std::to_string(i) +
          " at l = " + sweep::csv_number(a.distribution_l) +
          " (the first run with a snapshot there), two projections, over the shell",
      "point " + std::to_string(i) + " at l = " + sweep::csv_number(a.distribution_l) + ": " +
          describe(a.points[i], a.axes.empty() ? a.params : a.axes),
      panels, 1, 2, job.name + ".png", 1000, 520);
  return job;
}

}  // namespace wirepack::report
