// The wirepack executable (docs/design.md §1): subcommands wire the layers together.
// Exit codes: 0 success, 2 bad input (nothing is written), 1 a run failed.
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "app/render.hpp"
#include "report/accuracy.hpp"
#include "report/analyze.hpp"
#include "report/refine.hpp"
#include "report/twin.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/config/scene_config.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/errors.hpp"
#include "sweep/format.hpp"
#include "sweep/runfile/export.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/runfile/wire_profile.hpp"
#include "sweep/running/run.hpp"
#include "sweep/running/sweep_runner.hpp"

namespace {

namespace fs = std::filesystem;
using namespace wirepack::report;
using namespace wirepack::sweep;

// Threads inside a run fork and join about twenty parallel loops per step (tens of us each).
// libgomp reads its spin count when it loads, before main; with its default here the second
// thread sleeps between loops and waking it costs more than the loop saves (2 threads 1.3x
// slower than 1 on an elastic run; with GOMP_SPINCOUNT=300000, libgomp's documented value, 1.2-
// 1.3x faster). Unless the user chose a wait policy or spin count, the process starts again
// once with that count (same pid, same arguments); if that fails it goes on as it is.
void spin_between_parallel_loops(char** argv) {
  if (std::getenv("GOMP_SPINCOUNT") || std::getenv("OMP_WAIT_POLICY")) return;
  if (setenv("GOMP_SPINCOUNT", "300000", 1) != 0) return;
  execv("/proc/self/exe", argv);
}

constexpr int kOk = 0;
constexpr int kRunFailed = 1;
constexpr int kBadInput = 2;

// SIGTERM (a batch system's time limit, scancel) and SIGINT (Ctrl-C) stop a run or a sweep
// cleanly: the runs going write their checkpoints and the process exits with 128 + the signal,
// so the same command resumes them (docs/design.md §4.8). A second signal kills at once.
std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_stop_signal = 0;
static_assert(std::atomic<bool>::is_always_lock_free);  // safe to set in a signal handler

extern "C" void on_stop_signal(int sig) {
  g_stop_signal = sig;
  g_stop.store(true);
}

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // the second one takes the default action
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
}

int stopped_exit_code() {
  return 128 + static_cast<int>(g_stop_signal);
}

// The output's directory must exist and be writable before any work starts, so an hours-long
// run cannot end in an unwritable path.
void check_output_path(const std::string& out) {
  const fs::path path(out);
  fs::path dir = path.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (path.filename().empty() || fs::is_directory(path, ec))
    throw InputError(out + ": --out must name a file, not a directory");
  // A missing directory is created (the scene has been validated by now).
  if (!fs::is_directory(dir, ec) && !fs::create_directories(dir, ec))
    throw InputError(out + ": directory " + dir.string() + " cannot be created");
  if (::access(dir.c_str(), W_OK) != 0)
    throw InputError(out + ": directory " + dir.string() + " is not writable");
}

int cmd_run(const std::string& scene_path, const std::string& out, int threads,
            double checkpoint_every) {
  const Scene scene = scene_path.empty()
                          ? parse_scene(default_scene_json(), "<embedded default scene>")
                          : load_scene(scene_path);
  check_output_path(out);
  install_stop_handlers();
  RunOutcome outcome;
  try {
    outcome = run_scene(
        scene, out, &std::cerr, [threads] { return threads; }, recorded_series(),
        CheckpointOptions{checkpoint_every, &g_stop});
  } catch (const RunFileError& e) {
    // The simulation ended but its file could not be written (a full disk, a size limit).
    std::cerr << "wirepack: run file not written: " << e.what() << '\n';
    return kRunFailed;
  }
  if (outcome.status == RunStatus::Running) {
    std::cerr << "wirepack: stopped by signal " << g_stop_signal << '\n';
    return stopped_exit_code();
  }
  if (outcome.status != RunStatus::Complete) {
    std::cerr << "wirepack: run failed: " << outcome.failure << " (run file " << out << ")\n";
    return kRunFailed;
  }
  std::cout << out << '\n';
  return kOk;
}

