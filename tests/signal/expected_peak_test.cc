// Spectral moments and the expected extreme of a Gaussian process.
#include "ridefit/signal/expected_peak.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <unsupported/Eigen/FFT>
#include <vector>

namespace ridefit::signal {
namespace {

TEST(SpectralMoment, FlatBandMatchesTheClosedForm) {
  // S = 2 on [1, 5] Hz: m0 = 8, m2 = 2·(125 − 1)/3.
  std::vector<double> f, s;
  for (int k = 0; k < 2001; ++k) {
    f.push_back(std::exp(std::log(5.0) * k / 2000.0));
    s.push_back(2.0);
  }
  EXPECT_NEAR(spectral_moment(f, s, 0), 8.0, 1e-5 * 8.0);
  EXPECT_NEAR(spectral_moment(f, s, 2), 2.0 * 124.0 / 3.0, 1e-5 * 2.0 * 124.0 / 3.0);
}

// 300 seeded realisations of band-limited white noise (1–5 Hz, random phases, 81.9 s each):
// the mean of their largest |x| against Davenport's expectation.
TEST(ExpectedGaussianPeak, MatchesTheMeanOfSimulatedRecords) {
  const int n = 1 << 14;
  const double fs = 200.0, duration = n / fs, df = 1.0 / duration, level = 1e-4;  // m²/Hz
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
  std::normal_distribution<double> normal;
  Eigen::FFT<double> fft;
  double sum = 0.0;
  const int records = 300;
  for (int r = 0; r < records; ++r) {
    std::vector<std::complex<double>> spectrum(n, 0.0);
    for (int k = 1; k < n / 2; ++k) {
      const double f = k * df;
      if (f < 1.0 || f > 5.0) continue;
      // Gaussian amplitudes (Rayleigh magnitude) make the record Gaussian, not just its sum.
      const double a = std::sqrt(level * df / 2.0) * n;
      spectrum[k] = a * std::complex<double>(normal(rng), normal(rng)) / std::sqrt(2.0) *
                    std::polar(1.0, phase(rng));
      spectrum[n - k] = std::conj(spectrum[k]);
    }
    std::vector<double> x;
    fft.inv(x, spectrum);
    double peak = 0.0;
    for (double v : x) peak = std::max(peak, std::abs(v));
    sum += peak;
  }
  const double m0 = level * 4.0, m2 = level * (125.0 - 1.0) / 3.0;
  const double expected = expected_gaussian_peak(m0, m2, duration);
  EXPECT_NEAR(sum / records, expected, 0.03 * expected);
  // About 3.9 σ for ~560 excursions, far from the RMS and from a 3 σ rule of thumb.
  EXPECT_GT(expected / std::sqrt(m0), 3.5);
}

TEST(ExpectedGaussianPeak, ShortRecordsAreClampedAndZeroIsZero) {
  EXPECT_EQ(expected_gaussian_peak(0.0, 1.0, 10.0), 0.0);
  // n below e² is clamped: 2 + γ/2 = 2.29 σ.
  EXPECT_NEAR(expected_gaussian_peak(1.0, 1.0, 0.1), 2.0 + std::numbers::egamma / 2.0, 1e-12);
  EXPECT_THROW(expected_gaussian_peak(-1.0, 1.0, 1.0), std::invalid_argument);
}

}  // namespace
}  // namespace ridefit::signal
