#include "ridefit/comfort/impact_hardness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "support/throws_input_error.h"

namespace ridefit::comfort {
namespace {

using testing::throws_input_error;

constexpr double kPi = std::numbers::pi;
constexpr double kRate_Hz = 10000.0;
constexpr std::size_t kLead = 500;   // 0.05 s of quiet lead-in
constexpr std::size_t kLobe = 1000;  // half-waves of h = 0.1 s (5 Hz)

// A decaying obstacle response built from half-sine lobes of the given signed amplitudes,
// A·sin(π k/kLobe) each, after kLead zeros and followed by 0.1 s of zeros. Lobe j's peak
// is its middle sample, kLead + j·kLobe + kLobe/2, with value A_j exactly.
std::vector<double> lobes(const std::vector<double>& amplitudes) {
  std::vector<double> a(kLead, 0.0);
  for (double amplitude : amplitudes) {
    for (std::size_t k = 0; k < kLobe; ++k) {
      a.push_back(amplitude * std::sin(kPi * static_cast<double>(k) / kLobe));
    }
  }
  a.resize(a.size() + 1000, 0.0);
  return a;
}

constexpr std::size_t middle_of_lobe(std::size_t j) { return kLead + j * kLobe + kLobe / 2; }

// Hand values for lobes {2, −3, 1.5, −1, 0.5}, max |a| = 3:
// - onset threshold 0.05·3 = 0.15: 2·sin(πk/1000) ≥ 0.15 from k = ceil(1000·asin(0.075)/π)
//   = ceil(23.896) = 24, sample 524, t = 0.0524 s;
// - peaks +2 at 0.1 s, −3 at 0.2 s, (+1.5 at 0.3 s), −1 at 0.4 s; P2P = 2 + 3 = 5;
// - RMS from the onset (τ = 2.4 ms into lobe 1) to the middle of lobe 4:
//   ∫a² = h·(2² + 3² + 1.5²)/2 + h·1²/4 − 2²·(τ/2 − h·sin(2πτ/h)/(4π)) = 0.787482,
//   over 3.5h − τ = 0.3476 s: RMS = sqrt(2.26548) = 1.50515 (1.5 exactly without the
//   onset's 2.4 ms); the samples give 1.50498.
const std::vector<double> kAmplitudes{2.0, -3.0, 1.5, -1.0, 0.5};

TEST(ImpactHardness, TwoPeakPulseByHand) {
  const auto a = lobes(kAmplitudes);
  const ImpactHardness h = impact_hardness(a, kRate_Hz);
  EXPECT_EQ(h.onset_index, 524u);
  EXPECT_NEAR(h.onset_time_s, 0.0524, 1e-12);
  EXPECT_EQ(h.first_positive_peak.index, middle_of_lobe(0));
  EXPECT_NEAR(h.first_positive_peak.time_s, 0.1, 1e-12);
  EXPECT_NEAR(h.first_positive_peak.value, 2.0, 1e-12);
  EXPECT_EQ(h.first_negative_peak.index, middle_of_lobe(1));
  EXPECT_NEAR(h.first_negative_peak.value, -3.0, 1e-12);
  EXPECT_EQ(h.second_negative_peak.index, middle_of_lobe(3));
  EXPECT_NEAR(h.second_negative_peak.time_s, 0.4, 1e-12);
  EXPECT_NEAR(h.second_negative_peak.value, -1.0, 1e-12);
  EXPECT_NEAR(h.peak_to_peak, 5.0, 1e-12);
  EXPECT_NEAR(h.rms, 1.50515, 5e-4);
}

TEST(ImpactHardness, NoiseAndSmallWigglesAreNotPeaks) {
  // Seeded noise (σ = 0.01) everywhere and a 0.1-amplitude 50 Hz ripple on the first two
  // lobes: local extrema with swings under δ = 0.3 that must not count as peaks.
  auto a = lobes(kAmplitudes);
  std::mt19937_64 rng(20240607);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] += noise(rng);
    if (i >= kLead && i < kLead + 2 * kLobe) {
      a[i] += 0.1 * std::sin(2.0 * kPi * 50.0 * static_cast<double>(i - kLead) / kRate_Hz);
    }
  }
  const ImpactHardness h = impact_hardness(a, kRate_Hz);
  // The ripple moves the peaks by up to 0.1 and some ms; the noise by a few σ.
  EXPECT_NEAR(h.first_positive_peak.value, 2.0, 0.15);
  EXPECT_NEAR(h.first_positive_peak.time_s, 0.1, 0.006);
  EXPECT_NEAR(h.first_negative_peak.value, -3.0, 0.15);
  EXPECT_NEAR(h.first_negative_peak.time_s, 0.2, 0.006);
  EXPECT_NEAR(h.second_negative_peak.value, -1.0, 0.05);
  EXPECT_NEAR(h.second_negative_peak.time_s, 0.4, 0.01);
  EXPECT_NEAR(h.peak_to_peak, 5.0, 0.25);
  EXPECT_NEAR(h.rms, 1.505, 0.01);
}

