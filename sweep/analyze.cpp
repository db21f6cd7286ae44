#include "sweep/analyze.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <set>
#include <stdexcept>
#include <utility>

#include "analysis/distributions.hpp"
#include "analysis/purohit.hpp"
#include "analysis/stats.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/critical_table.hpp"
#include "sweep/errors.hpp"
#include "sweep/format.hpp"
#include "sweep/json_file.hpp"
#include "sweep/plots.hpp"
#include "sweep/run_file.hpp"
#include "sweep/sweep_config.hpp"
#include "sweep/sweep_manifest.hpp"

namespace wirepack::sweep {

namespace fs = std::filesystem;
using json = nlohmann::json;
using analysis::NaN;

const std::vector<ExponentSpec>& exponent_specs() {
  static const std::vector<ExponentSpec> specs = {{"alpha", "R_t"}, {"beta", "R_x"},
                                                  {"gamma", "R_y"}, {"delta", "U_b_hat"},
                                                  {"lambda", "K"},  {"tau", "N"}};
  return specs;
}

AnalysisSettings default_analysis_settings() {
  AnalysisSettings s;
  for (const auto& e : exponent_specs()) s.fit_windows[e.name] = LWindow{};
  return s;
}

namespace {

constexpr const char* kWindowRule = "must be [l_min, l_max] with 0 <= l_min < l_max";
constexpr int kMaxBins = 1000;
constexpr int kMaxResamples = 100000;
// A run's snapshot is "at" l when it lies within this distance in l (snapshots are taken at the
// first step past each multiple of output.snapshots_every_l, so they overshoot by a step).
constexpr double kSnapshotTolerance = 0.05;

constexpr const char* kRangeRule = "must be [x_min, x_max] with x_min < x_max";

std::optional<std::pair<double, double>> range_from_json(const json& v) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) return {};
  const double a = v[0].get<double>(), b = v[1].get<double>();
  if (!std::isfinite(a) || !std::isfinite(b) || !(a < b)) return {};
  return std::pair{a, b};
}

std::optional<LWindow> window_from_json(const json& v) {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) return {};
  const double a = v[0].get<double>(), b = v[1].get<double>();
  if (!std::isfinite(a) || !std::isfinite(b) || a < 0 || !(a < b)) return {};
  return LWindow{a, b};
}

// The offending value for a message: short arrays in full ("[50,5]"), else describe_value.
std::string got_text(const json& v) {
  if (v.is_array() && v.dump().size() <= 40) return v.dump();
  return describe_value(v);
}

std::string exponent_names() {
  std::string s;
  for (const auto& e : exponent_specs()) s += (s.empty() ? "" : ", ") + e.name;
  return s;
}

bool is_exponent(const std::string& name) {
  for (const auto& e : exponent_specs())
    if (e.name == name) return true;
  return false;
}

// Parses the whole of `text` as a finite double.
std::optional<double> to_double(const std::string& text) {
  if (text.empty()) return {};
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return {};
  return v;
}

}  // namespace

LWindow parse_l_window(const std::string& text, const std::string& flag) {
  const auto comma = text.find(',');
  if (comma != std::string::npos) {
    const auto a = to_double(text.substr(0, comma));
    const auto b = to_double(text.substr(comma + 1));
    if (a && b && *a >= 0 && *a < *b) return LWindow{*a, *b};
  }
  throw InputError(flag + ": must be L_MIN,L_MAX with 0 <= L_MIN < L_MAX, e.g. 5,50 (got \"" +
                   text + "\")");
}

RunFileList list_run_files(const std::string& dir_text) {
  const fs::path dir(dir_text);
  std::error_code ec;
  const bool nested = fs::is_directory(dir / "runs", ec);
  const fs::path runs_dir = nested ? dir / "runs" : dir;
  const std::string prefix = nested ? "runs/" : "";
  RunFileList list;
  list.runs_dir = runs_dir.string();
  for (const auto& e : fs::directory_iterator(runs_dir, ec)) {
    const std::string name = e.path().filename().string();
    const auto ends = [&](const std::string& s) {
      return name.size() > s.size() && name.compare(name.size() - s.size(), s.size(), s) == 0;
    };
    if (ends(".h5.part"))
      list.parts.push_back(prefix + name.substr(0, name.size() - 5));
    else if (ends(".h5") && e.is_regular_file(ec))
      list.files.push_back(prefix + name);
  }
  std::sort(list.files.begin(), list.files.end());
  std::sort(list.parts.begin(), list.parts.end());
  return list;
}

std::vector<double> series_column(const RunRecord& record, const std::string& name,
                                  std::size_t rows) {
  std::vector<double> v(rows, NaN);
  if (const Series* s = record.find_series(name))
    for (std::size_t i = 0; i < rows && i < s->values.size(); ++i) v[i] = s->values[i];
  return v;
}

std::size_t series_rows(const RunRecord& record) {
  const Series* l = record.find_series("l");
  return l ? l->values.size() : 0;
}

std::vector<double> values_in_window(const std::vector<double>& l, const std::vector<double>& y,
                                     const LWindow& w) {
  std::vector<double> out;
  for (std::size_t i = 0; i < l.size() && i < y.size(); ++i)
    if (l[i] >= w.l_min && l[i] <= w.l_max && std::isfinite(y[i])) out.push_back(y[i]);
  return out;
}