// The sweep's analysis block is checked with the sweep (exit 2 before any run), not first by
// `wirepack analyze` after a night of runs.
void check_analysis_block(const Sweep& sweep, const std::string& source) {
  AnalysisSettings settings = default_analysis_settings();
  apply_analysis_block(sweep.analysis, source, "/analysis", settings);
}

// A scene prints resolved (every default filled); a sweep (an object with "grid") prints
// resolved with its expanded runs: {"sweep": ..., "runs": [{index, id, file, point, seed}]}.
int cmd_validate(const std::string& path) {
  std::vector<std::string> duplicates;  // reported by load_scene / load_sweep below
  if (!is_sweep_json(load_json_file(path, &duplicates))) {
    const Scene scene = load_scene(path);
    std::cout << scene.resolved.dump(2) << '\n';
    const NumericsPreset& p = *find_numerics_preset(scene.numerics_preset);
    std::cerr << "numerics preset \"" << p.name << "\": element_length " << p.element_per_r
              << " r, shell_mesh_size " << p.mesh_per_r << " r, quasistatic_ratio "
              << p.quasistatic_ratio << ", tolerance " << p.tolerance
              << " (keys given in the scene override it)\n";
    return kOk;
  }
  const Sweep sweep = load_sweep(path);
  check_analysis_block(sweep, path);
  nlohmann::json runs = nlohmann::json::array();
  for (const auto& r : sweep.runs)
    runs.push_back({{"index", r.index},
                    {"id", r.id},
                    {"file", r.file},
                    {"point", r.point_values},
                    {"seed", r.seed}});
  std::cout << nlohmann::json{{"sweep", sweep.resolved}, {"runs", runs}}.dump(2) << '\n';
  return kOk;
}

struct SweepArgs {
  std::string path;   // sweep file; "" = the embedded default sweep
  std::string out;    // sweep directory; "" = sweeps/<name>
  int threads = 0;    // 0 = all cores
  std::string shard;  // "K/N"; "" = from SLURM_ARRAY_TASK_* or 0/1
  bool retry_failed = false;
  std::vector<std::string> only;                      // --only KEY=V1,V2,... (each a RunCondition)
  double checkpoint_every = kDefaultCheckpointEvery;  // [s]
};

// docs/design.md §6.2: exit 0 when every run of the shard is complete, 1 when any failed (a summary
// on stderr), 2 on bad input before anything is written. The manifest's path goes to stdout.
int cmd_sweep(const SweepArgs& a) {
  const Sweep sweep = a.path.empty() ? parse_sweep(default_sweep_json(), "<embedded default sweep>")
                                     : load_sweep(a.path);
  check_analysis_block(sweep, a.path.empty() ? "<embedded default sweep>" : a.path);
  const Shard shard =
      a.shard.empty() ? shard_from_env().value_or(Shard{}) : parse_shard(a.shard, "--shard");
  SweepOptions opt;
  opt.dir = a.out.empty() ? "sweeps/" + sweep.name : a.out;
  opt.threads = a.threads;
  opt.shard = shard;
  opt.retry_failed = a.retry_failed;
  for (const auto& c : a.only) opt.only.push_back(parse_run_condition(sweep, c, "--only"));
  opt.checkpoint_every_s = a.checkpoint_every;
  opt.progress = &std::cerr;
  opt.stop = &g_stop;
  install_stop_handlers();
  const SweepOutcome o = run_sweep(sweep, opt);

  std::cerr << "sweep " << sweep.name << ": " << o.runs << " runs"
            << (shard.count > 1 ? " in shard " + shard.text() : std::string()) << ", " << o.complete
            << " complete, " << o.failed << " failed (" << o.ran << " run now on " << o.threads
            << " thread" << (o.threads == 1 ? "" : "s") << " in " << format_duration(o.wall_s)
            << ", " << o.found << " found finished)\n";
  constexpr std::size_t kListed = 20;
  for (std::size_t i = 0; i < o.failures.size() && i < kListed; ++i)
    std::cerr << "  failed: " << (fs::path(opt.dir) / o.failures[i].first).string() << ": "
              << o.failures[i].second << '\n';
  if (o.failures.size() > kListed)
    std::cerr << "  ... and " << o.failures.size() - kListed << " more (see " << o.manifest
              << ")\n";
  if (o.failed > 0 && !a.retry_failed)
    std::cerr << "  (rerun with --retry-failed to run the failed ones again)\n";
  std::cout << o.manifest << '\n';
  if (g_stop.load()) {
    std::cerr << "sweep " << sweep.name << ": stopped by signal " << g_stop_signal << "; "
              << o.stopped << " run(s) stopped part-way"
              << (opt.checkpoint_every_s > 0 ? " with their checkpoints" : "")
              << "; the same command resumes\n";
    return stopped_exit_code();
  }
  return o.failed > 0 ? kRunFailed : kOk;
}

