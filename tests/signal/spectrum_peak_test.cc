#include "ridefit/signal/spectrum_peak.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

// Gaussian peaks are parabolas in ln PSD, so the refinement is exact for them.
std::vector<double> gaussian_peaks(const std::vector<double>& f,
                                   const std::vector<std::array<double, 3>>& peaks) {
  std::vector<double> p(f.size(), 0.0);
  for (std::size_t i = 0; i < f.size(); ++i) {
    for (const auto& [centre, height, width] : peaks) {
      p[i] += height * std::exp(-0.5 * std::pow((f[i] - centre) / width, 2));
    }
  }
  return p;
}

std::vector<double> grid(double step, std::size_t n) {
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = step * static_cast<double>(i);
  return f;
}

TEST(SpectrumPeak, LogParabolaIsExactForGaussianPeak) {
  const auto f = grid(0.5, 101);
  const auto p = gaussian_peaks(f, {{12.34, 3.0, 1.1}});
  const SpectrumPeak peak = find_peak(f, p, 0.0, 50.0);
  EXPECT_EQ(peak.bin, 25u);  // 12.5 Hz
  EXPECT_NEAR(peak.frequency_Hz, 12.34, 1e-9);
  EXPECT_NEAR(peak.psd, 3.0, 1e-9);
}

TEST(SpectrumPeak, HandlesNonUniformGrid) {
  std::vector<double> f;
  for (double x = 0.1; x < 100.0; x *= 1.05) f.push_back(x);  // log-spaced
  const auto p = gaussian_peaks(f, {{8.123, 2.0, 1.5}});
  EXPECT_NEAR(find_peak(f, p, 1.0, 50.0).frequency_Hz, 8.123, 1e-9);
}

TEST(SpectrumPeak, BandSelectsAmongPeaks) {
  const auto f = grid(0.25, 401);
  const auto p = gaussian_peaks(f, {{1.3, 10.0, 0.4}, {11.7, 0.5, 0.8}});
  EXPECT_NEAR(find_peak(f, p, 0.0, 100.0).frequency_Hz, 1.3, 1e-9);
  EXPECT_NEAR(find_peak(f, p, 5.0, 20.0).frequency_Hz, 11.7, 1e-9);
}

TEST(SpectrumPeak, NoRefinementWhereTheBandCutsASlope) {
  const auto f = grid(0.5, 41);
  const auto p = gaussian_peaks(f, {{5.2, 1.0, 1.0}});
  // Inside [7, 10] the PSD falls monotonically: the largest bin is the lower edge, 7 Hz.
  const SpectrumPeak peak = find_peak(f, p, 7.0, 10.0);
  EXPECT_EQ(peak.bin, 14u);
  EXPECT_DOUBLE_EQ(peak.frequency_Hz, 7.0);
  EXPECT_DOUBLE_EQ(peak.psd, p[14]);
  // At the spectrum's last bin there is no right neighbour.
  EXPECT_EQ(find_peak(f, std::vector<double>(f.begin(), f.end()), 0.0, 20.0).bin, 40u);
}

TEST(SpectrumPeak, BadInputsThrow) {
  const auto f = grid(1.0, 11);
  const std::vector<double> p(11, 1.0);
  EXPECT_THROW(find_peak(f, p, 3.2, 3.8), InputError);  // no bin inside
  EXPECT_THROW(find_peak(f, p, 5.0, 5.0), InputError);  // empty band
  EXPECT_THROW(find_peak(f, p, 6.0, 4.0), InputError);
  EXPECT_THROW(find_peak(f, p, 2.0, 12.0), InputError);  // beyond the spectrum
  EXPECT_THROW(find_peak(f, std::vector<double>(10, 1.0), 2.0, 4.0), InputError);
  auto negative = p;
  negative[4] = -1.0;
  EXPECT_THROW(find_peak(f, negative, 2.0, 4.0), InputError);
  auto unsorted = f;
  std::swap(unsorted[2], unsorted[3]);
  EXPECT_THROW(find_peak(unsorted, p, 2.0, 4.0), InputError);
}

}  // namespace
}  // namespace ridefit::signal
