// The integrated autocorrelation time against the closed form of a first-order autoregression.
#include "ridefit/signal/correlation_time.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace ridefit::signal {
namespace {

std::vector<double> autoregression(double rho, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> r(n);
  double x = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    x = rho * x + noise(rng);
    r[k] = x;
  }
  return r;
}

TEST(CorrelationTime, OfAnAutoregressionIsItsClosedForm) {
  // τ = (1 + ρ)/(1 − ρ): 1 for white noise, 19 for ρ = 0.9.
  for (const double rho : {0.0, 0.5, 0.9}) {
    const double expected = (1.0 + rho) / (1.0 - rho);
    const double tau = correlation_time_samples(autoregression(rho, 200000, 7));
    EXPECT_NEAR(tau, expected, 0.08 * expected) << "rho " << rho;
  }
}

TEST(CorrelationTime, OfADegenerateSeriesIsOne) {
  EXPECT_EQ(correlation_time_samples({}), 1.0);
  EXPECT_EQ(correlation_time_samples(std::vector<double>(100, 3.0)), 1.0);
  // A slow sine: strongly correlated, but never more than the number of samples.
  std::vector<double> sine(1000);
  for (std::size_t k = 0; k < sine.size(); ++k) sine[k] = std::sin(1e-3 * static_cast<double>(k));
  EXPECT_GT(correlation_time_samples(sine), 100.0);
  EXPECT_LE(correlation_time_samples(sine), 1000.0);
}

// Two records of white noise about different levels: each alone is uncorrelated, the series
// joined is not (its level steps once). Pooled by parts, τ is the parts' own, weighted by length.
TEST(CorrelationTime, PooledOverPartsIgnoresTheirJoins) {
  auto first = autoregression(0.0, 20000, 11);
  const auto second = autoregression(0.9, 10000, 12);
  std::vector<double> joined = first;
  for (double v : second) joined.push_back(v + 50.0);
  const std::size_t lengths[] = {first.size(), second.size()};
  const double expected = (20000.0 * 1.0 + 10000.0 * 19.0) / 30000.0;  // 7
  EXPECT_NEAR(pooled_correlation_time_samples(joined, lengths), expected, 0.1 * expected);
  EXPECT_GT(correlation_time_samples(joined), 100.0);
  // A length beyond the series leaves that part out; no parts: 1.
  const std::size_t too_long[] = {first.size(), 2 * second.size()};
  EXPECT_NEAR(pooled_correlation_time_samples(joined, too_long), 1.0, 0.1);
  EXPECT_EQ(pooled_correlation_time_samples(joined, {}), 1.0);
}

}  // namespace
}  // namespace ridefit::signal
