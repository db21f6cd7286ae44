#include "report/plot_jobs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

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
  return "[" + num(w.l_min) + ", " + num(w.l_max) + "]";
}

// The same with 3 significant digits, for plot keys.
std::string rounded_window_text(const LWindow& w) {
  char text[64];
  std::snprintf(text, sizeof(text), "[%.3g, %.3g]", w.l_min, w.l_max);
  return text;
}

}  // namespace

std::optional<PlotJob> view_plot(const Analysis& a, const View& v) {
  using plots::Curve;
  std::vector<double> xs;
  for (const auto& p : a.points) {
    const json x = leaf(p, v.pointer);
    if (!x.is_number()) return {};  // only numeric parameters are drawn
    xs.push_back(x.get<double>());
  }
  plots::Panel panel;
  panel.title =
      "D = max of D(l) over l in " + window_text(a.settings.D_window) + ": mean and SEM over seeds";
  panel.xlabel = v.name;
  panel.ylabel = "D";
  panel.y_from_zero = true;
  const auto [lo, hi] = std::minmax_element(xs.begin(), xs.end());
  panel.logx = *lo > 0 && *hi >= 100 * *lo;
  // One curve per combination of the other swept parameters (rows are sorted by them).
  std::string current = "\x01";
  for (const std::size_t i : v.order) {
    const GridPoint& p = a.points[i];
    const std::string title = describe(p, v.others);
    if (title != current) {
      panel.curves.push_back({title, Curve::Style::ErrorLines, {}});
      current = title;
    }
    const auto m = analysis::mean_sem(values(p, &RunData::D));
    panel.curves.back().rows.push_back({leaf(p, v.pointer).get<double>(), m.mean, m.sem});
  }
  PlotJob job;
  job.name = "D_vs_" + v.name;
  job.script =
      plots::script("D against " + v.name + " (paper Fig. 5); data: ../" + job.name + ".csv", "",
                    {panel}, 1, 1, job.name + ".png", 800, 600);
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
      panel.title = "mu = " + num(std::round(d.fit.mu * 1000) / 1000) +
                    ", sigma = " + num(std::round(d.fit.sigma * 1000) / 1000);
    } else {
      panel.title = "no fit";
    }
    panels.push_back(std::move(panel));
  }
  PlotJob job;
  job.name = "distributions_" + point_tag(i, a.points.size());
  job.script =
      plots::script("Distributions at l = " + num(a.distribution_l) + " of grid point " +
                        std::to_string(i) + " with lognormal fits; data: ../distributions.csv",
                    "point " + std::to_string(i) + " at l = " + num(a.distribution_l) + ": " +
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
      "The packing of grid point " + std::to_string(i) + " at l = " + num(a.distribution_l) +
          " (the first run with a snapshot there), two projections, over the shell",
      "point " + std::to_string(i) + " at l = " + num(a.distribution_l) + ": " +
          describe(a.points[i], a.axes.empty() ? a.params : a.axes),
      panels, 1, 2, job.name + ".png", 1000, 520);
  return job;
}

}  // namespace wirepack::report
