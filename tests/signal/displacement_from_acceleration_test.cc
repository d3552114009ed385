#include "ridefit/signal/displacement_from_acceleration.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <vector>

#include "support/throws_input_error.h"

namespace ridefit::signal {
namespace {

using testing::throws_input_error;

constexpr double kPi = std::numbers::pi;
constexpr double kRate_Hz = 200.0;
constexpr double kDuration_s = 40.0;
// Kept clear of the transients at the record's ends: 2/f_c = 2.7 s at 0.75 Hz.
constexpr double kEdge_s = 2.0 / 0.75;

std::vector<double> sampled(const std::function<double(double)>& f) {
  const auto n = static_cast<std::size_t>(kDuration_s * kRate_Hz);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = f(static_cast<double>(i) / kRate_Hz);
  return x;
}

// max |x − reference| over the record without kEdge_s at either end.
double max_error_inside(const std::vector<double>& x, const std::function<double(double)>& ref) {
  double error = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = static_cast<double>(i) / kRate_Hz;
    if (t < kEdge_s || t > kDuration_s - kEdge_s) continue;
    error = std::max(error, std::abs(x[i] - ref(t)));
  }
  return error;
}

double max_abs_inside(const std::vector<double>& x) {
  return max_error_inside(x, [](double) { return 0.0; });
}

TEST(DisplacementFromAcceleration, SineAboveTheCutOffIsIntegratedTwice) {
  // a = sin(2π·2t) m/s²: d = −a/(2π·2)², amplitude 6.33 mm; |H(2 Hz)| = 1 − 2e-4.
  const double omega = 2.0 * kPi * 2.0;
  const auto a = sampled([&](double t) { return std::sin(omega * t); });
  const auto d = displacement_from_acceleration(a, kRate_Hz);
  ASSERT_EQ(d.size(), a.size());
  const double amplitude = 1.0 / (omega * omega);
  EXPECT_LT(max_error_inside(d, [&](double t) { return -std::sin(omega * t) / (omega * omega); }),
            0.01 * amplitude);

  // v = −cos(ωt)/ω.
  const auto v = velocity_from_acceleration(a, kRate_Hz);
  EXPECT_LT(max_error_inside(v, [&](double t) { return -std::cos(omega * t) / omega; }),
            0.01 / omega);
}

TEST(DisplacementFromAcceleration, OffsetAndDriftOfTheSensorAreRemoved) {
  // A 0.3 m/s² offset and a 0.01 m/s³ drift would integrate to a parabola and a cubic.
  const double omega = 2.0 * kPi * 2.0;
  const auto a = sampled([&](double t) { return std::sin(omega * t) + 0.3 + 0.01 * t; });
  const auto d = displacement_from_acceleration(a, kRate_Hz);
  EXPECT_LT(max_error_inside(d, [&](double t) { return -std::sin(omega * t) / (omega * omega); }),
            0.01 / (omega * omega));
}

TEST(DisplacementFromAcceleration, SlowComponentIsSuppressedByTheHighPass) {
  // At 0.2 Hz the order-4 Butterworth high-pass at 0.75 Hz passes
  // |H| = 1/sqrt(1 + (0.75/0.2)^8) = 5.05e-3 of the double integral 1/(2π·0.2)² = 0.633 m.
  const double omega = 2.0 * kPi * 0.2;
  const auto a = sampled([&](double t) { return std::sin(omega * t); });
  const double gain = 1.0 / std::sqrt(1.0 + std::pow(0.75 / 0.2, 8.0));
  EXPECT_NEAR(gain, 5.05e-3, 1e-5);
  const auto d = displacement_from_acceleration(a, kRate_Hz);
  const double unfiltered = 1.0 / (omega * omega);
  EXPECT_LT(max_abs_inside(d), 0.01 * unfiltered);
  EXPECT_NEAR(max_abs_inside(d), gain * unfiltered, 0.05 * gain * unfiltered);
  const auto v = velocity_from_acceleration(a, kRate_Hz);
  EXPECT_NEAR(max_abs_inside(v), gain / omega, 0.05 * gain / omega);
}

TEST(DisplacementFromAcceleration, OrderAndCutOffShapeTheResponse) {
  // At the cut-off |H| = 1/√2 whatever the order.
  const double omega = 2.0 * kPi * 1.5;
  const auto a = sampled([&](double t) { return std::sin(omega * t); });
  HighPassIntegrationOptions options;
  options.high_pass_Hz = 1.5;
  options.high_pass_order = 6;
  const auto d = displacement_from_acceleration(a, kRate_Hz, options);
  EXPECT_NEAR(max_abs_inside(d), std::sqrt(0.5) / (omega * omega), 0.01 / (omega * omega));
}

TEST(DisplacementFromAcceleration, BadInputThrowsWithAMessageNamingTheProblem) {
  std::vector<double> a(1000, 0.0);
  a[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(
      throws_input_error([&] { displacement_from_acceleration(a, kRate_Hz); }, "sample 3 is nan"));
  const std::vector<double> one{1.0};
  EXPECT_TRUE(throws_input_error([&] { velocity_from_acceleration(one, kRate_Hz); }, "at least 2"));
  const std::vector<double> ok(1000, 0.0);
  EXPECT_TRUE(
      throws_input_error([&] { displacement_from_acceleration(ok, 0.0); }, "sample rate 0 Hz"));
  HighPassIntegrationOptions options;
  options.high_pass_Hz = 100.0;
  EXPECT_TRUE(throws_input_error([&] { displacement_from_acceleration(ok, kRate_Hz, options); },
                                 "cut-off 100 Hz"));
  options.high_pass_Hz = 0.0;
  EXPECT_TRUE(throws_input_error([&] { displacement_from_acceleration(ok, kRate_Hz, options); },
                                 "cut-off 0 Hz"));
  options.high_pass_Hz = 1e-9;
  EXPECT_TRUE(throws_input_error([&] { displacement_from_acceleration(ok, kRate_Hz, options); },
                                 "raise the cut-off"));
  options = {};
  options.high_pass_order = 2;
  EXPECT_TRUE(throws_input_error([&] { displacement_from_acceleration(ok, kRate_Hz, options); },
                                 "order 2 is invalid"));
  EXPECT_NO_THROW(velocity_from_acceleration(ok, kRate_Hz, options));
  options.high_pass_order = 1;
  EXPECT_TRUE(throws_input_error([&] { velocity_from_acceleration(ok, kRate_Hz, options); },
                                 "must lie in [2, 16]"));
}

}  // namespace
}  // namespace ridefit::signal
