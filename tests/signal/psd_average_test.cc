#include "ridefit/signal/psd_average.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "ridefit/signal/welch_psd.h"
#include "ridefit/synthetic/gaussian_noise.h"
#include "support/input_error_message.h"

namespace ridefit::signal {
namespace {

using testing::input_error_message;

// Mean and relative variance (variance / mean²) of the interior bins.
std::pair<double, double> interior_mean_and_relative_variance(const std::vector<double>& p) {
  double sum = 0.0, sum_sq = 0.0;
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    sum += p[k];
    sum_sq += p[k] * p[k];
  }
  const double n = static_cast<double>(p.size() - 2);
  const double mean = sum / n;
  return {mean, (sum_sq / n - mean * mean) / (mean * mean)};
}

TEST(PsdAverage, RepetitionsReduceVarianceAndAddDegreesOfFreedom) {
  const double fs = 500.0, sigma = 2.0;
  const std::size_t length = 4096, records = 8;
  const WelchOptions options{.segment_length_samples = length, .overlap_fraction = 0.0};
  std::mt19937_64 rng(99);
  std::vector<PowerSpectralDensity> runs;
  for (std::size_t r = 0; r < records; ++r) {
    runs.push_back(welch_psd(synthetic::gaussian_noise(4 * length, sigma, rng), fs, options));
  }
  const PowerSpectralDensity mean = average_psd(runs);
  EXPECT_EQ(mean.segment_count, 4 * records);
  EXPECT_DOUBLE_EQ(mean.degrees_of_freedom[10], 8.0 * static_cast<double>(records));
  EXPECT_DOUBLE_EQ(mean.degrees_of_freedom[0], 4.0 * static_cast<double>(records));
  // Equal records: the plain mean, bin by bin.
  double plain = 0.0;
  for (const auto& run : runs) plain += run.psd[123];
  EXPECT_NEAR(mean.psd[123], plain / static_cast<double>(records), 1e-15 * plain);

  // Relative variance 2/ν over ~2000 bins (correlated in pairs): the estimate of the variance
  // is good to about 6 % (single, χ²₈) and 5 % (averaged, χ²₆₄); allow 4 of those each.
  const auto [single_mean, single_variance] = interior_mean_and_relative_variance(runs[0].psd);
  const auto [mean_level, mean_variance] = interior_mean_and_relative_variance(mean.psd);
  EXPECT_NEAR(single_variance / (2.0 / 8.0), 1.0, 0.24);
  EXPECT_NEAR(mean_variance / (2.0 / 64.0), 1.0, 0.20);
  EXPECT_NEAR(single_variance / mean_variance, static_cast<double>(records), 0.35 * 8.0);
  const double level = 2.0 * sigma * sigma / fs;
  EXPECT_NEAR(mean_level / level, 1.0, 4.0 * std::sqrt(2.0 / 64.0 / 1000.0));
  EXPECT_NEAR(single_mean / level, 1.0, 4.0 * std::sqrt(2.0 / 8.0 / 1000.0));
}

TEST(PsdAverage, UnequalRecordsAreWeightedByDegreesOfFreedom) {
  std::mt19937_64 rng(3);
  const WelchOptions options{.segment_length_samples = 256};  // 50 % overlap
  const auto a = welch_psd(synthetic::gaussian_noise(256 * 3, 1.0, rng), 100.0, options);
  const auto b = welch_psd(synthetic::gaussian_noise(256 * 20, 1.0, rng), 100.0, options);
  const std::vector<PowerSpectralDensity> runs{a, b};
  const auto mean = average_psd(runs);
  EXPECT_EQ(mean.segment_count, a.segment_count + b.segment_count);
  for (std::size_t k : {0u, 17u, 128u}) {
    const double na = a.degrees_of_freedom[k], nb = b.degrees_of_freedom[k];
    EXPECT_DOUBLE_EQ(mean.degrees_of_freedom[k], na + nb);
    EXPECT_NEAR(mean.psd[k], (na * a.psd[k] + nb * b.psd[k]) / (na + nb), 1e-15) << k;
  }
  // A single record is returned unchanged.
  const auto one = average_psd(std::vector<PowerSpectralDensity>{a});
  EXPECT_EQ(one.degrees_of_freedom, a.degrees_of_freedom);
  for (std::size_t k = 0; k < a.psd.size(); ++k)
    EXPECT_NEAR(one.psd[k], a.psd[k], 1e-15 * a.psd[k]);
}

TEST(PsdAverage, MismatchedRecordsNameTheRecordAndTheQuantity) {
  std::mt19937_64 rng(4);
  const auto x = synthetic::gaussian_noise(2048, 1.0, rng);
  const auto base = welch_psd(x, 100.0, {.segment_length_samples = 256});
  const std::vector<std::string> names{"run_a.csv", "run_b.csv"};
  const auto message = [&](const PowerSpectralDensity& other) {
    const std::vector<PowerSpectralDensity> runs{base, other};
    return input_error_message([&] { average_psd(runs, names); });
  };

  const std::string rate = message(welch_psd(x, 200.0, {.segment_length_samples = 256}));
  EXPECT_NE(rate.find("run_b.csv has sample rate 200 Hz"), std::string::npos) << rate;
  EXPECT_NE(rate.find("run_a.csv has 100 Hz"), std::string::npos) << rate;
  const std::string length = message(welch_psd(x, 100.0, {.segment_length_samples = 512}));
  EXPECT_NE(length.find("run_b.csv has segment length (samples) 512"), std::string::npos) << length;
  const std::string hop =
      message(welch_psd(x, 100.0, {.segment_length_samples = 256, .overlap_fraction = 0.0}));
  EXPECT_NE(hop.find("hop (samples) 256"), std::string::npos) << hop;
  auto smoothed = base;
  smoothed.smoothing_bins = 3;
  EXPECT_NE(message(smoothed).find("smoothing width"), std::string::npos);
  auto bare = base;
  bare.degrees_of_freedom.clear();
  EXPECT_NE(message(bare).find("run_b.csv has 129 frequencies, 129 PSD values and 0 degrees"),
            std::string::npos)
      << message(bare);

  // Unnamed records are numbered.
  const std::vector<PowerSpectralDensity> unnamed{base, base, smoothed};
  EXPECT_NE(input_error_message([&] { average_psd(unnamed); }).find("spectrum 2"),
            std::string::npos);
  EXPECT_NE(input_error_message([&] {
              average_psd(std::vector<PowerSpectralDensity>{});
            }).find("no spectra"),
            std::string::npos);
  const std::vector<std::string> one_name{"only.csv"};
  EXPECT_NE(input_error_message([&] { average_psd(unnamed, one_name); }).find("1 names for 3"),
            std::string::npos);
}

}  // namespace
}  // namespace ridefit::signal
