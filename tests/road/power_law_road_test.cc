#include "ridefit/road/power_law_road.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ridefit/common/errors.h"
#include "ridefit/road/iso8608.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

// ∫ G dn by the trapezoidal rule on a fine logarithmic grid.
double numeric_band_variance(const PowerLawSpectrum& s, const SpatialBand& band) {
  const int steps = 200000;
  const double r = std::log(band.high_cycles_per_m / band.low_cycles_per_m) / steps;
  double sum = 0.0;
  for (int i = 0; i < steps; ++i) {
    const double a = band.low_cycles_per_m * std::exp(r * i);
    const double b = band.low_cycles_per_m * std::exp(r * (i + 1));
    sum += 0.5 * (s.psd_m3(a) + s.psd_m3(b)) * (b - a);
  }
  return sum;
}

TEST(RoadPowerLaw, CrIsThePsdAtOneCyclePerMetre) {
  PowerLawRoadParameters p;
  p.roughness_coefficient_m3 = kSeed001GravelHighwayCr_m3;
  p.waviness = kSeed001Waviness;
  const PowerLawSpectrum s = p.spectrum();
  EXPECT_DOUBLE_EQ(s.psd_m3(1.0), 4.4e-6);
  EXPECT_NEAR(s.psd_m3(0.5), 4.4e-6 * std::pow(0.5, -2.1), 1e-18);
}

TEST(RoadPowerLaw, SeedRoadsLandInTheIsoClassesTheirNamesSuggest) {
  auto at_n0 = [](double cr) { return PowerLawSpectrum{1.0, cr, kSeed001Waviness}.psd_m3(0.1); };
  // ISO 8608 class limits at n0 = 0.1 cycles/m: B is 32e-6..128e-6, D is 256e-6..1024e-6.
  EXPECT_NEAR(at_n0(kSeed001SmoothHighwayCr_m3), 6.043e-5, 1e-8);
  EXPECT_GT(at_n0(kSeed001SmoothHighwayCr_m3), 32e-6);
  EXPECT_LT(at_n0(kSeed001SmoothHighwayCr_m3), 128e-6);
  EXPECT_GT(at_n0(kSeed001GravelHighwayCr_m3), 256e-6);
  EXPECT_LT(at_n0(kSeed001GravelHighwayCr_m3), 1024e-6);
  EXPECT_GT(at_n0(kSeed001SuburbanRoadCr_m3), 256e-6);
  EXPECT_LT(at_n0(kSeed001SuburbanRoadCr_m3), 1100e-6);
}

TEST(RoadPowerLaw, BandVarianceClosedFormMatchesIntegration) {
  const SpatialBand band{0.011, 2.83};
  for (double w : {2.1, 2.0, 1.0, 1.5, 3.0}) {
    const PowerLawSpectrum s{1.0, 4.8e-7, w};
    EXPECT_NEAR(s.band_variance_m2(band) / numeric_band_variance(s, band), 1.0, 1e-8) << w;
  }
  const PowerLawSpectrum iso{0.1, 16e-6, 2.0};
  EXPECT_NEAR(iso.band_variance_m2(band) / numeric_band_variance(iso, band), 1.0, 1e-8);
}

TEST(RoadPowerLaw, SharesTheHarmonicMachineryWithIso8608) {
  // Cr = Gd(n0)·n0² and α = 2 is ISO class A: the same seed gives the same road.
  RandomRoadParameters random;
  random.duration_s = 30.0;
  random.seed = 4;
  PowerLawRoadParameters power;
  power.roughness_coefficient_m3 = 16e-6 * 0.1 * 0.1;
  power.waviness = 2.0;
  power.random = random;
  const SpatialProfileRoad a = make_power_law_road(power);
  const SpatialProfileRoad b = make_iso8608_road({Iso8608Class::kA, random});
  for (double t : {0.0, 0.4, 3.3, 17.0, 29.9}) {
    EXPECT_NEAR(a.at(t).elevation_m, b.at(t).elevation_m, 1e-15) << t;
    EXPECT_NEAR(a.at(t).rate_m_per_s, b.at(t).rate_m_per_s, 1e-13) << t;
  }
}

TEST(RoadPowerLaw, InvalidParametersNameTheKey) {
  auto message = [](const PowerLawRoadParameters& p) {
    return testing::input_error_message([&] { make_power_law_road(p); });
  };
  PowerLawRoadParameters p;
  p.roughness_coefficient_m3 = -1.0;
  EXPECT_NE(message(p).find("'roughness_coefficient_m3'"), std::string::npos);
  p = {};
  p.waviness = 21.0;
  EXPECT_NE(message(p).find("'waviness'"), std::string::npos);
  p = {};
  p.random.duration_s = 0.0;
  EXPECT_NE(message(p).find("'duration_s'"), std::string::npos);
}

TEST(RoadPowerLaw, MaxStepIsTheSampleSpacingInTime) {
  PowerLawRoadParameters p;
  p.random.speed_m_per_s = 25.0;
  p.random.duration_s = 5.0;
  p.random.sample_spacing_m = 0.02;
  const SpatialProfileRoad road = make_power_law_road(p);
  EXPECT_GT(road.max_step_s(), 0.0);
  EXPECT_TRUE(std::isfinite(road.max_step_s()));
  EXPECT_DOUBLE_EQ(road.max_step_s(), 0.02 / 25.0);
  // A rear wheel shares the profile and so the step.
  EXPECT_DOUBLE_EQ(road.with_offset(-2.7).max_step_s(), 0.02 / 25.0);
}

TEST(RoadPowerLaw, HugeRoadsAreInputErrors) {
  PowerLawRoadParameters p;
  p.random.speed_m_per_s = 100.0;
  p.random.duration_s = 1e6;
  try {
    make_power_law_road(p);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'duration_s'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ridefit::road
