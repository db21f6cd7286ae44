// The reductions of `wirepack analyze` (report/reductions.hpp) on runs made up in memory, with no
// run file: grouping by the point key, per-run summaries, seed averages, exponent fits and the
// tables written from them.
#include "report/reductions.hpp"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "report/tables.hpp"

namespace wirepack::report {
namespace {

using json = nlohmann::json;

// A complete run of a rigid scene at mu_s and seed, rows l = 1, 2, ..., 10: D = d0 / l,
// R_t = 0.5 l^0.5 (the other radii NaN, so no Purohit prediction), U_b_hat = 2 l^1.5, K = l,
// N = l^2.
RunData made_up_run(double mu_s, int seed, double d0) {
  RunData r;
  r.file = "runs/mu" + std::to_string(mu_s) + "_s" + std::to_string(seed) + ".h5";
  r.status = "complete";
  json config = {{"rho", 20},
                 {"mu_s", mu_s},
                 {"shell", "rigid"},
                 {"seed", seed},
                 {"wire", {{"radius", 5e-4}, {"youngs_modulus", 1e9}}},
                 {"output", {{"every_l", 1.0 + seed}}}};  // output differs: still one point
  set_run_config(r, config);
  for (int i = 1; i <= 10; ++i) {
    const double l = i;
    r.series["l"].push_back(l);
    r.series["D"].push_back(d0 / l);
    r.series["U_b_hat"].push_back(2 * std::pow(l, 1.5));
    r.series["K"].push_back(l);
    r.series["N"].push_back(l * l);
    r.series["R_t"].push_back(0.5 * std::sqrt(l));
    r.series["R_x"].push_back(NaN);
    r.series["R_y"].push_back(NaN);
    r.series["S_kappa"].push_back(1 - d0 / l);
    // D_chord rises then falls: its maximum in a window is not at the window's start.
    r.series["D_chord"].push_back(l == 3 ? 0.9 : 0.1);
  }
  r.every_l = 1;
  return r;
}

}  // namespace

// Runs that differ only in seed and output settings are one grid point; mu_s makes two. Points
// are ordered by the swept parameter, runs by point and seed.
TEST(Reductions, GroupsRunsByPointKey) {
  Analysis a;
  a.settings = default_analysis_settings();
  a.runs = {made_up_run(0.5, 2, 0.4), made_up_run(0.5, 1, 0.6), made_up_run(0, 1, 0.2),
            made_up_run(0, 2, 0.2)};
  for (auto& r : a.runs) summarize_run(r, a.settings);
  group(a, std::nullopt);
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.axes, std::vector<std::string>{"/mu_s"});
  EXPECT_EQ(leaf(a.points[0], "/mu_s"), json(0.0));
  EXPECT_EQ(leaf(a.points[1], "/mu_s"), json(0.5));
  EXPECT_TRUE(leaf(a.points[0], "/seed").is_null());  // the key leaves out the seed
  ASSERT_EQ(a.points[1].complete.size(), 2u);
  EXPECT_EQ(a.points[1].complete[0]->seed, json(1));
  EXPECT_EQ(a.runs[0].point, 0);
  EXPECT_EQ(a.runs[3].point, 1);
  EXPECT_EQ(a.runs[3].seed, json(2));
}

// feeder_spin enters a run's configuration only where it acts ("free"): grouped with runs
// without it, those get its meaning, "held", so the swept axis has both values and no blank.
TEST(Reductions, AKeyResolvedOnlyWhereItActsGetsItsMeaningElsewhere) {
  Analysis a;
  a.settings = default_analysis_settings();
  RunData held = made_up_run(0.5, 1, 0.6), free = made_up_run(0.5, 1, 0.2);
  json config = free.config;
  config["feeder_spin"] = "free";
  set_run_config(free, config);
  a.runs = {held, free};
  for (auto& r : a.runs) summarize_run(r, a.settings);
  group(a, std::nullopt);
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.axes, std::vector<std::string>{"/feeder_spin"});
  EXPECT_EQ(leaf(a.points[0], "/feeder_spin"), json("free"));
  EXPECT_EQ(leaf(a.points[1], "/feeder_spin"), json("held"));
  // Without any run that has it, the key stays out of the points (and of every table).
  Analysis b;
  b.settings = a.settings;
  b.runs = {made_up_run(0, 1, 0.2), made_up_run(0.5, 1, 0.6)};
  for (auto& r : b.runs) summarize_run(r, b.settings);
  group(b, std::nullopt);
  EXPECT_TRUE(leaf(b.points[0], "/feeder_spin").is_null());
}

