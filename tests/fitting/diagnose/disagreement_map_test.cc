// The disagreement map against spectra with known differences: a uniform gain, a shifted
// resonance, energy above the band, white and coloured residuals, and bad input.
#include "ridefit/fitting/diagnose/disagreement_map.h"

#include <gtest/gtest.h>

#include <fmt/core.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/biquad_cascade.h"
#include "ridefit/synthetic/gaussian_noise.h"

namespace ridefit::fitting::diagnose {
namespace {

constexpr double kRate_Hz = 200.0;

// White noise through a resonance at f [Hz], damping ratio ζ (the base-excited oscillator).
std::vector<double> resonance(const std::vector<double>& input, double f, double zeta = 0.1) {
  const double w = 2.0 * std::numbers::pi * f;
  const signal::AnalogueSection section{
      {w * w, 2.0 * zeta * w, 0.0}, {w * w, 2.0 * zeta * w, 1.0}, f};
  return signal::BiquadCascade::from_analogue(std::vector{section}, kRate_Hz).filter(input);
}

std::vector<double> noise(unsigned seed, std::size_t n = 60 * 200) {
  std::mt19937_64 rng(seed);
  return synthetic::gaussian_noise(n, 1.0, rng);
}

TEST(DisagreementMap, TwoRealisationsOfOneProcessAgree) {
  const auto measured = resonance(noise(1), 10.0), simulated = resonance(noise(2), 10.0);
  const auto map = map_disagreement({{"acc", measured, simulated}}, kRate_Hz);
  const auto& c = map.channels.front();
  std::size_t flagged = 0;
  for (bool s : c.significant) flagged += s ? 1 : 0;
  // At 99 % each bin is outside by chance 1 % of the time on the measured side alone; the
  // simulated estimate scatters too, so allow a few per cent.
  EXPECT_LT(static_cast<double>(flagged) / static_cast<double>(c.significant.size()), 0.06);
  EXPECT_TRUE(map.regions.empty() || std::abs(map.regions.front().size_dB) < 2.0);
  EXPECT_LT(map.gap_dB, 1.5);  // two χ²_30 estimates differ by ~1 dB RMS
  EXPECT_NEAR(c.measured_peak_Hz, 10.0, 1.0);
}

TEST(DisagreementMap, AUniformGainOfTwoIsSixDecibelsEverywhere) {
  const auto measured = resonance(noise(3), 10.0);
  std::vector<double> simulated = measured;
  for (double& v : simulated) v *= 2.0;
  const auto map = map_disagreement({{"acc", measured, simulated}}, kRate_Hz);
  EXPECT_NEAR(map.gap_dB, 20.0 * std::log10(2.0), 0.01);
  ASSERT_FALSE(map.regions.empty());
  EXPECT_NEAR(map.regions.front().size_dB, 6.02, 0.01);
  EXPECT_LE(map.regions.front().low_Hz, 1.0);
  EXPECT_GE(map.regions.front().high_Hz, 29.0);
  EXPECT_NEAR(map.channels.front().nrmse, 1.0, 1e-9);
}

TEST(DisagreementMap, AShiftedResonanceShowsAsTwoRegionsAndItsPeaks) {
  const auto input = noise(4);
  const auto measured = resonance(input, 24.0), simulated = resonance(input, 21.0);
  const auto map = map_disagreement({{"wheel_acc", measured, simulated}}, kRate_Hz);
  const auto& c = map.channels.front();
  EXPECT_NEAR(c.measured_peak_Hz, 24.0, 0.5);
  EXPECT_NEAR(c.simulated_peak_Hz, 21.0, 0.5);
  bool low_high = false, high_low = false;
  for (const auto& r : map.regions) {
    if (r.size_dB > 0 && r.low_Hz <= 21.0 && r.high_Hz >= 20.0) low_high = true;
    if (r.size_dB < 0 && r.low_Hz <= 25.0 && r.high_Hz >= 24.0) high_low = true;
  }
  EXPECT_TRUE(low_high) << "the simulation is too high around 21 Hz";
  EXPECT_TRUE(high_low) << "and too low around 24 Hz";
}

TEST(DisagreementMap, EnergyAboveTheBandIsFlaggedThere) {
  auto measured = resonance(noise(5), 5.0);
  const auto simulated = measured;
  // Impacts: a short spike every second adds broadband energy.
  for (std::size_t k = 0; k < measured.size(); k += 200) measured[k] += 20.0;
  DisagreementOptions options;
  options.band_high_Hz = 20.0;
  options.above_band_high_Hz = 60.0;
  const auto map = map_disagreement({{"body_acc", measured, simulated}}, kRate_Hz, options);
  const auto& c = map.channels.front();
  EXPECT_GT(c.measured_above_band_share, 3.0 * c.simulated_above_band_share);
  bool above = false;
  for (const auto& r : map.regions) above = above || (r.above_band && r.size_dB < -3.0);
  EXPECT_TRUE(above);
}

TEST(DisagreementMap, WhiteResidualPassesLjungBoxColouredFails) {
  const auto measured = resonance(noise(6), 10.0);
  auto white = measured, coloured = measured;
  const auto e = noise(7);
  const auto low_passed = resonance(noise(8), 3.0);
  for (std::size_t k = 0; k < measured.size(); ++k) {
    white[k] += 0.1 * e[k];
    coloured[k] += 0.1 * low_passed[k];
  }
  const auto w = map_disagreement({{"acc", measured, white}}, kRate_Hz).channels.front();
  const auto c = map_disagreement({{"acc", measured, coloured}}, kRate_Hz).channels.front();
  EXPECT_GT(w.residual_whiteness_p, 0.01);
  EXPECT_LT(w.residual_max_autocorrelation, 0.05);
  EXPECT_LT(c.residual_whiteness_p, 1e-6);
  EXPECT_NEAR(w.amplitude_dependence, 1.0, 0.15);
  // An error that grows with amplitude.
  auto growing = measured;
  double peak = 0.0;
  for (double v : measured) peak = std::max(peak, std::abs(v));
  for (double& v : growing) v *= 1.0 + 0.5 * std::abs(v) / peak;
  const auto g = map_disagreement({{"acc", measured, growing}}, kRate_Hz).channels.front();
  EXPECT_GT(g.amplitude_dependence, 10.0);
}

// Two realisations, the simulated one 1.5 dB higher everywhere: per bin that is half the
// F(ν, ν) interval's half-width (ν ≈ 55), so single bins make no region of it; the pooled
// windows do, and measure it.
TEST(DisagreementMap, AConsistentOnePointFiveDecibelsIsFoundByPooledBins) {
  const auto measured = resonance(noise(20), 10.0);
  auto simulated = resonance(noise(21), 10.0);
  for (double& v : simulated) v *= std::pow(10.0, 1.5 / 20.0);
  DisagreementOptions bins_only;
  bins_only.pooled_max_width_Hz = 0.0;
  bins_only.compare_peaks = false;
  double widest_bins = 0.0;
  for (const auto& r :
       map_disagreement({{"acc", measured, simulated}}, kRate_Hz, bins_only).regions) {
    widest_bins = std::max(widest_bins, r.high_Hz - r.low_Hz);
  }
  EXPECT_LT(widest_bins, 3.0);
  const auto map = map_disagreement({{"acc", measured, simulated}}, kRate_Hz);
  double covered = 0.0, weighted = 0.0;
  for (const auto& r : map.regions) {
    if (r.above_band || r.evidence == RegionEvidence::kPeakShift) continue;
    EXPECT_GT(r.size_dB, 0.0);
    covered += r.high_Hz - r.low_Hz;
    weighted += (r.high_Hz - r.low_Hz) * r.size_dB;
  }
  EXPECT_GT(covered, 15.0);  // of the 29.5 Hz band
  EXPECT_NEAR(weighted / covered, 1.5, 0.5);
}

// Neither the pooled windows nor the peak comparison raise alarms on two realisations of one
// process: a sharp (ζ = 0.1) and a broad (ζ = 0.3, a wheel hop's) resonance, 20 pairs each.
TEST(DisagreementMap, PooledBandsAndPeakShiftsStayQuietOnTwoRealisations) {
  int alarms = 0;
  std::string which;
  for (double zeta : {0.1, 0.3}) {
    for (unsigned seed = 0; seed < 20; ++seed) {
      const auto map = map_disagreement({{"acc", resonance(noise(100 + 2 * seed), 12.0, zeta),
                                          resonance(noise(101 + 2 * seed), 12.0, zeta)}},
                                        kRate_Hz);
      for (const auto& r : map.regions) {
        if (r.evidence != RegionEvidence::kBins) {
          ++alarms;
          which += fmt::format("ζ {} seed {}: {:.1f}–{:.1f} Hz {:+.2f} dB\n", zeta, seed, r.low_Hz,
                               r.high_Hz, r.size_dB);
          break;
        }
      }
    }
  }
  EXPECT_LE(alarms, 2) << which;
}

// A broad mode (ζ = 0.3) at 15 Hz measured and 17 Hz simulated: the ratio stays within a few dB
// on its flanks, but the peaks, each located by its half-power parabola, are further apart
// than they resolve.
TEST(DisagreementMap, AShiftedBroadPeakIsFoundByItsFrequency) {
  const auto measured = resonance(noise(30), 15.0, 0.3),
             simulated = resonance(noise(31), 17.0, 0.3);
  const auto map = map_disagreement({{"wheel_acc", measured, simulated}}, kRate_Hz);
  const auto& peak = map.channels.front().peak;
  EXPECT_TRUE(peak.significant);
  const double shift = peak.simulated.frequency_Hz - peak.measured.frequency_Hz;
  EXPECT_GT(shift, 1.3);
  EXPECT_LT(shift, 2.7);
  EXPECT_LT(peak.threshold_Hz, 1.5);  // a 9 Hz wide mode, located to a fraction of that
  bool region = false;
  for (const auto& r : map.regions) region = region || r.evidence == RegionEvidence::kPeakShift;
  EXPECT_TRUE(region);
}

// The measurement is the response plus white sensor noise that dominates above ~25 Hz; the
// simulation is the response alone (the same input). Without the floor the map reads the noise
// as the model missing energy; with it (the level added) the two agree.
TEST(DisagreementMap, TheNoiseFloorKeepsSensorNoiseFromLookingLikeADisagreement) {
  const auto input = noise(40);
  const auto response = resonance(input, 5.0, 0.2);
  auto measured = response;
  std::mt19937_64 rng(41);
  const double sigma = 0.05;
  const auto sensor = synthetic::gaussian_noise(measured.size(), sigma, rng);
  for (std::size_t k = 0; k < measured.size(); ++k) measured[k] += sensor[k];
  const double level = 2.0 * sigma * sigma / kRate_Hz;
  auto quiet_bins = [](const DisagreementMap& map) {
    double worst = 0.0;
    for (const auto& r : map.regions) worst = std::min(worst, r.size_dB);
    return worst;
  };
  const auto without = map_disagreement({{"body_acc", measured, response}}, kRate_Hz);
  const auto with = map_disagreement({{"body_acc", measured, response, level}}, kRate_Hz);
  EXPECT_LT(quiet_bins(without), -3.0);
  EXPECT_TRUE(with.regions.empty())
      << with.regions.front().low_Hz << " " << with.regions.front().size_dB;
  EXPECT_LT(with.gap_dB, 0.5 * without.gap_dB);
}

TEST(DisagreementMap, BadInputNamesTheChannelOrOption) {
  const auto x = resonance(noise(9), 10.0);
  auto expect_error = [](auto&& call, const std::string& words) {
    try {
      call();
      FAIL() << "no error for " << words;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expect_error([&] { map_disagreement({}, kRate_Hz); }, "at least one channel");
  expect_error(
      [&] {
        map_disagreement({{"wheel_acc", x, std::vector<double>(10, 0.0)}}, kRate_Hz);
      },
      "wheel_acc");
  auto bad = x;
  bad[17] = std::nan("");
  expect_error([&] { map_disagreement({{"body_acc", x, bad}}, kRate_Hz); }, "sample 17");
  DisagreementOptions inverted;
  inverted.band_low_Hz = 30.0;
  inverted.band_high_Hz = 1.0;
  expect_error([&] { map_disagreement({{"acc", x, x}}, kRate_Hz, inverted); }, "band");
  DisagreementOptions long_segment;
  long_segment.segment_s = 1000.0;
  expect_error([&] { map_disagreement({{"acc", x, x}}, kRate_Hz, long_segment); }, "segment");
  DisagreementOptions confidence;
  confidence.confidence = 1.0;
  expect_error([&] { map_disagreement({{"acc", x, x}}, kRate_Hz, confidence); }, "confidence");
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
