// `wirepack analyze` (docs/design.md §4.6, §5.8) on a hand-made sweep directory: two grid points
// (mu_s = 0 and 0.5) x three seeds, written with write_run_file from synthetic series and
// snapshots, one run failed. Checks grouping, n, mean and SEM exactly, the listing of skipped runs,
// the documented headers, recovery of synthetic power laws, NaN radii, the Purohit columns, the
// distributions, determinism, and bad input.
#include "report/analyze.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include <gtest/gtest.h>

#include "analysis/purohit.hpp"
#include "sweep/atomic_file.hpp"
#include "sweep/config/json_file.hpp"
#include "sweep/config/sweep_config.hpp"
#include "sweep/errors.hpp"
#include "sweep/runfile/run_file.hpp"
#include "sweep/running/run.hpp"
#include "sweep/running/sweep_manifest.hpp"
#include "sweep/temp_dir.hpp"

namespace wirepack::report {
namespace {

using namespace wirepack::sweep;

namespace fs = std::filesystem;
using json = nlohmann::json;
using wirepack::testing::read_text;
using wirepack::testing::TempDir;

// D's maximum over the window [5, 50] per run (run order: point major, seed minor); the failed
// run (point 1, seed 3) has none.
constexpr double kDmax[6] = {0.2, 0.3, 0.7, 0.5, 0.9, 0.0};
constexpr std::size_t kFailed = 5;
constexpr double kR = 20 * 0.5e-3;  // sphere radius rho r [m]

// Synthetic radii / R: power laws in l with exponents alpha, beta, gamma.
double Rt(double l) {
  return 0.3 * std::pow(l, -0.2);
}
double Rx(double l) {
  return 0.2 * std::pow(l, -0.1);
}
double Ry(double l) {
  return 0.25 * std::pow(l, -0.15);
}

// A planar wire of two turns whose radius oscillates six times per turn: curvature maxima every
// 1/6 turn, so loops for the detector. `phase` varies it per seed.
Snapshot snapshot(double l, double phase) {
  Snapshot s;
  s.l = l;
  if (l == 0) {
    s.wire = {{0, 0, -kR}, {0, 0, -kR + 1e-4}};
    s.curvature = {0, 0};
    return s;
  }
  const int n = 400;
  for (int i = 0; i < n; ++i) {
    const double th = 4 * std::numbers::pi * i / (n - 1);
    const double rad = 5e-3 * (1 + 0.3 * std::cos(6 * th + phase));
    s.wire.push_back({rad * std::cos(th), rad * std::sin(th), 1e-5 * th});
  }
  s.curvature.assign(s.wire.size(), 0.0);
  return s;
}

// The run of index i: y = a_s l^p series with seed-dependent prefactors; D = 0.95 before l = 5
// (the injection transient, outside the D window), then 0.1 with one peak kDmax[i] at l = 10.
RunRecord make_run(const SweepRun& run, std::size_t i, bool nan_radii) {
  RunRecord r;
  r.config = run.scene.resolved;
  r.status = i == kFailed ? RunStatus::Failed : RunStatus::Complete;
  r.failure = i == kFailed ? "NaN in the forces" : "";
  const int rows = i == kFailed ? 81 : 201;  // the failed run stops at l = 8
  const double s = static_cast<double>(run.seed);
  std::map<std::string, std::vector<double>> v;
  for (int k = 0; k < rows; ++k) {
    const double l = 0.1 * k;
    v["l"].push_back(l);
    v["U_b_hat"].push_back((1 + 0.1 * s) * std::pow(l, 1.5));
    v["K"].push_back(2 * (1 + 0.05 * s) * std::pow(l, 1.2));
    v["N"].push_back(3 * s * l * l);
    v["D"].push_back(l < 5 ? 0.95 : k == 100 ? kDmax[i] : 0.1);
    v["S"].push_back(1 - v["D"].back());
    v["D_chord"].push_back(0.5 * v["D"].back());  // S_kappa stays 0: D_kappa = 1
    v["R_t"].push_back(nan_radii ? NAN : Rt(l));
    v["R_x"].push_back(nan_radii ? NAN : Rx(l));
    v["R_y"].push_back(nan_radii ? NAN : Ry(l));
    v["wall_s"].push_back(0.01 * k);
    v["steps"].push_back(100.0 * k);
  }
  for (const auto& name : series_names()) {
    auto values = v.contains(name) ? v[name] : std::vector<double>(rows, 0.0);
    r.series.push_back({name, values});
  }
  for (const double l : {0.0, 5.0, 10.0, 15.0, 20.0})
    if (l <= 0.1 * (rows - 1)) r.snapshots.push_back(snapshot(l + (l > 0 ? 3e-5 : 0), s));
  return r;
}

Sweep synthetic_sweep(const std::string& analysis = R"({"fit_window": [2, 20]})") {
  return parse_sweep(parse_json_text(R"({"name": "syn", "base": {"rho": 20, "shell": "rigid",
      "l_max": 20}, "grid": {"mu_s": [0, 0.5]}, "seeds": 3, "analysis": )" +
                                         analysis + "}",
                                     "syn.json"),
                     "syn.json");
}

