// Band tests of a log-PSD ratio against ratios drawn from their exact null distribution (two
// independent χ²_ν/ν estimates per bin): the family-wise false-alarm rate, and the power to find
// a consistent 1.5 dB deviation no single bin shows.
#include "ridefit/fitting/diagnose/pooled_bands.h"

#include <gtest/gtest.h>

#include <boost/math/distributions/fisher_f.hpp>
#include <boost/math/special_functions/trigamma.hpp>
#include <cmath>
#include <random>
#include <vector>

namespace ridefit::fitting::diagnose {
namespace {

constexpr double kNu = 27.0;  // a 30 s record in 4 s Welch segments (50 % overlap)
// The null variance of one bin's log ratio of two independent estimates: 2·ψ'(ν/2).
const double kVariance = 2.0 * boost::math::trigamma(0.5 * kNu);

std::vector<double> null_log_ratios(std::size_t bins, std::mt19937_64& rng) {
  std::chi_squared_distribution<double> chi(kNu);
  std::vector<double> r(bins);
  for (double& v : r) v = std::log(chi(rng) / kNu) - std::log(chi(rng) / kNu);
  return r;
}

TEST(PooledBands, TwoSpectraThatAgreeRarelyGiveABand) {
  std::mt19937_64 rng(1);
  const std::vector<double> independent{1.0};
  int alarms = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const auto r = null_log_ratios(120, rng);
    if (!significant_pooled_bands(r, kVariance, independent, 0.01, 32).empty()) ++alarms;
  }
  // Bonferroni over all windows keeps the family-wise rate at most 1 %: 4 of 400 expected at
  // most (fewer: overlapping windows are correlated); 10 would be a rate of 2.5 %.
  EXPECT_LE(alarms, 10);
}

TEST(PooledBands, AConsistentOnePointFiveDecibelsIsFoundThatNoBinShows) {
  std::mt19937_64 rng(2);
  const std::vector<double> independent{1.0};
  const double shift = 1.5 * std::log(10.0) / 10.0;  // 1.5 dB in nepers
  const boost::math::fisher_f f_ratio(kNu, kNu);
  const double bin_limit = std::log(boost::math::quantile(f_ratio, 0.995));
  int found = 0, bins_flagged = 0, bins = 0;
  for (int trial = 0; trial < 50; ++trial) {
    auto r = null_log_ratios(120, rng);
    for (std::size_t k = 40; k < 80; ++k) r[k] += shift;  // 40 bins, 10 Hz at 0.25 Hz
    for (std::size_t k = 40; k < 80; ++k, ++bins) bins_flagged += std::abs(r[k]) > bin_limit;
    const auto bands = significant_pooled_bands(r, kVariance, independent, 0.01, 32);
    bool inside = false;
    for (const auto& b : bands) inside = inside || (b.first >= 30 && b.last <= 90 && b.z > 0);
    found += inside ? 1 : 0;
  }
  EXPECT_GE(found, 45);                // 90 % power at least
  EXPECT_LT(bins_flagged, bins / 10);  // while single bins see under 10 %
}

// The z of a window: its mean over √(2·ψ'(ν/2)·Σ_i Σ_j ρ(|i − j|))/w. Correlated neighbours
// (ρ = 0.5, 0.1) make a 16-bin window's Σρ 16 + 2·(15·0.5 + 14·0.1) = 33.8 instead of 16.
TEST(PooledBands, TheWindowsVarianceCountsTheBinsCorrelation) {
  const std::vector<double> r(16, 1.0);
  auto widest = [&](const std::vector<double>& rho) {
    for (const auto& b : significant_pooled_bands(r, kVariance, rho, 0.01, 16)) {
      if (b.last - b.first == 16) return b.z;
    }
    return 0.0;
  };
  EXPECT_NEAR(widest({1.0}), 1.0 / std::sqrt(kVariance * 16.0 / 256.0), 1e-9);
  EXPECT_NEAR(widest({1.0, 0.5, 0.1}), 1.0 / std::sqrt(kVariance * 33.8 / 256.0), 1e-9);
  EXPECT_TRUE(significant_pooled_bands(std::vector<double>{1.0}, kVariance, {}, 0.01, 8).empty());
}

// The null scatter: independent estimates' ratios scatter as 2·ψ'(ν/2) and the estimate says so;
// a ratio that scatters far less (a measurement and a simulation over the same road) with a
// smooth deviation on top is judged by its own scatter, the deviation left out; never below the
// floor.
TEST(PooledBands, TheNullScatterIsTheSmallerOfTheTheoryAndTheRatiosOwn) {
  std::mt19937_64 rng(3);
  const auto independent = null_log_ratios(400, rng);
  EXPECT_NEAR(log_ratio_variance(independent, kNu, std::vector<double>{1.0}, 0.0) / kVariance, 1.0,
              0.2);
  std::normal_distribution<double> normal(0.0, 0.02);
  std::vector<double> shared(400);
  for (std::size_t k = 0; k < shared.size(); ++k) {
    shared[k] = 0.3 * std::sin(static_cast<double>(k) / 40.0) + normal(rng);
  }
  EXPECT_NEAR(std::sqrt(log_ratio_variance(shared, kNu, std::vector<double>{1.0}, 0.0)), 0.02,
              0.004);
  EXPECT_DOUBLE_EQ(log_ratio_variance(shared, kNu, std::vector<double>{1.0}, 0.05 * 0.05),
                   0.05 * 0.05);
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
