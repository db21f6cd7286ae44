// Tests for analysis/stats: mean and SEM on hand-made numbers, power-law OLS (exact data, the
// fitting window, degenerate input, and the coverage of its standard error on noisy synthetic
// series), the seed bootstrap of the exponent, the lognormal MLE and histogram normalisation.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "analysis/stats.hpp"

namespace wirepack::analysis {
namespace {

// ----------------------------------------------------------------------------------------------
// mean_sem

TEST(MeanSem, HandMadeNumbers) {
  // 1, 2, 3, 4: mean 2.5, squared deviations 2.25 + 0.25 + 0.25 + 2.25 = 5, sd = sqrt(5/3).
  const std::vector<double> xs{1, 2, 3, 4};
  const MeanSem m = mean_sem(xs);
  EXPECT_EQ(m.n, 4u);
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_DOUBLE_EQ(m.sd, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(m.sem, std::sqrt(5.0 / 3.0) / 2);
}

TEST(MeanSem, NaNsAreSkipped) {
  const std::vector<double> xs{NaN, 1, 2, NaN, 3, 4, NaN};
  const MeanSem m = mean_sem(xs);
  EXPECT_EQ(m.n, 4u);
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_DOUBLE_EQ(m.sd, std::sqrt(5.0 / 3.0));
  EXPECT_DOUBLE_EQ(m.sem, std::sqrt(5.0 / 3.0) / 2);
}

// ----------------------------------------------------------------------------------------------
// distinct_outcomes

TEST(DistinctOutcomes, OneTrajectoryIsOneOutcome) {
  // Ten seeds of one reproducible path: Fig. 5b's mu_s = 1 before Engine VI, 0.0238290 +- 3e-7.
  std::vector<double> xs;
  for (int k = 0; k < 10; ++k) xs.push_back(0.0238290 + 3e-7 * ((k * 7) % 5 - 2));
  EXPECT_EQ(distinct_outcomes(xs), 1u);
}

TEST(DistinctOutcomes, IndependentSeedsAreTenOutcomes) {
  // Ten well separated values (0.05 apart, in shuffled order): ten outcomes.
  const std::vector<double> xs{0.35, 0.05, 0.45, 0.1, 0.3, 0.2, 0.5, 0.15, 0.4, 0.25};
  EXPECT_EQ(distinct_outcomes(xs), 10u);
}

TEST(DistinctOutcomes, GapIsBetweenSortedNeighboursAndNaNsAreSkipped) {
  // 0.6, 0.605, 0.62 | 0.9: the first three chain (0.005 and 0.015 > 0.01 splits), so
  // {0.6, 0.605}, {0.62}, {0.9} are three outcomes; NaNs are not outcomes.
  const std::vector<double> xs{0.62, NaN, 0.6, 0.9, 0.605, NaN};
  EXPECT_EQ(distinct_outcomes(xs), 3u);
  EXPECT_EQ(distinct_outcomes(xs, 0.5), 1u);
  EXPECT_EQ(distinct_outcomes(std::vector<double>{NaN}), 0u);
  EXPECT_EQ(distinct_outcomes(std::vector<double>{}), 0u);
}

TEST(MeanSem, SingleValueHasNoSpread) {
  const std::vector<double> xs{NaN, 7.25};
  const MeanSem m = mean_sem(xs);
  EXPECT_EQ(m.n, 1u);
  EXPECT_DOUBLE_EQ(m.mean, 7.25);
  EXPECT_TRUE(std::isnan(m.sd));
  EXPECT_TRUE(std::isnan(m.sem));
}

TEST(MeanSem, EmptyAndAllNaN) {
  for (const std::vector<double>& xs : {std::vector<double>{}, std::vector<double>{NaN, NaN}}) {
    const MeanSem m = mean_sem(xs);
    EXPECT_EQ(m.n, 0u);
    EXPECT_TRUE(std::isnan(m.mean));
    EXPECT_TRUE(std::isnan(m.sd));
    EXPECT_TRUE(std::isnan(m.sem));
  }
}

TEST(MeanSem, LargeOffsetDoesNotCancel) {
  // Two-pass variance: 1e9 + {1, 2, 3} has sd exactly 1.
  const std::vector<double> xs{1e9 + 1, 1e9 + 2, 1e9 + 3};
  EXPECT_DOUBLE_EQ(mean_sem(xs).sd, 1.0);
}

// ----------------------------------------------------------------------------------------------
// fit_power_law

// n points l_i evenly spaced on [lo, hi].
std::vector<double> linspace(double lo, double hi, int n) {
  std::vector<double> l;
  for (int i = 0; i < n; ++i) l.push_back(lo + (hi - lo) * i / (n - 1));
  return l;
}

// y = a l^p (1 + noise eta), eta ~ N(0, noise^2).
std::vector<double> power_series(const std::vector<double>& l, double a, double p, double noise,
                                 std::mt19937_64& rng) {
  std::normal_distribution<double> eta(0, noise);
  std::vector<double> y;
  for (double li : l) y.push_back(a * std::pow(li, p) * (1 + eta(rng)));
  return y;
}

TEST(PowerLaw, ExactDataIsRecovered) {
  const std::vector<double> l = linspace(1, 10, 12);
  std::vector<double> y;
  for (double li : l) y.push_back(3 * std::pow(li, 1.5));
  const PowerLawFit f = fit_power_law(l, y, 0, 1e9);
  ASSERT_TRUE(f.ok);
  EXPECT_EQ(f.n_points, 12u);
  // Exact data: round-off only (ln of O(30) values, 12 points).
  EXPECT_NEAR(f.exponent, 1.5, 1e-12);
  EXPECT_NEAR(f.log_prefactor, std::log(3.0), 1e-12);
  EXPECT_LT(f.stderr_, 1e-12);
  EXPECT_DOUBLE_EQ(f.l_min, 1);
  EXPECT_DOUBLE_EQ(f.l_max, 10);
}

TEST(PowerLaw, WindowAndInvalidPointsAreExcluded) {
  // Points outside [2, 8] follow another law; NaN, y <= 0 and l <= 0 must be skipped.
  std::vector<double> l{0.5, 1, 2, 3, 4, NaN, 5, 6, 7, 8, 9, 20, 0, -1};
  std::vector<double> y;
  for (double li : l) y.push_back(li >= 2 && li <= 8 ? 0.5 * li * li : 100.0);
  y[4] = -1;   // l = 4: y < 0
  y[6] = NaN;  // l = 5
  const PowerLawFit f = fit_power_law(l, y, 2, 8);
  ASSERT_TRUE(f.ok);
  EXPECT_EQ(f.n_points, 5u);  // l = 2, 3, 6, 7, 8
  EXPECT_NEAR(f.exponent, 2.0, 1e-12);
  EXPECT_NEAR(f.log_prefactor, std::log(0.5), 1e-12);
  EXPECT_DOUBLE_EQ(f.l_min, 2);
  EXPECT_DOUBLE_EQ(f.l_max, 8);
}

TEST(PowerLaw, DegenerateInputIsNotOk) {
  const std::vector<double> two_l{1, 2}, two_y{1, 4};
  const PowerLawFit a = fit_power_law(two_l, two_y, 0, 10);
  EXPECT_FALSE(a.ok);
  EXPECT_EQ(a.n_points, 2u);
  EXPECT_TRUE(std::isnan(a.exponent));
  const std::vector<double> same_l{3, 3, 3, 3}, ys{1, 2, 3, 4};
  const PowerLawFit b = fit_power_law(same_l, ys, 0, 10);
  EXPECT_FALSE(b.ok);
  EXPECT_EQ(b.n_points, 4u);
  EXPECT_TRUE(std::isnan(b.stderr_));
  const PowerLawFit c = fit_power_law({}, {}, 0, 10);
  EXPECT_FALSE(c.ok);
  EXPECT_EQ(c.n_points, 0u);
}

TEST(PowerLaw, StandardErrorCoversTheTrueExponent) {
  // 100 series y = 2 l^1.2 (1 + eta), eta ~ N(0, 0.05^2), 40 points on l in [5, 50]. ln(1 + eta)
  // is nearly normal with sd ~0.05, so the OLS slope is unbiased with a t(38) sampling law and
  // |p_hat - p| <= 2 se holds with probability 0.948. The count of hits among 100 independent
  // trials is Binomial(100, 0.948): mean 94.8, sd 2.2; requiring >= 90 fails with probability
  // ~2 % for a correct fit, and certainly for a stderr off by a factor 1.5 (coverage 0.79). The
  // seeds are fixed, so the test is deterministic.
  const std::vector<double> l = linspace(5, 50, 40);
  const double p = 1.2;
  int hits = 0;
  double mean_se = 0;
  for (int trial = 0; trial < 100; ++trial) {
    std::mt19937_64 rng(1000 + static_cast<std::uint64_t>(trial));
    const std::vector<double> y = power_series(l, 2.0, p, 0.05, rng);
    const PowerLawFit f = fit_power_law(l, y, 5, 50);
    ASSERT_TRUE(f.ok);
    ASSERT_EQ(f.n_points, 40u);
    if (std::abs(f.exponent - p) <= 2 * f.stderr_) ++hits;
    mean_se += f.stderr_ / 100;
  }
  RecordProperty("coverage_hits", hits);
  RecordProperty("mean_stderr", std::to_string(mean_se));
  EXPECT_GE(hits, 90);
  EXPECT_LE(hits, 100);
}

// ----------------------------------------------------------------------------------------------
// bootstrap_exponent_stderr

struct Seeds {
  std::vector<std::vector<double>> l, y;
};
// S seeds, each the 40-point series of the coverage test with its own noise.
Seeds noisy_seeds(int S, std::uint64_t base) {
  Seeds out;
  const std::vector<double> l = linspace(5, 50, 40);
  for (int s = 0; s < S; ++s) {
    std::mt19937_64 rng(base + static_cast<std::uint64_t>(s));
    out.l.push_back(l);
    out.y.push_back(power_series(l, 2.0, 1.2, 0.05, rng));
  }
  return out;
}

TEST(Bootstrap, MatchesPooledStderrAndSeedSpread) {
  const int S = 50;
  const Seeds d = noisy_seeds(S, 77);
  const double boot = bootstrap_exponent_stderr(d.l, d.y, 5, 50);
  ASSERT_TRUE(std::isfinite(boot));

  // Per-seed fits: with a common l grid the pooled OLS slope is the mean of the per-seed slopes,
  // so resampling seeds gives sd_seeds * sqrt((S - 1) / S) / sqrt(S) for infinitely many
  // resamples. With 1000 resamples the bootstrap sd has a Monte-Carlo relative error of
  // 1 / sqrt(2 * 1000) = 2.2 %: tolerance 8 % (3.5 of those).
  std::vector<double> per_seed;
  for (int s = 0; s < S; ++s) {
    const auto si = static_cast<std::size_t>(s);
    per_seed.push_back(fit_power_law(d.l[si], d.y[si], 5, 50).exponent);
  }
  const double spread = mean_sem(per_seed).sd * std::sqrt((S - 1.0) / S) / std::sqrt(S * 1.0);
  EXPECT_NEAR(boot / spread, 1.0, 0.08);

  // The pooled OLS stderr estimates the same quantity from the residuals: the two agree within
  // the sampling error of an sd from S = 50 seeds, 1 / sqrt(2 * 49) = 10 %: tolerance 30 %.
  std::vector<double> L, Y;
  for (int s = 0; s < S; ++s) {
    const auto si = static_cast<std::size_t>(s);
    L.insert(L.end(), d.l[si].begin(), d.l[si].end());
    Y.insert(Y.end(), d.y[si].begin(), d.y[si].end());
  }
  const PowerLawFit pooled = fit_power_law(L, Y, 5, 50);
  ASSERT_TRUE(pooled.ok);
  RecordProperty("bootstrap_stderr", std::to_string(boot));
  RecordProperty("pooled_ols_stderr", std::to_string(pooled.stderr_));
  RecordProperty("seed_spread_stderr", std::to_string(spread));
  EXPECT_NEAR(boot / pooled.stderr_, 1.0, 0.3);
}

TEST(Bootstrap, ReproducibleAndDegenerate) {
  const Seeds d = noisy_seeds(8, 5);
  const double a = bootstrap_exponent_stderr(d.l, d.y, 5, 50, 200, 42);
  const double b = bootstrap_exponent_stderr(d.l, d.y, 5, 50, 200, 42);
  EXPECT_EQ(a, b);  // same rng seed, same draws
  const double c = bootstrap_exponent_stderr(d.l, d.y, 5, 50, 200, 43);
  EXPECT_NE(a, c);
  // One seed cannot be resampled; a window with < 3 points never fits.
  const Seeds one = noisy_seeds(1, 5);
  EXPECT_TRUE(std::isnan(bootstrap_exponent_stderr(one.l, one.y, 5, 50)));
  EXPECT_TRUE(std::isnan(bootstrap_exponent_stderr(d.l, d.y, 5, 5.5)));
}

// ----------------------------------------------------------------------------------------------
// fit_lognormal, histogram

TEST(Lognormal, RecoversKnownParameters) {
  // The paper's kappa^2 fit: mu = -0.29, sigma = 0.83; 20000 samples. The MLE is within 3 of its
  // (Fisher) standard errors with probability 0.997 each.
  const double mu = -0.29, sigma = 0.83;
  std::mt19937_64 rng(2015);
  std::lognormal_distribution<double> dist(mu, sigma);
  std::vector<double> xs;
  for (int i = 0; i < 20000; ++i) xs.push_back(dist(rng));
  xs.push_back(0.0);  // skipped (x <= 0)
  xs.push_back(NaN);  // skipped
  const LognormalFit f = fit_lognormal(xs);
  ASSERT_TRUE(f.ok);
  EXPECT_EQ(f.n, 20000u);
  EXPECT_NEAR(f.mu_stderr, sigma / std::sqrt(20000.0), 0.05 * f.mu_stderr);
  EXPECT_NEAR(f.sigma_stderr, sigma / std::sqrt(40000.0), 0.05 * f.sigma_stderr);
  EXPECT_NEAR(f.mu, mu, 3 * f.mu_stderr);
  EXPECT_NEAR(f.sigma, sigma, 3 * f.sigma_stderr);
}

TEST(Lognormal, HandMadeAndDegenerate) {
  // ln x = {0, 2}: mu = 1, MLE sigma = 1 (divides by n).
  const std::vector<double> xs{1.0, std::exp(2.0)};
  const LognormalFit f = fit_lognormal(xs);
  ASSERT_TRUE(f.ok);
  EXPECT_NEAR(f.mu, 1.0, 1e-15);
  EXPECT_NEAR(f.sigma, 1.0, 1e-15);
  EXPECT_NEAR(f.mu_stderr, 1 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(f.sigma_stderr, 0.5, 1e-15);
  const std::vector<double> one{3.0, -1.0};
  EXPECT_FALSE(fit_lognormal(one).ok);
}

TEST(Histogram, NormalisedDensityAndBinEdges) {
  std::mt19937_64 rng(9);
  std::normal_distribution<double> z(0, 1);
  std::vector<double> xs;
  for (int i = 0; i < 5000; ++i) xs.push_back(z(rng));
  xs.push_back(NaN);
  const Histogram h = histogram(xs, -2, 3, 25);
  ASSERT_EQ(h.lo.size(), 25u);
  ASSERT_EQ(h.density.size(), 25u);
  double integral = 0;
  std::size_t counted = 0;
  for (std::size_t i = 0; i < 25; ++i) {
    integral += h.density[i] * (h.hi[i] - h.lo[i]);
    counted += h.count[i];
  }
  // Exact up to round-off of 25 terms.
  EXPECT_NEAR(integral, 1.0, 1e-12);
  std::size_t inside = 0;
  for (double x : xs) inside += x >= -2 && x < 3;
  EXPECT_EQ(counted, inside);
  EXPECT_DOUBLE_EQ(h.lo.front(), -2);
  EXPECT_DOUBLE_EQ(h.hi.back(), 3);
  for (std::size_t i = 1; i < 25; ++i) EXPECT_DOUBLE_EQ(h.lo[i], h.hi[i - 1]);
}

TEST(Histogram, HalfOpenBinsAndEmptyInput) {
  // [0, 1), [1, 2): 1 goes to the second bin, 2 (= hi) is outside.
  const std::vector<double> xs{0, 0.5, 1, 1.5, 2};
  const Histogram h = histogram(xs, 0, 2, 2);
  ASSERT_EQ(h.count.size(), 2u);
  EXPECT_EQ(h.count[0], 2u);
  EXPECT_EQ(h.count[1], 2u);
  EXPECT_DOUBLE_EQ(h.density[0], 0.5);
  const Histogram none = histogram({}, 0, 1, 4);
  ASSERT_EQ(none.density.size(), 4u);
  for (double d : none.density) EXPECT_EQ(d, 0.0);
  EXPECT_TRUE(histogram(xs, 1, 1, 3).lo.empty());
  EXPECT_TRUE(histogram(xs, 0, 1, 0).lo.empty());
}

// ----------------------------------------------------------------------------------------------
// fit_normal_to_histogram

// An exact histogram of a normal (bin-averaged densities) gives its parameters back, whatever
// the bin width and the window's position (1e-7: the stopping rule is on the steps, 1e-10 sigma).
TEST(HistogramNormalFit, ExactHistogramGivesTheParameters) {
  for (const auto& [mu, sigma, lo, hi, bins] :
       std::vector<std::tuple<double, double, double, double, int>>{
           {0.3, 1.7, -6, 6, 30}, {-2.0, 0.25, -3.5, 0.0, 7}, {5.0, 2.0, 1.0, 13.0, 60}}) {
    Histogram h;
    const double width = (hi - lo) / bins;
    for (int i = 0; i < bins; ++i) {
      const double a = lo + i * width, b = a + width;
      h.lo.push_back(a);
      h.hi.push_back(b);
      const double Pa = 0.5 * std::erfc(-(a - mu) / (sigma * std::sqrt(2.0)));
      const double Pb = 0.5 * std::erfc(-(b - mu) / (sigma * std::sqrt(2.0)));
      h.density.push_back((Pb - Pa) / width);
      h.count.push_back(0);
    }
    const HistogramNormalFit f = fit_normal_to_histogram(h);
    ASSERT_TRUE(f.ok) << mu;
    EXPECT_NEAR(f.mu, mu, 1e-7 * sigma);
    EXPECT_NEAR(f.sigma, sigma, 1e-7 * sigma);
    EXPECT_LT(f.rms, 1e-9 / sigma);
  }
}

// Samples of a normal: the least-squares fit and the maximum-likelihood fit (fit_lognormal on
// exp(x)) agree within a few of the ML standard errors (the histogram fit is less efficient, by
// about 2x in variance); a mixture of two normals is fitted differently by the two (the
// histogram fit follows the taller peak, the ML fit the overall spread).
TEST(HistogramNormalFit, SamplesAgreeWithTheMaximumLikelihoodFit) {
  std::mt19937_64 rng(17);
  std::normal_distribution<double> g(-1.0, 0.5);
  std::vector<double> xs(20000), ex;
  for (double& x : xs) x = g(rng);
  for (double x : xs) ex.push_back(std::exp(x));
  const HistogramNormalFit f = fit_normal_to_histogram(histogram(xs, -3.5, 1.5, 50));
  const LognormalFit ml = fit_lognormal(ex);
  ASSERT_TRUE(f.ok);
  EXPECT_NEAR(f.mu, -1.0, 5 * ml.mu_stderr);
  EXPECT_NEAR(f.sigma, 0.5, 5 * ml.sigma_stderr);
  EXPECT_NEAR(f.mu, ml.mu, 5 * ml.mu_stderr);

  // 75 % N(0, 1) + 25 % N(4, 1): ML sigma^2 = 1 + 0.1875 * 16 = 4 (sigma 2); the histogram fit
  // stays near the main peak with a width close to 1.
  std::normal_distribution<double> g0(0.0, 1.0), g1(4.0, 1.0);
  std::bernoulli_distribution pick(0.25);
  std::vector<double> mix(40000), emix;
  for (double& x : mix) x = pick(rng) ? g1(rng) : g0(rng);
  for (double x : mix) emix.push_back(std::exp(x));
  const HistogramNormalFit fm = fit_normal_to_histogram(histogram(mix, -5, 9, 70));
  const LognormalFit mlm = fit_lognormal(emix);
  ASSERT_TRUE(fm.ok);
  EXPECT_NEAR(mlm.sigma, 2.0, 0.05);
  EXPECT_LT(std::abs(fm.mu), 0.5);
  EXPECT_LT(fm.sigma, 1.5);
}

TEST(HistogramNormalFit, TooFewFilledBinsIsNotOk) {
  EXPECT_FALSE(fit_normal_to_histogram(Histogram{}).ok);
  const std::vector<double> two{0.1, 0.1, 0.9};
  EXPECT_FALSE(fit_normal_to_histogram(histogram(two, 0, 1, 10)).ok);  // 2 bins hold samples
  EXPECT_FALSE(fit_normal_to_histogram(histogram({}, 0, 1, 10)).ok);
}

}  // namespace
}  // namespace wirepack::analysis