// Writes the sweep's manifest and run files into `dir` (point 1 with NaN radii).
void write_sweep(const Sweep& sw, const std::string& dir) {
  fs::create_directories(fs::path(dir) / "runs");
  std::vector<ManifestEntry> entries;
  for (std::size_t i = 0; i < sw.runs.size(); ++i) {
    write_run_file(make_run(sw.runs[i], i, sw.runs[i].point == 1),
                   (fs::path(dir) / sw.runs[i].file).string());
    entries.push_back({&sw.runs[i], i == kFailed ? EntryStatus::Failed : EntryStatus::Complete});
  }
  write_file_atomic(manifest_path(dir, Shard{}), manifest_json(sw, Shard{}, entries).dump(1));
}

using Rows = std::vector<std::map<std::string, std::string>>;

// A CSV file as its header line and its rows keyed by column (no quoted commas in these files).
struct Csv {
  std::string header;
  Rows rows;
};
Csv read_csv(const std::string& path) {
  std::istringstream in(read_text(path));
  Csv csv;
  std::getline(in, csv.header);
  std::vector<std::string> names;
  std::stringstream hs(csv.header);
  for (std::string c; std::getline(hs, c, ',');) names.push_back(c);
  for (std::string line; std::getline(in, line);) {
    std::map<std::string, std::string> row;
    std::stringstream ls(line);
    std::size_t i = 0;
    for (std::string c; std::getline(ls, c, ','); ++i) row[i < names.size() ? names[i] : "?"] = c;
    if (line.back() == ',') row[names.back()] = "";
    EXPECT_EQ(row.size(), names.size()) << path << ": " << line;
    csv.rows.push_back(row);
  }
  return csv;
}

double d(const std::string& s) {
  return std::stod(s);
}

// Recorded rows (l = 0.1 k, k = 0 ... 200) inside the window [lo, hi].
int rows_in(double lo, double hi) {
  int n = 0;
  for (int k = 0; k <= 200; ++k) n += 0.1 * k >= lo && 0.1 * k <= hi;
  return n;
}

class Analyze : public ::testing::Test {
 protected:
  void SetUp() override {
    sweep_ = synthetic_sweep();
    write_sweep(sweep_, dir_.path().string());
  }
  AnalyzeResult analyze(AnalyzeOptions o = {}) {
    o.dir = dir_.path().string();
    if (o.gnuplot == "gnuplot") o.gnuplot = "";  // plots only where a test asks for them
    return analyze_sweep(o);
  }
  std::string out(const std::string& name) const { return dir_ / ("analysis/" + name); }

  TempDir dir_;
  Sweep sweep_;
};

const std::string kParams = "rho,xi,eps,mu_s,mu_d,l_max,shell";

