#include "ridefit/road/iso8608.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

constexpr Iso8608Class kClasses[] = {Iso8608Class::kA, Iso8608Class::kB, Iso8608Class::kC,
                                     Iso8608Class::kD, Iso8608Class::kE, Iso8608Class::kF,
                                     Iso8608Class::kG, Iso8608Class::kH};

double rms(const std::vector<double>& h) {
  double s = 0.0;
  for (double v : h) s += v * v;
  return std::sqrt(s / static_cast<double>(h.size()));
}

TEST(RoadIso8608, ClassLevelsAreTheStandardsGeometricMeans) {
  const double expected_m3[] = {16e-6,   64e-6,    256e-6,   1024e-6,
                                4096e-6, 16384e-6, 65536e-6, 262144e-6};
  for (int i = 0; i < 8; ++i) {
    EXPECT_NEAR(iso8608_reference_psd_m3(kClasses[i]), expected_m3[i], 1e-18 * (1 << (2 * i)));
    EXPECT_EQ(to_char(kClasses[i]), static_cast<char>('A' + i));
    EXPECT_EQ(parse_iso8608_class(std::string(1, static_cast<char>('A' + i))), kClasses[i]);
  }
  const PowerLawSpectrum a = iso8608_spectrum(Iso8608Class::kA);
  EXPECT_DOUBLE_EQ(a.psd_m3(0.1), 16e-6);
  EXPECT_DOUBLE_EQ(a.psd_m3(0.2), 4e-6);  // (n/n0)^-2
  EXPECT_DOUBLE_EQ(a.psd_m3(1.0), 16e-8);
  EXPECT_THROW(parse_iso8608_class("I"), InputError);
  EXPECT_THROW(parse_iso8608_class("a"), InputError);
  EXPECT_THROW(parse_iso8608_class("AB"), InputError);
}

TEST(RoadIso8608, BandRmsOfClassAIsTheClosedForm) {
  // ∫ 16e-6·(n/0.1)^-2 dn from 0.011 to 2.83 = 1.6e-7·(1/0.011 − 1/2.83) = 1.448892e-5 m².
  const PowerLawSpectrum a = iso8608_spectrum(Iso8608Class::kA);
  EXPECT_NEAR(a.band_variance_m2(SpatialBand{}), 1.448892e-5, 1e-11);
  EXPECT_NEAR(a.band_rms_m(SpatialBand{}), 3.80643e-3, 1e-8);
}

TEST(RoadIso8608, EachClassDoublesTheRms) {
  RandomRoadParameters random;
  random.duration_s = 20.0;
  random.fade_in_m = 0.0;
  double previous_band = 0.0;
  double previous_road = 0.0;
  for (Iso8608Class c : kClasses) {
    const double band = iso8608_spectrum(c).band_rms_m(random.band);
    const SpatialProfileRoad road = make_iso8608_road({c, random});
    std::vector<double> h;
    for (double t = 0.0; t < 20.0; t += 0.001) h.push_back(road.at(t).elevation_m);
    const double road_rms = rms(h);
    if (previous_band > 0.0) {
      EXPECT_NEAR(band / previous_band, 2.0, 1e-12) << to_char(c);
      // Same seed, same phases: the profile itself scales by exactly 2.
      EXPECT_NEAR(road_rms / previous_road, 2.0, 1e-9) << to_char(c);
    }
    previous_band = band;
    previous_road = road_rms;
  }
}

TEST(RoadIso8608, RoadFollowsTheSampledProfileAtTheSpeedAfterItsFadeIn) {
  Iso8608RoadParameters p;
  p.road_class = Iso8608Class::kC;
  p.random.speed_m_per_s = 50.0 / 3.6;
  p.random.duration_s = 60.0;
  p.random.seed = 9;
  const SpatialProfileRoad road = make_iso8608_road(p);
  EXPECT_DOUBLE_EQ(road.duration_s(), 60.0);
  const PowerLawSpectrum spectrum = iso8608_spectrum(p.road_class);
  const RandomProfile raw = random_profile([&](double n) { return spectrum.psd_m3(n); },
                                           p.random.band, 60.0 * 50.0 / 3.6, 0.05, 9);
  const double v = p.random.speed_m_per_s;
  for (std::size_t k = 100; k < raw.elevation_m.size(); k += 997) {  // beyond the 5 m fade-in
    const double t = 0.05 * static_cast<double>(k) / v;
    EXPECT_NEAR(road.at(t).elevation_m, raw.elevation_m[k], 1e-12) << k;
  }
  // Faded in: starts flat at 0 and never exceeds the raw profile inside the fade.
  EXPECT_EQ(road.at(0.0).elevation_m, 0.0);
  EXPECT_NEAR(road.at(0.0).rate_m_per_s, 0.0, 1e-15);
  EXPECT_NEAR(road.at(-1.0).rate_m_per_s, 0.0, 1e-15);
  for (std::size_t k = 0; k < 100; ++k) {
    EXPECT_LE(std::abs(road.at(0.05 * static_cast<double>(k) / v).elevation_m),
              std::abs(raw.elevation_m[k]) + 1e-15);
  }
}