// docs/design.md §4.6: CSV tables and plots of a sweep directory. Skipped runs (failed, missing,
// unreadable) and plot notices go to stderr; where the CSV and plots are goes to stdout.
int cmd_analyze(const AnalyzeOptions& opt) {
  const AnalyzeResult r = analyze_sweep(opt);
  std::cerr << "analyze " << opt.dir << ": " << r.runs << " runs, " << r.complete << " complete, "
            << r.skipped.size() << " skipped; " << r.points << " grid point"
            << (r.points == 1 ? "" : "s");
  if (!r.axes.empty()) {
    std::cerr << " (swept:";
    for (const auto& a : r.axes) std::cerr << ' ' << a;
    std::cerr << ')';
  }
  const auto& w = r.settings.D_window;
  std::cerr << "; D window [" << format_number(w.l_min) << ", " << format_number(w.l_max)
            << "], distributions at l = " << format_number(r.distribution_l);
  if (r.settings.order_parameter != "D")
    std::cerr << ", critical points of " << r.settings.order_parameter;
  if (!r.settings.fit_auto.empty()) {
    std::cerr << ", scaling windows by rule:";
    for (const auto& e : r.settings.fit_auto) std::cerr << ' ' << e;
  }
  std::cerr << '\n';
  constexpr std::size_t kListed = 20;
  for (std::size_t i = 0; i < r.skipped.size() && i < kListed; ++i)
    std::cerr << "  skipped (" << r.skipped[i].status << "): " << r.skipped[i].file
              << (r.skipped[i].reason.empty() ? "" : ": " + r.skipped[i].reason) << '\n';
  if (r.skipped.size() > kListed)
    std::cerr << "  ... and " << r.skipped.size() - kListed << " more (see runs.csv)\n";
  if (!r.plot_notice.empty()) std::cerr << "  " << r.plot_notice << '\n';
  std::cout << "CSV:   " << r.out << "/ (";
  for (std::size_t i = 0; i < r.csv.size(); ++i)
    std::cout << (i ? ", " : "") << fs::path(r.csv[i]).filename().string();
  std::cout << ")\n";
  if (!r.plots.empty())
    std::cout << "plots: " << (fs::path(r.out) / "plots").string() << "/ (" << r.plots.size()
              << " PNG)\n";
  else
    std::cout << "plots: none; " << r.plot_notice << '\n';
  return kOk;
}