TEST_F(Analyze, CurvesGroupSeedsWithExactMeanAndSem) {
  const AnalyzeResult r = analyze();
  EXPECT_EQ(r.points, 2u);
  EXPECT_EQ(r.complete, 5u);
  ASSERT_EQ(r.axes, std::vector<std::string>{"mu_s"});  // mu_d = 0.9 mu_s follows mu_s
  const Csv c = read_csv(out("curves.csv"));
  EXPECT_EQ(c.header, "point," + kParams +
                          ",n,n_failed,n_missing,D_l_min,D_l_max,D_mean,D_sem,D_avg_mean,"
                          "D_avg_sem,U_b_hat_mean,U_b_hat_sem,K_mean,K_sem,N_mean,N_sem,"
                          "l_reached_mean,l_reached_sem,wall_s_mean,wall_s_sem,D_chord_mean,"
                          "D_chord_sem,D_kappa_mean,D_kappa_sem");
  ASSERT_EQ(c.rows.size(), 2u);
  const auto& p0 = c.rows[0];
  const auto& p1 = c.rows[1];
  EXPECT_EQ(p0.at("mu_s"), "0");
  EXPECT_EQ(p1.at("mu_s"), "0.5");
  EXPECT_EQ(p1.at("mu_d"), "0.45");
  EXPECT_EQ(p0.at("shell"), "rigid");
  EXPECT_EQ(p0.at("n"), "3");
  EXPECT_EQ(p0.at("n_failed"), "0");
  EXPECT_EQ(p1.at("n"), "2");
  EXPECT_EQ(p1.at("n_failed"), "1");
  EXPECT_EQ(p1.at("n_missing"), "0");
  EXPECT_EQ(p0.at("D_l_min"), "5");
  EXPECT_EQ(p0.at("D_l_max"), "50");
  // D = 0.2, 0.3, 0.7: mean 0.4, s^2 = 0.07, SEM = sqrt(0.07 / 3).
  EXPECT_NEAR(d(p0.at("D_mean")), 0.4, 1e-15);
  EXPECT_NEAR(d(p0.at("D_sem")), std::sqrt(0.07 / 3), 1e-15);
  // D = 0.5, 0.9 (the failed seed left out): mean 0.7, s = sqrt(0.08), SEM = 0.2.
  EXPECT_NEAR(d(p1.at("D_mean")), 0.7, 1e-15);
  EXPECT_NEAR(d(p1.at("D_sem")), 0.2, 1e-15);
  // Final U_b_hat = (1 + 0.1 s) 20^1.5 for s = 1, 2, 3: mean 1.2 20^1.5, SEM 0.1 20^1.5 / sqrt 3.
  EXPECT_NEAR(d(p0.at("U_b_hat_mean")), 1.2 * std::pow(20, 1.5), 1e-9);
  EXPECT_NEAR(d(p0.at("U_b_hat_sem")), 0.1 * std::pow(20, 1.5) / std::sqrt(3), 1e-9);
  EXPECT_NEAR(d(p0.at("l_reached_mean")), 20, 1e-12);
  EXPECT_EQ(p0.at("l_reached_sem"), "0");

  const Csv v = read_csv(out("D_vs_mu_s.csv"));
  EXPECT_EQ(v.header,
            "mu_s,n,D_mean,D_sem,D_l_min,D_l_max,D_chord_mean,D_chord_sem,D_kappa_mean,"
            "D_kappa_sem,D_sd,D_chord_sd,D_kappa_sd,D_distinct,D_chord_distinct,D_kappa_distinct");
  // The variants are maximised over the window like D: D_chord = D / 2, D_kappa = 1 - |0|.
  EXPECT_NEAR(d(v.rows[1].at("D_chord_mean")), 0.5 * d(p1.at("D_mean")), 1e-15);
  EXPECT_NEAR(d(v.rows[1].at("D_chord_sem")), 0.5 * d(p1.at("D_sem")), 1e-15);
  EXPECT_EQ(v.rows[1].at("D_kappa_mean"), "1");
  EXPECT_EQ(v.rows[1].at("D_kappa_sem"), "0");
  // Seed spread and distinct outcomes: D = 0.2, 0.3, 0.7 (three outcomes, SD sqrt(0.07)) and
  // 0.5, 0.9 (two, SD sqrt(0.08)); D_kappa = 1 in both seeds of mu_s = 0.5: one outcome, SD 0.
  EXPECT_NEAR(d(v.rows[0].at("D_sd")), std::sqrt(0.07), 1e-15);
  EXPECT_NEAR(d(v.rows[1].at("D_sd")), std::sqrt(0.08), 1e-15);
  EXPECT_NEAR(d(v.rows[1].at("D_chord_sd")), 0.5 * std::sqrt(0.08), 1e-15);
  EXPECT_EQ(v.rows[0].at("D_distinct"), "3");
  EXPECT_EQ(v.rows[1].at("D_distinct"), "2");
  EXPECT_EQ(v.rows[1].at("D_chord_distinct"), "2");
  EXPECT_EQ(v.rows[1].at("D_kappa_sd"), "0");
  EXPECT_EQ(v.rows[1].at("D_kappa_distinct"), "1");
  ASSERT_EQ(v.rows.size(), 2u);
  EXPECT_EQ(v.rows[1].at("mu_s"), "0.5");
  EXPECT_EQ(v.rows[1].at("D_mean"), p1.at("D_mean"));
  EXPECT_FALSE(fs::exists(out("D_vs_mu_d.csv")));
}

