#include "ridefit/signal/psd_confidence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/psd_average.h"
#include "ridefit/signal/psd_smoothing.h"
#include "ridefit/signal/welch_psd.h"
#include "ridefit/synthetic/gaussian_noise.h"

namespace ridefit::signal {
namespace {

TEST(PsdConfidence, TwoDegreesOfFreedomMatchClosedForm) {
  // χ²₂ is exponential: its p-quantile is −2·ln(1 − p).
  const double p_hat = 3.0, confidence = 0.9;
  const ConfidenceBounds b = chi_squared_interval(p_hat, 2.0, confidence);
  EXPECT_NEAR(b.lower, 2.0 * p_hat / (-2.0 * std::log(0.05)), 1e-12);
  EXPECT_NEAR(b.upper, 2.0 * p_hat / (-2.0 * std::log(0.95)), 1e-10);
}

TEST(PsdConfidence, TabulatedQuantilesAndLargeDofLimit) {
  // χ²₁₀(0.025) = 3.2470, χ²₁₀(0.975) = 20.4832 (standard tables).
  const ConfidenceBounds b = chi_squared_interval(1.0, 10.0, 0.95);
  EXPECT_NEAR(b.lower, 10.0 / 20.4832, 1e-5);
  EXPECT_NEAR(b.upper, 10.0 / 3.2470, 1e-4);
  // Large ν: ν·P̂/P ≈ normal with variance 2ν, so the bounds approach P̂·(1 ∓ z·sqrt(2/ν)).
  const double nu = 1e6, z = 1.6448536269514722;
  const ConfidenceBounds wide = chi_squared_interval(1.0, nu, 0.9);
  EXPECT_NEAR(wide.lower, 1.0 - z * std::sqrt(2.0 / nu), 1e-5);
  EXPECT_NEAR(wide.upper, 1.0 + z * std::sqrt(2.0 / nu), 1e-5);
  // Fractional ν sits between its integer neighbours.
  const ConfidenceBounds frac = chi_squared_interval(1.0, 7.5, 0.9);
  EXPECT_LT(chi_squared_interval(1.0, 8.0, 0.9).upper, frac.upper);
  EXPECT_GT(chi_squared_interval(1.0, 7.0, 0.9).upper, frac.upper);
}

TEST(PsdConfidence, SpectrumIntervalUsesPerBinDof) {
  std::mt19937_64 rng(31);
  const auto s = welch_psd(synthetic::gaussian_noise(4096, 1.0, rng), 100.0,
                           {.segment_length_samples = 256, .overlap_fraction = 0.0});
  const PsdConfidenceInterval ci = psd_confidence_interval(s, 0.8);
  ASSERT_EQ(ci.lower.size(), s.psd.size());
  EXPECT_EQ(ci.confidence, 0.8);
  for (std::size_t k : {std::size_t{0}, std::size_t{5}, s.psd.size() - 1}) {
    const ConfidenceBounds b = chi_squared_interval(s.psd[k], s.degrees_of_freedom[k], 0.8);
    EXPECT_DOUBLE_EQ(ci.lower[k], b.lower) << k;
    EXPECT_DOUBLE_EQ(ci.upper[k], b.upper) << k;
  }
  // DC has half the degrees of freedom, so a wider interval relative to its estimate.
  EXPECT_GT(ci.upper[0] / s.psd[0], ci.upper[5] / s.psd[5]);
}

TEST(PsdConfidence, BadInputsThrow) {
  EXPECT_THROW(chi_squared_interval(1.0, 10.0, 1.0), InputError);
  EXPECT_THROW(chi_squared_interval(1.0, 10.0, 0.0), InputError);
  EXPECT_THROW(chi_squared_interval(1.0, 0.0, 0.9), InputError);
  EXPECT_THROW(chi_squared_interval(-1.0, 10.0, 0.9), InputError);
  EXPECT_THROW(chi_squared_interval(std::numeric_limits<double>::quiet_NaN(), 10.0, 0.9),
               InputError);
  PowerSpectralDensity hand_made;
  hand_made.frequency_Hz = {0.0, 1.0};
  hand_made.psd = {1.0, 1.0};
  EXPECT_THROW(psd_confidence_interval(hand_made), InputError);  // no degrees of freedom
}

// How often the interval misses the true white-noise level below and above.
struct Coverage {
  double below = 0.0;
  double above = 0.0;
  double trials = 0.0;
};

// Seeded realisations; every `stride`-th interior bin from bin 4 (clear of DC and the mean
// detrend), so that the bins counted within one realisation are nearly independent.
template <class Estimate>
Coverage white_noise_coverage(int realisations, double confidence, std::size_t stride,
                              Estimate&& estimate) {
  const double fs = 100.0, sigma = 0.7;
  const double level = 2.0 * sigma * sigma / fs;
  std::mt19937_64 rng(2024);
  Coverage c;
  for (int realisation = 0; realisation < realisations; ++realisation) {
    const PowerSpectralDensity s = estimate(fs, sigma, rng);
    const PsdConfidenceInterval ci = psd_confidence_interval(s, confidence);
    for (std::size_t k = 4; k + 4 < s.psd.size(); k += stride) {
      c.below += ci.upper[k] < level ? 1.0 : 0.0;
      c.above += ci.lower[k] > level ? 1.0 : 0.0;
      c.trials += 1.0;
    }
  }
  return c;
}

// Each tail should hold α/2 of the trials: allow 4 binomial standard deviations.
void expect_tails(const Coverage& c, double confidence) {
  const double tail = 0.5 * (1.0 - confidence);
  const double bound = 4.0 * std::sqrt(tail * (1.0 - tail) / c.trials);
  EXPECT_NEAR(c.below / c.trials, tail, bound) << c.trials << " trials";
  EXPECT_NEAR(c.above / c.trials, tail, bound) << c.trials << " trials";
  EXPECT_GT(c.trials, 10'000.0);
}

TEST(PsdConfidence, NinetyPercentCoverageWithoutOverlap) {
  const auto c =
      white_noise_coverage(400, 0.9, 4, [](double fs, double sigma, std::mt19937_64& rng) {
        return welch_psd(synthetic::gaussian_noise(8 * 256, sigma, rng), fs,
                         {.segment_length_samples = 256, .overlap_fraction = 0.0});
      });
  expect_tails(c, 0.9);
}

TEST(PsdConfidence, NinetyPercentCoverageWithHalfOverlap) {
  const auto c =
      white_noise_coverage(400, 0.9, 4, [](double fs, double sigma, std::mt19937_64& rng) {
        auto s = welch_psd(synthetic::gaussian_noise(8 * 256, sigma, rng), fs,
                           {.segment_length_samples = 256, .overlap_fraction = 0.5});
        EXPECT_EQ(s.segment_count, 15u);
        return s;
      });
  expect_tails(c, 0.9);
}

TEST(PsdConfidence, CoverageAfterAveragingAndSmoothing) {
  // Three repetitions of 4 segments at 50 % overlap, averaged, then smoothed over 5 bins:
  // bins 8 apart are nearly independent.
  const auto c =
      white_noise_coverage(800, 0.8, 8, [](double fs, double sigma, std::mt19937_64& rng) {
        std::vector<PowerSpectralDensity> runs;
        for (int r = 0; r < 3; ++r) {
          runs.push_back(welch_psd(synthetic::gaussian_noise(5 * 128, sigma, rng), fs,
                                   {.segment_length_samples = 256, .overlap_fraction = 0.5}));
        }
        return smooth_psd(average_psd(runs), 5);
      });
  expect_tails(c, 0.8);
}

}  // namespace
}  // namespace ridefit::signal
