#include "report/critical_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "report/csv_table.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/format.hpp"
#include "sweep/running/sweep_manifest.hpp"

namespace wirepack::report {

using json = nlohmann::json;
using analysis::NaN;
using sweep::canonical_json;
using sweep::csv_field;

namespace {

std::string join_row(const std::vector<std::string>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size(); ++i) s += (i ? "," : "") + cells[i];
  return s + '\n';
}

double mean_of(const std::vector<double>& v) {
  return analysis::mean_sem(v).mean;
}

const json& param(const CriticalPoint& p, const std::string& ptr) {
  static const json none;
  const auto it = p.params.find(ptr);
  return it == p.params.end() ? none : it->second;
}

}  // namespace

bool is_transition_axis(const std::string& pointer) {
  const sweep::KeySpec* spec = sweep::find_key(pointer);
  return spec && spec->roles.transition;
}

bool fitted_in_log(const std::string& pointer) {
  const sweep::KeySpec* spec = sweep::find_key(pointer);
  return spec && spec->roles.log_scale;
}

std::vector<analysis::CriticalSample> slice_samples(const CriticalSlice& slice,
                                                    const std::vector<CriticalPoint>& points) {
  std::vector<analysis::CriticalSample> out;
  for (const std::size_t i : slice.points) {
    const json& x = param(points[i], slice.axis);
    if (!x.is_number()) continue;
    if (slice.range &&
        (x.get<double>() < slice.range->first || x.get<double>() > slice.range->second))
      continue;
    out.push_back({x.get<double>(), points[i].D});
  }
  return out;
}

std::vector<CriticalSlice> critical_slices(
    const std::vector<std::string>& axes, const std::vector<CriticalPoint>& points, int resamples,
    const std::string& only, const std::map<std::string, std::pair<double, double>>& ranges) {
  std::vector<CriticalSlice> slices;
  for (const auto& axis : axes) {
    if (!is_transition_axis(axis) || (!only.empty() && axis != only)) continue;
    std::vector<std::string> keys;  // canonical `at` of each slice of this axis
    const std::size_t first = slices.size();
    for (std::size_t i = 0; i < points.size(); ++i) {
      std::vector<std::pair<std::string, json>> at;
      for (const auto& other : axes)
        if (other != axis) at.emplace_back(other, param(points[i], other));
      json key = json::array();
      for (const auto& [ptr, v] : at) key.push_back(v);
      const std::string k = canonical_json(key);
      auto it = std::find(keys.begin(), keys.end(), k);
      if (it == keys.end()) {
        keys.push_back(k);
        CriticalSlice s;
        s.axis = axis;
        s.at = at;
        s.options.log_x = fitted_in_log(axis);
        s.options.resamples = resamples;
        if (const auto r = ranges.find(axis); r != ranges.end()) s.range = r->second;
        slices.push_back(std::move(s));
        it = keys.end() - 1;
      }
      CriticalSlice& s = slices[first + static_cast<std::size_t>(it - keys.begin())];
      s.points.push_back(i);
      s.failed += points[i].failed;
      s.missing += points[i].missing;
    }
  }
  for (auto& s : slices) {
    s.fit = analysis::fit_critical(slice_samples(s, points), s.options);
    if (s.range)
      s.fit.note += (s.fit.note.empty() ? "" : "; ") + std::string("fitted on [") +
                    sweep::csv_number(s.range->first) + ", " + sweep::csv_number(s.range->second) +
                    "] (critical_ranges)";
    if (s.failed + s.missing > 0)
      s.fit.note += (s.fit.note.empty() ? "" : "; ") + std::to_string(s.failed) + " failed and " +
                    std::to_string(s.missing) + " missing run(s) left out";
  }
  return slices;
}

std::string critical_csv(const std::vector<std::string>& axes,
                         const std::vector<CriticalSlice>& slices) {
  std::vector<std::string> header = {"axis"};
  for (const auto& a : axes) header.push_back(column_name(a));
  for (const char* h : {"scale",      "points",       "values",   "n_failed",  "n_missing",
                        "x_min",      "x_max",        "status",   "model",     "side",
                        "x_c",        "x_c_lo",       "x_c_hi",   "b",         "b_lo",
                        "b_hi",       "width",        "D0",       "D_plateau", "aic_continuous",
                        "aic_smooth", "aic_constant", "aic_line", "resamples", "note"})
    header.push_back(h);
  std::string text = join_row(header);
  for (const auto& s : slices) {
    const auto& f = s.fit;
    std::vector<std::string> row = {column_name(s.axis)};
    for (const auto& a : axes) {
      std::string c;
      for (const auto& [ptr, v] : s.at)
        if (ptr == a) c = sweep::csv_cell(v);
      row.push_back(c);
    }
    const std::vector<std::string> rest = {s.options.log_x ? "log10" : "linear",
                                           std::to_string(f.points),
                                           std::to_string(f.values),
                                           std::to_string(s.failed),
                                           std::to_string(s.missing),
                                           sweep::csv_number(f.x_min),
                                           sweep::csv_number(f.x_max),
                                           csv_field(f.status),
                                           f.model,
                                           f.side > 0   ? "above"
                                           : f.side < 0 ? "below"
                                                        : "",
                                           sweep::csv_number(f.x_c),
                                           sweep::csv_number(f.x_c_lo),
                                           sweep::csv_number(f.x_c_hi),
                                           sweep::csv_number(f.b),
                                           sweep::csv_number(f.b_lo),
                                           sweep::csv_number(f.b_hi),
                                           sweep::csv_number(f.width),
                                           sweep::csv_number(f.D0),
                                           sweep::csv_number(f.D_plateau),
                                           sweep::csv_number(f.aic_continuous),
                                           sweep::csv_number(f.aic_smooth),
                                           sweep::csv_number(f.aic_constant),
                                           sweep::csv_number(f.aic_line),
                                           std::to_string(f.resamples),
                                           csv_field(f.note)};
    row.insert(row.end(), rest.begin(), rest.end());
    text += join_row(row);
  }
  return text;
}