TEST_F(Analyze, RunsListsEveryRunWithItsStatus) {
  const AnalyzeResult r = analyze();
  const Csv c = read_csv(out("runs.csv"));
  EXPECT_EQ(c.header, "file,point," + kParams +
                          ",seed,status,reason,D_l_min,D_l_max,D,D_avg,l_reached,wall_s,U_b_hat,K,"
                          "N,D_chord,D_kappa");
  ASSERT_EQ(c.rows.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) {
    const auto& row = c.rows[i];
    EXPECT_EQ(row.at("file"), sweep_.runs[i].file);
    EXPECT_EQ(row.at("point"), std::to_string(i / 3));
    EXPECT_EQ(row.at("seed"), std::to_string(i % 3 + 1));
    if (i == kFailed) {
      EXPECT_EQ(row.at("status"), "failed");
      EXPECT_EQ(row.at("reason"), "NaN in the forces");
      EXPECT_EQ(row.at("D"), "nan");
      EXPECT_NEAR(d(row.at("l_reached")), 8, 1e-12);
    } else {
      EXPECT_EQ(row.at("status"), "complete");
      EXPECT_EQ(d(row.at("D")), kDmax[i]);
      EXPECT_NEAR(d(row.at("D_avg")), 0.1 + (kDmax[i] - 0.1) / rows_in(5, 50), 1e-12);
    }
  }
  ASSERT_EQ(r.skipped.size(), 1u);
  EXPECT_EQ(r.skipped[0].status, "failed");
  EXPECT_EQ(r.skipped[0].file, sweep_.runs[kFailed].file);
}

TEST_F(Analyze, MissingAndKilledRunsAreListed) {
  // Seed 2 of point 0 killed (only its .part left), seed 3 never run.
  fs::rename(dir_ / sweep_.runs[1].file, dir_ / (sweep_.runs[1].file + ".part"));
  fs::remove(dir_ / sweep_.runs[2].file);
  const AnalyzeResult r = analyze();
  const Csv c = read_csv(out("runs.csv"));
  ASSERT_EQ(c.rows.size(), 6u);
  EXPECT_EQ(c.rows[1].at("status"), "missing");
  EXPECT_NE(c.rows[1].at("reason").find(".part"), std::string::npos);
  EXPECT_EQ(c.rows[2].at("status"), "missing");
  EXPECT_EQ(c.rows[2].at("mu_s"), "0");  // parameters from the manifest
  const Csv curves = read_csv(out("curves.csv"));
  EXPECT_EQ(curves.rows[0].at("n"), "1");
  EXPECT_EQ(curves.rows[0].at("n_missing"), "2");
  EXPECT_EQ(curves.rows[0].at("D_sem"), "nan");  // one seed: no SEM
  EXPECT_EQ(r.skipped.size(), 3u);
}

TEST_F(Analyze, ExponentsRecoverSyntheticPowerLaws) {
  analyze();
  const Csv c = read_csv(out("exponents.csv"));
  EXPECT_EQ(c.header,
            "point," + kParams +
                ",name,series,value,stderr,stderr_ols,stderr_bootstrap,log_prefactor,"
                "window_l_min,window_l_max,fit_l_min,fit_l_max,n_points,n_seeds,method,ok");
  ASSERT_EQ(c.rows.size(), 12u);
  const std::map<std::string, double> expected = {{"alpha", -0.2},  {"beta", -0.1},
                                                  {"gamma", -0.15}, {"delta", 1.5},
                                                  {"lambda", 1.2},  {"tau", 2.0}};
  for (std::size_t k = 0; k < 6; ++k) {
    const auto& row = c.rows[k];  // point 0: three seeds, finite radii
    EXPECT_EQ(row.at("point"), "0");
    EXPECT_NEAR(d(row.at("value")), expected.at(row.at("name")), 1e-9) << row.at("name");
    EXPECT_EQ(row.at("ok"), "true");
    EXPECT_EQ(row.at("window_l_min"), "2");  // from the sweep's analysis block
    EXPECT_EQ(row.at("window_l_max"), "20");
    EXPECT_EQ(row.at("n_points"), std::to_string(3 * rows_in(2, 20)));  // 181 rows x 3 seeds
    EXPECT_EQ(row.at("n_seeds"), "3");
    EXPECT_EQ(row.at("method"), "ols+bootstrap");
    EXPECT_EQ(row.at("stderr"), row.at("stderr_bootstrap"));
    EXPECT_NEAR(d(row.at("fit_l_min")), 2, 1e-12);
    EXPECT_NEAR(d(row.at("fit_l_max")), 20, 1e-12);
  }
  // Point 1: radii NaN -> no fit, no crash; the others fit with two seeds.
  for (std::size_t k = 6; k < 12; ++k) {
    const auto& row = c.rows[k];
    const bool radius = row.at("series").rfind("R_", 0) == 0;
    EXPECT_EQ(row.at("ok"), radius ? "false" : "true") << row.at("name");
    if (radius) {
      EXPECT_EQ(row.at("n_points"), "0");
      EXPECT_EQ(row.at("value"), "nan");
    } else {
      EXPECT_NEAR(d(row.at("value")), expected.at(row.at("name")), 1e-9);
      EXPECT_EQ(row.at("n_seeds"), "2");
      // Two seeds: the bootstrap is computed but the OLS error is reported.
      EXPECT_NE(row.at("stderr_bootstrap"), "nan");
      EXPECT_EQ(row.at("method"), "ols");
      EXPECT_EQ(row.at("stderr"), row.at("stderr_ols"));
    }
  }
}

