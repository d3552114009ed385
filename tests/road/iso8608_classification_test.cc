#include "ridefit/road/iso8608_classification.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ridefit/common/errors.h"
#include "ridefit/road/random_profile.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

RoadProfile class_profile(Iso8608Class road_class, double length_m, double spacing_m,
                          std::uint64_t seed) {
  const PowerLawSpectrum spectrum = iso8608_spectrum(road_class);
  const RandomProfile raw = random_profile([&](double n) { return spectrum.psd_m3(n); },
                                           SpatialBand{}, length_m, spacing_m, seed);
  RoadProfile profile;
  profile.elevation_m = raw.elevation_m;
  for (std::size_t k = 0; k < raw.elevation_m.size(); ++k) {
    profile.distance_m.push_back(static_cast<double>(k) * spacing_m);
  }
  return profile;
}

TEST(Iso8608ClassOf, BoundariesAreAFactorTwoAroundTheReference) {
  EXPECT_EQ(iso8608_class_of(31.9e-6), Iso8608Class::kA);
  EXPECT_EQ(iso8608_class_of(32.1e-6), Iso8608Class::kB);
  EXPECT_EQ(iso8608_class_of(127e-6), Iso8608Class::kB);
  EXPECT_EQ(iso8608_class_of(129e-6), Iso8608Class::kC);
  EXPECT_EQ(iso8608_class_of(1e-9), Iso8608Class::kA);
  EXPECT_EQ(iso8608_class_of(1.0), Iso8608Class::kH);
}

class Iso8608ClassificationOfClass : public ::testing::TestWithParam<int> {};

TEST_P(Iso8608ClassificationOfClass, GeneratedProfileComesBackInItsClass) {
  const auto road_class = static_cast<Iso8608Class>(GetParam());
  const RoadProfile profile = class_profile(road_class, 2000.0, 0.05, 7 + GetParam());
  const Iso8608Classification result = classify_iso8608(profile);
  const double reference = iso8608_reference_psd_m3(road_class);
  EXPECT_EQ(to_char(result.road_class), to_char(road_class));
  // 2 km at 5 cm: Gd(n0) within 5 % (measured 0.981–0.996 of the class's reference for A–E),
  // the free fit's within 6 % (0.985–1.032) and its waviness within 0.05 of 2 (2.000–2.016).
  EXPECT_NEAR(result.reference_psd_m3 / reference, 1.0, 0.05);
  EXPECT_NEAR(result.waviness, 2.0, 0.05);
  EXPECT_NEAR(result.free_fit_reference_psd_m3 / reference, 1.0, 0.06);
  EXPECT_DOUBLE_EQ(result.segment_length_m, 100.0);
  EXPECT_DOUBLE_EQ(result.band_low_cycles_per_m, 0.011);
  EXPECT_DOUBLE_EQ(result.band_high_cycles_per_m, 2.83);
  EXPECT_GT(result.fit_bins, 250U);
  ASSERT_EQ(result.psd_m3.size(), result.spatial_frequency_cycles_per_m.size());
  ASSERT_EQ(result.psd_lower_m3.size(), result.psd_m3.size());
  // The PSD at n0 (bin 10) lies in its confidence interval, which is on the right side of it.
  EXPECT_NEAR(result.spatial_frequency_cycles_per_m[10], 0.1, 1e-12);
  EXPECT_LT(result.psd_lower_m3[10], result.psd_m3[10]);
  EXPECT_GT(result.psd_upper_m3[10], result.psd_m3[10]);
}

INSTANTIATE_TEST_SUITE_P(ClassesAToE, Iso8608ClassificationOfClass, ::testing::Range(0, 5));

TEST(Iso8608Classification, ShortOrCoarseProfileNarrowsTheBand) {
  // 200 m at 0.25 m: segments of 50 m resolve 0.02 … 2 cycles/m.
  RoadProfile profile = class_profile(Iso8608Class::kC, 200.0, 0.05, 3);
  RoadProfile coarse;
  for (std::size_t k = 0; k < profile.distance_m.size(); k += 5) {
    coarse.distance_m.push_back(profile.distance_m[k]);
    coarse.elevation_m.push_back(profile.elevation_m[k]);
  }
  const Iso8608Classification result = classify_iso8608(coarse);
  EXPECT_NEAR(result.segment_length_m, 50.0, 1e-9);
  EXPECT_NEAR(result.band_low_cycles_per_m, 0.02, 1e-12);
  EXPECT_NEAR(result.band_high_cycles_per_m, 2.0, 1e-12);
  EXPECT_EQ(to_char(result.road_class), 'C');
}

TEST(Iso8608Classification, BadInputIsAnInputError) {
  const RoadProfile profile = class_profile(Iso8608Class::kB, 200.0, 0.05, 3);
  Iso8608ClassificationOptions options;
  options.segment_length_m = 500.0;
  const std::string message =
      ridefit::testing::input_error_message([&] { classify_iso8608(profile, options); });
  EXPECT_NE(message.find("longer than the profile"), std::string::npos) << message;
  const RoadProfile coarse{{0.0, 10.0, 20.0, 30.0, 40.0}, {0.0, 0.01, 0.0, 0.01, 0.0}};
  EXPECT_NE(ridefit::testing::input_error_message([&] {
              classify_iso8608(coarse);
            }).find("too short or too coarse"),
            std::string::npos);
  RoadProfile reversed = profile;
  reversed.distance_m[5] = reversed.distance_m[3];
  EXPECT_NE(
      ridefit::testing::input_error_message([&] { classify_iso8608(reversed); }).find("sample 5"),
      std::string::npos);
}

}  // namespace
}  // namespace ridefit::road
