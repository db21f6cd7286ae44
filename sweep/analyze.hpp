#pragma once
// `wirepack analyze DIR` (docs/design.md §4.6, §5.8): reads the run files of a sweep directory and
// writes tidy CSV tables (one header row each) and gnuplot plots. A grid point is a resolved scene
// minus its seed and its output settings; runs of one point differ only in the seed and are
// averaged (mean, SEM = s / sqrt(n), s with n - 1). Only complete runs enter the statistics;
// failed, missing (never run, or a .part leftover of a killed run) and unreadable ones are listed.
//
// Outputs, in OUT (default DIR/analysis), each written to a temporary name and renamed:
//   runs.csv           one row per run: parameters, seed, status, D over the D window, l reached,
//                      wall time, final U_b_hat, K, N
//   curves.csv         one row per grid point: n and mean, SEM of every run quantity
//   D_vs_<param>.csv   per swept parameter: D against it (the other swept parameters as columns)
//   exponents.csv      alpha, beta, gamma (R_t, R_x, R_y ~ l^p), delta (U_b_hat), lambda (K),
//                      tau (N) per grid point: pooled log-log OLS, seed-bootstrap stderr
//   series.csv         seed-averaged series over l per grid point, with the Purohit predictions
//                      of U_b_hat and K (paper Eqs. 4-7) from each run's measured radii
//   critical.csv       per swept transition parameter (mu_s, eps, xi, rho) and combination of
//                      the others: x_c of D(x) with its bootstrap interval (critical_table.hpp)
//   phase_diagram.csv  with two swept parameters: x_c of one against the other
//   distributions.csv  lognormal fits of kappa^2/<kappa^2> and Lambda/r at one l, with the
//                      histogram of the logarithm
//   plots/*.gp, *.png  gnuplot scripts (data inline) and their PNGs where gnuplot is present
// The README's section "Analysis" documents every column.
#include <cstddef>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/critical_table.hpp"
#include "sweep/run_file.hpp"