void apply_analysis_block(const json& block, const std::string& source, const std::string& pointer,
                          AnalysisSettings& s) {
  const std::string where = source + ": " + (pointer.empty() ? std::string("/") : pointer);
  if (!block.is_object())
    throw InputError(where + ": must be an object (got " + describe_value(block) + ")");
  std::vector<std::string> errors;
  const auto fail = [&](const std::string& key, const std::string& rule, const json& got) {
    errors.push_back(source + ": " + pointer_child(pointer, key) + ": " + rule + " (got " +
                     got_text(got) + ")");
  };
  static const std::vector<std::string> keys = {
      "D_window",       "fit_window",          "fit_windows",    "distribution_l",
      "histogram_bins", "bootstrap_resamples", "critical_ranges"};
  for (const auto& [key, value] : block.items()) {
    if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
    std::string valid;
    for (const auto& k : keys) valid += (valid.empty() ? "" : ", ") + k;
    errors.push_back(source + ": " + pointer_child(pointer, key) +
                     ": unknown key; valid keys: " + valid);
  }
  if (const auto it = block.find("D_window"); it != block.end()) {
    if (const auto w = window_from_json(*it))
      s.D_window = *w;
    else
      fail("D_window", kWindowRule, *it);
  }
  // fit_window sets every exponent's window, fit_windows then sets single ones.
  if (const auto it = block.find("fit_window"); it != block.end()) {
    if (const auto w = window_from_json(*it)) {
      for (auto& [name, fw] : s.fit_windows) fw = *w;
    } else {
      fail("fit_window", kWindowRule, *it);
    }
  }
  if (const auto it = block.find("fit_windows"); it != block.end()) {
    if (!it->is_object()) {
      fail("fit_windows", "must be an object {\"<exponent>\": [l_min, l_max]}", *it);
    } else {
      const std::string ptr = pointer_child(pointer, "fit_windows");
      for (const auto& [name, value] : it->items()) {
        if (!is_exponent(name)) {
          errors.push_back(source + ": " + pointer_child(ptr, name) +
                           ": unknown exponent; valid: " + exponent_names());
        } else if (const auto w = window_from_json(value)) {
          s.fit_windows[name] = *w;
        } else {
          errors.push_back(source + ": " + pointer_child(ptr, name) + ": " + kWindowRule +
                           " (got " + got_text(value) + ")");
        }
      }
    }
  }
  if (const auto it = block.find("distribution_l"); it != block.end()) {
    if (it->is_null())
      s.distribution_l.reset();
    else if (it->is_number() && std::isfinite(it->get<double>()) && it->get<double>() >= 0)
      s.distribution_l = it->get<double>();
    else
      fail("distribution_l", "must be a number >= 0, or null for the last common snapshot", *it);
  }
  if (const auto it = block.find("histogram_bins"); it != block.end()) {
    if (it->is_number_integer() && it->get<long long>() >= 1 && it->get<long long>() <= kMaxBins)
      s.histogram_bins = it->get<int>();
    else
      fail("histogram_bins", "must be an integer in [1, " + std::to_string(kMaxBins) + "]", *it);
  }
  if (const auto it = block.find("bootstrap_resamples"); it != block.end()) {
    if (it->is_number_integer() && it->get<long long>() >= 0 &&
        it->get<long long>() <= kMaxResamples)
      s.bootstrap_resamples = it->get<int>();
    else
      fail("bootstrap_resamples",
           "must be an integer in [0, " + std::to_string(kMaxResamples) + "] (0: no bootstrap)",
           *it);
  }
  if (const auto it = block.find("critical_ranges"); it != block.end()) {
    if (!it->is_object()) {
      fail("critical_ranges", "must be an object {\"<parameter>\": [x_min, x_max]}", *it);
    } else {
      const std::string ptr = pointer_child(pointer, "critical_ranges");
      for (const auto& [name, value] : it->items()) {
        if (!is_transition_axis("/" + name)) {
          errors.push_back(source + ": " + pointer_child(ptr, name) +
                           ": not a transition parameter; valid: mu_s, eps, xi, rho");
        } else if (const auto r = range_from_json(value)) {
          s.critical_ranges["/" + name] = *r;
        } else {
          errors.push_back(source + ": " + pointer_child(ptr, name) + ": " + kRangeRule + " (got " +
                           got_text(value) + ")");
        }
      }
    }
  }
  if (!errors.empty()) throw InputError(errors);
}

namespace {

// ---------------------------------------------------------------------------------------------
// Small helpers: CSV cells and tables, JSON leaves.

std::string num(double x) {
  return csv_number(x);
}
std::string cell(const json& v) {
  return csv_cell(v);
}

// A value as text for plot titles ("0.5", "rigid").
std::string text_of(const json& v) {
  if (v.is_number()) return num(v.get<double>());
  if (v.is_string()) return v.get<std::string>();
  return v.dump();
}

// A CSV table: one header row, then rows of exactly as many cells.
class Table {
 public:
  explicit Table(const std::vector<std::string>& header) : width_(header.size()) {
    if (std::set<std::string>(header.begin(), header.end()).size() != header.size())
      throw std::logic_error("analyze: a CSV header repeats a column name");
    add(header);
  }
  void add(const std::vector<std::string>& row) {
    if (row.size() != width_)
      throw std::logic_error("analyze: a CSV row has " + std::to_string(row.size()) +
                             " cells, the header " + std::to_string(width_));
    for (std::size_t i = 0; i < row.size(); ++i) text_ += (i ? "," : "") + row[i];
    text_ += '\n';
  }
  const std::string& text() const { return text_; }