TEST_F(Analyze, SeriesAreSeedMeansWithPurohitPredictions) {
  analyze();
  const Csv c = read_csv(out("series.csv"));
  EXPECT_EQ(c.header, "point," + kParams +
                          ",l,n,D_mean,D_sem,U_b_hat_mean,U_b_hat_sem,K_mean,K_sem,N_mean,N_sem,"
                          "R_t_mean,R_t_sem,R_x_mean,R_x_sem,R_y_mean,R_y_sem,S_kappa_mean,"
                          "S_kappa_sem,D_chord_mean,D_chord_sem,U_b_hat_purohit_mean,U_b_hat_"
                          "purohit_sem,K_purohit_mean,K_purohit_sem");
  ASSERT_EQ(c.rows.size(), 201u + 201u);
  const auto& row = c.rows[100];  // point 0, l = 10
  EXPECT_EQ(row.at("point"), "0");
  EXPECT_EQ(row.at("l"), "10");
  EXPECT_EQ(row.at("n"), "3");
  EXPECT_NEAR(d(row.at("U_b_hat_mean")), 1.2 * std::pow(10, 1.5), 1e-9);
  // Purohit from the radii in metres: U_b_hat = U_b r^2 / (R E_w I), L = l R.
  const double r = 0.5e-3, EI = 1e9 * std::numbers::pi * std::pow(r, 4) / 4;
  const auto p = analysis::purohit(10 * kR, Rt(10) * kR, Rx(10) * kR, Ry(10) * kR, EI);
  ASSERT_TRUE(p.ok);
  EXPECT_NEAR(d(row.at("U_b_hat_purohit_mean")), p.U_b * r * r / (kR * EI), 1e-9);
  EXPECT_NEAR(d(row.at("K_purohit_mean")), p.K, 1e-9);
  // Point 1 at l = 50 rows later: two complete seeds beyond l = 8, radii NaN.
  const auto& q = c.rows[201 + 100];
  EXPECT_EQ(q.at("point"), "1");
  EXPECT_EQ(q.at("n"), "2");
  EXPECT_EQ(q.at("R_t_mean"), "nan");
  EXPECT_EQ(q.at("K_purohit_mean"), "nan");
  EXPECT_EQ(c.rows[201 + 50].at("n"), "2");  // the failed run is not averaged
}

TEST_F(Analyze, DistributionsAtTheLastCommonSnapshot) {
  const AnalyzeResult r = analyze();
  EXPECT_EQ(r.distribution_l, 20);
  const Csv c = read_csv(out("distributions.csv"));
  EXPECT_EQ(c.header, "point," + kParams +
                          ",quantity,l,n_runs,n,mu,mu_stderr,sigma,sigma_stderr,ok,bin,ln_lo,"
                          "ln_hi,count,density,fit_density,mu_ls,sigma_ls,ls_ok");
  ASSERT_EQ(c.rows.size(), 2u * 2u * 30u);  // points x quantities x bins
  // The least-squares fit to the histogram is analysis::fit_normal_to_histogram of the same bins
  // (tested there); here: it ran, and it is near the MLE for these near-normal samples.
  EXPECT_EQ(c.rows[0].at("ls_ok"), "true");
  EXPECT_NEAR(d(c.rows[0].at("mu_ls")), d(c.rows[0].at("mu")), d(c.rows[0].at("sigma")));
  std::map<std::string, double> total;  // sum of density * width per (point, quantity)
  for (const auto& row : c.rows) {
    EXPECT_EQ(row.at("l"), "20");
    EXPECT_EQ(row.at("ok"), "true");
    EXPECT_EQ(row.at("n_runs"), row.at("point") == "0" ? "3" : "2");
    total[row.at("point") + row.at("quantity")] +=
        d(row.at("density")) * (d(row.at("ln_hi")) - d(row.at("ln_lo")));
  }
  EXPECT_EQ(total.size(), 4u);
  for (const auto& [key, t] : total) EXPECT_NEAR(t, 1, 1e-9) << key;
  EXPECT_EQ(c.rows[0].at("quantity"), "kappa2");
  EXPECT_EQ(c.rows[30].at("quantity"), "Lambda_over_r");

  AnalyzeOptions o;
  o.at_l = 10;
  o.bins = 5;
  EXPECT_EQ(analyze(o).distribution_l, 10);
  EXPECT_EQ(read_csv(out("distributions.csv")).rows.size(), 2u * 2u * 5u);

  // loop_sensitivity.csv: 3 smoothings x 3 prominences per point, at the same l; the row at the
  // detector's default (2 r, 0.25) is the distributions' loop fit.
  const Csv ls = read_csv(out("loop_sensitivity.csv"));
  EXPECT_EQ(ls.header, "point," + kParams +
                           ",l,n_runs,smoothing_r,min_prominence,loops,mu,mu_stderr,sigma,"
                           "sigma_stderr,ok");
  ASSERT_EQ(ls.rows.size(), 2u * 9u);
  const Csv dist = read_csv(out("distributions.csv"));
  for (const auto& row : ls.rows) {
    EXPECT_EQ(row.at("l"), "10");
    if (row.at("smoothing_r") != "2" || row.at("min_prominence") != "0.25") continue;
    for (const auto& drow : dist.rows)
      if (drow.at("point") == row.at("point") && drow.at("quantity") == "Lambda_over_r") {
        EXPECT_EQ(drow.at("mu"), row.at("mu"));
        EXPECT_EQ(drow.at("n"), row.at("loops"));
      }
  }
}

