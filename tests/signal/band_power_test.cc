#include "ridefit/signal/band_power.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

std::vector<double> grid(double step, std::size_t n) {
  std::vector<double> f(n);
  for (std::size_t i = 0; i < n; ++i) f[i] = step * static_cast<double>(i);
  return f;
}

TEST(SpectrumBandPower, ConstantDensityOverUnalignedBand) {
  const auto f = grid(0.5, 201);
  const std::vector<double> p(f.size(), 0.04);
  EXPECT_NEAR(band_power(f, p, 10.2, 20.7), 0.04 * 10.5, 1e-14);
  EXPECT_NEAR(band_rms(f, p, 10.2, 20.7), std::sqrt(0.04 * 10.5), 1e-14);
  EXPECT_NEAR(band_power(f, p, 0.0, 100.0), 4.0, 1e-13);  // the whole range
}

TEST(SpectrumBandPower, TrapezoidIsExactForLinearDensityAndEdgesInsideOneBin) {
  const auto f = grid(1.0, 51);
  std::vector<double> p(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) p[i] = 2.0 + 3.0 * f[i];
  const auto integral = [](double a, double b) { return 2.0 * (b - a) + 1.5 * (b * b - a * a); };
  EXPECT_NEAR(band_power(f, p, 3.3, 41.9), integral(3.3, 41.9), 1e-10);
  EXPECT_NEAR(band_power(f, p, 7.2, 7.7), integral(7.2, 7.7), 1e-12);
}

TEST(SpectrumBandPower, TrapezoidOnCurvedDensity) {
  // p = f² on a 0.1 Hz grid: the trapezoid overestimates ∫ by Δf²·(b − a)/6.
  const auto f = grid(0.1, 101);
  std::vector<double> p(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) p[i] = f[i] * f[i];
  EXPECT_NEAR(band_power(f, p, 2.0, 8.0), (512.0 - 8.0) / 3.0 + 0.01 * 6.0 / 6.0, 1e-10);
}

TEST(SpectrumBandPower, BadBandsThrow) {
  const auto f = grid(1.0, 11);
  const std::vector<double> p(11, 1.0);
  EXPECT_THROW(band_power(f, p, 4.0, 4.0), InputError);
  EXPECT_THROW(band_power(f, p, -1.0, 4.0), InputError);
  EXPECT_THROW(band_power(f, p, 4.0, 10.5), InputError);
  EXPECT_THROW(band_rms(f, p, 4.0, std::nan("")), InputError);
  EXPECT_NO_THROW(band_power(f, p, 0.0, 10.0 + 1e-12));  // rounding of a computed edge
}

}  // namespace
}  // namespace ridefit::signal