bool has_phase_diagram(const std::vector<std::string>& axes) {
  return axes.size() == 2 && (is_transition_axis(axes[0]) || is_transition_axis(axes[1]));
}

std::string phase_diagram_csv(const std::vector<std::string>& axes,
                              const std::vector<CriticalSlice>& slices) {
  if (!has_phase_diagram(axes)) return "";
  std::string text = join_row(
      {"axis", "across", "across_value", "status", "model", "x_c", "x_c_lo", "x_c_hi", "note"});
  for (const auto& s : slices) {
    if (s.at.size() != 1) continue;
    text += join_row({column_name(s.axis), column_name(s.at[0].first),
                      sweep::csv_cell(s.at[0].second), csv_field(s.fit.status), s.fit.model,
                      sweep::csv_number(s.fit.x_c), sweep::csv_number(s.fit.x_c_lo),
                      sweep::csv_number(s.fit.x_c_hi), csv_field(s.fit.note)});
  }
  return text;
}

std::vector<std::pair<std::string, std::string>> phase_diagram_plots(
    const std::vector<std::string>& axes, const std::vector<CriticalPoint>& points,
    const std::vector<CriticalSlice>& slices) {
  std::vector<std::pair<std::string, std::string>> out;
  if (!has_phase_diagram(axes)) return out;
  for (const auto& axis : axes) {
    if (!is_transition_axis(axis)) continue;
    const std::string across = axis == axes[0] ? axes[1] : axes[0];
    // D of every point at (across, axis); both must be numbers.
    std::vector<std::array<double, 3>> heat;
    bool numeric = true;
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& p : points) {
      const json &x = param(p, across), &y = param(p, axis);
      if (!x.is_number() || !y.is_number()) {
        numeric = false;
        break;
      }
      lo = std::min(lo, x.get<double>());
      hi = std::max(hi, x.get<double>());
      const double D = mean_of(p.D);
      if (std::isfinite(D)) heat.push_back({x.get<double>(), y.get<double>(), D});
    }
    if (!numeric || heat.empty()) continue;
    std::vector<std::array<double, 4>> line;  // across, x_c, lo, hi
    for (const auto& s : slices)
      if (s.axis == axis && s.at.size() == 1 && s.at[0].second.is_number() && s.fit.status == "ok")
        line.push_back({s.at[0].second.get<double>(), s.fit.x_c, s.fit.x_c_lo, s.fit.x_c_hi});
    std::sort(line.begin(), line.end());
    const std::string name = "phase_" + column_name(axis);
    std::ostringstream g;
    g << "# Phase diagram: D (mean over seeds, colour) over " << column_name(across) << " and "
      << column_name(axis) << ", with the critical " << column_name(axis)
      << " (line) and its 95 % bootstrap interval (band); data: ../curves.csv, "
         "../phase_diagram.csv\n"
      << "# Render: gnuplot " << name << ".gp\n"
      << "if (!exists(\"out\")) out = \"" << name << ".png\"\n"
      << "if (strstrt(GPVAL_TERMINALS, \"pngcairo\") > 0) {\n"
      << "  set terminal pngcairo noenhanced size 900,700\n"
      << "} else {\n"
      << "  set terminal png noenhanced size 900,700\n"
      << "}\n"
      << "set output out\n"
      << "set title \"D and the critical " << column_name(axis) << " against "
      << column_name(across) << "\"\n"
      << "set xlabel \"" << column_name(across) << "\"\nset ylabel \"" << column_name(axis)
      << "\"\n"
      << "set cblabel \"D (mean over seeds)\"\nset palette rgbformulae 33,13,10\n"
      << "set key outside top center horizontal\nset offsets graph 0.05, graph 0.05, graph "
         "0.05, graph 0.05\n";
    if (lo > 0 && hi >= 100 * lo) g << "set logscale x\n";
    if (fitted_in_log(axis)) g << "set logscale y\n";
    g << "$D << EOD\n";
    for (const auto& r : heat)
      g << sweep::csv_number(r[0]) << ' ' << sweep::csv_number(r[1]) << ' '
        << sweep::csv_number(r[2]) << '\n';
    g << "EOD\n";
    if (!line.empty()) {
      g << "$C << EOD\n";
      for (const auto& r : line)
        g << sweep::csv_number(r[0]) << ' ' << sweep::csv_number(r[1]) << ' '
          << sweep::csv_number(r[2]) << ' ' << sweep::csv_number(r[3]) << '\n';
      g << "EOD\n";
    }
    g << "plot $D using 1:2:3 with points pointtype 5 pointsize 3 palette title \"D\"";
    if (!line.empty())
      g << ", \\\n     $C using 1:3:4 with filledcurves fillstyle transparent solid 0.25 "
           "fillcolor rgb \"black\" title \"95 % interval of x_c\", \\\n     $C using 1:2 with "
           "linespoints linewidth 2 pointtype 7 linecolor rgb \"black\" title \"x_c\"";
    g << '\n';
    out.emplace_back(name, g.str());
  }
  return out;
}

}  // namespace wirepack::report
