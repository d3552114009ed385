#include "ridefit/road/uniform_spline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include "ridefit/road/resample.h"

namespace ridefit::road {
namespace {

TEST(RoadUniformSpline, PassesThroughEverySample) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 0.01);
  std::vector<double> samples(200);
  for (double& s : samples) s = noise(rng);
  const UniformSpline spline(samples, -3.0, 0.05);
  EXPECT_DOUBLE_EQ(spline.end(), -3.0 + 199 * 0.05);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    EXPECT_NEAR(spline.value(-3.0 + 0.05 * static_cast<double>(k)), samples[k], 1e-14) << k;
  }
}

TEST(RoadUniformSpline, ReproducesACubicWithItsSlope) {
  auto f = [](double x) { return 0.3 - 0.2 * x + 0.05 * x * x - 0.01 * x * x * x; };
  auto df = [](double x) { return -0.2 + 0.1 * x - 0.03 * x * x; };
  std::vector<double> samples;
  for (int k = 0; k <= 20; ++k) samples.push_back(f(0.5 * k));
  const UniformSpline spline(samples, 0.0, 0.5, df(0.0), df(10.0));
  for (double x = 0.0; x <= 10.0; x += 0.137) {
    EXPECT_NEAR(spline.value(x), f(x), 1e-12) << x;
    EXPECT_NEAR(spline.derivative(x), df(x), 1e-11) << x;
  }
}

TEST(RoadUniformSpline, SlopeIsContinuousAcrossKnotsAndMatchesDifferences) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<double> samples(50);
  for (double& s : samples) s = u(rng);
  const UniformSpline spline(samples, 0.0, 0.1);
  for (int k = 5; k < 45; ++k) {
    const double x = 0.1 * k;
    // C2: value and slope agree from both sides of a knot.
    EXPECT_NEAR(spline.derivative(x - 1e-12), spline.derivative(x + 1e-12), 1e-8) << k;
    const double h = 1e-6;
    const double central = (spline.value(x + 0.03 + h) - spline.value(x + 0.03 - h)) / (2 * h);
    EXPECT_NEAR(spline.derivative(x + 0.03), central, 1e-6) << k;
  }
}

TEST(RoadUniformSpline, HoldsEndValuesFlatOutsideAndRejectsTooFewSamples) {
  const UniformSpline spline({1.0, 2.0, 3.0, 4.0, 5.0}, 1.0, 1.0);
  EXPECT_DOUBLE_EQ(spline.value(-10.0), 1.0);
  EXPECT_DOUBLE_EQ(spline.value(100.0), 5.0);
  EXPECT_DOUBLE_EQ(spline.derivative(-10.0), 0.0);
  EXPECT_DOUBLE_EQ(spline.derivative(100.0), 0.0);
  EXPECT_NEAR(spline.derivative(3.0), 1.0, 1e-12);  // a line is reproduced
  EXPECT_THROW(UniformSpline({1.0, 2.0, 3.0, 4.0}, 0.0, 1.0), std::invalid_argument);
  EXPECT_NO_THROW(UniformSpline({1.0, 2.0, 3.0}, 0.0, 1.0, 0.0, 0.0));
  EXPECT_THROW(UniformSpline({1.0, 2.0, 3.0, 4.0, 5.0}, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(UniformSpline({1.0, 2.0, std::nan(""), 4.0, 5.0}, 0.0, 1.0), std::invalid_argument);
}

TEST(RoadUniformSpline, SevenSamplesPerWaveGiveTheDocumentedAccuracy) {
  // random_profile.h: at 7 samples per wave the spline misses the amplitude by 0.2 % and the
  // slope by 0.7 %.
  const double step = 1.0 / 7.0;
  std::vector<double> samples;
  for (int k = 0; k < 700; ++k) samples.push_back(std::sin(2 * std::numbers::pi * k * step));
  const UniformSpline spline(samples, 0.0, step);
  double value_error = 0.0;
  double slope_error = 0.0;
  for (double x = 20.0; x < 80.0; x += 0.001) {
    value_error =
        std::max(value_error, std::abs(spline.value(x) - std::sin(2 * std::numbers::pi * x)));
    slope_error = std::max(slope_error, std::abs(spline.derivative(x) / (2 * std::numbers::pi) -
                                                 std::cos(2 * std::numbers::pi * x)));
  }
  EXPECT_LT(value_error, 0.0025);
  EXPECT_LT(slope_error, 0.0075);
}

TEST(RoadResample, KeepsUniformDataExactly) {
  const std::vector<double> x{0.0, 0.1, 0.2, 0.30000000000000004, 0.4};
  const std::vector<double> y{1.0, -2.0, 3.0, -4.0, 5.0};
  const UniformSamples s = resample_uniform(x, y);
  EXPECT_EQ(s.values, y);
  EXPECT_DOUBLE_EQ(s.start, 0.0);
  EXPECT_DOUBLE_EQ(s.step, 0.1);
}

TEST(RoadResample, NonUniformDataGoesOnTheMedianGridWithoutOvershoot) {
  // A ramp then a plateau, sampled unevenly: PCHIP keeps the ramp linear and never
  // overshoots the plateau.
  const std::vector<double> x{0.0, 0.1, 0.25, 0.3, 0.4, 0.52, 0.6, 0.7, 0.8, 1.0};
  std::vector<double> y;
  for (double xi : x) y.push_back(std::min(xi, 0.5));
  const UniformSamples s = resample_uniform(x, y);
  EXPECT_DOUBLE_EQ(s.start, 0.0);
  EXPECT_NEAR(s.step, 0.1, 1e-12);  // median spacing, 11 points over [0, 1]
  ASSERT_EQ(s.values.size(), 11u);
  for (std::size_t k = 0; k < s.values.size(); ++k) {
    const double xk = 0.1 * static_cast<double>(k);
    EXPECT_LE(s.values[k], 0.5 + 1e-15) << k;
    if (xk <= 0.25) {
      EXPECT_NEAR(s.values[k], xk, 1e-12) << k;
    }
    if (xk >= 0.6) {
      EXPECT_NEAR(s.values[k], 0.5, 1e-12) << k;
    }
  }
}

TEST(RoadResample, CountIsKnownBeforeResamplingAndAtLeastFive) {
  const std::vector<double> uniform{0.0, 0.1, 0.2, 0.3};
  EXPECT_EQ(resampled_count(uniform), 4.0);
  // Median gap 0.8 m over 2 m: round(2.5) + 1 = 4 points, raised to the spline's 5.
  const std::vector<double> x{0.0, 0.1, 0.2, 1.0, 2.0}, y{0, 0, 1, 0, 0};
  EXPECT_EQ(resampled_count(x), 5.0);
  const UniformSamples s = resample_uniform(x, y);
  ASSERT_EQ(s.values.size(), 5u);
  EXPECT_DOUBLE_EQ(s.step, 0.5);
  // Absurd spacings give a count no allocation could hold; resample_uniform refuses it.
  const std::vector<double> gap{0.0, 1e-9, 2e-9, 3e-9, 1e6}, zeros(5, 0.0);
  EXPECT_GT(resampled_count(gap), 1e14);
  EXPECT_THROW(resample_uniform(gap, zeros), std::invalid_argument);
}

}  // namespace
}  // namespace ridefit::road