// Issue 51: the critical points of several sweep directories in one four-dimensional table.
int cmd_phase_diagram(const std::vector<std::string>& dirs, const AnalyzeOptions& opt) {
  const AnalyzeResult r = analyze_phase_diagram(dirs, opt);
  std::cerr << "analyze: " << dirs.size() << " sweep directories, " << r.points << " grid points\n";
  if (!r.plot_notice.empty()) std::cerr << "  " << r.plot_notice << '\n';
  std::cout << "CSV:   " << r.csv.front() << '\n';
  if (!r.plots.empty())
    std::cout << "plots: " << (fs::path(r.out) / "plots").string() << "/ (" << r.plots.size()
              << " PNG)\n";
  else if (!r.scripts.empty())
    std::cout << "plots: none; " << r.plot_notice << '\n';
  else
    std::cout << "plots: none (no transition parameter has two fitted critical points)\n";
  return kOk;
}

// Issue 16: rounds of new grid values at the transition, run into DIR. Exit 0, 1 when runs of
// the sweep failed, 2 on bad input (nothing written).
int cmd_refine(const RefineOptions& o) {
  const RefineOutcome r = refine_sweep(o);
  std::cerr << "refine " << o.dir << ": " << r.rounds << " round" << (r.rounds == 1 ? "" : "s")
            << " added " << r.added_runs << " runs (" << r.listed_runs
            << " refinement runs in all); stopped: " << r.stop << '\n';
  for (const auto& line : r.lines) std::cerr << "  " << line << '\n';
  if (r.failed > 0) std::cerr << "  " << r.failed << " run(s) of the sweep failed\n";
  if (!r.sweep_file.empty()) std::cout << r.sweep_file << '\n';
  return r.failed > 0 ? kRunFailed : kOk;
}

int cmd_accuracy(AccuracyOptions o, const std::string& window) {
  if (!window.empty()) o.window = parse_l_window(window, "--window");
  const AccuracyResult r = accuracy_study(o);
  std::cout << "accuracy: " << r.runs << " complete runs, " << r.ladders << " ladders, " << r.rows
            << " rows\nCSV:   " << r.csv << '\n';
  if (!r.plot.empty())
    std::cout << "plot:  " << r.plot << '\n';
  else
    std::cout << "plot:  none; " << r.plot_notice << '\n';
  return kOk;
}

// Issue 18: a picture and/or a movie of a run file (ParaView, else gnuplot).
int cmd_render(const wirepack::app::RenderOptions& o) {
  const wirepack::app::RenderPlan plan = wirepack::app::check_render(o);
  if (!o.out.empty()) check_output_path(o.out);
  if (!o.movie.empty()) check_output_path(o.movie);
  return wirepack::app::render_run(o, plan, std::cout, std::cerr);
}

int cmd_export(const std::string& run_file, const std::string& csv, const std::string& xmf,
               const std::string& profile, long snapshot) {
  try {
    if (!xmf.empty()) check_xdmf_source(run_file);  // before anything is written
    if (!csv.empty()) export_csv(run_file, csv);
    if (!xmf.empty()) export_xdmf(run_file, xmf);
    if (!profile.empty()) {
      // Default: the last snapshot (counted from the end when negative).
      if (snapshot < 0)
        snapshot += static_cast<long>(read_run_for_export(run_file).snapshots.size());
      export_profile(run_file, snapshot, profile);
    }
  } catch (const RunFileError& e) {
    throw InputError(e.what());
  } catch (const WriteError& e) {
    throw InputError(e.what());
  }
  return kOk;
}

