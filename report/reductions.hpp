#pragma once
// The reductions of `wirepack analyze` (docs/design.md §5.8): pure functions of runs held in
// memory (no files), so they can be tested on made-up runs. A grid point is a resolved scene
// minus its seed and its output settings (sweep::point_key); runs of one point differ only in
// the seed and are averaged (mean, SEM = s / sqrt(n), s with n - 1); only complete runs enter
// the statistics.
#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "analysis/distributions.hpp"
#include "analysis/stats.hpp"
#include "report/critical_table.hpp"
#include "report/settings.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/runfile/series.hpp"
#include "sweep/runfile/wire_profile.hpp"

namespace wirepack::report {

using analysis::NaN;

// The series kept per complete run (the columns of series.csv): those of `list` with an
// analysis_rank, by rank.
std::vector<std::string> kept_series(const sweep::SeriesList& list = sweep::recorded_series());
// The series the reductions name as physics quantities (summarize_run, exponent_specs): D,
// U_b_hat, K, N, R_t, R_x, R_y. Throws std::logic_error naming those `list` does not keep.
void check_named_series(const sweep::SeriesList& list);
// Purohit predictions added per row by summarize_run.
const std::vector<std::string>& predicted_series();

// One run of a sweep directory as the analysis sees it.
struct RunData {
  std::string file;    // relative to DIR
  std::string status;  // complete | failed | missing | unreadable | running
  std::string reason;
  nlohmann::json config;  // the resolved scene; null when unknown
  nlohmann::json seed;    // null when unknown
  std::string key;        // grid point: canonical JSON of the config without seed and output
  int point = -1;         // index of the grid point; -1 when unknown

