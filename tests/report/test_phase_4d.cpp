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

TEST(Phase4d, NoPictureFromOnePoint) {
  std::vector<PhaseSource> one = {sources()[2]};
  const auto rows = phase_rows(one);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_TRUE(phase_4d_plots(rows).empty());
}

}  // namespace
}  // namespace wirepack::report
