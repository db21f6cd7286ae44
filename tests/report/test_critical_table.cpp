// critical.csv, phase_diagram.csv and the phase-diagram plot (report/critical_table.hpp) on
// in-memory grid points: a mu_s x eps sweep with a known critical line mu_c(eps).
#include "report/critical_table.hpp"

#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "report/csv_rows.hpp"

namespace wirepack::report {
namespace {

using json = nlohmann::json;

// mu_c(eps) = 0.2 + 0.1 log10(eps / 10): 0.2 at eps = 10, 0.4 at eps = 1000.
double mu_c(double eps) {
  return 0.2 + 0.1 * std::log10(eps / 10);
}

// 13 mu_s x 3 eps, 10 seeds, D = 0.1 + 0.6 sqrt(mu_s - mu_c) above mu_c, noise 0.02; at eps =
// 1000 one run failed (its D is not in the list) and at mu_s = 0 one seed has no D (NaN).
std::vector<CriticalPoint> grid() {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0, 0.02);
  std::vector<CriticalPoint> points;
  for (double mu = 0; mu <= 0.9001; mu += 0.075) {
    for (double eps : {10.0, 100.0, 1000.0}) {
      CriticalPoint p;
      p.params = {{"/mu_s", json(std::round(mu * 1000) / 1000)}, {"/eps", json(eps)}};
      for (int s = 0; s < 10; ++s) {
        const double d = mu > mu_c(eps) ? 0.6 * std::sqrt(mu - mu_c(eps)) : 0;
        p.D.push_back(0.1 + d + noise(rng));
      }
      if (eps == 1000 && mu > 0.5 && mu < 0.6) {
        p.D.pop_back();
        p.failed = 1;
      }
      if (mu == 0) p.D[0] = NAN;
      points.push_back(p);
    }
  }
  return points;
}

std::vector<std::map<std::string, std::string>> parse(const std::string& text) {
  return testing::csv_rows(text);
}

TEST(CriticalTable, SlicesEveryTransitionAxisAtEveryValueOfTheOther) {
  const auto points = grid();
  const std::vector<std::string> axes = {"/mu_s", "/eps"};
  const auto slices = critical_slices(axes, points, 200);
  // mu_s at 3 eps values; eps at 13 mu_s values.
  ASSERT_EQ(slices.size(), 3u + 13u);
  const auto rows = parse(critical_csv(axes, slices));
  ASSERT_EQ(rows.size(), slices.size());
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& r = rows[k];
    EXPECT_EQ(r.at("axis"), "mu_s");
    EXPECT_EQ(r.at("mu_s"), "");
    const double eps = std::stod(r.at("eps"));
    EXPECT_EQ(r.at("scale"), "linear");
    EXPECT_EQ(r.at("status"), "ok") << r.at("note");
    EXPECT_EQ(r.at("model"), "continuous");
    EXPECT_EQ(r.at("side"), "above");
    EXPECT_NEAR(std::stod(r.at("x_c")), mu_c(eps), 0.04) << eps;
    EXPECT_LE(std::stod(r.at("x_c_lo")), std::stod(r.at("x_c")));
    EXPECT_GE(std::stod(r.at("x_c_hi")), std::stod(r.at("x_c")));
    EXPECT_EQ(r.at("points"), "13");
    EXPECT_EQ(r.at("resamples"), "200");
  }
  EXPECT_EQ(rows[0].at("values"), "129");  // one NaN
  EXPECT_EQ(rows[2].at("n_failed"), "1");
  EXPECT_NE(rows[2].at("note").find("1 failed"), std::string::npos);
  // eps slices: fitted in log10; three eps values are too few.
  EXPECT_EQ(rows[3].at("axis"), "eps");
  EXPECT_EQ(rows[3].at("scale"), "log10");
  EXPECT_EQ(rows[3].at("status"), "too few points");
  EXPECT_EQ(rows[3].at("x_c"), "nan");
}

TEST(CriticalTable, PhaseDiagramWithTwoAxes) {
  const auto points = grid();
  const std::vector<std::string> axes = {"/mu_s", "/eps"};
  const auto slices = critical_slices(axes, points, 200);
  ASSERT_TRUE(has_phase_diagram(axes));
  const auto rows = parse(phase_diagram_csv(axes, slices));
  ASSERT_EQ(rows.size(), slices.size());
  EXPECT_EQ(rows[1].at("axis"), "mu_s");
  EXPECT_EQ(rows[1].at("across"), "eps");
  EXPECT_EQ(rows[1].at("across_value"), "100");
  EXPECT_NEAR(std::stod(rows[1].at("x_c")), mu_c(100), 0.04);
  const auto plots = phase_diagram_plots(axes, points, slices);
  ASSERT_EQ(plots.size(), 2u);  // mu_s against eps, eps against mu_s
  EXPECT_EQ(plots[0].first, "phase_mu_s");
  const std::string& gp = plots[0].second;
  EXPECT_NE(gp.find("set logscale x"), std::string::npos);  // eps spans 100x
  EXPECT_NE(gp.find("$C << EOD\n10 "), std::string::npos);  // the critical line from eps 10
  EXPECT_NE(gp.find("filledcurves"), std::string::npos);
  // One or three axes: no phase diagram.
  EXPECT_FALSE(has_phase_diagram({"/mu_s"}));
  EXPECT_FALSE(has_phase_diagram({"/mu_s", "/eps", "/xi"}));
  EXPECT_FALSE(has_phase_diagram({"/numerics/tolerance", "/l_max"}));
  EXPECT_EQ(phase_diagram_csv({"/mu_s"}, slices), "");
}

// A falling tail beyond the crumpled maximum (as D(mu_s) at l = 20) is left out by a range.
TEST(CriticalTable, RangeLeavesOutTheGridValuesOutsideIt) {
  auto points = grid();
  for (auto& p : points)
    if (p.params.at("/mu_s").get<double>() > 0.6)
      for (double& d : p.D) d = 0.2;  // D falls back after 0.6
  const std::vector<std::string> axes = {"/mu_s", "/eps"};
  const auto slices = critical_slices(axes, points, 200, "/mu_s", {{"/mu_s", {0, 0.6}}});
  ASSERT_EQ(slices.size(), 3u);
  for (const auto& s : slices) {
    ASSERT_TRUE(s.range);
    EXPECT_EQ(s.fit.x_max, 0.6);
    EXPECT_EQ(s.fit.points, 9u);  // 0, 0.075, ..., 0.6
    EXPECT_NE(s.fit.note.find("fitted on [0, 0.6] (critical_ranges)"), std::string::npos);
    ASSERT_EQ(s.fit.status, "ok") << s.fit.note;
    EXPECT_NEAR(s.fit.x_c, mu_c(s.at[0].second.get<double>()), 0.04);
  }
  EXPECT_EQ(slice_samples(slices[0], points).size(), 9u);
}

TEST(CriticalTable, OnlyOneAxisAndNoTransitionAxes) {
  const auto points = grid();
  EXPECT_EQ(critical_slices({"/mu_s", "/eps"}, points, 50, "/mu_s").size(), 3u);
  const auto none = critical_slices({"/l_max"}, points, 50);
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(critical_csv({"/l_max"}, none).find('\n') + 1, critical_csv({"/l_max"}, none).size());
}

}  // namespace
}  // namespace wirepack::report
