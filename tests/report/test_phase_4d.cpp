// The four-dimensional phase diagram (report/phase_4d.hpp) on in-memory sweeps with a known
// critical surface mu_c(eps, xi): one mu_s x eps sweep at xi = 10, one mu_s x eps sweep at
// xi = 30 with a non-transition axis (shell_material), and one mu_s sweep at xi = 100, all at
// rho = 20: every slice becomes one row with all four control parameters, x_c lands within
// its interval of the truth, and the picture draws mu_c against eps with one curve per xi.
#include "report/phase_4d.hpp"

#include <cmath>
#include <map>
#include <random>
#include <sstream>

#include <gtest/gtest.h>

#include "report/csv_rows.hpp"
#include "report/plots.hpp"

namespace wirepack::report {
namespace {

using json = nlohmann::json;

// mu_c = 0.2 + 0.1 log10(eps / 10) + 0.001 (xi - 10): a surface over (eps, xi).
double mu_c(double eps, double xi) {
  return 0.2 + 0.1 * std::log10(eps / 10) + 0.001 * (xi - 10);
}

// mu_s in [0, 0.9] x the given eps values, 10 seeds, D = 0.1 + 0.6 sqrt(mu_s - mu_c) above mu_c,
// noise 0.02; every point carries rho, xi (and eps where not swept), as critical_points gives.
std::vector<CriticalPoint> sweep_points(const std::vector<double>& eps_values, double xi,
                                        unsigned seed, const json& material = nullptr) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0, 0.02);
  std::vector<CriticalPoint> points;
  for (double mu = 0; mu <= 0.9001; mu += 0.075) {
    for (double eps : eps_values) {
      CriticalPoint p;
      p.params = {{"/mu_s", json(std::round(mu * 1000) / 1000)},
                  {"/eps", json(eps)},
                  {"/xi", json(xi)},
                  {"/rho", json(20)}};
      if (!material.is_null()) p.params["/shell_material"] = material;
      for (int s = 0; s < 10; ++s) {
        const double d = mu > mu_c(eps, xi) ? 0.6 * std::sqrt(mu - mu_c(eps, xi)) : 0;
        p.D.push_back(0.1 + d + noise(rng));
      }
      points.push_back(p);
    }
  }
  return points;
}

std::vector<std::map<std::string, std::string>> parse(const std::string& text) {
  return testing::csv_rows(text);
}

std::vector<PhaseSource> sources() {
  std::vector<PhaseSource> s;
  s.push_back({"a", "D_chord", {"/mu_s", "/eps"}, sweep_points({10, 100, 1000}, 10, 1), 200, {}});
  auto b = sweep_points({10, 1000}, 30, 2, "linear");
  const auto b_neo = sweep_points({10, 1000}, 30, 3, "neo_hookean");
  b.insert(b.end(), b_neo.begin(), b_neo.end());
  s.push_back({"b", "D_chord", {"/mu_s", "/eps", "/shell_material"}, b, 200, {}});
  s.push_back({"c", "D", {"/mu_s"}, sweep_points({1000}, 100, 4), 200, {}});
  return s;
}

TEST(Phase4d, EveryCriticalPointWithAllFourParameters) {
  const auto rows = phase_rows(sources());
  // a: 3 eps slices of mu_s + 13 mu_s slices of eps; b: 4 of mu_s (eps x material) + 26 of
  // eps; c: 1 of mu_s.
  ASSERT_EQ(rows.size(), 3u + 13u + 4u + 26u + 1u);
  const auto csv = parse(phase_4d_csv(rows));
  ASSERT_EQ(csv.size(), rows.size());
  int checked = 0;
  for (const auto& r : csv) {
    EXPECT_EQ(r.at("rho"), "20");
    if (r.at("axis") != "mu_s") continue;
    EXPECT_EQ(r.at("mu_s"), "");  // the axis's own column is blank
    const double eps = std::stod(r.at("eps")), xi = std::stod(r.at("xi"));
    const double truth = mu_c(eps, xi);
    ASSERT_EQ(r.at("status"), "ok") << r.at("source") << " eps " << eps;
    EXPECT_LE(std::stod(r.at("x_c_lo")), truth + 0.02) << r.at("source") << " eps " << eps;
    EXPECT_GE(std::stod(r.at("x_c_hi")), truth - 0.02) << r.at("source") << " eps " << eps;
    EXPECT_NEAR(std::stod(r.at("x_c")), truth, 0.05);
    if (r.at("source") == "b") {
      EXPECT_TRUE(r.at("other") == "shell_material=linear" ||
                  r.at("other") == "shell_material=neo_hookean")
          << r.at("other");
    }
    if (r.at("source") == "c") {
      EXPECT_EQ(r.at("xi"), "100");  // not swept there: from its points
      EXPECT_EQ(r.at("order_parameter"), "D");
    }
    ++checked;
  }
  EXPECT_EQ(checked, 8);
}