// Twin runs: the snapshot-by-snapshot separation modulo the rotation about the feed axis, and
// the l where it first exceeds the threshold (in r). Prints one line; --csv writes the rows.
int cmd_twin(const std::string& a, const std::string& b, double threshold_r,
             const std::string& csv) {
  try {
    if (!csv.empty()) check_output_path(csv);
    const TwinComparison c =
        compare_twins(read_run_for_export(a), read_run_for_export(b), threshold_r);
    if (!csv.empty()) write_file_atomic(csv, twin_csv(c));
    const auto top = std::max_element(c.separation_r.begin(), c.separation_r.end());
    std::cout << "snapshots compared: " << c.l.size() << " (l <= " << format_number(c.l.back())
              << "); ";
    const std::string t = format_number(threshold_r) + " r";
    if (std::isnan(c.parting_l))
      std::cout << "never parted by more than " << t << " (largest " << format_number(*top)
                << " r)";
    else
      std::cout << "parted by more than " << t << " at l = " << format_number(c.parting_l);
    const auto rms = std::max_element(c.rms_r.begin(), c.rms_r.end());
    if (std::isnan(c.parting_rms_l))
      std::cout << "; rms never above " << t << " (largest " << format_number(*rms) << " r)\n";
    else
      std::cout << "; rms above " << t << " at l = " << format_number(c.parting_rms_l) << "\n";
  } catch (const RunFileError& e) {
    throw InputError(e.what());
  } catch (const WriteError& e) {
    throw InputError(e.what());
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "wirepack: elastic wires injected into spherical shells (Vetter, Wittel, "
      "Herrmann, EPL 112, 44003, 2015)"};
  app.footer("Exit codes: 0 success, 2 bad input (nothing written), 1 a run failed.");
  app.set_version_flag("--version", build_version() + " (" + build_git() + ")");
  app.require_subcommand(1);

  std::string scene_path, out_path;
  auto* run = app.add_subcommand("run",
                                 "simulate one scene; progress on stderr, then the run "
                                 "file's path on stdout");
  run->add_option("scene", scene_path,
                  "scene file (JSON); without one, the embedded default scene (rigid sphere, "
                  "rho = 20, mu_s = 0, l_max = 20; see scenes/rigid_default.json)");
  run->add_option("-o,--out", out_path, "run file to write (HDF5)")->required();
  int run_threads = 1;
  run->add_option("-j,--threads", run_threads,
                  "threads of the force loops (default 1); the run file is bitwise the same "
                  "for any count")
      ->check(CLI::Range(1, 1024));
  const std::string checkpoint_help =
      "seconds of wall time between checkpoints (RUN.h5.ckpt; default 300, 0: none); a run "
      "whose checkpoint exists resumes from it, bitwise the same as uninterrupted";
  double run_checkpoint_every = kDefaultCheckpointEvery;
  run->add_option("--checkpoint-every", run_checkpoint_every, checkpoint_help)
      ->check(CLI::Range(0.0, 1e9));
  SweepArgs sweep_args;
  auto* sweep = app.add_subcommand(
      "sweep",
      "run every (grid point, seed) of a sweep file as parallel runs into one directory; "
      "rerunning resumes (finished runs are kept)");
  sweep->add_option("sweep", sweep_args.path,
                    "sweep file (JSON); without one, the embedded default sweep (elastic "
                    "shell, rho = 20, xi = 10, eps = 1e3, mu_s = 0, 0.1, 0.25, 0.5, 2 seeds, "
                    "l_max = 14; see scenes/default.sweep.json)");
  sweep->add_option("-o,--out", sweep_args.out,
                    "sweep directory (default sweeps/NAME, NAME from the sweep file)");
  sweep->add_option("-j,--threads", sweep_args.threads, "concurrent runs (default: all cores)")
      ->check(CLI::Range(1, 4096));
  sweep->add_option("--shard", sweep_args.shard,
                    "K/N: run only every N-th run of the run order, starting at K (default: "
                    "from SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT, else 0/1)");
  sweep->add_flag("--retry-failed", sweep_args.retry_failed,
                  "run again the runs whose file says failed (kept otherwise)");
  sweep
      ->add_option("--only", sweep_args.only,
                   "KEY=V1,V2,...: run only the runs whose grid axis KEY (or seed) has one of "
                   "these values; repeat for several axes (all must hold). The manifest still "
                   "lists every run; the others stay pending for a later invocation")
      ->allow_extra_args(false);
  sweep->add_option("--checkpoint-every", sweep_args.checkpoint_every, checkpoint_help)
      ->check(CLI::Range(0.0, 1e9));

  // The transition parameters, as the scene schema's rows name them (KeySpec::Roles).
  const std::string transition_names =
      wirepack::sweep::key_names_with(&wirepack::sweep::KeySpec::Roles::transition);
  AnalyzeOptions analyze_opt;
  std::string d_window;
  double at_l = -1;
  int bins = 0, resamples = -1;
  bool no_plots = false;
  auto* analyze = app.add_subcommand(
      "analyze",
      "tables (CSV) and plots of a sweep directory: D curves, scaling exponents, seed-averaged "
      "series, curvature and loop-length distributions (docs/reference.md, \"Analysis\")");
  std::vector<std::string> analyze_dirs;
  analyze
      ->add_option("dir", analyze_dirs,
                   "sweep directory (written by wirepack sweep); several: their critical points "
                   "in one four-dimensional table, OUT/phase_diagram_4d.csv, and its plots")
      ->required();
  analyze->add_option("-o,--out", analyze_opt.out,
                      "output directory (default DIR/analysis; required with several DIRs)");
  auto* d_window_opt = analyze->add_option(
      "--d-window", d_window, "L_MIN,L_MAX: l window of D's maximum and mean (default 5,50)");
  analyze
      ->add_option("--fit-window", analyze_opt.fit_windows,
                   "L_MIN,L_MAX (every exponent) or NAME=L_MIN,L_MAX (alpha, beta, gamma, "
                   "delta, lambda, tau): l window of the power-law fits (default 5,50); "
                   "repeatable")
      ->allow_extra_args(false);  // one value per --fit-window, so DIR may follow
  auto* at_l_opt = analyze->add_option(
      "--at-l", at_l, "l of the distributions (default: the last snapshot common to the runs)");
  auto* bins_opt = analyze->add_option("--bins", bins, "histogram bins (default 30)");
  auto* resamples_opt = analyze->add_option(
      "--resamples", resamples, "seed-bootstrap resamples of the exponents (default 1000; 0: off)");
  analyze
      ->add_option("--critical-range", analyze_opt.critical_ranges,
                   "NAME=X_MIN,X_MAX: fit the critical point of NAME (" + transition_names +
                       ") on the grid values inside only, e.g. mu_s=0,0.6; "
                       "repeatable")
      ->allow_extra_args(false);
  analyze
      ->add_option("--fit-auto", analyze_opt.fit_auto,
                   "all or NAME (alpha, ... tau): start that exponent's window where the "
                   "scaling-window rule says (inside its fit window) and fit log-spaced points; "
                   "repeatable")
      ->allow_extra_args(false);
  analyze->add_option("--order-parameter", analyze_opt.order_parameter,
                      "D (the paper's, default), D_chord or D_kappa: the order parameter of the "
                      "critical points and the phase diagram");
  analyze->add_flag("--no-plots", no_plots, "write the gnuplot scripts but do not run gnuplot");

  RefineOptions refine_opt;
  double until_ci = 0;
  long budget = 0;
  auto* refine = app.add_subcommand(
      "refine",
      "add seeds or grid values where they narrow the interval of the critical point most "
      "(before a fit: where D changes fastest) and run them; resumable (docs/reference.md, "
      "\"Critical points\")");
  refine->add_option("dir", refine_opt.dir, "sweep directory (written by wirepack sweep)")
      ->required();
  refine->add_option("--axis", refine_opt.axis,
                     "the parameter to refine: one of " + transition_names +
                         " (default mu_s if swept, else the one swept)");
  refine
      ->add_option("--runs", refine_opt.runs,
                   "new runs per slice and round, in whole points of all seeds (default 4 "
                   "points)")
      ->check(CLI::Range(1, 100000));
  refine
      ->add_option("--add", refine_opt.add,
                   "auto (default): seeds at the values in and next to the interval of x_c while "
                   "they have too few for it (docs/reference.md, \"Refinement\"), then new "
                   "values; values: values only; seeds: seeds only")
      ->check(CLI::IsMember({"auto", "values", "seeds"}));
  auto* until_ci_opt = refine->add_option(
      "--until-ci", until_ci,
      "stop when every 95 % interval of x_c is at most this wide (units of the parameter)");
  auto* budget_opt = refine->add_option(
      "--budget", budget,
      "most runs the refinement may hold in DIR in all, across reruns (default: one round; "
      "with --until-ci, 10 rounds)");
  refine
      ->add_option("--critical-range", refine_opt.critical_ranges,
                   "NAME=X_MIN,X_MAX: fit and refine inside this range only (as for analyze)")
      ->allow_extra_args(false);
  refine->add_option("-j,--threads", refine_opt.threads, "concurrent runs (default: all cores)")
      ->check(CLI::Range(1, 4096));

  AccuracyOptions accuracy_opt;
  std::string accuracy_window;
  bool accuracy_no_plots = false;
  auto* accuracy = app.add_subcommand(
      "accuracy",
      "accuracy-vs-time study of sweep directories whose grids are ladders over numerics "
      "(element_length, shell_mesh_size, quasistatic_ratio, tolerance): error against the "
      "finest setting and wall time per setting, CSV and a Pareto plot (docs/reference.md, "
      "\"Accuracy and presets\")");
  accuracy->add_option("dirs", accuracy_opt.dirs, "sweep directories (pooled)")->required();
  accuracy->add_option("-o,--out", accuracy_opt.out, "output directory (default DIR/accuracy)");
  accuracy->add_option("--window", accuracy_window,
                       "L_MIN,L_MAX: l window of the errors and of D_max (default 5,50)");
  accuracy->add_flag("--no-plots", accuracy_no_plots, "write the gnuplot script only");

  std::string validate_path;
  auto* validate = app.add_subcommand(
      "validate",
      "check a scene or sweep file and print it resolved (all defaults; a sweep with its runs)");
  validate->add_option("file", validate_path, "scene or sweep file (JSON)")->required();

  std::string run_file, csv_path, xmf_path, profile_path;
  long profile_snapshot = -1;
  auto* exp = app.add_subcommand("export",
                                 "convert a run file: series to CSV, snapshots to "
                                 "an XDMF sidecar for ParaView");
  exp->add_option("run_file", run_file,
                  "run file (HDF5), or the checkpoint RUN.h5.ckpt of a run part-way (--csv and "
                  "--profile: what it has recorded so far)")
      ->required();
  auto* outputs = exp->add_option_group("outputs", "at least one of");
  outputs->add_option("--csv", csv_path, "write the series as CSV");
  outputs->add_option("--xdmf", xmf_path, "write an XDMF file referencing the run file");
  outputs->add_option("--profile", profile_path,
                      "write one snapshot's wire, node by node from the hole, as CSV: curvature, "
                      "signed curvature about the coil normal, gap to the shell, entry chord");
  outputs->require_option(1, 3);
  exp->add_option("--snapshot", profile_snapshot,
                  "snapshot of --profile, from 0; negative counts from the end (default -1, the "
                  "last)");

  std::string twin_a, twin_b, twin_csv_path;
  double twin_threshold = 1.0;
  auto* twin = app.add_subcommand(
      "twin",
      "compare twin runs (one scene, perturbations differing by a tiny perturbation/offset): "
      "where their wires part, modulo a rotation about the feed axis");
  twin->add_option("run_a", twin_a, "run file (HDF5) or checkpoint")->required();
  twin->add_option("run_b", twin_b, "its twin")->required();
  twin->add_option("--threshold", twin_threshold,
                   "separation that counts as parted, in wire radii r (default 1)")
      ->check(CLI::PositiveNumber);
  twin->add_option("--csv", twin_csv_path, "write l and the separation / r per snapshot");

  wirepack::app::RenderOptions render_opt;
  auto* render = app.add_subcommand(
      "render",
      "draw a run file with ParaView (pvbatch, off-screen): the wire as a tube coloured by its "
      "curvature kappa R, the shell translucent and coloured by a field; a picture of one "
      "snapshot and/or a movie of all (falls back to gnuplot without ParaView; "
      "docs/reference.md, \"Pictures and movies\")");
  render->add_option("run_file", render_opt.run_file, "run file (HDF5)")->required();
  auto* render_outputs = render->add_option_group("outputs", "at least one of");
  render_outputs->add_option("-o,--out", render_opt.out, "picture to write (PNG)");
  render_outputs->add_option("--movie", render_opt.movie,
                             "movie over all snapshots to write (MP4, H.264; needs ffmpeg)");
  render_outputs->require_option(1, 2);
  render->add_option("--snapshot", render_opt.snapshot,
                     "snapshot of the picture, 0 to count - 1 (default: the last)");
  render->add_flag("--half-radius", render_opt.half_radius,
                   "draw the wire at half its radius, to show the inside (as the paper does)");
  render
      ->add_option("--shell-field", render_opt.shell_field,
                   "colour of an elastic shell: area_stretch (default), contact_pressure, "
                   "clamped or none")
      ->check(CLI::IsMember({"area_stretch", "contact_pressure", "clamped", "none"}));
  render->add_option("--size", render_opt.size, "picture size WxH in pixels (default 1200x900)");
  render->add_option("--kappa-range", render_opt.kappa_range,
                     "A,B: kappa R at the ends of the wire's colour map (default 0,3)");
  render->add_option("--title", render_opt.title, "title (default: the run file's name)");

  auto* schema = app.add_subcommand("schema", "print the scene file keys as a Markdown table");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help (code 0) or the usage error
    return code == 0 ? kOk : kBadInput;
  }

  if ((*run && run_threads > 1) || *sweep || *refine) spin_between_parallel_loops(argv);

  try {
    if (*run) return cmd_run(scene_path, out_path, run_threads, run_checkpoint_every);
    if (*sweep) return cmd_sweep(sweep_args);
    if (*validate) return cmd_validate(validate_path);
    if (*analyze) {
      if (*d_window_opt) analyze_opt.D_window = d_window;
      if (*at_l_opt) analyze_opt.at_l = at_l;
      if (*bins_opt) analyze_opt.bins = bins;
      if (*resamples_opt) analyze_opt.resamples = resamples;
      if (no_plots) analyze_opt.gnuplot.clear();
      if (analyze_dirs.size() > 1) return cmd_phase_diagram(analyze_dirs, analyze_opt);
      analyze_opt.dir = analyze_dirs.front();
      return cmd_analyze(analyze_opt);
    }
    if (*refine) {
      if (*until_ci_opt) refine_opt.until_ci = until_ci;
      if (*budget_opt) refine_opt.budget = budget;
      refine_opt.progress = &std::cerr;
      return cmd_refine(refine_opt);
    }
    if (*accuracy) {
      if (accuracy_no_plots) accuracy_opt.gnuplot.clear();
      return cmd_accuracy(accuracy_opt, accuracy_window);
    }
    if (*exp) return cmd_export(run_file, csv_path, xmf_path, profile_path, profile_snapshot);
    if (*render) return cmd_render(render_opt);
    if (*twin) return cmd_twin(twin_a, twin_b, twin_threshold, twin_csv_path);
    if (*schema) {
      std::cout << schema_markdown();
      return kOk;
    }
  } catch (const InputError& e) {
    for (const auto& m : e.messages()) std::cerr << m << '\n';
    return kBadInput;
  } catch (const std::exception& e) {
    std::cerr << "wirepack: " << e.what() << '\n';
    return kRunFailed;
  }
  return kBadInput;
}
