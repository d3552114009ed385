#include "ridefit/signal/equivalent_dof.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/hann_window.h"

namespace ridefit::signal {
namespace {

TEST(EquivalentDof, HannOverlapCorrelationIsOneSixthAtHalfOverlap) {
  for (std::size_t length : {64u, 256u, 4096u}) {
    const auto w = periodic_hann_window(length);
    EXPECT_NEAR(window_overlap_correlation(w, 0), 1.0, 1e-14);
    EXPECT_NEAR(window_overlap_correlation(w, length / 2), 1.0 / 6.0, 1e-14) << length;
    EXPECT_EQ(window_overlap_correlation(w, length), 0.0);
  }
  // Rectangular window: ρ(D) = 1 − D/L.
  const std::vector<double> rect(100, 2.0);
  EXPECT_NEAR(window_overlap_correlation(rect, 25), 0.75, 1e-15);
}

TEST(EquivalentDof, WelchFormulaAgainstClosedForms) {
  const auto w = periodic_hann_window(512);
  // No overlap: independent segments, two degrees of freedom each.
  EXPECT_DOUBLE_EQ(welch_degrees_of_freedom(w, 512, 10), 20.0);
  EXPECT_DOUBLE_EQ(welch_degrees_of_freedom(w, 600, 3), 6.0);  // gaps between segments
  // 50 %: only neighbours overlap, ρ = 1/6.
  for (std::size_t k : {1u, 2u, 9u, 100u}) {
    const double kk = static_cast<double>(k);
    EXPECT_NEAR(welch_degrees_of_freedom(w, 256, k),
                2.0 * kk / (1.0 + 2.0 * (1.0 - 1.0 / kk) / 36.0), 1e-12 * kk)
        << k;
  }
  // 75 % overlap: three neighbours overlap; ρ by direct sums, independent of the library.
  double rho1 = 0.0, rho2 = 0.0, rho3 = 0.0, power = 0.0;
  for (std::size_t n = 0; n < 512; ++n) {
    power += w[n] * w[n];
    if (n + 128 < 512) rho1 += w[n] * w[n + 128];
    if (n + 256 < 512) rho2 += w[n] * w[n + 256];
    if (n + 384 < 512) rho3 += w[n] * w[n + 384];
  }
  rho1 /= power, rho2 /= power, rho3 /= power;
  const double k = 50.0;
  const double expected =
      2.0 * k /
      (1.0 + 2.0 * ((1.0 - 1.0 / k) * rho1 * rho1 + (1.0 - 2.0 / k) * rho2 * rho2 +
                    (1.0 - 3.0 / k) * rho3 * rho3));
  EXPECT_NEAR(welch_degrees_of_freedom(w, 128, 50), expected, 1e-10);
  EXPECT_GT(rho3, 0.0);  // so the third lag mattered
}

TEST(EquivalentDof, BinCorrelationOfHannWithoutOverlap) {
  const auto w = periodic_hann_window(256);
  const auto corr = welch_bin_correlation(w, 256, 7, 4);
  ASSERT_EQ(corr.size(), 5u);
  EXPECT_DOUBLE_EQ(corr[0], 1.0);
  EXPECT_NEAR(corr[1], 4.0 / 9.0, 1e-12);
  EXPECT_NEAR(corr[2], 1.0 / 36.0, 1e-12);
  EXPECT_NEAR(corr[3], 0.0, 1e-12);
  EXPECT_NEAR(corr[4], 0.0, 1e-12);
}

TEST(EquivalentDof, BinCorrelationWithOverlapIncludesCrossSegmentTerms) {
  const auto w = periodic_hann_window(256);
  const auto single = welch_bin_correlation(w, 128, 1, 3);
  const auto many = welch_bin_correlation(w, 128, 1000, 3);
  // One segment: overlap is irrelevant.
  EXPECT_NEAR(single[1], 4.0 / 9.0, 1e-12);
  // Overlapped segments add correlated pairs whose cross-bin terms differ from the lag-0 ones.
  EXPECT_GT(std::abs(many[1] - single[1]), 1e-3);
  EXPECT_GT(many[3], 1e-6);
  EXPECT_LT(many[3], 0.01);
}

TEST(EquivalentDof, BadInputsThrow) {
  const auto w = periodic_hann_window(16);
  EXPECT_THROW(welch_degrees_of_freedom(w, 0, 3), InputError);
  EXPECT_THROW(welch_degrees_of_freedom(w, 8, 0), InputError);
  EXPECT_THROW(welch_degrees_of_freedom(std::vector<double>{}, 8, 3), InputError);
  EXPECT_THROW(window_overlap_correlation(std::vector<double>(8, 0.0), 2), InputError);
  EXPECT_THROW(welch_bin_correlation(w, 0, 3, 2), InputError);
}

}  // namespace
}  // namespace ridefit::signal