TEST_F(Analyze, MorphologyAtTheDistributionsSnapshot) {
  AnalyzeOptions o;
  o.at_l = 10;
  analyze(o);
  const Csv c = read_csv(out("morphology.csv"));
  EXPECT_EQ(c.header, "file,point," + kParams +
                          ",seed,l,D,D_chord,D_kappa,chord_R,reversals,order_length_R,"
                          "min_block_R");
  ASSERT_EQ(c.rows.size(), 5u);  // the complete runs: 3 of point 0, 2 of point 1
  // The snapshot: two turns of a wire whose radius oscillates six times per turn (radius
  // 5 mm (1 + 0.3 cos 6 theta), R = 10 mm). Its curvature changes sign in each lobe's valley over
  // stretches far shorter than R: one sense block, the wire without its chord, whatever the seed.
  double length = 0, edge = 0;  // the wire's length and its longest edge [m]
  {
    const Snapshot s = snapshot(10, 1);
    for (std::size_t i = 0; i + 1 < s.wire.size(); ++i) {
      double d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += std::pow(s.wire[i + 1][k] - s.wire[i][k], 2);
      length += std::sqrt(d2);
      edge = std::max(edge, std::sqrt(d2));
    }
  }
  for (const auto& row : c.rows) {
    EXPECT_NEAR(d(row.at("l")), 10, 1e-4);
    EXPECT_EQ(row.at("reversals"), "0") << row.at("file");
    EXPECT_EQ(row.at("min_block_R"), "1");
    // The paper's D counts those short reversed stretches; the blocks do not.
    EXPECT_GT(d(row.at("D_chord")), 0.0) << row.at("file");
    // chord + body = the wire, but for the two end nodes' half edges and the edge at the cut.
    EXPECT_NEAR(d(row.at("order_length_R")) + d(row.at("chord_R")), length / kR, 2 * edge / kR);
  }
  EXPECT_EQ(c.rows[0].at("point"), "0");
  EXPECT_EQ(c.rows[4].at("point"), "1");
}

TEST_F(Analyze, FlagsOverrideTheAnalysisBlock) {
  AnalyzeOptions o;
  o.D_window = "12,50";  // leaves out the peak at l = 10
  o.fit_windows = {"tau=4,8"};
  o.resamples = 0;
  const AnalyzeResult r = analyze(o);
  EXPECT_EQ(r.settings.D_window.l_min, 12);
  EXPECT_EQ(r.settings.fit_windows.at("alpha").l_min, 2);  // from the block
  const Csv c = read_csv(out("curves.csv"));
  EXPECT_NEAR(d(c.rows[0].at("D_mean")), 0.1, 1e-15);
  EXPECT_EQ(c.rows[0].at("D_l_min"), "12");
  const Csv e = read_csv(out("exponents.csv"));
  EXPECT_EQ(e.rows[5].at("name"), "tau");
  EXPECT_EQ(e.rows[5].at("window_l_min"), "4");
  EXPECT_EQ(e.rows[5].at("n_points"), std::to_string(3 * rows_in(4, 8)));
  EXPECT_EQ(e.rows[5].at("method"), "ols");
  EXPECT_EQ(e.rows[5].at("stderr"), e.rows[5].at("stderr_ols"));
}

