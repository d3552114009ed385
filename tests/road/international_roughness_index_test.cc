#include "ridefit/road/international_roughness_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <tuple>

#include "ridefit/common/errors.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/random_profile.h"
#include "support/input_error_message.h"

namespace ridefit::road {
namespace {

using std::numbers::pi;

RoadProfile sampled(double length_m, double spacing_m, const auto& elevation) {
  RoadProfile profile;
  const auto count = static_cast<std::size_t>(std::round(length_m / spacing_m)) + 1;
  for (std::size_t k = 0; k < count; ++k) {
    const double x = static_cast<double>(k) * spacing_m;
    profile.distance_m.push_back(x);
    profile.elevation_m.push_back(elevation(x));
  }
  return profile;
}

// The golden car's steady response to y = a·sin(2πx/L): with H(jω) = (Z_s − Z_u)/Y from
//   (s² + cs + k2)·Z_s − (cs + k2)·Z_u = 0,
//   −(cs + k2)·Z_s + (μs² + cs + k2 + k1)·Z_u = k1·Y,
// the suspension velocity has amplitude |H(jω)|·ω·a·g at ω = 2πV/L, where g =
// sin(πb/L)/(πb/L) is the gain of the b = 0.25 m moving average, and its mean absolute value
// is 2/π of that. IRI = that mean / V, ×1000 for m/km.
double closed_form_iri_m_per_km(double amplitude_m, double wavelength_m) {
  const GoldenQuarterCar car;
  const double omega = 2.0 * pi * car.speed_m_per_s / wavelength_m;
  const std::complex<double> s(0.0, omega);
  const std::complex<double> a11 = s * s + car.damping * s + car.suspension_stiffness;
  const std::complex<double> a12 = -(car.damping * s + car.suspension_stiffness);
  const std::complex<double> a22 = car.unsprung_mass_ratio * s * s + car.damping * s +
                                   car.suspension_stiffness + car.tyre_stiffness;
  const std::complex<double> det = a11 * a22 - a12 * a12;
  const std::complex<double> zs = -a12 * car.tyre_stiffness / det;  // per unit Y
  const std::complex<double> zu = a11 * car.tyre_stiffness / det;
  const double arg = pi * 0.25 / wavelength_m;
  const double gain = std::sin(arg) / arg;
  return 1000.0 * (2.0 / pi) * std::abs(zs - zu) * omega * amplitude_m * gain / car.speed_m_per_s;
}

class IriOfSinusoid : public ::testing::TestWithParam<std::tuple<double, double>> {};

// The slope of each step is held over the step (E1926's zero-order hold), which multiplies the
// fundamental by a further sin(π·dx/L)/(π·dx/L): 1.8 % at dx = 0.25 m and L = 2.4 m, 0.01 % at
// dx = 0.05 m.
TEST_P(IriOfSinusoid, EqualsTheGoldenCarSteadyStateResponse) {
  const double wavelength = std::get<0>(GetParam());  // (Clang 14: no structured binding in a
  const double spacing = std::get<1>(GetParam());     // lambda's capture)
  const double amplitude = 0.002;
  const RoadProfile profile = sampled(
      2000.0, spacing, [&](double x) { return amplitude * std::sin(2.0 * pi * x / wavelength); });
  IriOptions options;
  options.segment_length_m = 10.0 * wavelength;  // whole periods per segment
  const InternationalRoughnessIndex iri = international_roughness_index(profile, options);
  const double hold = std::sin(pi * spacing / wavelength) / (pi * spacing / wavelength);
  const double expected = closed_form_iri_m_per_km(amplitude, wavelength) * hold;
  EXPECT_NEAR(iri.iri_m_per_km, expected, 0.01 * expected)
      << "L = " << wavelength << " m, dx = " << spacing << " m";
  EXPECT_DOUBLE_EQ(iri.spacing_m, spacing);
  ASSERT_GE(iri.segments.size(), 5U);
  // The first segment holds the start's transient (the standard's initial state is not the
  // sine's steady state), the last one may hold a partial period.
  for (std::size_t k = 1; k + 1 < iri.segments.size(); ++k) {
    EXPECT_NEAR(iri.segments[k].iri_m_per_km, expected, 0.01 * expected) << k;
  }
  EXPECT_DOUBLE_EQ(iri.segments.back().end_m, 2000.0);
}

// 2.4 m is near the wheel hop (about 11 Hz at 80 km/h), 15 m near the body bounce.
INSTANTIATE_TEST_SUITE_P(Wavelengths, IriOfSinusoid,
                         ::testing::Combine(::testing::Values(2.4, 5.0, 15.0, 40.0),
                                            ::testing::Values(0.05, 0.25)));

TEST(Iri, ConstantSlopeHasZeroIri) {
  const RoadProfile profile = sampled(300.0, 0.25, [](double x) { return 0.03 * x; });
  EXPECT_NEAR(international_roughness_index(profile).iri_m_per_km, 0.0, 1e-9);
}

TEST(Iri, IndependentOfSampling) {
  const PowerLawSpectrum spectrum = iso8608_spectrum(Iso8608Class::kC);
  const RandomProfile fine =
      random_profile([&](double n) { return spectrum.psd_m3(n); }, SpatialBand{}, 2000.0, 0.01, 11);
  RoadProfile reference;
  for (std::size_t k = 0; k < fine.elevation_m.size(); ++k) {
    reference.distance_m.push_back(static_cast<double>(k) * fine.spacing_m);
    reference.elevation_m.push_back(fine.elevation_m[k]);
  }
  auto every = [&](std::size_t step) {
    RoadProfile out;
    for (std::size_t k = 0; k < reference.distance_m.size(); k += step) {
      out.distance_m.push_back(reference.distance_m[k]);
      out.elevation_m.push_back(reference.elevation_m[k]);
    }
    return out;
  };
  RoadProfile jittered;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (double x = 0.0; x <= 2000.0; x += 0.05) {
    const double at = std::clamp(x + jitter(rng), 0.0, 2000.0);
    if (!jittered.distance_m.empty() && at <= jittered.distance_m.back()) continue;
    jittered.distance_m.push_back(at);
    jittered.elevation_m.push_back(elevation_at(reference, at));
  }
  const double iri_005 = international_roughness_index(every(5)).iri_m_per_km;
  const double iri_025 = international_roughness_index(every(25)).iri_m_per_km;
  const InternationalRoughnessIndex iri_jittered = international_roughness_index(jittered);
  EXPECT_GT(iri_005, 2.0);  // class C: a few m/km
  EXPECT_LT(iri_005, 20.0);
  EXPECT_NEAR(iri_025, iri_005, 0.02 * iri_005);
  EXPECT_NEAR(iri_jittered.iri_m_per_km, iri_005, 0.02 * iri_005);
  EXPECT_LE(iri_jittered.spacing_m, 0.05 + 1e-12);
}

TEST(Iri, BadInputIsAnInputError) {
  using ridefit::testing::input_error_message;
  const RoadProfile short_profile = sampled(50.0, 0.25, [](double) { return 0.0; });
  EXPECT_NE(input_error_message([&] {
              international_roughness_index(short_profile);
            }).find("shorter than 100 m"),
            std::string::npos);
  RoadProfile profile = sampled(200.0, 0.25, [](double x) { return 0.001 * std::sin(x); });
  profile.elevation_m[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(input_error_message([&] { international_roughness_index(profile); }).find("sample 7"),
            std::string::npos);
  profile.elevation_m[7] = 0.0;
  profile.distance_m[9] = profile.distance_m[8];
  EXPECT_NE(input_error_message([&] { international_roughness_index(profile); }).find("sample 9"),
            std::string::npos);
  profile.distance_m[9] = 9 * 0.25;
  IriOptions options;
  options.segment_length_m = -1.0;
  EXPECT_THROW(international_roughness_index(profile, options), InputError);
}

}  // namespace
}  // namespace ridefit::road
