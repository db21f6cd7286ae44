#include "report/analyze.hpp"

#include <unistd.h>

#include <filesystem>
#include <set>

#include "report/critical_table.hpp"
#include "report/csv_table.hpp"
#include "report/phase_4d.hpp"
#include "report/plot_jobs.hpp"
#include "report/plots.hpp"
#include "report/reductions.hpp"
#include "report/sweep_dir.hpp"
#include "report/tables.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/errors.hpp"

namespace wirepack::report {

namespace fs = std::filesystem;
using sweep::InputError;
using sweep::write_file_atomic;

namespace {

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

// The runs of o.dir read under the settings (the defaults, the sweep file's, o's flags) and
// grouped into points; `manifest`: the manifest read ("" when none). (The points hold pointers
// into a.runs, whose buffer a move keeps.)
Analysis read_and_group(const AnalyzeOptions& o, std::string& manifest) {
  Analysis a;
  a.settings = default_analysis_settings();
  Directory d = open_directory(o.dir, a.settings);
  apply_flags(o, a.settings);
  check_named_series(o.series);
  a.kept = kept_series(o.series);
  manifest = d.manifest;
  read_runs(o.dir, d, a.settings, a.kept);
  a.runs = std::move(d.runs);
  group(a, d.sweep);
  return a;
}

}  // namespace

AnalyzeResult analyze_sweep(const AnalyzeOptions& o) {
  AnalyzeResult result;
  std::string manifest;
  Analysis a = read_and_group(o, manifest);
  if (!manifest.empty()) result.settings_source = manifest;

  const fs::path out = o.out.empty() ? fs::path(o.dir) / "analysis" : fs::path(o.out);
  prepare_out(out);

  // Tables.
  const Fits fits = fit_all(a);
  std::vector<MeanSeries> series;
  for (const auto& p : a.points) series.push_back(mean_series(p, a.kept));
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
  files.emplace_back("loop_sensitivity.csv", loop_sensitivity_csv(a, samples));
  files.emplace_back("morphology.csv", morphology_csv(a, samples));
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
    if (auto job = view_plot(a, v, slices)) jobs.push_back(std::move(*job));
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
  std::string manifest;
  Analysis a = read_and_group(o, manifest);
  CriticalData c;
  c.axes = a.axes;
  c.points = critical_points(a);
  c.settings = a.settings;
  return c;
}

AnalyzeResult analyze_phase_diagram(const std::vector<std::string>& dirs, const AnalyzeOptions& o) {
  if (o.out.empty())
    throw InputError(
        "analyze: with several sweep directories, --out must name the output directory");
  std::vector<PhaseSource> sources;
  AnalyzeResult result;
  for (const auto& dir : dirs) {
    AnalyzeOptions one = o;
    one.dir = dir;
    CriticalData c = read_critical_data(one);
    result.points += c.points.size();
    sources.push_back({dir, c.settings.order_parameter, c.axes, std::move(c.points),
                       c.settings.bootstrap_resamples, c.settings.critical_ranges});
  }
  const fs::path out(o.out);
  prepare_out(out);
  result.out = out.string();
  const auto rows = phase_rows(sources);
  const std::string csv = (out / "phase_diagram_4d.csv").string();
  write_file_atomic(csv, phase_4d_csv(rows));
  result.csv.push_back(csv);
  const std::string gnuplot = plots::find_program(o.gnuplot);
  std::vector<std::string> failures;
  for (const auto& [name, script] : phase_4d_plots(rows)) {
    const std::string gp = (out / "plots" / (name + ".gp")).string();
    const std::string png = (out / "plots" / (name + ".png")).string();
    write_file_atomic(gp, script);
    result.scripts.push_back(gp);
    if (gnuplot.empty()) continue;
    if (const std::string err = plots::render(gnuplot, gp, png); err.empty())
      result.plots.push_back(png);
    else
      failures.push_back(name + ": " + err);
  }
  if (gnuplot.empty() && !result.scripts.empty())
    result.plot_notice = "gnuplot not found: scripts written, no PNGs";
  else if (!failures.empty())
    result.plot_notice = failures.front();
  return result;
}

}  // namespace wirepack::report