TEST_F(Analyze, FullRunWritesEveryFileWithOneHeaderRowDeterministically) {
  AnalyzeOptions o;
  o.gnuplot = "gnuplot-that-does-not-exist";
  const AnalyzeResult r = analyze(o);
  const std::vector<std::string> names = {
      "runs.csv",          "curves.csv",           "D_vs_mu_s.csv",  "exponents.csv", "series.csv",
      "distributions.csv", "loop_sensitivity.csv", "morphology.csv", "critical.csv"};
  ASSERT_EQ(r.csv.size(), names.size());
  // Two values of mu_s: a row that says so, no number that looks like a result.
  const Csv crit = read_csv(out("critical.csv"));
  ASSERT_EQ(crit.rows.size(), 1u);
  EXPECT_EQ(crit.rows[0].at("axis"), "mu_s");
  EXPECT_EQ(crit.rows[0].at("status"), "too few points");
  EXPECT_EQ(crit.rows[0].at("x_c"), "nan");
  EXPECT_EQ(crit.rows[0].at("points"), "2");
  EXPECT_EQ(crit.rows[0].at("values"), "5");
  EXPECT_EQ(crit.rows[0].at("n_failed"), "1");
  EXPECT_FALSE(fs::exists(out("phase_diagram.csv")));
  std::map<std::string, std::string> first;
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(r.csv[i], out(names[i]));
    const std::string text = read_text(out(names[i]));
    first[names[i]] = text;
    const std::string header = text.substr(0, text.find('\n'));
    EXPECT_EQ(text.find(header, 1), std::string::npos) << names[i] << ": header repeated";
    EXPECT_GT(std::count(text.begin(), text.end(), '\n'), 1) << names[i];
  }
  // Scripts are written without gnuplot; the notice says why there are no PNGs.
  EXPECT_TRUE(r.plots.empty());
  EXPECT_NE(r.plot_notice.find("not found"), std::string::npos);
  // D_vs_mu_s; scaling, distributions and packing of 2 points
  EXPECT_EQ(r.scripts.size(), 7u);
  const auto packing = std::find_if(r.scripts.begin(), r.scripts.end(), [](const std::string& s) {
    return s.find("packing_p0.gp") != std::string::npos;
  });
  ASSERT_NE(packing, r.scripts.end());
  // The picture draws the wire of the snapshot in units of R (rigid: the circle of radius 1).
  EXPECT_NE(read_text(*packing).find("set size ratio -1"), std::string::npos);
  for (const auto& s : r.scripts) EXPECT_TRUE(fs::exists(s)) << s;
  // No temporary files left.
  for (const auto& e : fs::recursive_directory_iterator(dir_ / "analysis"))
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();

  // The same directory gives the same bytes.
  analyze(o);
  for (const auto& name : names) EXPECT_EQ(read_text(out(name)), first[name]) << name;

  // With gnuplot (where installed) every script becomes a PNG.
  o.gnuplot = "gnuplot";
  AnalyzeOptions with_plots = o;
  with_plots.dir = dir_.path().string();
  const AnalyzeResult p = analyze_sweep(with_plots);
  if (p.plot_notice.find("not found") != std::string::npos) GTEST_SKIP() << p.plot_notice;
  EXPECT_EQ(p.plot_notice, "");
  ASSERT_EQ(p.plots.size(), 7u);
  for (const auto& png : p.plots) {
    ASSERT_TRUE(fs::exists(png)) << png;
    EXPECT_EQ(read_text(png).substr(1, 3), "PNG");
  }
}