namespace wirepack::sweep {

// A closed interval of l = L / R.
struct LWindow {
  double l_min = 5;   // [-]
  double l_max = 50;  // [-]
};

// "L_MIN,L_MAX" of a command-line flag (`flag` names it in the message): 0 <= L_MIN < L_MAX.
// Throws InputError.
LWindow parse_l_window(const std::string& text, const std::string& flag);

// The run files of a directory: DIR/runs/*.h5 when DIR/runs exists (a sweep directory), else
// DIR/*.h5; names relative to DIR ("runs/NAME.h5"), sorted. `parts`: the NAME.h5 of each
// NAME.h5.part there (a run killed before its rename).
struct RunFileList {
  std::string runs_dir;  // the directory searched
  std::vector<std::string> files;
  std::vector<std::string> parts;
};
RunFileList list_run_files(const std::string& dir);

// Series `name` of a run record as a column of `rows` values, NaN where the series is missing
// or shorter.
std::vector<double> series_column(const RunRecord& record, const std::string& name,
                                  std::size_t rows);
// The rows of a run record: the length of its series "l" (0 without one).
std::size_t series_rows(const RunRecord& record);
// The finite values of y at rows whose l lies in w, in row order.
std::vector<double> values_in_window(const std::vector<double>& l, const std::vector<double>& y,
                                     const LWindow& w);

// One scaling exponent: y ~ l^exponent for the series `series`.
struct ExponentSpec {
  std::string name;    // "alpha"
  std::string series;  // "R_t"
};
// alpha R_t, beta R_x, gamma R_y, delta U_b_hat, lambda K, tau N (paper section "Quantitative
// comparison"), in this order.
const std::vector<ExponentSpec>& exponent_specs();

// The analysis settings: the sweep file's `analysis` block, then the command-line flags.
struct AnalysisSettings {
  LWindow D_window;                            // D maximised and averaged over it
  std::map<std::string, LWindow> fit_windows;  // one per exponent name (all six present)
  std::optional<double> distribution_l;        // none: the last snapshot common to the runs
  int histogram_bins = 30;                     // bins of each distribution histogram
  int bootstrap_resamples = 1000;              // seed-bootstrap resamples (< 2: no bootstrap)
  // Ranges of the critical-point fits: parameter pointer ("/mu_s") -> [x_min, x_max]; grid
  // values outside are left out of that parameter's fits (e.g. a falling tail of D).
  std::map<std::string, std::pair<double, double>> critical_ranges;
};

// Defaults: every window [5, 50], distribution at the last common snapshot, 30 bins, 1000
// resamples.
AnalysisSettings default_analysis_settings();

// Applies an `analysis` block (keys D_window, fit_window, fit_windows, distribution_l,
// histogram_bins, bootstrap_resamples; see the README) onto `s`. `source` and `pointer` (the
// block's JSON pointer in that file) name it in messages: `SOURCE: POINTER/D_window: rule (got
// ...)`. Throws InputError listing every problem; unknown keys are errors.
void apply_analysis_block(const nlohmann::json& block, const std::string& source,
                          const std::string& pointer, AnalysisSettings& s);

struct AnalyzeOptions {
  std::string dir;  // the sweep directory (DIR/runs/*.h5, DIR/manifest*.json)
  std::string out;  // output directory; "" = DIR/analysis
  // Command-line overrides of the analysis block:
  std::optional<std::string> D_window;       // "L_MIN,L_MAX"
  std::vector<std::string> fit_windows;      // "L_MIN,L_MAX" (every exponent) or "NAME=L_MIN,L_MAX"
  std::optional<double> at_l;                // l of the distributions
  std::optional<int> bins;                   // histogram bins
  std::optional<int> resamples;              // bootstrap resamples
  std::vector<std::string> critical_ranges;  // "NAME=X_MIN,X_MAX" (mu_s, eps, xi, rho)
  std::string gnuplot = "gnuplot";           // plotting program (PATH is searched); "" = no plots
};

// A run that did not enter the statistics.
struct SkippedRun {
  std::string file;    // relative to DIR
  std::string status;  // "failed" | "missing" | "unreadable" | "running"
  std::string reason;
};

struct AnalyzeResult {
  std::string out;                   // the output directory
  std::vector<std::string> csv;      // CSV files written (paths), in writing order
  std::vector<std::string> scripts;  // gnuplot scripts written
  std::vector<std::string> plots;    // PNGs written
  std::string plot_notice;           // why plots are missing ("" when every one was made)
  std::size_t runs = 0;              // runs listed in runs.csv
  std::size_t complete = 0;          // complete runs analysed
  std::size_t points = 0;            // grid points
  std::vector<SkippedRun> skipped;   // in runs.csv order
  std::vector<std::string> axes;     // swept parameters (CSV column names)
  AnalysisSettings settings;         // as used
  double distribution_l = 0;         // l of distributions.csv (NaN when no run is complete)
  std::string settings_source;       // the manifest whose analysis block was used ("" none)
};

// Reads DIR, writes every output, returns what was done. Deterministic: the same directory
// gives byte-identical CSV. Throws InputError (exit 2) when DIR is not a sweep directory (not a
// directory, no run files and no manifest), a manifest cannot be parsed, a setting breaks its
// rule, or OUT cannot be created; nothing is written then.
AnalyzeResult analyze_sweep(const AnalyzeOptions& options);

// The per-point D of DIR for the critical-point fits (`wirepack refine`): DIR read as by
// analyze_sweep (same settings and errors), nothing written.
struct CriticalData {
  std::vector<std::string> axes;      // swept parameters (JSON pointers), analysis order
  std::vector<CriticalPoint> points;  // in point order
  AnalysisSettings settings;
};
CriticalData read_critical_data(const AnalyzeOptions& options);

}  // namespace wirepack::sweep