 private:
  std::size_t width_;
  std::string text_;
};

template <class... Parts>
std::vector<std::string> cat(Parts&&... parts) {
  std::vector<std::string> out;
  (out.insert(out.end(), parts.begin(), parts.end()), ...);
  return out;
}

// Leaves of a JSON object: pointer -> value (arrays count as leaves).
void flatten(const json& j, const std::string& pointer, std::map<std::string, json>& out) {
  if (j.is_object() && !j.empty()) {
    for (const auto& [k, v] : j.items()) flatten(v, pointer_child(pointer, k), out);
  } else {
    out[pointer] = j;
  }
}

// Total order on parameter values: absent, numbers (by value), strings, anything else.
int compare_values(const json& a, const json& b) {
  const auto rank = [](const json& v) {
    return v.is_null() ? 0 : v.is_number() ? 1 : v.is_string() ? 2 : 3;
  };
  if (rank(a) != rank(b)) return rank(a) < rank(b) ? -1 : 1;
  if (a.is_number()) {
    const double x = a.get<double>(), y = b.get<double>();
    return x < y ? -1 : y < x ? 1 : 0;
  }
  const std::string x = a.is_string() ? a.get<std::string>() : canonical_json(a);
  const std::string y = b.is_string() ? b.get<std::string>() : canonical_json(b);
  return x.compare(y) < 0 ? -1 : x.compare(y) > 0 ? 1 : 0;
}

// CSV column of a scene pointer: "/mu_s" -> "mu_s", "/numerics/element_length" ->
// "numerics.element_length".
std::string column_name(const std::string& pointer) {
  std::string s = pointer.substr(1);
  std::replace(s.begin(), s.end(), '/', '.');
  return s;
}

// ---------------------------------------------------------------------------------------------
// Runs.

// The series kept per complete run (the summary quantities of series.csv).
const std::vector<std::string>& kept_series() {
  static const std::vector<std::string> names = {"D", "U_b_hat", "K", "N", "R_t", "R_x", "R_y"};
  return names;
}
// Purohit predictions added per row.
const std::vector<std::string>& predicted_series() {
  static const std::vector<std::string> names = {"U_b_hat_purohit", "K_purohit"};
  return names;
}

struct Run {
  std::string file;    // relative to DIR
  std::string status;  // complete | failed | missing | unreadable | running
  std::string reason;
  json config;      // the resolved scene; null when unknown
  json seed;        // null when unknown
  std::string key;  // grid point: canonical JSON of the config without seed and output
  int point = -1;   // index of the grid point; -1 when unknown