TEST(Phase4d, PictureIsMuCAgainstEpsOneCurvePerXi) {
  const auto plots = phase_4d_plots(phase_rows(sources()));
  const auto it = std::find_if(plots.begin(), plots.end(),
                               [](const auto& p) { return p.first == "phase4d_mu_s"; });
  ASSERT_NE(it, plots.end());
  const std::string& g = it->second;
  // eps and xi take three values each; eps leaves 4 curves, xi would leave 7.
  EXPECT_NE(g.find("critical mu_s against eps"), std::string::npos);
  EXPECT_NE(g.find("set logscale x"), std::string::npos);  // eps spans two decades
  // One curve per (rho, xi[, material]) combination: xi = 10; 30 linear; 30 neo; 100.
  for (const char* label : {"rho = 20, xi = 10", "rho = 20, xi = 30, shell_material=linear",
                            "rho = 20, xi = 30, shell_material=neo_hookean", "rho = 20, xi = 100"})
    EXPECT_NE(g.find(label), std::string::npos) << label;
}

// The bars are the 95 % intervals themselves (asymmetric; they were half their width about x_c):
// every data row of the picture is (eps, x_c, x_c_lo, x_c_hi) of one fitted row, and xi's
// decade (10 to 100) is drawn on a log axis.
TEST(Phase4d, PictureBarsAreTheIntervals) {
  const auto rows = phase_rows(sources());
  const auto plots = phase_4d_plots(rows);
  ASSERT_FALSE(plots.empty());
  const std::string& g = plots.front().second;
  EXPECT_NE(g.find(":2:3:4 with yerrorlines"), std::string::npos);
  std::istringstream in(g);
  int data = 0;
  for (std::string line; std::getline(in, line);) {
    std::istringstream cells(line);
    double x, y, lo, hi;
    if (!(cells >> x >> y >> lo >> hi)) continue;
    ++data;
    bool found = false;
    for (const auto& r : rows) {
      const auto& f = r.slice.fit;
      const auto eps = r.at.find("/eps");
      if (r.axis != "/mu_s" || f.status != "ok" || eps == r.at.end()) continue;
      // format_number keeps 10 significant digits.
      const auto same = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::abs(b); };
      found = found || (same(x, eps->second.get<double>()) && same(y, f.x_c) &&
                        same(lo, f.x_c_lo) && same(hi, f.x_c_hi));
    }
    EXPECT_TRUE(found) << line;
    EXPECT_LE(lo, y);
    EXPECT_GE(hi, y);
  }
  EXPECT_EQ(data, 8);  // the 8 fitted mu_s slices: 3 of a, 4 of b, 1 of c
  // Two points a decade apart in xi alone: a log x axis.
  std::vector<PhaseSource> two = {sources()[0], sources()[2]};
  two[0].points = sweep_points({1000}, 10, 5);
  two[0].axes = {"/mu_s"};
  const auto xi_plots = phase_4d_plots(phase_rows(two));
  ASSERT_EQ(xi_plots.size(), 1u);
  EXPECT_NE(xi_plots[0].second.find("critical mu_s against xi"), std::string::npos);
  EXPECT_NE(xi_plots[0].second.find("set logscale x"), std::string::npos);
}

