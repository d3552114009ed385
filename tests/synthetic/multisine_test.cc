// Rig displacement histories: a sum of sines with the amplitudes, frequencies and phases asked
// for, the lab's named histories, and the seeded random rig motion.
#include "ridefit/synthetic/multisine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace ridefit::synthetic {
namespace {

TEST(SyntheticMultisine, OneSineHasTheRequestedAmplitudeFrequencyAndPhase) {
  const Multisine x{{0.002}, {3.0}, {0.4}};
  const double w = 2.0 * std::numbers::pi * 3.0;
  // The crest where 2π·3·t + 0.4 = π/2, a period later the same, half a period later the trough.
  const double crest_s = (0.5 * std::numbers::pi - 0.4) / w;
  EXPECT_NEAR(x(crest_s), 0.002, 1e-12);
  EXPECT_NEAR(x(crest_s + 1.0 / 3.0), 0.002, 1e-12);
  EXPECT_NEAR(x(crest_s + 0.5 / 3.0), -0.002, 1e-12);
  for (double t = 0.0; t < 2.0; t += 0.01237) {
    EXPECT_NEAR(x(t), 0.002 * std::sin(w * t + 0.4), 1e-12) << t;
  }
}

TEST(SyntheticMultisine, LabThreeSinesAreTheRigTestsHistory) {
  const Multisine x = lab_three_sines();
  const double w = 2.0 * std::numbers::pi;
  for (double t = 0.0; t < 5.0; t += 0.0731) {
    EXPECT_NEAR(x(t),
                0.003 * std::sin(w * 0.7 * t) + 0.0015 * std::sin(w * 2.3 * t) +
                    0.0008 * std::sin(w * 6.1 * t),
                1e-15);
  }
}

TEST(SyntheticMultisine, RandomRigMotionIsLogSpacedReproducibleAndAboutFourMillimetresRms) {
  std::mt19937_64 a(3), b(3), c(4);
  const Multisine x = random_rig_motion(a), same = random_rig_motion(b),
                  other = random_rig_motion(c, 0.5);
  ASSERT_EQ(x.frequency_Hz.size(), 40u);
  EXPECT_DOUBLE_EQ(x.frequency_Hz.front(), 0.5);
  EXPECT_NEAR(x.frequency_Hz.back(), 20.0, 1e-12);
  EXPECT_NEAR(x.frequency_Hz[1] / x.frequency_Hz[0], x.frequency_Hz[39] / x.frequency_Hz[38],
              1e-12);
  EXPECT_EQ(x.phase_rad, same.phase_rad);
  EXPECT_NE(x.phase_rad, other.phase_rad);
  EXPECT_NEAR(other.amplitude_m[7], 0.5 * x.amplitude_m[7], 1e-18);
  // RMS over a long record: √(Σ aᵢ²/2) = 4.09 mm for incommensurate sines.
  double sum = 0.0;
  const int n = 400000;
  for (int k = 0; k < n; ++k) sum += std::pow(x(k * 1e-3), 2);
  EXPECT_NEAR(std::sqrt(sum / n), 0.00409, 0.0001);
}

}  // namespace
}  // namespace ridefit::synthetic