TEST(RoadIso8608, ARearWheelSeesTheFrontWheelsRoadAWheelbaseLater) {
  Iso8608RoadParameters p;
  p.random.speed_m_per_s = 20.0;
  p.random.duration_s = 10.0;
  const SpatialProfileRoad front = make_iso8608_road(p);
  const double wheelbase_m = 2.79;
  const SpatialProfileRoad rear = front.with_offset(-wheelbase_m);
  for (double t : {0.3, 2.0, 7.5}) {
    const RoadSample f = front.at(t);
    const RoadSample r = rear.at(t + wheelbase_m / 20.0);
    EXPECT_NEAR(r.elevation_m, f.elevation_m, 1e-12) << t;
    EXPECT_NEAR(r.rate_m_per_s, f.rate_m_per_s, 1e-9) << t;
  }
  EXPECT_EQ(rear.at(0.0).elevation_m, 0.0);  // still behind the start
}

TEST(RoadIso8608, InvalidSettingsNameTheKey) {
  auto message = [](const Iso8608RoadParameters& p) {
    return testing::input_error_message([&] { make_iso8608_road(p); });
  };
  Iso8608RoadParameters p;
  p.random.speed_m_per_s = 0.0;
  EXPECT_NE(message(p).find("'speed_m_per_s'"), std::string::npos);
  p = {};
  p.random.sample_spacing_m = 0.2;
  EXPECT_NE(message(p).find("'sample_spacing_m'"), std::string::npos);
  p = {};
  p.random.fade_in_m = -1.0;
  EXPECT_NE(message(p).find("'fade_in_m'"), std::string::npos);
  p = {};
  p.random.band.high_cycles_per_m = 0.001;
  EXPECT_NE(message(p).find("'band_high_cycles_per_m'"), std::string::npos);
}

TEST(RoadIso8608, MaxStepIsTheSampleSpacingInTime) {
  Iso8608RoadParameters p;
  p.random.speed_m_per_s = 20.0;
  p.random.duration_s = 10.0;
  p.random.sample_spacing_m = 0.04;
  const SpatialProfileRoad road = make_iso8608_road(p);
  EXPECT_GT(road.max_step_s(), 0.0);
  EXPECT_TRUE(std::isfinite(road.max_step_s()));
  EXPECT_DOUBLE_EQ(road.max_step_s(), 0.04 / 20.0);
}

TEST(RoadIso8608, SettingsThatWouldExhaustMemoryOrStarveTheSplineAreInputErrors) {
  auto message = [](const Iso8608RoadParameters& p) {
    return testing::input_error_message([&] { make_iso8608_road(p); });
  };
  auto expect_in = [](const std::string& text, const std::vector<std::string>& fragments) {
    for (const auto& f : fragments) EXPECT_NE(text.find(f), std::string::npos) << f << ": " << text;
  };
  Iso8608RoadParameters p;
  p.random.duration_s = 1e9;  // std::bad_alloc before
  EXPECT_THROW(make_iso8608_road(p), InputError);
  expect_in(message(p), {"'duration_s'", "'speed_m_per_s'", "'sample_spacing_m'", "samples"});
  p = {};
  p.random.sample_spacing_m = 1e-9;
  expect_in(message(p), {"'sample_spacing_m'", "more than 2e+07"});
  p = {};
  p.random.band.low_cycles_per_m = 1e-9;  // an FFT of 1.6e11 points
  expect_in(message(p), {"'band_low_cycles_per_m'"});
  p = {};
  p.random.speed_m_per_s = 1e-6;  // 10 µm of road: 2 samples, the spline needs 5
  p.random.duration_s = 10.0;
  EXPECT_THROW(make_iso8608_road(p), InputError);
  expect_in(message(p), {"'speed_m_per_s'", "'duration_s'", "at least 5 samples"});
  p = {};
  p.random.speed_m_per_s = 1e6;  // 8 GB
  expect_in(message(p), {"'speed_m_per_s'", "150 m/s"});
  p = {};
  p.random.speed_m_per_s = 150.0;  // the limit itself is fine
  p.random.duration_s = 1.0;
  EXPECT_NO_THROW(make_iso8608_road(p));
  p = {};
  p.random.speed_m_per_s = 1.0;
  p.random.duration_s = 2.0;
  p.random.fade_in_m = 5.0;  // longer than the 2 m of road
  expect_in(message(p), {"'fade_in_m'", "2 m"});
  p.random.fade_in_m = 2.0;  // exactly the road is fine
  EXPECT_NO_THROW(make_iso8608_road(p));
  p = {};
  p.random.duration_s = 1e-4;
  expect_in(message(p), {"'duration_s'"});
}

}  // namespace
}  // namespace ridefit::road
