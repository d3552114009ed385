#include "ridefit/signal/welch_psd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/band_power.h"
#include "ridefit/signal/spectrum_peak.h"
#include "ridefit/synthetic/gaussian_noise.h"

namespace ridefit::signal {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> sine(double amplitude, double frequency_Hz, double phase_rad,
                         double sample_rate_Hz, std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / sample_rate_Hz;
    x[i] = amplitude * std::sin(2.0 * kPi * frequency_Hz * t + phase_rad);
  }
  return x;
}

// Rectangle-rule Σ P·Δf: exactly the quantity Parseval ties to the windowed mean square.
double total_power(const PowerSpectralDensity& s) {
  double sum = 0.0;
  for (double p : s.psd) sum += p;
  return sum * s.frequency_resolution_Hz;
}

TEST(WelchPsd, BinCentredSineGivesPeakAndPower) {
  const double fs = 1000.0, amplitude = 2.0, f0 = 50.0;
  const auto x = sine(amplitude, f0, 0.3, fs, 20'000);
  const auto s = welch_psd(x, fs, {.segment_length_samples = 1000});
  ASSERT_DOUBLE_EQ(s.frequency_resolution_Hz, 1.0);
  EXPECT_EQ(s.segment_count, 39u);  // hop 500: (20000 − 1000)/500 + 1
  ASSERT_EQ(s.psd.size(), 501u);

  const SpectrumPeak peak = find_peak(s, 10.0, 200.0);
  EXPECT_EQ(peak.bin, 50u);
  EXPECT_NEAR(peak.frequency_Hz, f0, 1e-6);  // symmetric lobe: the vertex is the bin
  EXPECT_NEAR(band_power(s, 40.0, 60.0), amplitude * amplitude / 2.0,
              0.01 * amplitude * amplitude / 2.0);
  EXPECT_NEAR(band_rms(s, 40.0, 60.0), amplitude / std::sqrt(2.0), 0.005 * amplitude);
}

TEST(WelchPsd, OffBinSineGivesInterpolatedPeakAndPower) {
  const double fs = 1000.0, amplitude = 0.7, f0 = 50.37;
  const auto x = sine(amplitude, f0, 1.1, fs, 30'000);
  const auto s = welch_psd(x, fs, {.segment_length_samples = 1000});
  const double bin = s.frequency_resolution_Hz;

  const SpectrumPeak peak = find_peak(s, 10.0, 200.0);
  EXPECT_LE(std::abs(s.frequency_Hz[peak.bin] - f0), 0.5 * bin);  // the raw maximum bin
  EXPECT_LE(std::abs(peak.frequency_Hz - f0), 0.02 * bin);        // log-parabola refinement
  EXPECT_GT(std::abs(s.frequency_Hz[peak.bin] - f0), 0.3 * bin);  // so the refinement mattered
  EXPECT_NEAR(band_power(s, 40.0, 60.0), amplitude * amplitude / 2.0,
              0.01 * amplitude * amplitude / 2.0);
}

// The log-parabola bias of the Hann main lobe across the whole bin.
TEST(WelchPsd, PeakInterpolationAcrossBinOffsets) {
  const double fs = 256.0;
  for (double offset : {0.1, 0.2, 0.3, 0.4, 0.5}) {
    const double f0 = 32.0 + offset;  // 1 Hz bins
    const auto s = welch_psd(sine(1.0, f0, 0.4, fs, 256 * 40), fs, {.segment_length_samples = 256});
    EXPECT_NEAR(find_peak(s, 20.0, 40.0).frequency_Hz, f0, 0.02) << offset;
  }
}

TEST(WelchPsd, WhiteNoiseLevelScatterAndParseval) {
  const double fs = 200.0, sigma = 0.3;
  const std::size_t n = 1u << 20, length = 1024;
  std::mt19937_64 rng(20240611);
  const std::vector<double> x = synthetic::gaussian_noise(n, sigma, rng);

  // The scatter over bins checks the equivalent degrees of freedom at several overlaps
  // (50 % and 75 % lean on the numerically summed window correlation).
  for (double overlap : {0.0, 0.5, 0.75}) {
    const auto s =
        welch_psd(x, fs, {.segment_length_samples = length, .overlap_fraction = overlap});
    const double nu = s.degrees_of_freedom[1];

    // Interior bins (DC is removed by the mean detrend, Nyquist is not doubled).
    double sum = 0.0, sum_sq = 0.0;
    const std::size_t first = 1, last = s.psd.size() - 2;
    const double bins = static_cast<double>(last - first + 1);
    for (std::size_t i = first; i <= last; ++i) {
      sum += s.psd[i];
      sum_sq += s.psd[i] * s.psd[i];
    }
    const double mean = sum / bins;
    const double level = 2.0 * sigma * sigma / fs;
    // ν·P/level ~ χ²_ν: relative standard deviation sqrt(2/ν) per bin.
    const double bin_relative_sd = std::sqrt(2.0 / nu);
    // Adjacent Hann bins are correlated; count the mean as over bins/2 independent values and
    // allow 4 standard deviations.
    EXPECT_NEAR(mean / level, 1.0, 4.0 * bin_relative_sd / std::sqrt(bins / 2.0)) << overlap;
    // The scatter's own relative error is about sqrt(1/bins) ≈ 3 %; 10 % is over 3 of those
    // and well under the gap to the naive 2K at 75 % overlap (ν ≈ 1.04·K: sd 39 % larger).
    const double scatter = std::sqrt(sum_sq / bins - mean * mean) / mean;
    EXPECT_NEAR(scatter / bin_relative_sd, 1.0, 0.10) << overlap;

    EXPECT_NEAR(band_power(s, 0.0, fs / 2.0), sigma * sigma, 0.01 * sigma * sigma) << overlap;
    EXPECT_NEAR(total_power(s), sigma * sigma, 0.01 * sigma * sigma) << overlap;
  }
}

TEST(WelchPsd, CarriesDegreesOfFreedomAndHop) {
  std::mt19937_64 rng(5);
  const auto x = synthetic::gaussian_noise(5000, 1.0, rng);
  const auto plain = welch_psd(x, 100.0, {.segment_length_samples = 500, .overlap_fraction = 0.0});
  EXPECT_EQ(plain.hop_samples, 500u);
  EXPECT_EQ(plain.smoothing_bins, 1u);
  ASSERT_EQ(plain.degrees_of_freedom.size(), plain.psd.size());
  EXPECT_DOUBLE_EQ(plain.degrees_of_freedom[1], 20.0);      // 2 per independent segment
  EXPECT_DOUBLE_EQ(plain.degrees_of_freedom[0], 10.0);      // DC: real, one per segment
  EXPECT_DOUBLE_EQ(plain.degrees_of_freedom.back(), 10.0);  // Nyquist (even L)

  const auto half = welch_psd(x, 100.0, {.segment_length_samples = 500});
  EXPECT_EQ(half.hop_samples, 250u);
  EXPECT_EQ(half.segment_count, 19u);
  EXPECT_NEAR(half.degrees_of_freedom[7], 38.0 / (1.0 + 2.0 * (18.0 / 19.0) / 36.0), 1e-10);

  const auto odd = welch_psd(x, 100.0, {.segment_length_samples = 499, .overlap_fraction = 0.0});
  EXPECT_DOUBLE_EQ(odd.degrees_of_freedom.back(), 20.0);  // odd L: no Nyquist bin
}

// The one-sided factor c_k: 1 at DC and Nyquist, 2 elsewhere. A constant c (no detrend) puts
// |Σw|² = (cL/2)² into DC and (cL/4)² into bins ±1; scaled by fs·Σw² = fs·3L/8 that is
// P[0]·Δf = 2c²/3 and P[1]·Δf = 2·c²/6 = c²/3, summing to c². The alternating sequence c·(−1)^n
// mirrors it at Nyquist.
TEST(WelchPsd, OneSidedScalingAtDcAndNyquist) {
  const double c = 1.7, fs = 64.0;
  const std::size_t length = 128;
  const WelchOptions options{
      .segment_length_samples = length, .overlap_fraction = 0.0, .detrend = Detrend::kNone};
  const auto dc = welch_psd(std::vector<double>(4 * length, c), fs, options);
  const double df = dc.frequency_resolution_Hz;
  EXPECT_NEAR(dc.psd[0] * df, 2.0 * c * c / 3.0, 1e-12);
  EXPECT_NEAR(dc.psd[1] * df, c * c / 3.0, 1e-12);
  EXPECT_NEAR(dc.psd[2] * df, 0.0, 1e-12);

  std::vector<double> alternating(4 * length);
  for (std::size_t i = 0; i < alternating.size(); ++i) alternating[i] = i % 2 == 0 ? c : -c;
  const auto ny = welch_psd(alternating, fs, options);
  const std::size_t last = ny.psd.size() - 1;
  EXPECT_DOUBLE_EQ(ny.frequency_Hz[last], fs / 2.0);
  EXPECT_NEAR(ny.psd[last] * df, 2.0 * c * c / 3.0, 1e-12);
  EXPECT_NEAR(ny.psd[last - 1] * df, c * c / 3.0, 1e-12);
  EXPECT_NEAR(ny.psd[0] * df, 0.0, 1e-12);
}

// One segment, no detrend, no overlap: Σ P·Δf equals Σ(w·x)²/Σw² to rounding, for even L
// (a Nyquist bin, not doubled) and odd L (no Nyquist bin).
TEST(WelchPsd, ScalingMatchesWindowedMeanSquareForEvenAndOddLength) {
  for (std::size_t n : {256u, 255u, 1000u, 999u}) {
    std::mt19937_64 rng(7 + n);
    std::uniform_real_distribution<double> uniform(-1.0, 3.0);
    std::vector<double> x(n);
    for (double& v : x) v = uniform(rng);
    double weighted = 0.0, window_power = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double w =
          0.5 - 0.5 * std::cos(2.0 * kPi * static_cast<double>(i) / static_cast<double>(n));
      weighted += w * w * x[i] * x[i];
      window_power += w * w;
    }
    const auto s = welch_psd(
        x, 50.0, {.segment_length_samples = n, .overlap_fraction = 0.0, .detrend = Detrend::kNone});
    EXPECT_EQ(s.psd.size(), n / 2 + 1);
    EXPECT_EQ(s.segment_count, 1u);
    EXPECT_NEAR(total_power(s), weighted / window_power, 1e-12 * weighted / window_power) << n;
  }
}

TEST(WelchPsd, LinearDetrendRemovesRampAndKeepsSine) {
  const double fs = 100.0, amplitude = 0.5, f0 = 10.0;
  const std::size_t n = 10'000;
  auto x = sine(amplitude, f0, 0.0, fs, n);
  for (std::size_t i = 0; i < n; ++i) x[i] += 4.0 + 3.0 * static_cast<double>(i) / fs;
  const double sine_power = amplitude * amplitude / 2.0;

  const auto linear = welch_psd(x, fs, {.segment_length_s = 5.0, .detrend = Detrend::kLinear});
  EXPECT_NEAR(total_power(linear), sine_power, 0.01 * sine_power);
  // Not zero: over a segment the sine itself has a small least-squares slope, which the
  // detrend removes along with the ramp.
  EXPECT_LT(band_power(linear, 0.0, 5.0), 1e-3 * sine_power);

  // With the mean only, each segment's ramp (±7.5 over 5 s) leaks into the low bins.
  const auto mean = welch_psd(x, fs, {.segment_length_s = 5.0, .detrend = Detrend::kMean});
  EXPECT_GT(band_power(mean, 0.0, 5.0), 20.0 * sine_power);

  // A pure ramp vanishes entirely.
  std::vector<double> ramp(n);
  for (std::size_t i = 0; i < n; ++i) ramp[i] = -2.0 + 0.01 * static_cast<double>(i);
  const auto flat = welch_psd(ramp, fs, {.segment_length_s = 5.0, .detrend = Detrend::kLinear});
  EXPECT_LT(total_power(flat), 1e-20);
}

TEST(WelchPsd, SegmentLengthAndCountConventions) {
  const std::vector<double> x = sine(1.0, 3.0, 0.0, 100.0, 1000);
  const auto by_seconds = welch_psd(x, 100.0, {.segment_length_s = 2.0});
  EXPECT_EQ(by_seconds.segment_length_samples, 200u);
  EXPECT_EQ(by_seconds.segment_count, 9u);  // hop 100
  EXPECT_DOUBLE_EQ(by_seconds.frequency_resolution_Hz, 0.5);
  EXPECT_DOUBLE_EQ(by_seconds.frequency_Hz.back(), 50.0);

  const auto by_default = welch_psd(x, 100.0);  // 8 segments at 50 %: floor(1000/4.5)
  EXPECT_EQ(by_default.segment_length_samples, 222u);
  EXPECT_EQ(by_default.segment_count, 8u);

  const auto no_overlap =
      welch_psd(x, 100.0, {.segment_length_samples = 300, .overlap_fraction = 0.0});
  EXPECT_EQ(no_overlap.segment_count, 3u);  // the last 100 samples are dropped

  const auto whole = welch_psd(x, 100.0, {.segment_length_samples = 1000});
  EXPECT_EQ(whole.segment_count, 1u);
}

TEST(WelchPsd, EigenOverloadMatchesSpan) {
  const std::vector<double> x = sine(1.5, 7.0, 0.2, 64.0, 640);
  const Eigen::VectorXd v = Eigen::Map<const Eigen::VectorXd>(x.data(), 640);
  const auto a = welch_psd(x, 64.0, {.segment_length_samples = 128});
  const auto b = welch_psd(v, 64.0, {.segment_length_samples = 128});
  ASSERT_EQ(a.psd.size(), b.psd.size());
  for (std::size_t k = 0; k < a.psd.size(); ++k) EXPECT_EQ(a.psd[k], b.psd[k]);
}

void expect_input_error(const std::vector<double>& x, double fs, const WelchOptions& options,
                        const std::string& fragment) {
  try {
    welch_psd(x, fs, options);
    ADD_FAILURE() << "no InputError; expected one mentioning '" << fragment << "'";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(WelchPsd, BadInputsThrowWithClearMessages) {
  const std::vector<double> x(500, 1.0);
  expect_input_error({}, 100.0, {}, "has 0 samples");
  expect_input_error(x, 0.0, {}, "sample rate");
  expect_input_error(x, -5.0, {}, "sample rate");
  expect_input_error(x, std::numeric_limits<double>::quiet_NaN(), {}, "sample rate");
  expect_input_error(x, 100.0, {.overlap_fraction = 1.0}, "[0, 1)");
  expect_input_error(x, 100.0, {.overlap_fraction = -0.1}, "[0, 1)");
  expect_input_error(x, 100.0, {.segment_length_samples = 501}, "at most 500 samples");
  expect_input_error(x, 100.0, {.segment_length_s = 10.0}, "at most 500 samples");
  expect_input_error(x, 100.0, {.segment_length_s = -1.0}, "positive");
  expect_input_error(x, 100.0, {.segment_length_samples = 1}, "at least 2");
  expect_input_error(x, 100.0, {.segment_length_samples = 100, .segment_length_s = 1.0},
                     "only one");
  expect_input_error({1.0}, 100.0, {}, "at least 2");
  // The default segment never drops below 2 samples on a short signal.
  EXPECT_EQ(welch_psd(std::vector<double>(5, 0.0), 100.0).segment_length_samples, 2u);

  auto bad = x;
  bad[123] = std::numeric_limits<double>::quiet_NaN();
  expect_input_error(bad, 100.0, {}, "sample 123");
  bad[123] = std::numeric_limits<double>::infinity();
  expect_input_error(bad, 100.0, {}, "sample 123");
}

TEST(WelchPsd, DetrendNamesRoundTrip) {
  for (Detrend d : {Detrend::kNone, Detrend::kMean, Detrend::kLinear}) {
    EXPECT_EQ(parse_detrend(to_string(d)), d);
  }
  EXPECT_THROW(parse_detrend("quadratic"), InputError);
}

}  // namespace
}  // namespace ridefit::signal