// Points of two sweeps at the same parameters (e.g. one protocol at l <= 30, another at l <= 50)
// are two curves named by their source, not one curve through both.
TEST(Phase4d, TwoSourcesAreTwoCurves) {
  std::vector<PhaseSource> two = {sources()[0], sources()[0]};
  two[1].name = "a_long";
  two[1].points = sweep_points({10, 100, 1000}, 10, 6);
  const auto plots = phase_4d_plots(phase_rows(two));
  ASSERT_FALSE(plots.empty());
  const std::string& g = plots.front().second;
  EXPECT_NE(g.find("rho = 20, xi = 10 (a)"), std::string::npos) << g;
  EXPECT_NE(g.find("rho = 20, xi = 10 (a_long)"), std::string::npos) << g;
  // They share every eps, so they are drawn side by side: shifted by opposite fractions of a
  // decade (eps is on a log axis), within 8 % of its two decades, while the data keep eps.
  std::vector<double> offsets;
  for (std::size_t at = g.find("using ($1*10**("); at != std::string::npos;
       at = g.find("using ($1*10**(", at + 1))
    offsets.push_back(std::stod(g.substr(at + 15)));
  ASSERT_EQ(offsets.size(), 2u) << g;
  EXPECT_DOUBLE_EQ(offsets[0], -offsets[1]);
  EXPECT_GT(std::abs(offsets[0]), 0.0);
  EXPECT_LE(std::abs(offsets[0] - offsets[1]), 0.08 * 2 + 1e-12);
  EXPECT_NE(g.find("\n10 "), std::string::npos) << g;  // the datablock's eps is 10, as run
}

// Curves at different x values are not shifted.
TEST(Phase4d, CurvesThatShareNoXAreDrawnWhereTheyAre) {
  std::vector<PhaseSource> two = {sources()[0], sources()[0]};
  two[1].name = "a_shifted";
  two[1].points = sweep_points({20, 200, 2000}, 10, 7);
  const auto plots = phase_4d_plots(phase_rows(two));
  ASSERT_FALSE(plots.empty());
  const std::string& g = plots.front().second;
  EXPECT_EQ(g.find("$1"), std::string::npos) << g;
  EXPECT_NE(g.find("using 1:2:3:4 with yerrorlines"), std::string::npos) << g;
}

// Of three curves, two share their x values and one shares none: the two are drawn side by side,
// the third where it is.
TEST(Phase4d, OnlyCurvesThatShareAnXAreShifted) {
  std::vector<PhaseSource> three = {sources()[0], sources()[0], sources()[0]};
  three[1].name = "a_long";
  three[1].points = sweep_points({10, 100, 1000}, 10, 6);
  three[2].name = "a_apart";
  three[2].points = sweep_points({20, 200, 2000}, 10, 7);
  const auto plots = phase_4d_plots(phase_rows(three));
  ASSERT_FALSE(plots.empty());
  const std::string& g = plots.front().second;
  std::size_t shifted = 0;
  for (std::size_t at = g.find("using ($1*10**("); at != std::string::npos;
       at = g.find("using ($1*10**(", at + 1))
    ++shifted;
  EXPECT_EQ(shifted, 2u) << g;
  // The plot clause of the curve apart is its own, unshifted.
  const std::size_t apart = g.find("title \"rho = 20, xi = 10 (a_apart)\"");
  ASSERT_NE(apart, std::string::npos) << g;
  const std::size_t clause = g.rfind("using ", apart);
  EXPECT_EQ(g.compare(clause, 12, "using 1:2:3:"), 0) << g.substr(clause, apart - clause);
}

// The axes are fitted to the points and their bars, with a margin on every side (gnuplot would
// widen a log axis to whole decades, and a bar ending on a tick would touch the frame), and the
// x ticks are the grid values, so that each point reads off its parameter.
TEST(Phase4d, PictureIsFittedToItsDataWithTicksAtTheGridValues) {
  std::vector<PhaseSource> one = {sources()[0]};
  one[0].points = sweep_points({30, 100, 1000}, 10, 1);
  const auto plots = phase_4d_plots(phase_rows(one));
  ASSERT_EQ(plots.size(), 1u);
  const std::string& g = plots.front().second;
  EXPECT_NE(g.find("set autoscale fix\n"), std::string::npos) << g;
  EXPECT_NE(g.find("set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"),
            std::string::npos)
      << g;
  EXPECT_NE(g.find("set xtics (30, 100, 1000)\n"), std::string::npos) << g;
  // A panel without margins keeps gnuplot's ranges.
  plots::Panel plain;
  plain.curves.push_back({"", plots::Curve::Style::Points, {{1, 2, 0, 0}}, 0});
  const std::string p = plots::script("", "", {plain}, 1, 1, "p.png", 100, 100);
  EXPECT_EQ(p.find("set autoscale fix"), std::string::npos) << p;
  EXPECT_EQ(p.find("set xtics ("), std::string::npos) << p;
}

TEST(Phase4d, NoPictureFromOnePoint) {
  std::vector<PhaseSource> one = {sources()[2]};
  const auto rows = phase_rows(one);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_TRUE(phase_4d_plots(rows).empty());
}

}  // namespace
}  // namespace wirepack::report
