// The D-against-parameter plot of `wirepack analyze` (paper Fig. 5, with the inset of Fig. 5b):
// a synthetic sweep over mu_s with a continuous transition at mu_c = 0.3 in its per-seed D
// (run files written with write_run_file). The plot shows the chosen order parameter, the
// literal D beside it, the fitted model and x_c with its interval from critical.csv, and an
// inset whose x range brackets x_c; without a fitted transition none of these (the golden
// outputs check that page byte for byte). Rendered by gnuplot where it is installed.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>

#include "report/analyze.hpp"
#include "report/plots.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/running/run.hpp"
#include "sweep/running/sweep_manifest.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::report {
namespace {

namespace fs = std::filesystem;
using namespace wirepack::sweep;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

// Per-seed peak of D over the window: 0.05 in the coil, rising linearly above mu_c = 0.3
// (b = 1), plus a seed offset of +-0.01; D_chord is half of it.
double peak_D(double mu, int seed) {
  return 0.05 + 1.2 * std::max(0.0, mu - 0.3) + 0.01 * (seed - 2);
}

// With `reentrant`, mu_s = 1 coils again (D 0.04 < the coil's 0.05), as Fig. 5b's mu_s = 1
// does.
RunRecord make_run(const SweepRun& run, bool reentrant = false) {
  RunRecord r;
  r.config = run.scene.resolved;
  r.status = RunStatus::Complete;
  const double mu = run.scene.resolved["mu_s"].get<double>();
  const double peak = reentrant && mu > 0.9 ? 0.04 : peak_D(mu, run.seed);
  std::map<std::string, std::vector<double>> v;
  for (int k = 0; k <= 100; ++k) {
    const double l = 0.1 * k;
    v["l"].push_back(l);
    v["D"].push_back(l < 2 ? 0.95 : k == 60 ? peak : 0.02);
    v["D_chord"].push_back(0.5 * v["D"].back());
    v["U_b_hat"].push_back(std::pow(l, 1.5));
    v["K"].push_back(std::pow(l, 1.2));
    v["R_t"].push_back(NAN);
    v["R_x"].push_back(NAN);
    v["R_y"].push_back(NAN);
  }
  for (const auto& name : series_names()) {
    auto values = v.contains(name) ? v[name] : std::vector<double>(101, 0.0);
    r.series.push_back({name, values});
  }
  Snapshot s;
  s.l = 10;
  s.wire = {{0, 0, -0.01}, {0, 1e-3, -0.009}, {1e-3, 1e-3, -0.008}};
  s.curvature = {0, 100, 0};
  r.snapshots = {s};
  return r;
}

// mu_s = 0 ... 0.6 in steps of 0.1, 3 seeds, D over l in [2, 10]; with `not_run_yet`, also
// mu_s = 0.8 and 1, whose runs are pending (a campaign part-way); with `reentrant`, also
// mu_s = 0.8 and 1, run, with mu_s = 1 coiled again.
void write_transition_sweep(const std::string& dir, const std::string& analysis,
                            bool not_run_yet = false, bool reentrant = false) {
  const std::string grid = not_run_yet || reentrant ? "[0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.8, 1]"
                                                    : "[0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6]";
  const Sweep sw = parse_sweep(
      parse_json_text(R"({"name": "tr", "base": {"rho": 20, "shell": "rigid", "l_max": 10},
          "grid": {"mu_s": )" +
                          grid + R"(}, "seeds": 3, "analysis": )" + analysis + "}",
                      "tr.json"),
      "tr.json");
  fs::create_directories(fs::path(dir) / "runs");
  std::vector<ManifestEntry> entries;
  for (const auto& run : sw.runs) {
    if (not_run_yet && run.point_values["mu_s"].get<double>() > 0.7) {
      entries.push_back({&run, EntryStatus::Pending});
      continue;
    }
    write_run_file(make_run(run, reentrant), (fs::path(dir) / run.file).string());
    entries.push_back({&run, EntryStatus::Complete});
  }
  write_file_atomic(manifest_path(dir, Shard{}), manifest_json(sw, Shard{}, entries).dump(1));
}

// The value of column `name` in the first data row of a CSV text.
std::string first_row_value(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  std::string header, row, cell;
  std::getline(in, header);
  std::getline(in, row);
  std::vector<std::string> names, cells;
  std::stringstream h(header), c(row);
  while (std::getline(h, cell, ',')) names.push_back(cell);
  while (std::getline(c, cell, ',')) cells.push_back(cell);
  for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i)
    if (names[i] == name) return cells[i];
  return "";
}

// The first number after `key` in `text` (NaN when `key` is absent).
double number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  if (at == std::string::npos) return NAN;
  return std::stod(text.substr(at + key.size()));
}