// friction_stiffness_ratio, resolved only where given: a point without it is Mindlin's, and the
// number sorts before that name on the axis.
TEST(Reductions, StickStiffnessAbsentMeansMindlin) {
  Analysis a;
  a.settings = default_analysis_settings();
  RunData mindlin = made_up_run(0.75, 1, 0.4), stiff = made_up_run(0.75, 1, 0.2);
  json config = stiff.config;
  config["friction_stiffness_ratio"] = 3.2;
  set_run_config(stiff, config);
  a.runs = {mindlin, stiff};
  for (auto& r : a.runs) summarize_run(r, a.settings);
  group(a, std::nullopt);
  ASSERT_EQ(a.points.size(), 2u);
  EXPECT_EQ(a.axes, std::vector<std::string>{"/friction_stiffness_ratio"});
  EXPECT_EQ(leaf(a.points[0], "/friction_stiffness_ratio"), json(3.2));
  EXPECT_EQ(leaf(a.points[1], "/friction_stiffness_ratio"), json("mindlin"));
}

// D is the maximum of D(l) over the D window and D_avg its mean; U_b_hat, K, N are the last rows;
// no Purohit prediction without the radii.
TEST(Reductions, SummarizesOneRun) {
  AnalysisSettings s = default_analysis_settings();
  s.D_window = {2, 4};
  RunData r = made_up_run(0, 1, 0.6);
  summarize_run(r, s);
  EXPECT_DOUBLE_EQ(r.D, 0.3);
  EXPECT_DOUBLE_EQ(r.D_avg, (0.3 + 0.2 + 0.15) / 3);
  EXPECT_DOUBLE_EQ(r.U_b_hat, 2 * std::pow(10.0, 1.5));
  EXPECT_DOUBLE_EQ(r.K, 10);
  EXPECT_DOUBLE_EQ(r.N, 100);
  // The variants are maximised over the same window: D_chord peaks at l = 3; D_kappa =
  // 1 - |S_kappa| = 0.6 / l is largest at l = 2.
  EXPECT_DOUBLE_EQ(r.D_chord, 0.9);
  EXPECT_DOUBLE_EQ(r.D_kappa, 0.3);
  s.D_window = {4, 10};
  RunData outside = made_up_run(0, 1, 0.6);
  summarize_run(outside, s);
  EXPECT_DOUBLE_EQ(outside.D_chord, 0.1);
  // A run file from before the series: no D_chord column, NaN.
  RunData old = made_up_run(0, 1, 0.6);
  old.series.erase("D_chord");
  summarize_run(old, s);
  EXPECT_TRUE(std::isnan(old.D_chord));
  ASSERT_EQ(r.series.at("U_b_hat_purohit").size(), 10u);
  EXPECT_TRUE(std::isnan(r.series.at("U_b_hat_purohit")[0]));
}

// Seed means per point and row, and the power laws fitted over the pooled rows.
TEST(Reductions, SeedMeansAndExponents) {
  Analysis a;
  a.settings = default_analysis_settings();
  a.settings.bootstrap_resamples = 0;
  a.runs = {made_up_run(0, 1, 0.2), made_up_run(0, 2, 0.6)};
  for (auto& r : a.runs) summarize_run(r, a.settings);
  group(a, std::nullopt);
  ASSERT_EQ(a.points.size(), 1u);
  EXPECT_TRUE(a.axes.empty());

  const MeanSeries m = mean_series(a.points[0]);
  ASSERT_EQ(m.l.size(), 10u);
  EXPECT_EQ(m.n[0], 2u);
  EXPECT_DOUBLE_EQ(m.q.at("D")[1].mean, 0.2);  // (0.1 + 0.3) / 2 at l = 2
  EXPECT_DOUBLE_EQ(m.q.at("D")[1].sem, 0.1);
  EXPECT_DOUBLE_EQ(m.q.at("S_kappa")[1].mean, 0.8);  // every kept series is averaged

  const Fits fits = fit_all(a);
  ASSERT_EQ(fits.size(), 1u);
  ASSERT_EQ(fits[0].size(), exponent_specs().size());
  const auto& alpha = fits[0][0];  // R_t ~ l^0.5 on l in [5, 10]
  ASSERT_TRUE(alpha.fit.ok);
  EXPECT_NEAR(alpha.fit.exponent, 0.5, 1e-12);
  EXPECT_NEAR(fits[0][3].fit.exponent, 1.5, 1e-12);  // delta: U_b_hat
  EXPECT_FALSE(fits[0][1].fit.ok);                   // beta: R_x is NaN throughout
  EXPECT_EQ(values(a.points[0], &RunData::D), (std::vector<double>{0.2 / 5, 0.6 / 5}));
}

