#pragma once
// The settings of `wirepack analyze` (docs/design.md §4.6, §5.8): defaults, then the sweep file's
// `analysis` block, then the command-line flags; and the one parser of an l window given on the
// command line.
#include <map>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/runfile/series.hpp"

namespace wirepack::report {

// A closed interval of l = L / R.
struct LWindow {
  double l_min = 5;   // [-]
  double l_max = 50;  // [-]
};

// "L_MIN,L_MAX" of a command-line flag (`flag` names it in the message): 0 <= L_MIN < L_MAX.
// Throws InputError.
LWindow parse_l_window(const std::string& text, const std::string& flag);

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
  // Exponents whose window starts where analysis::find_scaling_window's rule says, inside
  // their fit window, fitted over log-spaced points (docs/design.md §5.8).
  std::set<std::string> fit_auto;
  // The order parameter of the critical points and the phase diagram: "D" (the paper's,
  // literal), "D_chord" or "D_kappa" (docs/design.md §5.3). The D tables carry all three.
  std::string order_parameter = "D";
  std::optional<double> distribution_l;  // none: the last snapshot common to the runs
  int histogram_bins = 30;               // bins of each distribution histogram
  int bootstrap_resamples = 1000;        // seed-bootstrap resamples (< 2: no bootstrap)
  // Ranges of the critical-point fits: parameter pointer ("/mu_s") -> [x_min, x_max]; grid
  // values outside are left out of that parameter's fits (e.g. a falling tail of D).
  std::map<std::string, std::pair<double, double>> critical_ranges;
};

// "D", "D_chord" or "D_kappa": the order parameters the analysis reduces (docs/design.md §5.3).
bool is_order_parameter(const std::string& name);

// Defaults: every window [5, 50], distribution at the last common snapshot, 30 bins, 1000
// resamples.
AnalysisSettings default_analysis_settings();

// Applies an `analysis` block (keys D_window, fit_window, fit_windows, fit_auto, distribution_l,
// histogram_bins, bootstrap_resamples, critical_ranges, order_parameter; see docs/reference.md)
// onto `s`. `source` and `pointer` (the block's JSON pointer in that file) name it in
// messages: `SOURCE: POINTER/D_window: rule (got ...)`. Throws InputError listing every
// problem; unknown keys are errors.
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
  std::vector<std::string> fit_auto;         // "all" or exponent names
  std::optional<std::string> order_parameter;  // D, D_chord, D_kappa
  std::string gnuplot = "gnuplot";             // plotting program (PATH is searched); "" = no plots
  // The recorded series (docs/design.md §5.7); the analysis keeps those with an analysis_rank.
  sweep::SeriesList series = sweep::recorded_series();
};

// Applies the command-line overrides of `o` onto `s`. Throws InputError naming the flag.
void apply_flags(const AnalyzeOptions& o, AnalysisSettings& s);

}  // namespace wirepack::report