TEST_F(Analyze, BadInputIsAnInputErrorAndWritesNothing) {
  AnalyzeOptions o;
  o.dir = dir_ / "no-such-dir";
  EXPECT_THROW(analyze_sweep(o), InputError);
  o.dir = dir_.write("a-file", "x");
  EXPECT_THROW(analyze_sweep(o), InputError);
  fs::create_directory(dir_ / "empty");
  o.dir = dir_ / "empty";
  EXPECT_THROW(analyze_sweep(o), InputError);

  const auto message = [&](AnalyzeOptions opt) {
    try {
      analyze(opt);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  AnalyzeOptions bad;
  bad.D_window = "5";
  EXPECT_NE(message(bad).find("--d-window"), std::string::npos);
  bad = {};
  bad.fit_windows = {"zeta=1,2"};
  EXPECT_NE(message(bad).find("unknown exponent"), std::string::npos);
  bad = {};
  bad.at_l = -1;
  EXPECT_NE(message(bad).find("--at-l"), std::string::npos);
  for (const std::string text : {"mu_s=0.6,0", "mu_d=0,1", "mu_s", "mu_s=0,x"}) {
    bad = {};
    bad.critical_ranges = {text};
    EXPECT_NE(message(bad).find("--critical-range: must be NAME=X_MIN,X_MAX"), std::string::npos)
        << text;
  }
  EXPECT_FALSE(fs::exists(dir_ / "analysis"));

  // A bad window in the sweep's analysis block names the manifest and the key.
  TempDir other;
  write_sweep(synthetic_sweep(R"({"D_window": [50, 5], "bins": 3})"), other.path().string());
  o = {};
  o.dir = other.path().string();
  try {
    analyze_sweep(o);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ASSERT_EQ(e.messages().size(), 2u);
    EXPECT_EQ(e.messages()[0], other / "manifest.json" +
                                   ": /sweep/analysis/bins: unknown key; valid keys: D_window, "
                                   "fit_window, fit_windows, distribution_l, histogram_bins, "
                                   "bootstrap_resamples, critical_ranges, fit_auto, "
                                   "order_parameter");
    EXPECT_EQ(e.messages()[1], other / "manifest.json" +
                                   ": /sweep/analysis/D_window: must be [l_min, l_max] with 0 <= "
                                   "l_min < l_max (got [50,5])");
  }
  EXPECT_FALSE(fs::exists(other / "analysis"));
}

TEST(AnalysisBlock, DefaultsAndEveryKey) {
  AnalysisSettings s = default_analysis_settings();
  EXPECT_EQ(s.D_window.l_min, 5);
  EXPECT_EQ(s.fit_windows.size(), 6u);
  apply_analysis_block(json::parse(R"({"D_window": [0, 30], "fit_window": [3, 40],
      "fit_windows": {"tau": [10, 20]}, "distribution_l": 15, "histogram_bins": 12,
      "bootstrap_resamples": 0})"),
                       "s.json", "/analysis", s);
  EXPECT_EQ(s.D_window.l_max, 30);
  EXPECT_EQ(s.fit_windows.at("alpha").l_min, 3);
  EXPECT_EQ(s.fit_windows.at("tau").l_min, 10);
  EXPECT_EQ(s.distribution_l, 15);
  EXPECT_EQ(s.histogram_bins, 12);
  EXPECT_EQ(s.bootstrap_resamples, 0);
  EXPECT_THROW(apply_analysis_block(json::parse(R"({"histogram_bins": 0})"), "s.json", "", s),
               InputError);
  EXPECT_THROW(
      apply_analysis_block(json::parse(R"({"fit_windows": {"tau": [5]}})"), "s.json", "", s),
      InputError);
  apply_analysis_block(json::parse(R"({"critical_ranges": {"mu_s": [0, 0.6], "eps": [10, 1e4]}})"),
                       "s.json", "/analysis", s);
  EXPECT_EQ(s.critical_ranges.at("/mu_s"), (std::pair<double, double>{0, 0.6}));
  EXPECT_EQ(s.critical_ranges.at("/eps").second, 1e4);
  // fit_auto: true (every exponent), a list, or false; order_parameter: D, D_chord, D_kappa.
  EXPECT_TRUE(s.fit_auto.empty());
  EXPECT_EQ(s.order_parameter, "D");
  apply_analysis_block(json::parse(R"({"fit_auto": true, "order_parameter": "D_chord"})"), "s.json",
                       "/analysis", s);
  EXPECT_EQ(s.fit_auto.size(), 6u);
  EXPECT_EQ(s.order_parameter, "D_chord");
  apply_analysis_block(json::parse(R"({"fit_auto": ["delta", "tau"]})"), "s.json", "/analysis", s);
  EXPECT_EQ(s.fit_auto, (std::set<std::string>{"delta", "tau"}));
  try {
    apply_analysis_block(json::parse(R"({"fit_auto": ["zeta"], "order_parameter": "S"})"), "s.json",
                         "/analysis", s);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ASSERT_EQ(e.messages().size(), 2u);
    EXPECT_EQ(e.messages()[0],
              "s.json: /analysis/fit_auto: must be true, false or a list of exponents (alpha, "
              "beta, gamma, delta, lambda, tau) (got [\"zeta\"])");
    EXPECT_EQ(e.messages()[1],
              "s.json: /analysis/order_parameter: must be one of \"D\", \"D_chord\", "
              "\"D_kappa\" (got \"S\")");
  }
  EXPECT_EQ(s.order_parameter, "D_chord");  // a rejected block changes nothing it rejects
  try {
    apply_analysis_block(
        json::parse(R"({"critical_ranges": {"mu_d": [0, 1], "rho": [20, 10], "xi": 3}})"), "s.json",
        "/analysis", s);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    ASSERT_EQ(e.messages().size(), 3u);
    EXPECT_EQ(e.messages()[0],
              "s.json: /analysis/critical_ranges/mu_d: not a transition parameter; valid: rho, "
              "xi, eps, mu_s");
    EXPECT_EQ(e.messages()[1],
              "s.json: /analysis/critical_ranges/rho: must be [x_min, x_max] with x_min < x_max "
              "(got [20,10])");
  }
}

}  // namespace
}  // namespace wirepack::report