TEST(ViewPlot, TransitionGetsItsFitAndAnInsetAboutXc) {
  TempDir dir;
  write_transition_sweep(dir.path().string(),
                         R"({"D_window": [2, 10], "order_parameter": "D_chord"})");
  AnalyzeOptions o;
  o.dir = dir.path().string();
  o.gnuplot = "";
  analyze_sweep(o);
  const std::string crit = read_text(dir / "analysis/critical.csv");
  ASSERT_EQ(first_row_value(crit, "status"), "ok") << crit;
  const double x_c = std::stod(first_row_value(crit, "x_c"));
  const double x_lo = std::stod(first_row_value(crit, "x_c_lo"));
  const double x_hi = std::stod(first_row_value(crit, "x_c_hi"));
  EXPECT_NEAR(x_c, 0.3, 0.05);  // the synthetic mu_c, from 7 grid values

  const std::string gp = read_text(dir / "analysis/plots/D_vs_mu_s.gp");
  // The chosen order parameter, and the literal D beside it.
  EXPECT_NE(gp.find("set ylabel \"D_chord\""), std::string::npos) << gp;
  EXPECT_NE(gp.find("D_chord = max of D_chord(l)"), std::string::npos);
  EXPECT_NE(gp.find("title \"literal D\""), std::string::npos);
  // The fit with x_c and its interval, as critical.csv has them (3 digits in the key).
  char key[128];
  std::snprintf(key, sizeof(key), "title \"fit: mu_s_c = %.3g [%.3g, %.3g]\"", x_c, x_lo, x_hi);
  EXPECT_NE(gp.find(key), std::string::npos) << key << "\n" << gp;
  EXPECT_NE(gp.find("title \"D_chord\""), std::string::npos);
  EXPECT_DOUBLE_EQ(number_after(gp, "set arrow from "), x_c);
  EXPECT_DOUBLE_EQ(number_after(gp, "rect from "), x_lo);
  // The inset: beside the main panel (which keeps the left 0.66 of the canvas), its x range
  // bracketing x_c's interval and inside the grid.
  EXPECT_NE(gp.find("set multiplot title"), std::string::npos);
  EXPECT_NE(gp.find("set size 0.66, 1"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set origin 0.66, 0.3"), std::string::npos) << gp;
  EXPECT_NE(gp.find("rect from screen 0.66, screen 0.3 to screen 1, screen 0.75"),
            std::string::npos);  // the inset's opaque background
  EXPECT_NE(gp.find("set title \"about mu_s_c (continuous)\""), std::string::npos);
  const auto range_at = gp.find("set xrange [");
  ASSERT_NE(range_at, std::string::npos);
  const double r_lo = number_after(gp.substr(range_at), "set xrange [");
  const double r_hi = number_after(gp.substr(range_at), ":");
  EXPECT_LE(r_lo, x_lo);
  EXPECT_GE(r_hi, x_hi);
  EXPECT_GE(r_lo, 0.0);
  EXPECT_LE(r_hi, 0.6);
  EXPECT_LT(r_hi - r_lo, 0.6) << "the inset magnifies nothing";
  // Its ticks: at most three intervals over its range (gnuplot's own crowded a narrow inset).
  const auto tics_at = gp.find("set xtics ", range_at);
  ASSERT_NE(tics_at, std::string::npos) << gp;
  const double step = number_after(gp.substr(tics_at), "set xtics ");
  EXPECT_GT(step, 0.0);
  EXPECT_LE((r_hi - r_lo) / step, 3.0 + 1e-9);

  // gnuplot accepts the script (where it is installed).
  o.gnuplot = "gnuplot";
  const AnalyzeResult p = analyze_sweep(o);
  if (p.plot_notice.find("not found") != std::string::npos) GTEST_SKIP() << p.plot_notice;
  EXPECT_EQ(p.plot_notice, "");
  const std::string png = dir / "analysis/plots/D_vs_mu_s.png";
  ASSERT_TRUE(fs::exists(png));
  EXPECT_EQ(read_text(png).substr(1, 3), "PNG");
}

// Grid values not run yet (their D is NaN) do not move the inset (an inset over the panel, put
// on the side read from the end points, hid Fig. 5b's mu_s = 0.3 point part-way).
TEST(ViewPlot, InsetBesideThePanelWhileGridValuesAreNotRunYet) {
  TempDir dir;
  write_transition_sweep(dir.path().string(),
                         R"({"D_window": [2, 10], "order_parameter": "D_chord"})", true);
  AnalyzeOptions o;
  o.dir = dir.path().string();
  o.gnuplot = "";
  analyze_sweep(o);
  const std::string gp = read_text(dir / "analysis/plots/D_vs_mu_s.gp");
  EXPECT_NE(gp.find("set origin 0.66, 0.3"), std::string::npos) << gp;
}

// A curve that comes back down at its last grid value (the coil again at the highest mu_s): the
// inset stays beside the panel (over it, read from the end points, it went over the data).
TEST(ViewPlot, InsetBesideThePanelWhenTheCurveComesBackDown) {
  TempDir dir;
  write_transition_sweep(dir.path().string(),
                         R"({"D_window": [2, 10], "order_parameter": "D_chord"})", false, true);
  AnalyzeOptions o;
  o.dir = dir.path().string();
  o.gnuplot = "";
  o.critical_ranges = {"mu_s=0,0.8"};  // the transition's models are monotonic: fitted up to 0.8
  analyze_sweep(o);
  const std::string gp = read_text(dir / "analysis/plots/D_vs_mu_s.gp");
  ASSERT_NE(gp.find("set multiplot"), std::string::npos) << "no transition fitted:\n" << gp;
  EXPECT_NE(gp.find("set origin 0.66, 0.3"), std::string::npos) << gp;
}

// Tick spacings 1, 2, 5 x 10^k, the smallest giving at most N intervals: the refined critical
// study's inset ([0.6878, 0.7122], 11 labels 0.002 apart from gnuplot, which overlapped) gets
// 0.01; Fig. 5b's ([0.2, 0.4]) 0.1.
TEST(ViewPlot, TickStepLeavesAtMostTheIntervalsAsked) {
  EXPECT_DOUBLE_EQ(plots::tick_step(0.6878, 0.7122, 3), 0.01);
  EXPECT_DOUBLE_EQ(plots::tick_step(0.2, 0.4, 3), 0.1);
  EXPECT_DOUBLE_EQ(plots::tick_step(0.2, 0.4, 4), 0.05);
  EXPECT_DOUBLE_EQ(plots::tick_step(0, 1, 5), 0.2);  // exactly 5 intervals of 0.2
  EXPECT_DOUBLE_EQ(plots::tick_step(0, 30, 3), 10.0);
  EXPECT_DOUBLE_EQ(plots::tick_step(1, 1, 3), 0.0);  // empty range: gnuplot decides
  EXPECT_DOUBLE_EQ(plots::tick_step(0, NAN, 3), 0.0);
  for (double w : {1e-4, 3.7e-3, 0.02, 0.26, 7.0, 130.0}) {
    const double s = plots::tick_step(0.5, 0.5 + w, 3);
    EXPECT_LE(w / s, 3.0 + 1e-9) << w;
    EXPECT_GT(w / s, 1.2) << w;  // not coarser than needed: the next smaller step gives > 3
  }
}

// A curve's x offset goes into its `using` x column in the form of its axis: a factor
// 10^offset on a log axis (a shift of `offset` decades), a sum on a linear one; a curve without
// an offset keeps column 1; the columns after x stay those of its style.
TEST(ViewPlot, XOffsetIsAFactorOnALogAxisAndASumOnALinearOne) {
  for (const bool logx : {true, false}) {
    plots::Panel p;
    p.logx = logx;
    plots::Curve shifted{"a", plots::Curve::Style::IntervalLines, {{{1, 2, 1.5, 2.5}}}, -0.25};
    plots::Curve plain{"b", plots::Curve::Style::Points, {{{1, 3, 0, 0}}}, 0};
    p.curves = {shifted, plain};
    const std::string gp = plots::script("", "t", {p}, 1, 1, "x.png", 400, 300);
    const std::string want = logx ? "using ($1*10**(-0.25)):2:3:4 with yerrorlines"
                                  : "using ($1+(-0.25)):2:3:4 with yerrorlines";
    EXPECT_NE(gp.find(want), std::string::npos) << gp;
    EXPECT_NE(gp.find("using 1:2 with points"), std::string::npos) << gp;
  }
}

TEST(ViewPlot, LiteralDAloneWithoutTheOrderParameterOrAFit) {
  TempDir dir;
  // Only mu_s <= 0.2: the coil, no transition in range.
  write_transition_sweep(dir.path().string(), R"({"D_window": [2, 10]})");
  AnalyzeOptions o;
  o.dir = dir.path().string();
  o.gnuplot = "";
  o.critical_ranges = {"mu_s=0,0.2"};
  analyze_sweep(o);
  const std::string gp = read_text(dir / "analysis/plots/D_vs_mu_s.gp");
  EXPECT_NE(gp.find("set ylabel \"D\""), std::string::npos) << gp;
  EXPECT_EQ(gp.find("literal D"), std::string::npos);
  EXPECT_EQ(gp.find("fit: "), std::string::npos);
  EXPECT_EQ(gp.find("set multiplot"), std::string::npos);
  EXPECT_EQ(gp.find("set arrow"), std::string::npos);
}

}  // namespace
}  // namespace wirepack::report
