// Critical-point fits against synthetic D(x) of known x_c, b and noise (analysis/critical.hpp).
#include "analysis/critical.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

namespace wirepack::analysis {
namespace {

// The truth of the synthetic data: D = 0.1 below x_c = 0.437, 0.1 + 0.6 (x - 0.437)^0.5 above
// (x_c off every grid value used: a kink on a grid value is pinned unrealistically well).
const ContinuousFit kTruth = {0.437, 0.5, 0.1, 0.6, +1, 0};
constexpr double kNoise = 0.03;  // standard deviation of D per seed
constexpr int kSeeds = 10;

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> x;
  for (int i = 0; i < n; ++i) x.push_back(a + (b - a) * i / (n - 1));
  return x;
}

// kSeeds values of model(x) + Gaussian noise at each x.
std::vector<CriticalSample> simulate(const std::vector<double>& xs,
                                     const std::function<double(double)>& model, double noise,
                                     std::mt19937_64& rng, int seeds = kSeeds) {
  std::normal_distribution<double> eps(0, noise);
  std::vector<CriticalSample> out;
  for (double x : xs) {
    CriticalSample s{x, {}};
    for (int k = 0; k < seeds; ++k) s.D.push_back(model(x) + eps(rng));
    out.push_back(s);
  }
  return out;
}

double truth(double x) {
  return continuous_model(x, kTruth);
}

CriticalOptions fast_options() {
  CriticalOptions o;
  o.resamples = 200;  // 1000 in `wirepack analyze`; 200 keeps the 200-repetition test short
  return o;
}

TEST(Critical, RecoversTheTruthOnContinuousData) {
  std::mt19937_64 rng(1);
  const auto data = simulate(linspace(0, 1, 11), truth, kNoise, rng);
  const CriticalResult r = fit_critical(data, fast_options());
  ASSERT_EQ(r.status, "ok") << r.note;
  EXPECT_EQ(r.model, "continuous");
  EXPECT_EQ(r.side, 1);
  EXPECT_NEAR(r.x_c, kTruth.u_c, 0.05);
  EXPECT_NEAR(r.b, 0.5, 0.25);
  EXPECT_NEAR(r.D0, 0.1, 0.02);
  EXPECT_NEAR(r.D_plateau, truth(1.0), 0.03);
  EXPECT_LT(r.x_c_lo, r.x_c);
  EXPECT_GT(r.x_c_hi, r.x_c);
  EXPECT_LE(r.b_lo, r.b);
  EXPECT_GE(r.b_hi, r.b);
  EXPECT_EQ(r.points, 11u);
  EXPECT_EQ(r.values, 110u);
  EXPECT_EQ(r.resamples, 200u);
}

// The acceptance test: the 95 % interval covers the true x_c in 90-99 % of 200
// repetitions (fixed RNG seed).
TEST(Critical, IntervalCoversTheTrueCriticalPoint) {
  std::mt19937_64 rng(20261201);
  int covered = 0, fitted = 0;
  constexpr int kRepetitions = 200;
  for (int rep = 0; rep < kRepetitions; ++rep) {
    const auto data = simulate(linspace(0, 1, 11), truth, kNoise, rng);
    CriticalOptions o = fast_options();
    o.rng_seed = 1000 + rep;
    const CriticalResult r = fit_critical(data, o);
    if (r.status != "ok") continue;
    ++fitted;
    if (r.x_c_lo <= kTruth.u_c && kTruth.u_c <= r.x_c_hi) ++covered;
  }
  const double coverage = static_cast<double>(covered) / kRepetitions;
  std::printf("coverage of the 95 %% interval: %d / %d = %.3f (%d fitted)\n", covered, kRepetitions,
              coverage, fitted);
  EXPECT_EQ(fitted, kRepetitions);
  EXPECT_GE(coverage, 0.90);
  EXPECT_LE(coverage, 0.99);
}

TEST(Critical, PrefersTheSmoothModelOnASigmoid) {
  std::mt19937_64 rng(2);
  const auto sigmoid = [](double x) { return 0.1 + 0.5 / (1 + std::exp(-(x - 0.5) / 0.08)); };
  const auto data = simulate(linspace(0, 1, 11), sigmoid, kNoise, rng);
  const CriticalResult r = fit_critical(data, fast_options());
  ASSERT_EQ(r.status, "ok") << r.note;
  EXPECT_EQ(r.model, "smooth");
  EXPECT_LT(r.aic_smooth, r.aic_continuous - 10);
  EXPECT_NEAR(r.x_c, 0.5, 0.05);
  EXPECT_NEAR(r.width, 0.08, 0.03);
  EXPECT_NEAR(r.D0, 0.1, 0.03);
  EXPECT_NEAR(r.D_plateau, 0.6, 0.03);
  EXPECT_TRUE(std::isnan(r.b));
  EXPECT_LT(r.x_c_lo, 0.5);
  EXPECT_GT(r.x_c_hi, 0.5);
}

TEST(Critical, PrefersTheContinuousModelOnAKink) {
  std::mt19937_64 rng(3);
  const auto data = simulate(linspace(0, 1, 11), truth, kNoise, rng);
  const CriticalResult r = fit_critical(data, fast_options());
  ASSERT_EQ(r.status, "ok");
  EXPECT_EQ(r.model, "continuous");
  EXPECT_LT(r.aic_continuous, r.aic_smooth);
}

// eps-like: D departs from its plateau below x_c = 10^3, fitted in log10(x).
TEST(Critical, DecreasingTransitionInLogX) {
  std::mt19937_64 rng(4);
  const ContinuousFit down = {3.0, 0.7, 0.05, 0.4, -1, 0};
  std::vector<double> xs;
  for (double u : linspace(1, 5, 9)) xs.push_back(std::pow(10.0, u));
  const auto data = simulate(
      xs, [&](double x) { return continuous_model(std::log10(x), down); }, kNoise, rng);
  CriticalOptions o = fast_options();
  o.log_x = true;
  const CriticalResult r = fit_critical(data, o);
  ASSERT_EQ(r.status, "ok") << r.note;
  EXPECT_EQ(r.model, "continuous");
  EXPECT_EQ(r.side, -1);
  EXPECT_NEAR(std::log10(r.x_c), 3.0, 0.15);
  EXPECT_LE(r.x_c_lo, r.x_c);
  EXPECT_GE(r.x_c_hi, r.x_c);
  EXPECT_GT(r.x_c_lo, std::pow(10.0, 2.5));
  EXPECT_LT(r.x_c_hi, std::pow(10.0, 3.5));
  EXPECT_NEAR(r.D0, 0.05, 0.02);
}

TEST(Critical, FlatOrLinearDataHaveNoTransition) {
  std::mt19937_64 rng(5);
  for (const auto& model : std::vector<std::function<double(double)>>{
           [](double) { return 0.3; }, [](double x) { return 0.1 + 0.4 * x; }}) {
    const CriticalResult r =
        fit_critical(simulate(linspace(0, 1, 11), model, kNoise, rng), fast_options());
    EXPECT_EQ(r.status, "no transition in range") << r.note;
    EXPECT_EQ(r.model, "");
    EXPECT_TRUE(std::isnan(r.x_c));
    EXPECT_TRUE(std::isnan(r.x_c_lo));
    EXPECT_FALSE(r.note.empty());
  }
}

TEST(Critical, TransitionBelowTheRangeIsNotReportedAsOne) {
  std::mt19937_64 rng(6);
  const ContinuousFit below = {-0.3, 0.5, 0.1, 0.6, +1, 0};
  const auto data = simulate(
      linspace(0, 1, 11), [&](double x) { return continuous_model(x, below); }, 0.005, rng);
  const CriticalResult r = fit_critical(data, fast_options());
  EXPECT_EQ(r.status, "no transition in range") << r.note;
  EXPECT_TRUE(std::isnan(r.x_c));
}

TEST(Critical, TooFewPointsAndNoData) {
  std::mt19937_64 rng(7);
  const auto one = simulate({0.5}, truth, kNoise, rng);
  CriticalResult r = fit_critical(one, fast_options());
  EXPECT_EQ(r.status, "too few points");
  EXPECT_EQ(r.points, 1u);
  EXPECT_TRUE(std::isnan(r.x_c));
  r = fit_critical(simulate({0.2, 0.5, 0.8}, truth, kNoise, rng), fast_options());
  EXPECT_EQ(r.status, "too few points");
  r = fit_critical({}, fast_options());
  EXPECT_EQ(r.status, "no data");
  r = fit_critical({{0.1, {NAN, NAN}}, {0.2, {}}}, fast_options());
  EXPECT_EQ(r.status, "no data");
  EXPECT_EQ(r.points, 0u);
}

// NaN D (a failed run, a run without a D window) are skipped; a point without any is left out.
TEST(Critical, NaNValuesAreSkipped) {
  std::mt19937_64 rng(8);
  auto data = simulate(linspace(0, 1, 11), truth, kNoise, rng);
  data[3].D[0] = NAN;
  data[7].D[2] = INFINITY;
  for (double& d : data[10].D) d = NAN;
  data.push_back({NAN, {0.5, 0.5}});
  const CriticalResult r = fit_critical(data, fast_options());
  ASSERT_EQ(r.status, "ok") << r.note;
  EXPECT_EQ(r.points, 10u);
  EXPECT_EQ(r.values, 98u);
  EXPECT_NEAR(r.x_c, kTruth.u_c, 0.05);
  EXPECT_TRUE(std::isfinite(r.x_c_lo) && std::isfinite(r.x_c_hi));
}

TEST(Critical, OneSeedPerPointGivesNoInterval) {
  std::mt19937_64 rng(9);
  const auto data = simulate(linspace(0, 1, 21), truth, 0.01, rng, 1);
  const CriticalResult r = fit_critical(data, fast_options());
  EXPECT_EQ(r.status, "no interval") << r.note;
  EXPECT_NEAR(r.x_c, kTruth.u_c, 0.05);
  EXPECT_TRUE(std::isnan(r.x_c_lo));
}

TEST(Critical, ProposalBeforeAFitBisectsTheSteepestGap) {
  // D jumps between 0.4 and 0.6: the first value goes there, then into its halves' neighbours.
  std::vector<CriticalSample> data = {{0.0, {0.1, 0.1}},
                                      {0.2, {0.1, 0.12}},
                                      {0.4, {0.12, 0.1}},
                                      {0.6, {0.5, 0.52}},
                                      {0.8, {0.55, 0.56}}};
  CriticalResult none;
  none.status = "too few points";
  const auto x = propose_refinement(data, none, 1, fast_options());
  ASSERT_EQ(x.size(), 1u);
  EXPECT_DOUBLE_EQ(x[0], 0.5);
  const auto x3 = propose_refinement(data, none, 3, fast_options());
  EXPECT_EQ(x3, (std::vector<double>{0.45, 0.5, 0.55}));
  EXPECT_TRUE(propose_refinement({data[0]}, none, 3, fast_options()).empty());
}

TEST(Critical, ProposalWithAnIntervalFillsIt) {
  std::vector<CriticalSample> data;
  for (double x : linspace(0, 1, 6)) data.push_back({x, {truth(x)}});
  CriticalResult fit;
  fit.status = "ok";
  fit.x_c_lo = 0.33;
  fit.x_c_hi = 0.47;
  const auto x = propose_refinement(data, fit, 3, fast_options());
  ASSERT_EQ(x.size(), 3u);
  for (double v : x) {
    EXPECT_GT(v, 0.33);
    EXPECT_LT(v, 0.47);
    EXPECT_NE(v, 0.4);
  }
  EXPECT_TRUE(std::is_sorted(x.begin(), x.end()));
  // Rounded to 4 digits of the range: printed short.
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", x[0]);
  EXPECT_EQ(std::strtod(buf, nullptr), x[0]);
  EXPECT_NEAR(x[0] * 1e4, std::round(x[0] * 1e4), 1e-6);
}

// Median interval width of x_c over repetitions: a uniform grid against a coarse grid refined
// by propose_refinement, both with the same number of runs.
TEST(Critical, RefinementNarrowsTheIntervalAtEqualRuns) {
  constexpr int kReps = 40;
  std::vector<double> uniform_w, refined_w;
  int refined_covered = 0;
  std::mt19937_64 rng(11);
  const CriticalOptions o = fast_options();
  for (int rep = 0; rep < kReps; ++rep) {
    // Uniform: 16 values x 10 seeds = 160 runs.
    const auto u = fit_critical(simulate(linspace(0, 1, 16), truth, kNoise, rng), o);
    ASSERT_EQ(u.status, "ok");
    uniform_w.push_back(u.x_c_hi - u.x_c_lo);
    // Refined: 6 values (60 runs), then 5 rounds of 2 values (100 runs).
    auto data = simulate(linspace(0, 1, 6), truth, kNoise, rng);
    CriticalResult r = fit_critical(data, o);
    for (int round = 0; round < 5; ++round) {
      const auto xs = propose_refinement(data, r, 2, o);
      ASSERT_EQ(xs.size(), 2u) << r.status << " " << r.x_c << " [" << r.x_c_lo << ", " << r.x_c_hi
                               << "] " << data.size() << " values";
      for (const auto& s : simulate(xs, truth, kNoise, rng)) data.push_back(s);
      r = fit_critical(data, o);
    }
    ASSERT_EQ(data.size(), 16u);
    ASSERT_EQ(r.status, "ok") << r.note;
    refined_w.push_back(r.x_c_hi - r.x_c_lo);
    refined_covered += r.x_c_lo <= kTruth.u_c && kTruth.u_c <= r.x_c_hi;
  }
  std::sort(uniform_w.begin(), uniform_w.end());
  std::sort(refined_w.begin(), refined_w.end());
  const double factor = uniform_w[kReps / 2] / refined_w[kReps / 2];
  std::printf(
      "median CI width of x_c: uniform %.4f, refined %.4f, factor %.2f; refined intervals "
      "covering x_c: %d / %d\n",
      uniform_w[kReps / 2], refined_w[kReps / 2], factor, refined_covered, kReps);
  EXPECT_GE(factor, 2.0);
  // A narrow interval must still cover the truth (at 95 % nominal, >= 80 % of the repetitions).
  EXPECT_GE(refined_covered, kReps * 8 / 10);
}

// Seeds before values: at the values in and next to the interval while they have fewer than
// kMinSeedsNearCritical finite D, as many as the least-seeded lacks.
TEST(Critical, SeedsGoToTheValuesAroundTheIntervalUntilTheyHaveEnough) {
  std::vector<CriticalSample> data;
  for (double x : linspace(0, 1, 11)) data.push_back({x, {truth(x), truth(x) + 0.01}});
  data[5].D.push_back(NAN);  // a failed run is no seed
  CriticalResult fit;
  fit.status = "ok";
  fit.x_c_lo = 0.33;
  fit.x_c_hi = 0.52;
  SeedProposal p = propose_seeds(data, fit, fast_options());
  EXPECT_EQ(p.x, (std::vector<double>{0.3, 0.4, 0.5, 0.6}));
  EXPECT_EQ(p.seeds, kMinSeedsNearCritical - 2);
  // Enough seeds there (elsewhere too few): nothing, unless forced (then one at least).
  for (auto& s : data)
    while (s.x > 0.25 && s.x < 0.65 && s.D.size() < kMinSeedsNearCritical) s.D.push_back(0.1);
  data[5].D.push_back(0.1);  // its NaN did not count
  EXPECT_TRUE(propose_seeds(data, fit, fast_options()).x.empty());
  p = propose_seeds(data, fit, fast_options(), true);
  EXPECT_EQ(p.x.size(), 4u);
  EXPECT_EQ(p.seeds, 1u);
  // An interval between two values: those two; at the range's end: the two last.
  fit.x_c_lo = 0.42;
  fit.x_c_hi = 0.47;
  EXPECT_EQ(propose_seeds(data, fit, fast_options(), true).x, (std::vector<double>{0.4, 0.5}));
  fit.x_c_lo = 0.95;
  fit.x_c_hi = 1.2;
  EXPECT_EQ(propose_seeds(data, fit, fast_options(), true).x, (std::vector<double>{0.9, 1.0}));
  // No interval: nothing, or forced, around the steepest step of the mean.
  fit.status = "no transition in range";
  EXPECT_TRUE(propose_seeds(data, fit, fast_options()).x.empty());
  std::vector<CriticalSample> step;
  for (double x : linspace(0, 1, 6)) step.push_back({x, {x < 0.5 ? 0.1 : 0.8}});
  p = propose_seeds(step, fit, fast_options(), true);
  EXPECT_EQ(p.x, (std::vector<double>{0.2, 0.4, 0.6, 0.8}));
  EXPECT_EQ(p.seeds, kMinSeedsNearCritical - 1);
  // Fewer than two values: nothing.
  EXPECT_TRUE(propose_seeds({{0.5, {0.1}}}, fit, fast_options(), true).x.empty());
}

// kMinSeedsNearCritical's measurement (critical.hpp): on noisy continuous transitions over 11
// values, the fit claims the transition far more often with 5 seeds a value than with 2, and its
// interval covers the truth more often. 100 data sets each; the binomial SE of a rate near 0.5
// is 0.05, so the margins asked are 4-6 SE below the differences measured (0.52, 0.20).
TEST(Critical, FiveSeedsAValueFindAndCoverTheTransitionFarMoreOftenThanTwo) {
  constexpr int kSets = 100;
  const CriticalOptions o = fast_options();
  const auto rates = [&](int seeds) {
    std::mt19937_64 rng(9);
    int ok = 0, covered = 0;
    for (int k = 0; k < kSets; ++k) {
      const auto r = fit_critical(simulate(linspace(0, 1, 11), truth, 0.1, rng, seeds), o);
      if (r.status != "ok") continue;
      ++ok;
      covered += r.x_c_lo <= kTruth.u_c && kTruth.u_c <= r.x_c_hi;
    }
    return std::make_pair(double(ok) / kSets, ok > 0 ? double(covered) / ok : 0.0);
  };
  const auto [ok2, cover2] = rates(2);
  const auto [ok5, cover5] = rates(static_cast<int>(kMinSeedsNearCritical));
  std::printf("transition found: %.2f (2 seeds), %.2f (5); covered when found: %.2f, %.2f\n", ok2,
              ok5, cover2, cover5);
  EXPECT_GE(ok5 - ok2, 0.2);
  EXPECT_GE(cover5, 0.75);
  EXPECT_GE(cover5 - cover2, 0.05);
}

// A jump between two adjacent grid values (coil at x <= 0.4, crumpled at x >= 0.5, nothing in
// between: a coarse grid over a sharp transition) puts the logistic's midpoint anywhere between
// them; a bootstrap over two nearly equal seeds then gives an interval far narrower than what the
// data know (the coarse phase-diagram sweep: 0.211 [0.210, 0.215] between grid values 0.2 and
// 0.3). The interval must be the whole gap, and say why; a crossover a grid value sees (the
// sigmoid of PrefersTheSmoothModelOnASigmoid, width 0.08 on a 0.1 grid) keeps its bootstrap one.
TEST(Critical, ACrossoverSharperThanTheGridGetsTheWholeGap) {
  const auto jump = [](double x) { return x < 0.437 ? 0.1 : 0.7; };
  std::mt19937_64 rng(12);
  int ok = 0, covered = 0;
  for (int k = 0; k < 50; ++k) {
    const auto r = fit_critical(simulate(linspace(0, 0.6, 7), jump, 0.01, rng, 2), fast_options());
    if (r.status != "ok") continue;
    ++ok;
    covered += r.x_c_lo <= 0.437 && 0.437 <= r.x_c_hi;
    EXPECT_LE(r.x_c_lo, 0.4 + 1e-12) << r.note;
    EXPECT_GE(r.x_c_hi, 0.5 - 1e-12) << r.note;
    EXPECT_NE(r.note.find("sharper than the grid"), std::string::npos) << r.note;
  }
  std::printf("  jump between grid values: %d of 50 fits ok, %d cover x_c\n", ok, covered);
  EXPECT_GE(ok, 40);
  EXPECT_EQ(covered, ok);

  std::mt19937_64 rng2(2);
  const auto sigmoid = [](double x) { return 0.1 + 0.5 / (1 + std::exp(-(x - 0.5) / 0.08)); };
  const CriticalResult r =
      fit_critical(simulate(linspace(0, 1, 11), sigmoid, kNoise, rng2), fast_options());
  ASSERT_EQ(r.status, "ok") << r.note;
  EXPECT_EQ(r.note.find("sharper than the grid"), std::string::npos) << r.note;
  EXPECT_LT(r.x_c_hi - r.x_c_lo, 0.1);
}

}  // namespace
}  // namespace wirepack::analysis
