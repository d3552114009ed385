#include "ridefit/signal/zero_phase_low_pass.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::signal {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<double> sine(double frequency_Hz, double rate_Hz, std::size_t n, double offset = 0.0) {
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) {
    x[k] = offset + std::sin(2.0 * kPi * frequency_Hz * static_cast<double>(k) / rate_Hz);
  }
  return x;
}

// Forward and backward: |H|² = 1/(1 + (f/f_c)⁴) with no phase. At the cut-off, where the
// bilinear transform is pre-warped, the gain is exactly 1/2; at f_c/4 it is 1/(1 + 1/256).
TEST(ZeroPhaseLowPass, GainIsTheSquaredButterworthAndThePhaseIsZero) {
  const double rate = 1000.0, cutoff = 40.0;
  for (const auto& [f, gain] : {std::pair{40.0, 0.5}, std::pair{10.0, 1.0 / (1.0 + 1.0 / 256.0)}}) {
    const auto x = sine(f, rate, 4000, 0.3);
    const auto y = zero_phase_low_pass(x, rate, cutoff);
    ASSERT_EQ(y.size(), x.size());
    // Away from the ends, the output is the input's sine scaled, in phase, on the same offset.
    for (std::size_t k = 1000; k < 3000; ++k) {
      EXPECT_NEAR(y[k] - 0.3, gain * (x[k] - 0.3), 2e-3) << "f " << f << ", sample " << k;
    }
  }
}

// Odd reflection at the ends and a steady start: a ramp on an offset comes out unchanged, at the
// ends too, and a sine well inside the pass band is kept to its last sample.
TEST(ZeroPhaseLowPass, EndsGetNoTransient) {
  std::vector<double> ramp(500);
  for (std::size_t k = 0; k < ramp.size(); ++k) ramp[k] = -0.03 + 1e-5 * static_cast<double>(k);
  const auto y = zero_phase_low_pass(ramp, 200.0, 5.0);
  for (std::size_t k = 0; k < ramp.size(); ++k) EXPECT_NEAR(y[k], ramp[k], 1e-12);
  const auto x = sine(2.0, 1000.0, 3001);
  const auto z = zero_phase_low_pass(x, 1000.0, 80.0);
  EXPECT_NEAR(z.front(), x.front(), 1e-4);
  EXPECT_NEAR(z.back(), x.back(), 1e-4);
  EXPECT_NEAR(z[125], x[125], 1e-4);  // the first peak
}

TEST(ZeroPhaseLowPass, BadInputIsAnInputError) {
  const auto x = sine(2.0, 1000.0, 100);
  EXPECT_THROW(zero_phase_low_pass(x, 1000.0, 500.0), InputError);
  EXPECT_THROW(zero_phase_low_pass(x, 1000.0, 0.0), InputError);
  EXPECT_THROW(zero_phase_low_pass(x, 0.0, 10.0), InputError);
  EXPECT_THROW(zero_phase_low_pass(std::vector<double>{1.0, 2.0, 3.0}, 1000.0, 10.0), InputError);
  auto bad = x;
  bad[50] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(zero_phase_low_pass(bad, 1000.0, 10.0), InputError);
}

}  // namespace
}  // namespace ridefit::signal