TEST(ImpactHardness, NegativeFirstLobeStartsTheSequenceAtTheFirstPositiveLobe) {
  // Mirrored: −2, +3, −1.5, +1, −0.5. Peaks +3 (0.2 s), −1.5 (0.3 s), −0.5 (0.5 s).
  std::vector<double> mirrored;
  for (double amplitude : kAmplitudes) mirrored.push_back(-amplitude);
  const ImpactHardness h = impact_hardness(lobes(mirrored), kRate_Hz);
  EXPECT_EQ(h.onset_index, 524u);
  EXPECT_EQ(h.first_positive_peak.index, middle_of_lobe(1));
  EXPECT_EQ(h.first_negative_peak.index, middle_of_lobe(2));
  EXPECT_EQ(h.second_negative_peak.index, middle_of_lobe(4));
  EXPECT_NEAR(h.peak_to_peak, 4.5, 1e-12);
}

TEST(ImpactHardness, RecordsWithoutAnObstacleResponseThrow) {
  EXPECT_TRUE(throws_input_error([&] { impact_hardness(std::vector<double>(100, 0.0), kRate_Hz); },
                                 "zero everywhere"));
  // Ends after the second positive lobe: no second negative peak.
  EXPECT_TRUE(throws_input_error(
      [&] {
        impact_hardness(lobes({2.0, -3.0, 1.5}), kRate_Hz);
      },
      "no second negative peak"));
  // A second negative lobe too small to be a peak (0.2 < δ = 0.3).
  EXPECT_TRUE(throws_input_error(
      [&] {
        impact_hardness(lobes({2.0, -3.0, 1.5, -0.2}), kRate_Hz);
      },
      "no second negative peak"));
  // One positive bump only.
  EXPECT_TRUE(throws_input_error([&] { impact_hardness(lobes({2.0}), kRate_Hz); },
                                 "no first negative peak"));
  // One negative bump only.
  EXPECT_TRUE(throws_input_error([&] { impact_hardness(lobes({-2.0}), kRate_Hz); },
                                 "no first positive peak"));
  // Starts inside the first lobe: no lead-in.
  const auto a = lobes(kAmplitudes);
  const std::vector<double> late(a.begin() + 700, a.end());
  EXPECT_TRUE(throws_input_error([&] { impact_hardness(late, kRate_Hz); },
                                 "the record must start before the obstacle"));
}

TEST(ImpactHardness, BadInputThrowsWithAMessageNamingTheProblem) {
  auto a = lobes(kAmplitudes);
  EXPECT_TRUE(throws_input_error([&] { impact_hardness(a, -1.0); }, "sample rate -1 Hz"));
  ImpactHardnessOptions options;
  options.onset_fraction = 1.5;
  EXPECT_TRUE(
      throws_input_error([&] { impact_hardness(a, kRate_Hz, options); }, "onset_fraction is 1.5"));
  options = {};
  options.prominence_fraction = 0.0;
  EXPECT_TRUE(throws_input_error([&] { impact_hardness(a, kRate_Hz, options); },
                                 "prominence_fraction is 0"));
  a[1234] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(throws_input_error([&] { impact_hardness(a, kRate_Hz); }, "sample 1234 is nan"));
  EXPECT_TRUE(throws_input_error(
      [&] {
        impact_hardness(std::vector<double>{1.0, 2.0}, kRate_Hz);
      },
      "at least 3"));
}

}  // namespace
}  // namespace ridefit::comfort
