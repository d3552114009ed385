#include "ridefit/signal/psd_smoothing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/welch_psd.h"
#include "ridefit/synthetic/gaussian_noise.h"

namespace ridefit::signal {
namespace {

TEST(PsdSmoothing, LinearRampIsUnchangedEverywhere) {
  std::vector<double> ramp(40);
  for (std::size_t k = 0; k < ramp.size(); ++k) ramp[k] = 3.0 - 0.25 * static_cast<double>(k);
  const auto smoothed = moving_average(ramp, 7);
  ASSERT_EQ(smoothed.size(), ramp.size());
  for (std::size_t k = 0; k < ramp.size(); ++k) EXPECT_NEAR(smoothed[k], ramp[k], 1e-14) << k;
}

TEST(PsdSmoothing, SpikeIsSpreadOverTheWindowWithItsAreaKept) {
  std::vector<double> p(30, 0.0);
  p[12] = 10.0;
  const auto smoothed = moving_average(p, 5);
  double area = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    EXPECT_DOUBLE_EQ(smoothed[k], k >= 10 && k <= 14 ? 2.0 : 0.0) << k;
    area += smoothed[k];
  }
  EXPECT_DOUBLE_EQ(area, 10.0);
}

TEST(PsdSmoothing, WindowShrinksSymmetricallyAtTheEdges) {
  // Bin k averages k−h_k … k+h_k, h_k = min(2, k, n−1−k).
  std::vector<double> p(10, 0.0);
  p[1] = 15.0;
  const auto smoothed = moving_average(p, 5);
  EXPECT_DOUBLE_EQ(smoothed[0], 0.0);  // the end bin is its own window
  EXPECT_DOUBLE_EQ(smoothed[1], 5.0);  // bins 0 … 2
  EXPECT_DOUBLE_EQ(smoothed[2], 3.0);  // bins 0 … 4
  EXPECT_DOUBLE_EQ(smoothed[3], 3.0);  // bins 1 … 5
  EXPECT_DOUBLE_EQ(smoothed[4], 0.0);  // bins 2 … 6
  std::vector<double> q(10, 1.0);
  q[9] = 7.0;
  EXPECT_DOUBLE_EQ(moving_average(q, 5)[9], 7.0);
  EXPECT_DOUBLE_EQ(moving_average(q, 5)[8], 3.0);  // bins 7 … 9
  EXPECT_EQ(moving_average(q, 1), q);
}

TEST(PsdSmoothing, BadWindowsAndValuesThrow) {
  const std::vector<double> p(9, 1.0);
  EXPECT_THROW(moving_average(p, 4), InputError);
  EXPECT_THROW(moving_average(p, 0), InputError);
  EXPECT_THROW(moving_average(p, 11), InputError);
  EXPECT_NO_THROW(moving_average(p, 9));
  auto bad = p;
  bad[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(moving_average(bad, 3), InputError);
}

TEST(PsdSmoothing, DegreesOfFreedomWithoutOverlapMatchClosedForm) {
  // Hann bins without overlap: corr(1) = 4/9, corr(2) = 1/36, so for M = 5 in the interior
  //   ν_s = M²·ν / (M + 2·(4·4/9 + 3·1/36)).
  std::mt19937_64 rng(8);
  const auto s = welch_psd(synthetic::gaussian_noise(6 * 128, 1.0, rng), 50.0,
                           {.segment_length_samples = 128, .overlap_fraction = 0.0});
  const auto smoothed = smooth_psd(s, 5);
  EXPECT_EQ(smoothed.smoothing_bins, 5u);
  const double nu = 12.0;
  EXPECT_NEAR(smoothed.degrees_of_freedom[20], 25.0 * nu / (5.0 + 2.0 * (16.0 / 9.0 + 3.0 / 36.0)),
              1e-10);
  // The end bins keep theirs (window of one); bin 1 averages 0 … 2 including the half-ν DC bin.
  EXPECT_DOUBLE_EQ(smoothed.degrees_of_freedom[0], 6.0);
  EXPECT_GT(smoothed.degrees_of_freedom[1], nu);
  EXPECT_LT(smoothed.degrees_of_freedom[1], smoothed.degrees_of_freedom[20]);
  EXPECT_THROW(smooth_psd(smoothed, 3), InputError);  // already smoothed
  EXPECT_THROW(smooth_psd(s, 6), InputError);
}

// Over seeded realisations, the smoothed estimate's relative variance is 2/ν_s — far from the
// 2/(M·ν) that independent bins would give.
TEST(PsdSmoothing, DegreesOfFreedomMatchObservedVariance) {
  for (double overlap : {0.0, 0.5}) {
    const double fs = 100.0, sigma = 1.0, level = 2.0 * sigma * sigma / fs;
    const std::size_t window = 9;
    std::mt19937_64 rng(77);
    double sum_sq = 0.0, count = 0.0, nu = 0.0;
    for (int realisation = 0; realisation < 300; ++realisation) {
      const auto s =
          smooth_psd(welch_psd(synthetic::gaussian_noise(2048, sigma, rng), fs,
                               {.segment_length_samples = 512, .overlap_fraction = overlap}),
                     window);
      nu = s.degrees_of_freedom[100];
      // Bins 16 apart share no window: independent samples.
      for (std::size_t k = 16; k + 16 < s.psd.size(); k += 16) {
        const double r = s.psd[k] / level - 1.0;
        sum_sq += r * r;
        count += 1.0;
      }
    }
    const double observed = sum_sq / count;  // about 4500 nearly normal samples: ±2 % (1 sd)
    EXPECT_NEAR(observed / (2.0 / nu), 1.0, 0.08) << overlap;
    const auto plain = welch_psd(std::vector<double>(2048, 0.0), fs,
                                 {.segment_length_samples = 512, .overlap_fraction = overlap});
    const double independent = 2.0 / (static_cast<double>(window) * plain.degrees_of_freedom[100]);
    EXPECT_GT(observed / independent, 1.5) << overlap;
  }
}

}  // namespace
}  // namespace ridefit::signal
