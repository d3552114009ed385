// The shape of a spectral disagreement no library effect explains: a panel's resonance, a
// low-pass, a gain or modes shifted along frequency, hidden in a measured-over-simulated ratio
// beside the scatter of two Welch estimates, is named with its channel, frequency and sign; the
// scatter alone names nothing.
#include "ridefit/fitting/diagnose/spectral_shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "support/scatter.h"

namespace ridefit::fitting::diagnose {
namespace {

// A car-like simulated spectrum: body mode 1.2 Hz, wheel mode 11 Hz.
double simulated_psd(double f) {
  auto mode = [](double f_Hz, double f0, double zeta) {
    const double r = f_Hz / f0;
    return 1.0 / ((1.0 - r * r) * (1.0 - r * r) + 4.0 * zeta * zeta * r * r);
  };
  return 0.01 * mode(f, 1.2, 0.3) * mode(f, 11.0, 0.2) * (1.0 + f);
}

// 10·log10(P_meas/P_sim) a channel lacks at f (0 for none).
using Missing = std::function<double(double)>;

// Two channels on 0.25 Hz bins over 0.5–30 Hz; each bin's ratio scatters as two Welch estimates'
// (about 0.8 dB, neighbours correlated at 0.5 as the Hann window makes them), seeded.
DisagreementMap map_of(const Missing& body, const Missing& wheel, unsigned seed) {
  std::mt19937_64 rng(seed);
  const double rho = 0.5;
  std::normal_distribution<double> innovation(0.0, 0.8 * std::sqrt(1.0 - rho * rho));
  DisagreementMap map;
  for (const auto& [name, missing] : {std::pair{"body_acc", body}, std::pair{"wheel_acc", wheel}}) {
    ChannelDisagreement c;
    c.channel = name;
    double scatter = 0.0;
    for (double f = 0.5; f <= 30.0; f += 0.25) {
      scatter = rho * scatter + innovation(rng);
      const double lacking = (missing ? missing(f) : 0.0) + scatter;
      c.frequency_Hz.push_back(f);
      c.simulated_psd.push_back(simulated_psd(f));
      c.measured_psd.push_back(simulated_psd(f) * std::pow(10.0, lacking / 10.0));
      c.ratio_dB.push_back(-lacking);
    }
    map.channels.push_back(c);
  }
  return map;
}

SpectralShape shape_of(const Missing& body, const Missing& wheel, unsigned seed = 1) {
  return spectral_shape(map_of(body, wheel, seed), 0.5, 30.0);
}

TEST(SpectralShape, NamesAPanelResonanceOnItsChannel) {
  // The body accelerometer on a panel: a 12 Hz mode with 8 % damping (the benchmark's outside
  // case).
  const SpectralShape s = shape_of(
      [](double f) {
        const double r = f / 12.0;
        const std::complex<double> d(0.0, 2.0 * 0.08 * r);
        return 10.0 * std::log10(std::norm((1.0 + d) / (1.0 - r * r + d)));
      },
      {});
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "resonance") << describe(s);
  EXPECT_EQ(s.terms[0].channel, "body_acc");
  EXPECT_GT(s.terms[0].frequency_Hz, 12.0 / std::exp2(1.0 / 6.0)) << describe(s);
  EXPECT_LT(s.terms[0].frequency_Hz, 12.0 * std::exp2(1.0 / 6.0)) << describe(s);
  // A ζ = 0.08 mount is a little sharper than the dictionary's ζ = 0.1: about 1.1 of its shape.
  EXPECT_NEAR(s.terms[0].coefficient, 1.15, 0.15) << describe(s);
}

// An absorber's notch at one of the dictionary's frequencies (0.5 Hz · 2^(21/6) = 5.66 Hz): its
// shape, negated, is found exactly.
constexpr double kOnTheGrid_Hz = 5.656854249492381;

TEST(SpectralShape, NamesAnAntiresonanceBySign) {
  const SpectralShape s = shape_of({}, [](double f) {
    const double r = f / 6.0;
    const std::complex<double> d(0.0, 2.0 * 0.1 * r);
    return -10.0 * std::log10(std::norm((1.0 + d) / (1.0 - r * r + d)));
  });
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "resonance") << describe(s);
  EXPECT_EQ(s.terms[0].channel, "wheel_acc");
  EXPECT_NEAR(s.terms[0].frequency_Hz, kOnTheGrid_Hz, 1e-9) << describe(s);
  EXPECT_NEAR(s.terms[0].coefficient, -1.0, 0.1) << describe(s);
  EXPECT_NE(s.terms[0].words.find("antiresonance"), std::string::npos) << s.terms[0].words;
}

