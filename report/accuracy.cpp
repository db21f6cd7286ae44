#include "report/accuracy.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "report/csv_table.hpp"
#include "report/plots.hpp"
#include "report/reductions.hpp"
#include "report/sweep_dir.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/errors.hpp"
#include "sweep/format.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/runfile/series.hpp"
#include "sweep/running/sweep_manifest.hpp"

namespace wirepack::report {

namespace fs = std::filesystem;
using json = nlohmann::json;
using sweep::canonical_json;
using sweep::InputError;
using sweep::point_scene;
using sweep::read_run_file;
using sweep::run_id;
using sweep::RunRecord;
using sweep::RunStatus;
using sweep::write_file_atomic;

namespace {

// The compared series (relative RMS errors): those the series list marks, in its order.
const std::vector<std::string>& compared_series() {
  static const std::vector<std::string> names = sweep::accuracy_series();
  return names;
}

// The study names U_b_hat, K (err_UK), N (scaled by ell / r) among the compared series, and reads
// l, D, steps and wall_s: a series list without them is a programming error.
void check_accuracy_series() {
  const auto& c = compared_series();
  for (const char* name : {"U_b_hat", "K", "N"})
    if (std::find(c.begin(), c.end(), name) == c.end())
      throw std::logic_error(std::string("accuracy: series ") + name + " is not compared");
  for (const char* name : {"l", "D", "steps", "wall_s"})
    if (!sweep::find_series_def(name))
      throw std::logic_error(std::string("accuracy: series ") + name + " is not recorded");
}

struct Run {
  std::string file;   // as found (DIR/runs/NAME.h5)
  std::string scene;  // canonical config without knobs, seed, output
  std::string label;  // scene in words, e.g. "shell=rigid mu_s=0"
  std::uint64_t seed = 0;
  std::vector<double> knob;                           // values of accuracy_knobs()
  std::map<std::string, std::vector<double>> series;  // l and the compared series, D
  double l_end = NaN, steps = NaN, wall_s = NaN;
  double D_max = NaN;  // over the window
};

double last(const std::vector<double>& v) {
  return v.empty() ? NaN : v.back();
}

// Reads every complete run of `dirs` (each id once, first found first).
std::vector<Run> read_runs(const std::vector<std::string>& dirs, const LWindow& w) {
  std::vector<Run> runs;
  std::set<std::string> ids;
  for (const auto& d : dirs) {
    const fs::path runs_dir = fs::path(d) / "runs";
    std::error_code ec;
    if (!fs::is_directory(runs_dir, ec))
      throw InputError(d + ": not a sweep directory (no runs/ in it)");
    for (const auto& name : list_run_files(d).files) {
      const fs::path f = fs::path(d) / name;
      RunRecord rec;
      try {
        rec = read_run_file(f.string());
      } catch (const std::exception&) {
        continue;  // unreadable: not part of the study
      }
      if (rec.status != RunStatus::Complete) continue;
      if (!ids.insert(run_id(rec.config)).second) continue;
      Run r;
      r.file = f.string();
      r.seed = rec.config.value("seed", std::uint64_t{0});
      json scene = point_scene(rec.config);
      for (const auto& k : accuracy_knobs()) {
        const auto ptr = json::json_pointer("/numerics/" + k);
        r.knob.push_back(scene.contains(ptr) ? scene[ptr].get<double>() : NaN);
        if (scene.contains(ptr)) scene["numerics"].erase(k);
      }
      r.scene = canonical_json(scene);
      const std::size_t rows = series_rows(rec);
      r.series["l"] = series_column(rec, "l", rows);
      for (const auto& s : compared_series()) r.series[s] = series_column(rec, s, rows);
      // N counts element pairs: N ell / r (contacts per wire radius) compares element lengths.
      const double ell = r.knob[0];
      const double wire_r = rec.config.contains(json::json_pointer("/wire/radius"))
                                ? rec.config[json::json_pointer("/wire/radius")].get<double>()
                                : NaN;
      for (auto& n : r.series["N"]) n *= ell / wire_r;
      r.series["D"] = series_column(rec, "D", rows);
      r.l_end = last(r.series["l"]);
      r.steps = last(series_column(rec, "steps", rows));
      r.wall_s = last(series_column(rec, "wall_s", rows));
      double dmax = -1;
      for (const double D : values_in_window(r.series["l"], r.series["D"], w))
        dmax = std::max(dmax, D);
      if (dmax >= 0) r.D_max = dmax;
      runs.push_back(std::move(r));
    }
  }
  return runs;
}

// Labels: the scene parameters that differ between the scenes found, as "key=value ...".
void label_scenes(std::vector<Run>& runs) {
  std::map<std::string, std::map<std::string, json>> leaves;  // scene -> pointer -> value
  for (const auto& r : runs) {
    if (leaves.contains(r.scene)) continue;
    const json flat = json::parse(r.scene).flatten();
    auto& m = leaves[r.scene];
    for (const auto& [k, v] : flat.items()) m[k] = v;
  }
  std::set<std::string> varying;
  for (const auto& [scene, m] : leaves)
    for (const auto& [k, v] : m)
      for (const auto& [other, m2] : leaves) {
        const auto it = m2.find(k);
        if (it == m2.end() || it->second != v) varying.insert(k);
      }
  if (varying.empty()) {  // one scene: say which, by the schema's label keys (mu_s, shell)
    const auto keys = sweep::keys_with(&sweep::KeySpec::Roles::label);
    varying.insert(keys.begin(), keys.end());
  }
  for (auto& r : runs) {
    std::string label;
    const auto& m = leaves[r.scene];
    for (const auto& k : varying) {
      const auto it = m.find(k);
      const std::string name = k.substr(k.rfind('/') + 1);
      const std::string value = it == m.end() ? "-"
                                : it->second.is_number()
                                    ? sweep::csv_number(it->second.get<double>())
                                : it->second.is_string() ? it->second.get<std::string>()
                                                         : it->second.dump();
      label += (label.empty() ? "" : " ") + name + "=" + value;
    }
    r.label = label.empty() ? "scene" : label;
  }
}

// The most frequent value of each knob among `runs` (ties: the smallest).
std::vector<double> centre_values(const std::vector<const Run*>& family) {
  std::vector<double> out;
  for (std::size_t k = 0; k < accuracy_knobs().size(); ++k) {
    std::map<double, int> count;
    for (const Run* r : family) ++count[r->knob[k]];
    double best = NaN;
    int n = 0;
    for (const auto& [v, c] : count)
      if (c > n) best = v, n = c;
    out.push_back(best);
  }
  return out;
}

bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

struct Row {
  const Run* run;
  const Run* ref;
  std::string knob;  // a knob name, "combined" or "seed"
  double value;
  double l_to = NaN;              // end of the error window
  std::vector<double> errs = {};  // relative RMS errors of compared_series(), in order
  double err_UK = NaN;            // the larger of the U_b_hat and K errors
};

// The errors of `row.run` against `row.ref` over [w.l_min, min(w.l_max, both l_end)], once.
void compare(Row& row, const LWindow& w) {
  const Run& r = *row.run;
  const Run& ref = *row.ref;
  row.l_to = std::min({w.l_max, r.l_end, ref.l_end});
  row.errs.clear();
  for (const auto& s : compared_series())
    row.errs.push_back(relative_rms_error(r.series.at("l"), r.series.at(s), ref.series.at("l"),
                                          ref.series.at(s), w.l_min, row.l_to));
  const auto err_of = [&](const std::string& name) {
    const auto& c = compared_series();
    return row.errs[std::find(c.begin(), c.end(), name) - c.begin()];
  };
  const double eU = err_of("U_b_hat"), eK = err_of("K");
  row.err_UK = std::isfinite(eU) && std::isfinite(eK) ? std::max(eU, eK) : NaN;
}

std::string csv_text(const std::vector<Row>& rows, const LWindow& w) {
  std::ostringstream out;
  const auto& cols = accuracy_columns();
  for (std::size_t i = 0; i < cols.size(); ++i) out << (i ? "," : "") << cols[i];
  out << '\n';
  for (const Row& row : rows) {
    const Run& r = *row.run;
    const Run& ref = *row.ref;
    std::string label = r.label;
    if (label.find(',') != std::string::npos) label = "\"" + label + "\"";
    out << label << ',' << r.seed << ',' << row.knob << ',' << sweep::csv_number(row.value) << ','
        << (row.run == row.ref ? 1 : 0);
    for (const double k : r.knob) out << ',' << sweep::csv_number(k);
    out << ',' << sweep::csv_number(r.l_end) << ',' << sweep::csv_number(r.steps) << ','
        << sweep::csv_number(r.wall_s) << ',' << sweep::csv_number(r.wall_s / ref.wall_s) << ','
        << sweep::csv_number(r.D_max) << ',' << sweep::csv_number(std::abs(r.D_max - ref.D_max));
    for (const double e : row.errs) out << ',' << sweep::csv_number(e);
    out << ',' << sweep::csv_number(row.err_UK) << ',' << sweep::csv_number(w.l_min) << ','
        << sweep::csv_number(row.l_to) << ',' << fs::path(r.file).filename().string() << ','
        << fs::path(ref.file).filename().string() << '\n';
  }
  return out.str();
}

}  // namespace

const std::vector<std::string>& accuracy_knobs() {
  static const std::vector<std::string> k = {"element_length", "shell_mesh_size",
                                             "quasistatic_ratio", "tolerance"};
  return k;
}

const std::vector<std::string>& accuracy_columns() {
  static const std::vector<std::string> c = [] {
    std::vector<std::string> out = {"scene", "seed", "knob", "value", "is_reference"};
    for (const auto& k : accuracy_knobs()) out.push_back(k);
    for (const char* s : {"l_end", "steps", "wall_s", "wall_ratio", "D_max", "err_D_max"})
      out.push_back(s);
    for (const auto& s : compared_series()) out.push_back("err_" + s);
    for (const char* s : {"err_UK", "l_from", "l_to", "file", "reference_file"}) out.push_back(s);
    return out;
  }();
  return c;
}

double relative_rms_error(const std::vector<double>& l, const std::vector<double>& y,
                          const std::vector<double>& l_ref, const std::vector<double>& y_ref,
                          double lo, double hi) {
  double num2 = 0, den2 = 0;
  int n = 0;
  for (std::size_t i = 0; i < l.size() && i < y.size(); ++i) {
    const double x = l[i];
    if (!(x >= lo && x <= hi) || !std::isfinite(y[i])) continue;
    // The reference at x: linear interpolation between its bracketing rows.
    const auto it = std::lower_bound(l_ref.begin(), l_ref.end(), x);
    if (it == l_ref.end()) continue;
    const std::size_t j = static_cast<std::size_t>(it - l_ref.begin());
    double yr = y_ref[j];
    if (l_ref[j] != x) {
      if (j == 0) continue;
      const double t = (x - l_ref[j - 1]) / (l_ref[j] - l_ref[j - 1]);
      yr = (1 - t) * y_ref[j - 1] + t * y_ref[j];
    }
    if (!std::isfinite(yr)) continue;
    num2 += (y[i] - yr) * (y[i] - yr);
    den2 += yr * yr;
    ++n;
  }
  if (n == 0 || den2 == 0) return NaN;
  return std::sqrt(num2 / den2);
}

AccuracyResult accuracy_study(const AccuracyOptions& o) {
  check_accuracy_series();
  if (o.dirs.empty()) throw InputError("accuracy: at least one sweep directory is needed");
  if (!(o.window.l_min < o.window.l_max))
    throw InputError("accuracy: --window: L_MIN must be < L_MAX");
  std::vector<Run> runs = read_runs(o.dirs, o.window);
  if (runs.empty()) throw InputError(o.dirs[0] + ": no complete run file in the given directories");
  label_scenes(runs);

  // Families: scene and seed; ladders around each family's centre.
  std::map<std::pair<std::string, std::uint64_t>, std::vector<const Run*>> families;
  std::map<std::string, std::vector<const Run*>> by_scene;
  for (const auto& r : runs) {
    families[{r.scene, r.seed}].push_back(&r);
    by_scene[r.scene].push_back(&r);
  }
  // The centre setting of a scene: over all its seeds, so every seed has the same centre.
  std::map<std::string, std::vector<double>> centre_of;
  for (const auto& [scene, list] : by_scene) centre_of[scene] = centre_values(list);
  std::vector<Row> rows;
  std::map<std::string, std::vector<const Run*>> centres;  // scene -> centre per seed
  AccuracyResult result;
  for (auto& [key, family] : families) {
    std::sort(family.begin(), family.end(),
              [](const Run* a, const Run* b) { return a->knob < b->knob; });
    const std::vector<double>& c = centre_of.at(key.first);
    const Run* centre = nullptr;
    for (const Run* r : family) {
      bool all = true;
      for (std::size_t k = 0; k < c.size(); ++k) all = all && same(r->knob[k], c[k]);
      if (all) centre = r;
    }
    if (!centre) continue;  // no run at the centre setting: no ladder can be formed
    centres[key.first].push_back(centre);
    for (std::size_t k = 0; k < accuracy_knobs().size(); ++k) {
      std::vector<const Run*> ladder;
      for (const Run* r : family) {
        bool others = true;
        for (std::size_t m = 0; m < c.size(); ++m)
          if (m != k) others = others && same(r->knob[m], c[m]);
        if (others) ladder.push_back(r);
      }
      if (ladder.size() < 2) continue;
      std::sort(ladder.begin(), ladder.end(),
                [k](const Run* a, const Run* b) { return a->knob[k] < b->knob[k]; });
      ++result.ladders;
      for (const Run* r : ladder)
        rows.push_back({r, ladder.front(), accuracy_knobs()[k], r->knob[k]});
    }
  }
  // Runs in no ladder (several knobs off the centre, e.g. presets) against the family's finest
  // run in every knob, when the family has one (knob "combined").
  for (auto& [key, family] : families) {
    const Run* finest = nullptr;
    for (const Run* f : family) {
      bool all = true;
      for (const Run* r : family)
        for (std::size_t k = 0; k < f->knob.size(); ++k) all = all && !(r->knob[k] < f->knob[k]);
      if (all) finest = f;
    }
    if (!finest) continue;
    std::vector<const Run*> loose;
    for (const Run* r : family) {
      bool listed = false;
      for (const Row& row : rows) listed = listed || (row.run == r && row.knob != "seed");
      if (!listed) loose.push_back(r);
    }
    if (loose.empty() || (loose.size() == 1 && loose[0] == finest)) continue;
    if (std::find(loose.begin(), loose.end(), finest) == loose.end()) loose.push_back(finest);
    for (const Run* r : loose) rows.push_back({r, finest, "combined", NaN});
  }
  // Chaos floor: each scene's centres against its smallest seed.
  for (auto& [scene, cs] : centres) {
    if (cs.size() < 2) continue;
    std::sort(cs.begin(), cs.end(), [](const Run* a, const Run* b) { return a->seed < b->seed; });
    for (const Run* r : cs) rows.push_back({r, cs.front(), "seed", static_cast<double>(r->seed)});
  }
  for (Row& row : rows) compare(row, o.window);
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
    if (a.run->label != b.run->label) return a.run->label < b.run->label;
    if ((a.knob == "seed") != (b.knob == "seed")) return b.knob == "seed";
    if (a.run->seed != b.run->seed) return a.run->seed < b.run->seed;
    if (a.knob != b.knob) return a.knob < b.knob;
    return a.value < b.value;
  });

  result.out = o.out.empty() ? (fs::path(o.dirs[0]) / "accuracy").string() : o.out;
  std::error_code ec;
  fs::create_directories(result.out, ec);
  if (ec || !fs::is_directory(result.out))
    throw InputError(result.out + ": cannot create the output directory (" + ec.message() + ")");
  result.runs = runs.size();
  result.rows = rows.size();
  result.csv = (fs::path(result.out) / "accuracy.csv").string();
  write_file_atomic(result.csv, csv_text(rows, o.window));

  // Pareto plot: per scene, error (max over U_b_hat, K, N) against wall time, log-log.
  std::map<std::string, plots::Panel> panels;
  std::map<std::string, std::map<std::string, plots::Curve>> curves;
  std::map<std::string, std::pair<double, double>> wall_range;
  std::map<std::string, double> floor;
  for (const Row& row : rows) {
    const Run& r = *row.run;
    if (row.run == row.ref) continue;
    const double e = row.err_UK;
    if (row.knob == "seed") {
      const auto [f, fresh] = floor.try_emplace(r.label, e);
      if (!fresh) f->second = std::isnan(f->second) ? e : std::max(f->second, e);
      continue;
    }
    auto& cv = curves[r.label][row.knob];
    cv.title = row.knob;
    cv.style = plots::Curve::Style::Points;
    cv.rows.push_back({r.wall_s, e, NaN});
    auto& wr = wall_range.try_emplace(r.label, r.wall_s, r.wall_s).first->second;
    wr.first = std::min(wr.first, r.wall_s);
    wr.second = std::max(wr.second, r.wall_s);
  }
  std::vector<plots::Panel> list;
  for (auto& [label, cs] : curves) {
    plots::Panel p;
    p.title = label;
    p.xlabel = "wall time per run [s]";
    p.ylabel = "rel. RMS error of U_b hat, K (larger)";
    p.logx = p.logy = true;
    p.key = "top right";
    for (auto& [k, cv] : cs) p.curves.push_back(cv);
    if (const auto f = floor.find(label); f != floor.end() && std::isfinite(f->second)) {
      plots::Curve fl;
      fl.title = "seed floor";
      fl.style = plots::Curve::Style::Lines;
      const auto [a, b] = wall_range[label];
      fl.rows = {{a, f->second, NaN}, {b, f->second, NaN}};
      p.curves.push_back(fl);
    }
    list.push_back(std::move(p));
  }
  const fs::path gp = fs::path(result.out) / "pareto.gp";
  if (!list.empty()) {
    const int cols = static_cast<int>(std::min<std::size_t>(list.size(), 3));
    const int nrows = static_cast<int>((list.size() + cols - 1) / cols);
    write_file_atomic(gp.string(),
                      plots::script("wirepack accuracy: error against wall time (Pareto front)",
                                    "accuracy vs time", list, nrows, cols, "pareto.png", 500 * cols,
                                    400 * nrows));
    const std::string program = o.gnuplot.empty() ? "" : plots::find_program(o.gnuplot);
    if (program.empty()) {
      result.plot_notice = o.gnuplot.empty() ? "plots not requested" : "gnuplot not found";
    } else {
      const std::string png = (fs::path(result.out) / "pareto.png").string();
      result.plot_notice = plots::render(program, gp.string(), png);
      if (result.plot_notice.empty()) result.plot = png;
    }
  } else {
    result.plot_notice = "no ladder with two settings";
  }
  return result;
}

}  // namespace wirepack::report