  // runs.csv quantities (complete runs; l_reached and wall_s also for failed ones)
  double D = NaN, D_avg = NaN, l_reached = NaN, wall_s = NaN, U_b_hat = NaN, K = NaN, N = NaN;
  // The order parameter's variants (docs/design.md §5.3) maximised over the D window like D:
  // series D_chord, and 1 - |S_kappa|; NaN for run files recorded before those series.
  double D_chord = NaN, D_kappa = NaN;
  // complete runs: series by name (l, kept_series, predicted_series), equal lengths
  std::map<std::string, std::vector<double>> series;
  double every_l = 0.1;            // output.every_l of the run
  std::vector<double> snapshot_l;  // l of each snapshot
};

// Sets a run's scene, seed and point key from a resolved scene (nothing if not an object).
void set_run_config(RunData& r, const nlohmann::json& config);

// The finite values of y at rows whose l lies in w, in row order.
std::vector<double> values_in_window(const std::vector<double>& l, const std::vector<double>& y,
                                     const LWindow& w);

// The number at a JSON pointer of a scene, NaN when absent or not a number.
double number_at(const nlohmann::json& config, const char* pointer);

// A complete run's quantities from its series "l" and kept_series(): D and D_avg over the D
// window, the maxima of D_chord and D_kappa = 1 - |S_kappa| there, the last U_b_hat, K, N, and the
// Purohit series (paper Eqs. 4-7) from its radii. Nothing for a run that is not complete.
void summarize_run(RunData& r, const AnalysisSettings& settings);

// The index of the snapshot nearest to l, if one lies within 0.05 in l.
std::optional<std::size_t> snapshot_near(const std::vector<double>& ls, double l);

struct GridPoint {
  std::string key;
  std::map<std::string, nlohmann::json>
      leaves;                            // pointer -> value of its scene (without seed, output)
  std::vector<const RunData*> complete;  // seeds order
  std::size_t failed = 0, missing = 0;
};

// The always-listed parameters; swept ones beyond them are appended.
const std::vector<std::string>& fixed_parameters();

// The swept parameters: leaves whose value differs between points, in order of preference (the
// sweep's axes, then the control parameters, then by pointer), leaving out those determined by
// the ones already chosen (mu_d = 0.9 mu_s follows mu_s).
std::vector<std::string> swept_parameters(const std::vector<GridPoint>& points,
                                          const std::optional<sweep::Sweep>& sweep);

// The value of a point's scene at a pointer (null when absent).
nlohmann::json leaf(const GridPoint& p, const std::string& ptr);

// The analysis of one directory.
struct Analysis {
  AnalysisSettings settings;
  std::vector<RunData> runs;        // runs.csv order: by point, seed, file
  std::vector<GridPoint> points;    // in point order
  std::vector<std::string> axes;    // swept parameters (pointers)
  std::vector<std::string> params;  // parameter columns (pointers)
  std::vector<std::string> param_names;
  double distribution_l = NaN;
  std::vector<std::string> kept = kept_series();  // series kept per run (series.csv order)
};

// Groups a.runs into grid points by their key, orders points (by the swept parameters, the
// first slowest) and runs (by point, seed, file), and sets the parameter columns.
void group(Analysis& a, const std::optional<sweep::Sweep>& sweep);

// A run quantity over the complete runs of a point, in seed order.
// The RunData field of an order parameter name (settings.hpp: is_order_parameter); D otherwise.
double RunData::*order_parameter_field(const std::string& name);
std::vector<double> values(const GridPoint& p, double RunData::*field);

// D against one swept parameter: the other swept parameters first, sorted by them, then by it.
struct View {
  std::string name;  // column of the parameter
  std::string pointer;
  std::vector<std::string> others;  // pointers of the other swept parameters
  std::vector<std::size_t> order;   // point indices in row order
};
View make_view(const Analysis& a, const std::string& ptr);

// One exponent fit of one point.
struct ExponentFit {
  analysis::PowerLawFit fit;
  double stderr_bootstrap = NaN;
  std::size_t seeds = 0;
  bool auto_window = false;  // window start by the scaling-window rule, log-spaced fit
};
// The power law of `series` over the pooled rows of p's complete runs in w (OLS of every row),
// or with auto_window: from where analysis::find_scaling_window's rule starts the scaling
// window inside w (on the pooled seeds), fitted over log-spaced points
// (analysis::fit_power_law_log_spaced); the bootstrap over seeds refits the same window.
ExponentFit fit_exponent(const GridPoint& p, const std::string& series, const LWindow& w,
                         int resamples, bool auto_window = false);
// The reported standard error is the seed bootstrap's from 3 seeds on, else the OLS one.
bool use_bootstrap(const ExponentFit& f);
double reported_stderr(const ExponentFit& f);

using Fits = std::vector<std::vector<ExponentFit>>;  // [point][exponent]
Fits fit_all(const Analysis& a);

// Seed-averaged series of one point: rows at the nominal l = k every_l.
struct MeanSeries {
  std::vector<double> l;
  std::vector<std::size_t> n;
  std::map<std::string, std::vector<analysis::MeanSem>> q;  // by series name
};
// `kept`: the series averaged besides the Purohit ones (each run holds them).
MeanSeries mean_series(const GridPoint& p, const std::vector<std::string>& kept = kept_series());

// The last snapshot l that every complete run has (rounded to 0.001), NaN without complete runs.
double common_snapshot_l(const Analysis& a);

// The distribution samples of one point at the distribution l.
struct Samples {
  std::vector<double> kappa2;  // kappa^2 / <kappa^2>, pooled over the runs
  std::vector<double> loops;   // Lambda / r, pooled
  std::size_t runs = 0;        // runs with a snapshot at l
  // The loop parameters over the detector's settings (smoothing 1, 2, 4 r x prominence 0.1,
  // 0.25, 0.5), the runs' wires pooled (analysis::loop_sensitivity).
  std::vector<analysis::LoopSensitivityRow> loop_sensitivity;
  // Each of those runs' order parameters at l (sweep::order_variants: the paper's D, without the
  // entry chord, curvature-weighted, and the sense blocks), in the point's seed order.
  struct RunOrder {
    const RunData* run = nullptr;
    double l = NaN;  // the snapshot's l [-]
    sweep::OrderVariants order;
  };
  std::vector<RunOrder> orders;
  // The packing of the first of those runs: its wire and shell vertices (none if rigid) at l
  // [m], the cavity radius R [m].
  std::vector<std::array<double, 3>> wire, shell;
  double R = NaN;
};

// Density of N(mu, sigma^2) at x.
double normal_pdf(double x, double mu, double sigma);

// Lognormal fit and histogram of ln x for one sample set.
struct Distribution {
  std::string quantity;
  analysis::LognormalFit fit;
  analysis::Histogram hist;  // of ln x
  std::vector<double> fit_density;
  // The paper's "best-fitting density": the normal density least-squares fitted to hist.
  analysis::HistogramNormalFit ls_fit;
};
Distribution distribution(const std::string& quantity, const std::vector<double>& xs, int bins);

using Distributions = std::vector<std::array<Distribution, 2>>;  // [point][kappa2, Lambda]

// The grid points as the critical-point fits see them (critical_table.hpp).
std::vector<CriticalPoint> critical_points(const Analysis& a);

}  // namespace wirepack::report
