#pragma once
// `wirepack analyze DIR` (docs/design.md §4.6, §5.8): reads the run files of a sweep directory and
// writes tidy CSV tables (one header row each) and gnuplot plots. The steps live in report/:
// settings, sweep_dir (reading), reductions (pure), tables, plot_jobs. A grid point is a resolved
// scene minus its seed and its output settings; runs of one point differ only in the seed and are
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
// docs/reference.md, section "Analysis", documents every column.
#include <cstddef>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/critical_table.hpp"
#include "report/settings.hpp"

namespace wirepack::report {

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

// `wirepack analyze DIR DIR ... --out OUT`: the critical points of every sweep directory (each
// read as by analyze_sweep, under its own settings) in one four-dimensional table,
// OUT/phase_diagram_4d.csv, with OUT/plots/phase4d_<parameter>.gp and .png (phase_4d.hpp).
// InputError (exit 2) as analyze_sweep, or when OUT is empty; nothing is written then.
AnalyzeResult analyze_phase_diagram(const std::vector<std::string>& dirs,
                                    const AnalyzeOptions& options);

// The per-point D of DIR for the critical-point fits (`wirepack refine`): DIR read as by
// analyze_sweep (same settings and errors), nothing written.
struct CriticalData {
  std::vector<std::string> axes;      // swept parameters (JSON pointers), analysis order
  std::vector<CriticalPoint> points;  // in point order
  AnalysisSettings settings;
};
CriticalData read_critical_data(const AnalyzeOptions& options);

}  // namespace wirepack::report