  // runs.csv quantities (complete runs; l_reached and wall_s also for failed ones)
  double D = NaN, D_avg = NaN, l_reached = NaN, wall_s = NaN, U_b_hat = NaN, K = NaN, N = NaN;
  // complete runs: series by name (l, kept_series, predicted_series), equal lengths
  std::map<std::string, std::vector<double>> series;
  double every_l = 0.1;            // output.every_l of the run
  std::vector<double> snapshot_l;  // l of each snapshot
};

void set_config(Run& r, const json& config) {
  if (!config.is_object()) return;
  r.config = config;
  r.seed = config.contains("seed") ? config["seed"] : json();
  r.key = point_key(config);
}

double number_at(const json& config, const char* pointer) {
  const json::json_pointer p(pointer);
  if (!config.is_object() || !config.contains(p) || !config[p].is_number()) return NaN;
  return config[p].get<double>();
}

const std::vector<double>* series_of(const RunRecord& rec, const std::string& name) {
  const Series* s = rec.find_series(name);
  return s ? &s->values : nullptr;
}

double last_of(const std::vector<double>* v) {
  return v && !v->empty() ? v->back() : NaN;
}

// Reads `r.file` (already known to exist) and fills the run's quantities.
void read_run(const fs::path& dir, Run& r, const AnalysisSettings& settings) {
  RunRecord rec;
  try {
    rec = read_run_file((dir / r.file).string());
  } catch (const std::exception& e) {
    r.status = "unreadable";
    r.reason = e.what();
    return;
  }
  set_config(r, rec.config);
  r.status = to_string(rec.status);
  r.reason = rec.failure;
  const auto* l = series_of(rec, "l");
  r.l_reached = last_of(l);
  r.wall_s = last_of(series_of(rec, "wall_s"));
  if (rec.status != RunStatus::Complete) return;

  const std::size_t rows = series_rows(rec);
  r.series["l"] = series_column(rec, "l", rows);
  for (const auto& name : kept_series()) r.series[name] = series_column(rec, name, rows);

  // D over the D window: its maximum (the paper's D) and its mean.
  const auto& L = r.series["l"];
  const std::vector<double> in_window = values_in_window(L, r.series["D"], settings.D_window);
  if (!in_window.empty()) {
    r.D = *std::max_element(in_window.begin(), in_window.end());
    r.D_avg = analysis::mean_sem(in_window).mean;
  }
  r.U_b_hat = last_of(&r.series["U_b_hat"]);
  r.K = last_of(&r.series["K"]);
  r.N = last_of(&r.series["N"]);

  // Purohit model (paper Eqs. 4-7) from this run's radii at each l: L = l R, radii R_* R,
  // EI = E_w pi r^4 / 4, U_b_hat = U_b r^2 / (R EI).
  const double wire_r = number_at(rec.config, "/wire/radius");
  const double R = number_at(rec.config, "/rho") * wire_r;
  const double EI =
      number_at(rec.config, "/wire/youngs_modulus") * std::numbers::pi * std::pow(wire_r, 4) / 4;
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

  const double every = number_at(rec.config, "/output/every_l");
  if (std::isfinite(every) && every > 0) r.every_l = every;
  for (const auto& s : rec.snapshots) r.snapshot_l.push_back(s.l);
}

// The index of the snapshot nearest to l, if one lies within kSnapshotTolerance.
std::optional<std::size_t> snapshot_near(const std::vector<double>& ls, double l) {
  std::optional<std::size_t> best;
  for (std::size_t k = 0; k < ls.size(); ++k)
    if (std::abs(ls[k] - l) <= kSnapshotTolerance &&
        (!best || std::abs(ls[k] - l) < std::abs(ls[*best] - l)))
      best = k;
  return best;
}

// ---------------------------------------------------------------------------------------------
// The sweep directory.

struct Directory {
  std::optional<Sweep> sweep;  // from the manifest, when there is one
  std::string manifest;        // its path ("" none)
  std::vector<Run> runs;       // every expected or found run, by file name
};

// Opens DIR: its manifest (whose analysis block is applied to `settings`) and the list of runs,
// expected or found, by file name; nothing is read from the run files yet.
Directory open_directory(const std::string& dir_text, AnalysisSettings& settings) {
  const fs::path dir(dir_text);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(dir_text + ": " +
                     (fs::exists(dir, ec) ? "not a directory" : "no such directory") +
                     " (give the directory written by `wirepack sweep`)");
  Directory d;
  d.manifest = find_manifest(dir.string());
  if (!d.manifest.empty()) {
    const json m = load_json_file(d.manifest);
    if (!m.is_object() || !m.contains("sweep"))
      throw InputError(d.manifest + ": /sweep: required key is missing (not a sweep manifest)");
    d.sweep = parse_sweep(m["sweep"], d.manifest + " (/sweep)");
    apply_analysis_block(d.sweep->analysis, d.manifest, "/sweep/analysis", settings);
  }

  // Run files: DIR/runs/*.h5 (a sweep directory), else DIR/*.h5 (a directory of run files).
  const RunFileList found = list_run_files(dir_text);
  std::map<std::string, Run> by_file;
  for (const auto& f : found.files) by_file[f].file = f;
  const std::set<std::string> parts(found.parts.begin(), found.parts.end());
  for (const auto& f : parts) by_file[f].file = f;
  if (d.sweep) {
    for (const auto& sr : d.sweep->runs) {
      Run& r = by_file[sr.file];
      r.file = sr.file;
      set_config(r, sr.scene.resolved);  // replaced by the file's own where it can be read
    }
  }
  if (by_file.empty())
    throw InputError(dir_text + ": no run files (" + (fs::path(found.runs_dir) / "*.h5").string() +
                     ") and no manifest: not a sweep directory");
  for (auto& [file, r] : by_file) {
    r.status = fs::exists(dir / file, ec) ? "" : "missing";
    if (!r.status.empty())
      r.reason = parts.contains(file) ? "only a .part file: the run was killed before it finished"
                                      : "no run file: not run yet";
    d.runs.push_back(std::move(r));
  }
  return d;
}

// Reads every run file that exists.
void read_runs(const std::string& dir, Directory& d, const AnalysisSettings& settings) {
  for (auto& r : d.runs)
    if (r.status.empty()) read_run(dir, r, settings);
}

// ---------------------------------------------------------------------------------------------
// Grid points and swept parameters.

struct Point {
  std::string key;
  std::map<std::string, json> leaves;  // pointer -> value of its scene (without seed, output)
  std::vector<const Run*> complete;    // seeds order
  std::size_t failed = 0, missing = 0;
};

// The always-listed parameters; swept ones beyond them are appended.
const std::vector<std::string>& fixed_parameters() {
  static const std::vector<std::string> p = {"/rho",  "/xi",    "/eps",  "/mu_s",
                                             "/mu_d", "/l_max", "/shell"};
  return p;
}

// The swept parameters: leaves whose value differs between points, in order of preference (the
// sweep's axes, then the control parameters, then by pointer), leaving out those determined by
// the ones already chosen (mu_d = 0.9 mu_s follows mu_s).
std::vector<std::string> swept_parameters(const std::vector<Point>& points,
                                          const std::optional<Sweep>& sweep) {
  std::set<std::string> all;
  for (const auto& p : points)
    for (const auto& [ptr, v] : p.leaves) all.insert(ptr);
  const auto value = [](const Point& p, const std::string& ptr) {
    const auto it = p.leaves.find(ptr);
    return it == p.leaves.end() ? std::string("-") : canonical_json(it->second);
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
  add("/injection_speed");
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

json leaf(const Point& p, const std::string& ptr) {
  const auto it = p.leaves.find(ptr);
  return it == p.leaves.end() ? json() : it->second;
}

// ---------------------------------------------------------------------------------------------
// The analysis proper.

struct Analysis {
  AnalysisSettings settings;
  std::vector<Run> runs;            // runs.csv order: by point, seed, file
  std::vector<Point> points;        // in point order
  std::vector<std::string> axes;    // swept parameters (pointers)
  std::vector<std::string> params;  // parameter columns (pointers)
  std::vector<std::string> param_names;
  double distribution_l = NaN;
};

std::vector<std::string> param_cells(const Analysis& a, const Point& p) {
  std::vector<std::string> cells;
  for (const auto& ptr : a.params) cells.push_back(cell(leaf(p, ptr)));
  return cells;
}

std::vector<std::string> mean_sem_cells(std::span<const double> xs) {
  const auto m = analysis::mean_sem(xs);
  return {num(m.mean), num(m.sem)};
}

void group(Analysis& a, const std::optional<Sweep>& sweep) {
  std::map<std::string, Point> by_key;
  for (const auto& r : a.runs) {
    if (r.key.empty()) continue;
    Point& p = by_key[r.key];
    if (p.key.empty()) {
      p.key = r.key;
      flatten(point_scene(r.config), "", p.leaves);
    }
  }
  std::vector<Point> points;
  for (auto& [key, p] : by_key) points.push_back(std::move(p));
  a.axes = swept_parameters(points, sweep);
  // Points ordered by the swept parameters (the first slowest), ties by their scene.
  std::sort(points.begin(), points.end(), [&](const Point& x, const Point& y) {
    for (const auto& ptr : a.axes)
      if (const int c = compare_values(leaf(x, ptr), leaf(y, ptr)); c != 0) return c < 0;
    return x.key < y.key;
  });
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < points.size(); ++i) index[points[i].key] = static_cast<int>(i);
  for (auto& r : a.runs) r.point = r.key.empty() ? -1 : index.at(r.key);
  // runs.csv order: point (unknown last), seed, file.
  std::sort(a.runs.begin(), a.runs.end(), [](const Run& x, const Run& y) {
    const auto px = x.point < 0 ? std::numeric_limits<int>::max() : x.point;
    const auto py = y.point < 0 ? std::numeric_limits<int>::max() : y.point;
    if (px != py) return px < py;
    if (const int c = compare_values(x.seed, y.seed); c != 0) return c < 0;
    return x.file < y.file;
  });
  for (const auto& r : a.runs) {
    if (r.point < 0) continue;
    Point& p = points[r.point];
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

std::string runs_csv(const Analysis& a) {
  Table t(cat(std::vector<std::string>{"file", "point"}, a.param_names,
              std::vector<std::string>{"seed", "status", "reason", "D_l_min", "D_l_max", "D",
                                       "D_avg", "l_reached", "wall_s", "U_b_hat", "K", "N"}));
  for (const auto& r : a.runs) {
    std::vector<std::string> params(a.params.size());
    if (r.point >= 0) params = param_cells(a, a.points[r.point]);
    t.add(cat(
        std::vector<std::string>{csv_field(r.file), r.point >= 0 ? std::to_string(r.point) : ""},
        params,
        std::vector<std::string>{cell(r.seed), r.status, csv_field(r.reason),
                                 num(a.settings.D_window.l_min), num(a.settings.D_window.l_max),
                                 num(r.D), num(r.D_avg), num(r.l_reached), num(r.wall_s),
                                 num(r.U_b_hat), num(r.K), num(r.N)}));
  }
  return t.text();
}

// The run quantities averaged in curves.csv, with their accessors.
const std::vector<std::pair<std::string, double Run::*>>& curve_quantities() {
  static const std::vector<std::pair<std::string, double Run::*>> q = {
      {"D", &Run::D}, {"D_avg", &Run::D_avg},         {"U_b_hat", &Run::U_b_hat}, {"K", &Run::K},
      {"N", &Run::N}, {"l_reached", &Run::l_reached}, {"wall_s", &Run::wall_s}};
  return q;
}

std::vector<double> values(const Point& p, double Run::*field) {
  std::vector<double> v;
  for (const Run* r : p.complete) v.push_back(r->*field);
  return v;
}

std::string curves_csv(const Analysis& a) {
  std::vector<std::string> header = {"point"};
  header.insert(header.end(), a.param_names.begin(), a.param_names.end());
  for (const char* h : {"n", "n_failed", "n_missing", "D_l_min", "D_l_max"}) header.push_back(h);
  for (const auto& [name, field] : curve_quantities()) {
    header.push_back(name + "_mean");
    header.push_back(name + "_sem");
  }
  Table t(header);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const Point& p = a.points[i];
    std::vector<std::string> row =
        cat(std::vector<std::string>{std::to_string(i)}, param_cells(a, p));
    for (const std::size_t n : {p.complete.size(), p.failed, p.missing})
      row.push_back(std::to_string(n));
    row.push_back(num(a.settings.D_window.l_min));
    row.push_back(num(a.settings.D_window.l_max));
    for (const auto& [name, field] : curve_quantities())
      for (auto& c : mean_sem_cells(values(p, field))) row.push_back(std::move(c));
    t.add(row);
  }
  return t.text();
}

// D against one swept parameter: the other swept parameters first, sorted by them, then by it.
struct View {
  std::string name;  // column of the parameter
  std::string pointer;
  std::vector<std::string> others;  // pointers of the other swept parameters
  std::vector<std::size_t> order;   // point indices in row order
};

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

std::string view_csv(const Analysis& a, const View& v) {
  std::vector<std::string> header;
  for (const auto& o : v.others) header.push_back(column_name(o));
  header.push_back(v.name);
  for (const char* h : {"n", "D_mean", "D_sem", "D_l_min", "D_l_max"}) header.push_back(h);
  Table t(header);
  for (const std::size_t i : v.order) {
    const Point& p = a.points[i];
    std::vector<std::string> row;
    for (const auto& o : v.others) row.push_back(cell(leaf(p, o)));
    row.push_back(cell(leaf(p, v.pointer)));
    row.push_back(std::to_string(p.complete.size()));
    for (auto& c : mean_sem_cells(values(p, &Run::D))) row.push_back(std::move(c));
    row.push_back(num(a.settings.D_window.l_min));
    row.push_back(num(a.settings.D_window.l_max));
    t.add(row);
  }
  return t.text();
}

// One exponent fit of one point.
struct ExponentFit {
  analysis::PowerLawFit fit;
  double stderr_bootstrap = NaN;
  std::size_t seeds = 0;
};

ExponentFit fit_exponent(const Point& p, const std::string& series, const LWindow& w,
                         int resamples) {
  std::vector<std::vector<double>> ls, ys;
  std::vector<double> pooled_l, pooled_y;
  for (const Run* r : p.complete) {
    const auto& l = r->series.at("l");
    const auto& y = r->series.at(series);
    ls.push_back(l);
    ys.push_back(y);
    pooled_l.insert(pooled_l.end(), l.begin(), l.end());
    pooled_y.insert(pooled_y.end(), y.begin(), y.end());
  }
  ExponentFit f;
  f.seeds = p.complete.size();
  f.fit = analysis::fit_power_law(pooled_l, pooled_y, w.l_min, w.l_max);
  if (f.fit.ok && f.seeds >= 2 && resamples >= 2)
    f.stderr_bootstrap = analysis::bootstrap_exponent_stderr(ls, ys, w.l_min, w.l_max, resamples);
  return f;
}

// The reported standard error is the seed bootstrap's from 3 seeds on (with 2 it has only three
// distinct resamples), else the OLS one, which ignores that neighbouring points of a series are
// correlated.
constexpr std::size_t kBootstrapMinSeeds = 3;
bool use_bootstrap(const ExponentFit& f) {
  return f.seeds >= kBootstrapMinSeeds && std::isfinite(f.stderr_bootstrap);
}
double reported_stderr(const ExponentFit& f) {
  return use_bootstrap(f) ? f.stderr_bootstrap : f.fit.stderr_;
}

using Fits = std::vector<std::vector<ExponentFit>>;  // [point][exponent]

Fits fit_all(const Analysis& a) {
  Fits fits(a.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (const auto& e : exponent_specs())
      fits[i].push_back(fit_exponent(a.points[i], e.series, a.settings.fit_windows.at(e.name),
                                     a.settings.bootstrap_resamples));
  return fits;
}

std::string exponents_csv(const Analysis& a, const Fits& fits) {
  Table t(cat(
      std::vector<std::string>{"point"}, a.param_names,
      std::vector<std::string>{"name", "series", "value", "stderr", "stderr_ols",
                               "stderr_bootstrap", "log_prefactor", "window_l_min", "window_l_max",
                               "fit_l_min", "fit_l_max", "n_points", "n_seeds", "method", "ok"}));
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (std::size_t k = 0; k < exponent_specs().size(); ++k) {
      const auto& spec = exponent_specs()[k];
      const ExponentFit& f = fits[i][k];
      const LWindow& w = a.settings.fit_windows.at(spec.name);
      const bool boot = use_bootstrap(f);
      t.add(cat(std::vector<std::string>{std::to_string(i)}, param_cells(a, a.points[i]),
                std::vector<std::string>{
                    spec.name, spec.series, num(f.fit.exponent), num(reported_stderr(f)),
                    num(f.fit.stderr_), num(f.stderr_bootstrap), num(f.fit.log_prefactor),
                    num(w.l_min), num(w.l_max), num(f.fit.l_min), num(f.fit.l_max),
                    std::to_string(f.fit.n_points), std::to_string(f.seeds),
                    boot ? "ols+bootstrap" : "ols", f.fit.ok ? "true" : "false"}));
    }
  }
  return t.text();
}

// Seed-averaged series of one point: rows at the nominal l = k every_l.
struct MeanSeries {
  std::vector<double> l;
  std::vector<std::size_t> n;
  std::map<std::string, std::vector<analysis::MeanSem>> q;  // by series name
};

MeanSeries mean_series(const Point& p) {
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
  const auto names = cat(kept_series(), predicted_series());
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

std::string series_csv(const Analysis& a, const std::vector<MeanSeries>& ms) {
  std::vector<std::string> header =
      cat(std::vector<std::string>{"point"}, a.param_names, std::vector<std::string>{"l", "n"});
  const auto names = cat(kept_series(), predicted_series());
  for (const auto& name : names) {
    header.push_back(name + "_mean");
    header.push_back(name + "_sem");
  }
  Table t(header);
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const auto params = param_cells(a, a.points[i]);
    const MeanSeries& m = ms[i];
    for (std::size_t j = 0; j < m.l.size(); ++j) {
      std::vector<std::string> row =
          cat(std::vector<std::string>{std::to_string(i)}, params,
              std::vector<std::string>{num(m.l[j]), std::to_string(m.n[j])});
      for (const auto& name : names) {
        row.push_back(num(m.q.at(name)[j].mean));
        row.push_back(num(m.q.at(name)[j].sem));
      }
      t.add(row);
    }
  }
  return t.text();
}

// The last snapshot l that every complete run has (rounded to 0.001), NaN without complete runs.
double common_snapshot_l(const Analysis& a) {
  const Run* first = nullptr;
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

// The distribution samples of one point at the distribution l.
struct Samples {
  std::vector<double> kappa2;  // kappa^2 / <kappa^2>, pooled over the runs
  std::vector<double> loops;   // Lambda / r, pooled
  std::size_t runs = 0;        // runs with a snapshot at l
  // The packing of the first of those runs: its wire and shell vertices (none if rigid) at l
  // [m], the cavity radius R [m].
  std::vector<std::array<double, 3>> wire, shell;
  double R = NaN;
};

std::vector<Samples> distribution_samples(const fs::path& dir, const Analysis& a) {
  std::vector<Samples> out(a.points.size());
  if (!std::isfinite(a.distribution_l)) return out;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (const Run* r : a.points[i].complete) {
      const auto k = snapshot_near(r->snapshot_l, a.distribution_l);
      if (!k) continue;
      RunRecord rec;
      try {
        rec = read_run_file((dir / r->file).string());
      } catch (const std::exception&) {
        continue;  // read once already; a file changed since is left out
      }
      if (*k >= rec.snapshots.size()) continue;
      std::vector<analysis::Vec3> x;
      for (const auto& p : rec.snapshots[*k].wire) x.emplace_back(p[0], p[1], p[2]);
      const double wire_r = number_at(r->config, "/wire/radius");
      Samples& s = out[i];
      if (s.runs == 0) {
        s.wire = rec.snapshots[*k].wire;
        s.shell = rec.snapshots[*k].shell_vertices;
        s.R = number_at(r->config, "/rho") * wire_r;
      }
      ++s.runs;
      const auto k2 = analysis::normalized_squared_curvature(x);
      s.kappa2.insert(s.kappa2.end(), k2.begin(), k2.end());
      if (std::isfinite(wire_r) && wire_r > 0)
        for (const double lambda : analysis::loop_lengths(x, wire_r))
          s.loops.push_back(lambda / wire_r);
    }
  }
  return out;
}

// Density of N(mu, sigma^2) at x.
double normal_pdf(double x, double mu, double sigma) {
  const double z = (x - mu) / sigma;
  return std::exp(-z * z / 2) / (sigma * std::sqrt(2 * std::numbers::pi));
}

// Lognormal fit and histogram of ln x for one sample set.
struct Distribution {
  std::string quantity;
  analysis::LognormalFit fit;
  analysis::Histogram hist;  // of ln x
  std::vector<double> fit_density;
};

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
  return d;
}

using Distributions = std::vector<std::array<Distribution, 2>>;  // [point][kappa2, Lambda]

std::string distributions_csv(const Analysis& a, const std::vector<Samples>& samples,
                              const Distributions& ds) {
  Table t(cat(std::vector<std::string>{"point"}, a.param_names,
              std::vector<std::string>{"quantity", "l", "n_runs", "n", "mu", "mu_stderr", "sigma",
                                       "sigma_stderr", "ok", "bin", "ln_lo", "ln_hi", "count",
                                       "density", "fit_density"}));
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const auto params = param_cells(a, a.points[i]);
    for (const Distribution& d : ds[i]) {
      const std::vector<std::string> fit = {d.quantity,
                                            num(a.distribution_l),
                                            std::to_string(samples[i].runs),
                                            std::to_string(d.fit.n),
                                            num(d.fit.mu),
                                            num(d.fit.mu_stderr),
                                            num(d.fit.sigma),
                                            num(d.fit.sigma_stderr),
                                            d.fit.ok ? "true" : "false"};
      const auto head = cat(std::vector<std::string>{std::to_string(i)}, params, fit);
      if (d.hist.lo.empty()) {
        t.add(cat(head, std::vector<std::string>{"", "nan", "nan", "0", "nan", "nan"}));
        continue;
      }
      for (std::size_t b = 0; b < d.hist.lo.size(); ++b)
        t.add(cat(head, std::vector<std::string>{std::to_string(b), num(d.hist.lo[b]),
                                                 num(d.hist.hi[b]), std::to_string(d.hist.count[b]),
                                                 num(d.hist.density[b]), num(d.fit_density[b])}));
    }
  }
  return t.text();
}

// ---------------------------------------------------------------------------------------------
// Plots.

// "mu_s = 0.5, eps = 1000" for the given parameters of a point.
std::string describe(const Point& p, const std::vector<std::string>& pointers) {
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

struct PlotJob {
  std::string name;    // file stem in plots/
  std::string script;  // gnuplot script text
};

std::string window_text(const LWindow& w) {
  return "[" + num(w.l_min) + ", " + num(w.l_max) + "]";
}

// The same with 3 significant digits, for plot keys.
std::string rounded_window_text(const LWindow& w) {
  char text[64];
  std::snprintf(text, sizeof(text), "[%.3g, %.3g]", w.l_min, w.l_max);
  return text;
}

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
    const Point& p = a.points[i];
    const std::string title = describe(p, v.others);
    if (title != current) {
      panel.curves.push_back({title, Curve::Style::ErrorLines, {}});
      current = title;
    }
    const auto m = analysis::mean_sem(values(p, &Run::D));
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

// The packing of grid point i at the distribution l (first run with a snapshot there): the wire
// seen from the pole (x, y) and from the side (x, z) in units of R, over the elastic shell's
// vertices (grey dots), or in the rigid sphere's circle.
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

// Removes files of an earlier analysis that this one did not write (another grid, no gnuplot).
void remove_stale(const fs::path& dir, const std::set<std::string>& keep,
                  const std::vector<std::string>& prefixes) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (keep.contains(e.path().string())) continue;
    for (const auto& p : prefixes)
      if (name.rfind(p, 0) == 0) {
        fs::remove(e.path(), ec);
        break;
      }
  }
}