// With the scaling-window rule the window starts after a crossover and the fit is over log-spaced
// points: U_b_hat ~ l^0.3 up to l = 8, ~ l^1.2 after (continuous), rows every 0.05 to l = 100;
// the fixed window [2, 100] mixes the two laws.
TEST(Reductions, AutoWindowStartsAfterTheCrossover) {
  GridPoint p;
  std::vector<RunData> runs(3);
  for (std::size_t s = 0; s < runs.size(); ++s) {
    RunData& r = runs[s];
    const double a = 1 + 0.05 * static_cast<double>(s);  // seeds differ in prefactor only
    for (int i = 20; i <= 2000; ++i) {
      const double l = 0.05 * i;
      r.series["l"].push_back(l);
      r.series["U_b_hat"].push_back(
          a * (l < 8 ? std::pow(l, 0.3) : std::pow(8, 0.3) * std::pow(l / 8, 1.2)));
    }
    p.complete.push_back(&r);
  }
  const LWindow w{2, 100};
  const ExponentFit fixed = fit_exponent(p, "U_b_hat", w, 0);
  ASSERT_TRUE(fixed.fit.ok);
  EXPECT_LT(fixed.fit.exponent, 1.1);  // the crossover drags the fixed window's fit down
  const ExponentFit automatic = fit_exponent(p, "U_b_hat", w, 200, true);
  ASSERT_TRUE(automatic.fit.ok);
  EXPECT_TRUE(automatic.auto_window);
  EXPECT_GE(automatic.fit.l_min, 8 * std::pow(10, -0.05));
  EXPECT_LE(automatic.fit.l_min, 8 * std::pow(10, 0.3));
  // The seeds' prefactors differ by a constant factor in ln y: the pooled geometric means lie on
  // the law, and every bootstrap draw gives nearly the same exponent.
  EXPECT_NEAR(automatic.fit.exponent, 1.2, 0.02);
  EXPECT_LT(automatic.stderr_bootstrap, 0.02);
}

// The critical points see the order parameter the settings name.
TEST(Reductions, CriticalPointsUseTheChosenOrderParameter) {
  Analysis a;
  a.settings = default_analysis_settings();
  a.settings.D_window = {2, 4};  // D_chord peaks at 0.9 at l = 3
  a.runs = {made_up_run(0, 1, 0.6)};
  for (auto& r : a.runs) summarize_run(r, a.settings);
  group(a, std::nullopt);
  EXPECT_EQ(critical_points(a).at(0).D, (std::vector<double>{0.3}));
  a.settings.order_parameter = "D_chord";
  EXPECT_EQ(critical_points(a).at(0).D, (std::vector<double>{0.9}));
  a.settings.order_parameter = "D_kappa";
  EXPECT_EQ(critical_points(a).at(0).D, values(a.points[0], &RunData::D_kappa));
}

// The tables come from the in-memory analysis alone: one runs.csv row per run, one curves.csv
// row per point.
TEST(Reductions, TablesFromMemory) {
  Analysis a;
  a.settings = default_analysis_settings();
  a.runs = {made_up_run(0, 1, 0.2), made_up_run(0.5, 1, 0.6)};
  for (auto& r : a.runs) summarize_run(r, a.settings);
  group(a, std::nullopt);
  const auto lines = [](const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  };
  const auto runs = lines(runs_csv(a));
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].rfind("file,point,rho,xi,eps,mu_s,", 0), 0u) << runs[0];
  EXPECT_NE(runs[2].find(",0.5,"), std::string::npos) << runs[2];
  EXPECT_EQ(lines(curves_csv(a)).size(), 3u);
  const auto crit = critical_points(a);
  ASSERT_EQ(crit.size(), 2u);
  EXPECT_EQ(crit[1].D, (std::vector<double>{0.6 / 5}));
}

}  // namespace wirepack::report
