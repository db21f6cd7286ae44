#include "report/sweep_dir.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "analysis/distributions.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/errors.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/running/sweep_manifest.hpp"

namespace wirepack::report {

namespace fs = std::filesystem;
using json = nlohmann::json;
using analysis::NaN;
using sweep::InputError;
using sweep::read_run_file;
using sweep::RunRecord;
using sweep::RunStatus;
using sweep::Series;

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

namespace {

const std::vector<double>* series_of(const RunRecord& rec, const std::string& name) {
  const Series* s = rec.find_series(name);
  return s ? &s->values : nullptr;
}

double last_of(const std::vector<double>* v) {
  return v && !v->empty() ? v->back() : NaN;
}

}  // namespace

void read_run(const fs::path& dir, RunData& r, const AnalysisSettings& settings,
              const std::vector<std::string>& kept) {
  RunRecord rec;
  try {
    rec = read_run_file((dir / r.file).string());
  } catch (const std::exception& e) {
    r.status = "unreadable";
    r.reason = e.what();
    return;
  }
  set_run_config(r, rec.config);
  r.status = to_string(rec.status);
  r.reason = rec.failure;
  const auto* l = series_of(rec, "l");
  r.l_reached = last_of(l);
  r.wall_s = last_of(series_of(rec, "wall_s"));
  if (rec.status != RunStatus::Complete) return;

  const std::size_t rows = series_rows(rec);
  r.series["l"] = series_column(rec, "l", rows);
  for (const auto& name : kept) r.series[name] = series_column(rec, name, rows);

  const double every = number_at(rec.config, "/output/every_l");
  if (std::isfinite(every) && every > 0) r.every_l = every;
  for (const auto& s : rec.snapshots) r.snapshot_l.push_back(s.l);
  summarize_run(r, settings);
}

Directory open_directory(const std::string& dir_text, AnalysisSettings& settings) {
  const fs::path dir(dir_text);
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw InputError(dir_text + ": " +
                     (fs::exists(dir, ec) ? "not a directory" : "no such directory") +
                     " (give the directory written by `wirepack sweep`)");
  Directory d;
  d.manifest = sweep::find_manifest(dir.string());
  if (!d.manifest.empty()) {
    const json m = sweep::load_json_file(d.manifest);
    if (!m.is_object() || !m.contains("sweep"))
      throw InputError(d.manifest + ": /sweep: required key is missing (not a sweep manifest)");
    d.sweep = sweep::parse_sweep(m["sweep"], d.manifest + " (/sweep)");
    apply_analysis_block(d.sweep->analysis, d.manifest, "/sweep/analysis", settings);
  }

  // Run files: DIR/runs/*.h5 (a sweep directory), else DIR/*.h5 (a directory of run files).
  const RunFileList found = list_run_files(dir_text);
  std::map<std::string, RunData> by_file;
  for (const auto& f : found.files) by_file[f].file = f;
  const std::set<std::string> parts(found.parts.begin(), found.parts.end());
  for (const auto& f : parts) by_file[f].file = f;
  if (d.sweep) {
    for (const auto& sr : d.sweep->runs) {
      RunData& r = by_file[sr.file];
      r.file = sr.file;
      set_run_config(r, sr.scene.resolved);  // replaced by the file's own where it can be read
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

void read_runs(const std::string& dir, Directory& d, const AnalysisSettings& settings,
               const std::vector<std::string>& kept) {
  for (auto& r : d.runs)
    if (r.status.empty()) read_run(dir, r, settings, kept);
}

std::vector<Samples> distribution_samples(const fs::path& dir, const Analysis& a) {
  std::vector<Samples> out(a.points.size());
  if (!std::isfinite(a.distribution_l)) return out;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    std::vector<std::vector<analysis::Vec3>> wires;
    double loop_r = NaN;
    for (const RunData* r : a.points[i].complete) {
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
      try {
        const sweep::Scene scene = sweep::parse_scene(r->config, r->file + " (config)");
        std::vector<analysis::Vec3> sv;
        for (const auto& q : rec.snapshots[*k].shell_vertices) sv.emplace_back(q[0], q[1], q[2]);
        s.orders.push_back(
            {r, rec.snapshots[*k].l,
             sweep::order_variants(x, scene.engine, sv, rec.snapshots[*k].shell_triangles)});
      } catch (const std::exception&) {
        // a config this version cannot resolve: no order parameters for the run
      }
      const auto k2 = analysis::normalized_squared_curvature(x);
      s.kappa2.insert(s.kappa2.end(), k2.begin(), k2.end());
      if (std::isfinite(wire_r) && wire_r > 0) {
        for (const double lambda : analysis::loop_lengths(x, wire_r))
          s.loops.push_back(lambda / wire_r);
        loop_r = wire_r;
        wires.push_back(std::move(x));
      }
    }
    if (!wires.empty()) {
      static const std::vector<double> smoothings{1, 2, 4}, prominences{0.1, 0.25, 0.5};
      out[i].loop_sensitivity = analysis::loop_sensitivity(wires, loop_r, smoothings, prominences);
    }
  }
  return out;
}

}  // namespace wirepack::report