TEST(SpectralShape, NamesALowPassWithItsCorner) {
  const SpectralShape s =
      shape_of({}, [](double f) { return -10.0 * std::log10(1.0 + (f / 8.0) * (f / 8.0)); });
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "low_pass") << describe(s);
  EXPECT_EQ(s.terms[0].channel, "wheel_acc");
  EXPECT_NEAR(std::log2(s.terms[0].frequency_Hz / 8.0), 0.0, 0.25) << describe(s);
  EXPECT_NEAR(s.terms[0].coefficient, 1.0, 0.06) << describe(s);
}

TEST(SpectralShape, NamesAGainAsALevel) {
  const double gain_dB = 20.0 * std::log10(1.2);
  const SpectralShape s = shape_of([&](double) { return gain_dB; }, {});
  ASSERT_FALSE(s.terms.empty());
  EXPECT_EQ(s.terms[0].id, "level") << describe(s);
  EXPECT_NEAR(s.terms[0].coefficient, gain_dB, 0.4) << describe(s);
}

TEST(SpectralShape, NamesModesShiftedAlongFrequency) {
  // The car's modes 6 % higher, then 6 % lower, than the model's: P_meas(f) = P_sim(f / 1.06).
  for (const double shift : {1.06, 1.0 / 1.06}) {
    const Missing moved = [&](double f) {
      return 10.0 * std::log10(simulated_psd(f / shift) / simulated_psd(f));
    };
    const SpectralShape s = shape_of(moved, moved);
    ASSERT_FALSE(s.terms.empty());
    EXPECT_EQ(s.terms[0].id, "frequency_shift") << describe(s);
    EXPECT_NEAR(s.terms[0].coefficient, shift - 1.0, 0.012) << describe(s);
    EXPECT_NE(s.terms[0].words.find(shift > 1.0 ? "higher" : "lower"), std::string::npos)
        << s.terms[0].words;
    EXPECT_NE(coefficient_text(s.terms[0]).find(" %"), std::string::npos);
  }
}

// The level's standard error says how far it scatters over 60 seeds (bins correlated at 0.5):
// the level is named first in at least 50 of them, and over those spread and mean reported error
// agree within a third.
TEST(SpectralShape, StandardErrorsMatchTheScatter) {
  const double gain_dB = 20.0 * std::log10(1.2);
  std::vector<double> level, error;
  for (unsigned seed = 0; seed < 60; ++seed) {
    const SpectralShape s = shape_of([&](double) { return gain_dB; }, {}, 300 + seed);
    if (s.terms.empty() || s.terms[0].id != "level") continue;
    level.push_back(s.terms[0].coefficient);
    error.push_back(s.terms[0].standard_error);
  }
  EXPECT_GE(level.size(), 50u);
  ASSERT_GE(level.size(), 10u);
  EXPECT_NEAR(testing::spread_over_reported_error(level, error), 1.0, 1.0 / 3.0);
}

TEST(SpectralShape, NamesNothingInTheEstimatesScatter) {
  int quiet = 0;
  for (unsigned seed = 0; seed < 40; ++seed) {
    if (shape_of({}, {}, 100 + seed).terms.empty()) ++quiet;
  }
  EXPECT_GE(quiet, 38);
}

TEST(SpectralShape, RefusesABadBand) {
  const DisagreementMap map = map_of({}, {}, 1);
  EXPECT_THROW(spectral_shape(map, 0.0, 30.0), InputError);
  EXPECT_THROW(spectral_shape(map, 30.0, 5.0), InputError);
  SparseSelectionOptions options;
  options.min_share = 0.0;
  EXPECT_THROW(spectral_shape(map, 0.5, 30.0, options), InputError);
}

}  // namespace
}  // namespace ridefit::fitting::diagnose