void apply_flags(const AnalyzeOptions& o, AnalysisSettings& s) {
  if (o.D_window) s.D_window = parse_l_window(*o.D_window, "--d-window");
  for (const auto& text : o.fit_windows) {
    const auto eq = text.find('=');
    if (eq == std::string::npos) {
      const LWindow w = parse_l_window(text, "--fit-window");
      for (auto& [name, fw] : s.fit_windows) fw = w;
      continue;
    }
    const std::string name = text.substr(0, eq);
    if (!is_exponent(name))
      throw InputError("--fit-window: unknown exponent \"" + name +
                       "\"; valid: " + exponent_names());
    s.fit_windows[name] = parse_l_window(text.substr(eq + 1), "--fit-window " + name);
  }
  if (o.at_l) {
    if (!std::isfinite(*o.at_l) || *o.at_l < 0)
      throw InputError("--at-l: must be a number >= 0 (got " + num(*o.at_l) + ")");
    s.distribution_l = *o.at_l;
  }
  if (o.bins) {
    if (*o.bins < 1 || *o.bins > kMaxBins)
      throw InputError("--bins: must be an integer in [1, " + std::to_string(kMaxBins) + "] (got " +
                       std::to_string(*o.bins) + ")");
    s.histogram_bins = *o.bins;
  }
  if (o.resamples) {
    if (*o.resamples < 0 || *o.resamples > kMaxResamples)
      throw InputError("--resamples: must be an integer in [0, " + std::to_string(kMaxResamples) +
                       "] (got " + std::to_string(*o.resamples) + ")");
    s.bootstrap_resamples = *o.resamples;
  }
  for (const auto& text : o.critical_ranges) {
    const auto eq = text.find('=');
    const auto comma = text.find(',', eq == std::string::npos ? 0 : eq);
    const std::string name = text.substr(0, eq);
    std::optional<double> a, b;
    if (eq != std::string::npos && comma != std::string::npos) {
      a = to_double(text.substr(eq + 1, comma - eq - 1));
      b = to_double(text.substr(comma + 1));
    }
    if (eq == std::string::npos || !is_transition_axis("/" + name) || !a || !b || !(*a < *b))
      throw InputError(
          "--critical-range: must be NAME=X_MIN,X_MAX with NAME one of mu_s, eps, xi, rho and "
          "X_MIN < X_MAX, e.g. mu_s=0,0.6 (got \"" +
          text + "\")");
    s.critical_ranges["/" + name] = {*a, *b};
  }
}

