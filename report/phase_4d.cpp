#include "report/phase_4d.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "report/csv_table.hpp"
#include "report/plots.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/config/sweep_config.hpp"

namespace wirepack::report {

using json = nlohmann::json;

namespace {

std::vector<std::string> transition_keys() {
  return sweep::keys_with(&sweep::KeySpec::Roles::transition);
}

std::string row_text(const std::vector<std::string>& cells) {
  std::string t;
  for (std::size_t i = 0; i < cells.size(); ++i) t += (i ? "," : "") + cells[i];
  return t + '\n';
}

// "key=value; ..." of the non-transition parameters a row is at.
std::string other_text(const PhaseRow& r) {
  std::string t;
  for (const auto& [ptr, v] : r.other)
    t += (t.empty() ? "" : "; ") + column_name(ptr) + "=" +
         (v.is_string() ? v.get<std::string>() : v.dump());
  return t;
}

}  // namespace

std::vector<PhaseRow> phase_rows(const std::vector<PhaseSource>& sources) {
  std::vector<PhaseRow> rows;
  for (const auto& src : sources) {
    const auto slices = critical_slices(src.axes, src.points, src.resamples, "", src.ranges);
    for (const auto& s : slices) {
      PhaseRow r;
      r.source = src.name;
      r.order_parameter = src.order_parameter;
      r.axis = s.axis;
      r.slice = s;
      // Swept parameters from the slice; the others are one value over the sweep's points.
      for (const auto& [ptr, v] : s.at) {
        if (sweep::find_key(ptr) && sweep::find_key(ptr)->roles.transition)
          r.at[ptr] = v;
        else
          r.other.emplace_back(ptr, v);
      }
      for (const auto& key : transition_keys()) {
        if (key == s.axis || r.at.contains(key) || s.points.empty()) continue;
        const auto& params = src.points[s.points.front()].params;
        const auto it = params.find(key);
        r.at[key] = it == params.end() ? json() : it->second;
      }
      rows.push_back(std::move(r));
    }
  }
  return rows;
}

std::string phase_4d_csv(const std::vector<PhaseRow>& rows) {
  const auto keys = transition_keys();
  std::vector<std::string> header = {"source", "order_parameter", "axis"};
  for (const auto& k : keys) header.push_back(column_name(k));
  for (const char* h :
       {"other", "status", "model", "x_c", "x_c_lo", "x_c_hi", "points", "values", "note"})
    header.push_back(h);
  std::string text = row_text(header);
  for (const auto& r : rows) {
    const auto& f = r.slice.fit;
    std::vector<std::string> cells = {sweep::csv_field(r.source), r.order_parameter,
                                      column_name(r.axis)};
    for (const auto& k : keys) {
      const auto it = r.at.find(k);
      cells.push_back(k == r.axis || it == r.at.end() ? "" : sweep::csv_cell(it->second));
    }
    for (const auto& c :
         {sweep::csv_field(other_text(r)), sweep::csv_field(f.status), f.model,
          sweep::csv_number(f.x_c), sweep::csv_number(f.x_c_lo), sweep::csv_number(f.x_c_hi),
          std::to_string(f.points), std::to_string(f.values), sweep::csv_field(f.note)})
      cells.push_back(c);
    text += row_text(cells);
  }
  return text;
}

std::vector<std::pair<std::string, std::string>> phase_4d_plots(const std::vector<PhaseRow>& rows) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& axis : transition_keys()) {
    std::vector<const PhaseRow*> ok;
    for (const auto& r : rows)
      if (r.axis == axis && r.slice.fit.status == "ok") ok.push_back(&r);
    if (ok.size() < 2) continue;
    // x: the transition parameter with the most distinct numeric values among these rows, on a
    // tie the one that leaves the fewest curves (combinations of the rest).
    std::string x_key;
    std::size_t most = 0, fewest = 0;
    for (const auto& k : transition_keys()) {
      if (k == axis) continue;
      std::set<double> seen;
      std::set<std::string> rest;
      for (const auto* r : ok) {
        if (const auto it = r->at.find(k); it != r->at.end() && it->second.is_number())
          seen.insert(it->second.get<double>());
        std::string key = other_text(*r);
        for (const auto& [k2, v] : r->at)
          if (k2 != k) {
            key += '\x1f';
            key += v.dump();
          }
        rest.insert(key);
      }
      if (seen.size() > most || (seen.size() == most && rest.size() < fewest)) {
        most = seen.size();
        fewest = rest.size();
        x_key = k;
      }
    }
    if (most < 2) continue;
    // One curve per combination of the other parameters (and the non-transition ones), and per
    // source where the rows come from several: their protocols (l window, seeds) may differ, so
    // their points are not joined.
    std::set<std::string> sources;
    for (const auto* r : ok) sources.insert(r->source);
    std::map<std::string, plots::Curve> curves;
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    std::set<double> grid_x;  // the x values of the points: the ticks, while there are few
    for (const auto* r : ok) {
      const auto xit = r->at.find(x_key);
      if (xit == r->at.end() || !xit->second.is_number()) continue;
      std::string label;
      for (const auto& [k, v] : r->at)
        if (k != x_key)
          label += (label.empty() ? "" : ", ") + column_name(k) + " = " + sweep::csv_cell(v);
      if (const std::string o = other_text(*r); !o.empty())
        label += (label.empty() ? "" : ", ") + o;
      if (sources.size() > 1) label += " (" + r->source + ")";
      plots::Curve& c = curves[label];
      c.title = label;
      c.style = plots::Curve::Style::IntervalLines;
      const double x = xit->second.get<double>();
      const auto& f = r->slice.fit;
      c.rows.push_back({x, f.x_c, f.x_c_lo, f.x_c_hi});  // the bar: the 95 % interval
      grid_x.insert(x);
      lo = std::min(lo, x);
      hi = std::max(hi, x);
    }
    plots::Panel p;
    p.title = "critical " + column_name(axis) + " against " + column_name(x_key);
    p.xlabel = column_name(x_key);
    p.ylabel = column_name(axis) + "_c (bars: 95 % bootstrap interval)";
    p.logx = lo > 0 && hi >= 10 * lo;
    p.margins = true;
    if (grid_x.size() <= 8) p.xtics.assign(grid_x.begin(), grid_x.end());
    p.logy = fitted_in_log(axis);
    p.key = "outside bottom center";
    // Curves that share an x value would hide each other's bars: the n curves that share one
    // with another are drawn shifted, the k-th of them by (k - (n - 1) / 2) steps, all within
    // 8 % of the x span (of its decades on a log axis); the data keep their x, and a curve that
    // shares none stays where it is.
    std::map<double, int> curves_at;
    for (auto& [label, c] : curves) {
      std::set<double> xs;
      for (const auto& r : c.rows) xs.insert(r[0]);
      for (const double x : xs) ++curves_at[x];
    }
    const auto shares = [&](const plots::Curve& c) {
      return std::any_of(c.rows.begin(), c.rows.end(),
                         [&](const plots::Row& r) { return curves_at[r[0]] > 1; });
    };
    double n = 0;
    for (const auto& [label, c] : curves) n += shares(c);
    const double span = p.logx ? std::log10(hi / lo) : hi - lo;
    const double step = span * std::min(0.02, 0.08 / std::max(1.0, n - 1));
    double k = 0;
    for (auto& [label, c] : curves) {
      std::sort(c.rows.begin(), c.rows.end());
      if (shares(c)) c.x_offset = (k++ - (n - 1) / 2) * step;
      p.curves.push_back(std::move(c));
    }
    const std::string name = "phase4d_" + column_name(axis);
    out.emplace_back(name, plots::script("The four-dimensional phase diagram: x_c of " +
                                             column_name(axis) + " from ../phase_diagram_4d.csv",
                                         "", {p}, 1, 1, name + ".png", 900, 700));
  }
  return out;
}

}  // namespace wirepack::report