// The grid points as the critical-point fits see them (critical_table.hpp).
std::vector<CriticalPoint> critical_points(const Analysis& a) {
  std::vector<CriticalPoint> out;
  for (const auto& p : a.points) {
    CriticalPoint c;
    for (const auto& ptr : a.axes) c.params[ptr] = leaf(p, ptr);
    c.D = values(p, &Run::D);
    c.failed = p.failed;
    c.missing = p.missing;
    out.push_back(std::move(c));
  }
  return out;
}

// Creates OUT (and OUT/plots); InputError when impossible.
void prepare_out(const fs::path& out) {
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw InputError(out.string() + ": --out must name a directory (it is a file)");
  fs::create_directories(out / "plots", ec);
  if (!fs::is_directory(out / "plots", ec) || ::access(out.c_str(), W_OK) != 0 ||
      ::access((out / "plots").c_str(), W_OK) != 0)
    throw InputError(out.string() + ": cannot create a writable output directory");
}

}  // namespace

AnalyzeResult analyze_sweep(const AnalyzeOptions& o) {
  AnalyzeResult result;
  Analysis a;
  a.settings = default_analysis_settings();
  Directory d = open_directory(o.dir, a.settings);
  apply_flags(o, a.settings);
  if (!d.manifest.empty()) result.settings_source = d.manifest;
  read_runs(o.dir, d, a.settings);
  a.runs = std::move(d.runs);
  group(a, d.sweep);

  const fs::path out = o.out.empty() ? fs::path(o.dir) / "analysis" : fs::path(o.out);
  prepare_out(out);

  // Tables.
  const Fits fits = fit_all(a);
  std::vector<MeanSeries> series;
  for (const auto& p : a.points) series.push_back(mean_series(p));
  a.distribution_l = a.settings.distribution_l ? *a.settings.distribution_l : common_snapshot_l(a);
  const auto samples = distribution_samples(o.dir, a);
  Distributions dists;
  for (const auto& s : samples)
    dists.push_back({distribution("kappa2", s.kappa2, a.settings.histogram_bins),
                     distribution("Lambda_over_r", s.loops, a.settings.histogram_bins)});
  std::vector<View> views;
  for (const auto& ptr : a.axes) views.push_back(make_view(a, ptr));

  std::vector<std::pair<std::string, std::string>> files = {{"runs.csv", runs_csv(a)},
                                                            {"curves.csv", curves_csv(a)}};
  for (const auto& v : views) files.emplace_back("D_vs_" + v.name + ".csv", view_csv(a, v));
  files.emplace_back("exponents.csv", exponents_csv(a, fits));
  files.emplace_back("series.csv", series_csv(a, series));
  files.emplace_back("distributions.csv", distributions_csv(a, samples, dists));
  const auto crit_points = critical_points(a);
  const auto slices = critical_slices(a.axes, crit_points, a.settings.bootstrap_resamples, "",
                                      a.settings.critical_ranges);
  files.emplace_back("critical.csv", critical_csv(a.axes, slices));
  if (has_phase_diagram(a.axes))
    files.emplace_back("phase_diagram.csv", phase_diagram_csv(a.axes, slices));
  std::set<std::string> written;
  for (const auto& [name, text] : files) {
    const std::string path = (out / name).string();
    write_file_atomic(path, text);
    result.csv.push_back(path);
    written.insert(path);
  }
  remove_stale(out, written, {"D_vs_", "phase_diagram"});

  // Plots: scripts always, PNGs where gnuplot is present.
  std::vector<PlotJob> jobs;
  for (const auto& v : views)
    if (auto job = view_plot(a, v)) jobs.push_back(std::move(*job));
  for (auto& [name, script] : phase_diagram_plots(a.axes, crit_points, slices))
    jobs.push_back({name, script});
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    if (a.points[i].complete.empty()) continue;
    jobs.push_back(scaling_plot(a, i, series[i], fits[i]));
    jobs.push_back(distribution_plot(a, i, dists[i]));
    if (auto job = packing_plot(a, i, samples[i])) jobs.push_back(std::move(*job));
  }
  const fs::path plot_dir = out / "plots";
  const std::string gnuplot = plots::find_program(o.gnuplot);
  std::set<std::string> kept;
  std::vector<std::string> failures;
  for (const auto& job : jobs) {
    const std::string gp = (plot_dir / (job.name + ".gp")).string();
    const std::string png = (plot_dir / (job.name + ".png")).string();
    write_file_atomic(gp, job.script);
    result.scripts.push_back(gp);
    kept.insert(gp);
    if (gnuplot.empty()) continue;
    const std::string err = plots::render(gnuplot, gp, png);
    if (err.empty()) {
      result.plots.push_back(png);
      kept.insert(png);
    } else {
      failures.push_back(err);
      kept.insert(png + ".log");
    }
  }
  remove_stale(plot_dir, kept, {"D_vs_", "scaling_p", "distributions_p", "phase_", "packing_p"});
  if (o.gnuplot.empty())
    result.plot_notice = "plots not drawn (--no-plots); gnuplot scripts in " + plot_dir.string();
  else if (gnuplot.empty())
    result.plot_notice =
        "plots skipped: " + o.gnuplot + " not found; gnuplot scripts in " + plot_dir.string();
  else if (!failures.empty())
    result.plot_notice = std::to_string(failures.size()) + " plot(s) failed: " + failures.front();

  result.out = out.string();
  result.runs = a.runs.size();
  result.points = a.points.size();
  for (const auto& r : a.runs) {
    if (r.status == "complete")
      ++result.complete;
    else
      result.skipped.push_back({r.file, r.status, r.reason});
  }
  for (const auto& ptr : a.axes) result.axes.push_back(column_name(ptr));
  result.settings = a.settings;
  result.distribution_l = a.distribution_l;
  return result;
}

CriticalData read_critical_data(const AnalyzeOptions& o) {
  Analysis a;
  a.settings = default_analysis_settings();
  Directory d = open_directory(o.dir, a.settings);
  apply_flags(o, a.settings);
  read_runs(o.dir, d, a.settings);
  a.runs = std::move(d.runs);
  group(a, d.sweep);
  CriticalData c;
  c.axes = a.axes;
  c.points = critical_points(a);
  c.settings = a.settings;
  return c;
}

}  // namespace wirepack::sweep
