// The harmonic generator shared by ISO 8608 and seed 001's power law: its spectrum (slope and
// level of the periodogram), its variance against the band integral, and its seeding.
#include "ridefit/road/random_profile.h"

#include <gtest/gtest.h>
#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/power_law_road.h"

namespace ridefit::road {
namespace {

struct LineFit {
  double slope = 0.0;
  double log_level_at_one = 0.0;  // ln G at n = 1 cycle/m
  double psd_m3(double n) const { return std::exp(log_level_at_one + slope * std::log(n)); }
};

// Hann-windowed periodogram of the whole stretch (one-sided, m^3), averaged in half-octave
// bins from n_low to n_high, and a straight line fitted to ln(bin mean) against ln(bin
// geometric-mean frequency), each bin weighted by its number of periodogram points (its
// inverse variance).
LineFit fit_periodogram(std::vector<double> h, double spacing_m, double n_low, double n_high) {
  const std::size_t m = h.size();
  double mean = 0.0;
  for (double v : h) mean += v / static_cast<double>(m);
  double window_power = 0.0;
  for (std::size_t j = 0; j < m; ++j) {
    const double w = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * static_cast<double>(j) /
                                          static_cast<double>(m));
    h[j] = (h[j] - mean) * w;
    window_power += w * w;
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, h);
  const double dn = 1.0 / (static_cast<double>(m) * spacing_m);
  double sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (double lo = n_low; lo < n_high * 0.999; lo *= std::sqrt(2.0)) {
    const double hi = lo * std::sqrt(2.0);
    double sum_p = 0.0, sum_log_n = 0.0;
    int count = 0;
    for (auto k = static_cast<std::size_t>(std::ceil(lo / dn)); static_cast<double>(k) * dn < hi;
         ++k) {
      sum_p += 2.0 * spacing_m * std::norm(spectrum[k]) / window_power;
      sum_log_n += std::log(static_cast<double>(k) * dn);
      ++count;
    }
    const double x = sum_log_n / count;
    const double y = std::log(sum_p / count);
    const double w = count;
    sw += w, sx += w * x, sy += w * y, sxx += w * x * x, sxy += w * x * y;
  }
  LineFit fit;
  fit.slope = (sw * sxy - sx * sy) / (sw * sxx - sx * sx);
  fit.log_level_at_one = (sy - fit.slope * sx) / sw;
  return fit;
}

double mean_square(const std::vector<double>& h) {
  double s = 0.0;
  for (double v : h) s += v * v;
  return s / static_cast<double>(h.size());
}

const double kDriveLength_m = 60.0 * 50.0 / 3.6;  // 60 s at 50 km/h

TEST(RoadRandomProfile, Iso8608PeriodogramHasSlopeMinusTwoAndTheClassLevel) {
  const PowerLawSpectrum spectrum = iso8608_spectrum(Iso8608Class::kA);
  auto psd = [&](double n) { return spectrum.psd_m3(n); };
  for (std::uint64_t seed : {1u, 2u}) {
    const RandomProfile profile = random_profile(psd, SpatialBand{}, kDriveLength_m, 0.05, seed);
    const LineFit fit = fit_periodogram(profile.elevation_m, 0.05, 0.02, 2.0);
    // Statistical bounds: over seeds 1–12 the fit scatters with σ ≈ 0.02 in slope and 6 % in
    // level, so these are 4σ and 3σ.
    EXPECT_NEAR(fit.slope, -2.0, 0.08) << "seed " << seed;
    EXPECT_NEAR(fit.psd_m3(0.1) / 16e-6, 1.0, 0.2) << "seed " << seed;
  }
}

TEST(RoadRandomProfile, PowerLawPeriodogramHasTheSeedsSlopeAndLevel) {
  PowerLawRoadParameters p;
  p.roughness_coefficient_m3 = kSeed001GravelHighwayCr_m3;
  const PowerLawSpectrum spectrum = p.spectrum();
  const RandomProfile profile = random_profile([&](double n) { return spectrum.psd_m3(n); },
                                               SpatialBand{}, kDriveLength_m, 0.05, 3);
  const LineFit fit = fit_periodogram(profile.elevation_m, 0.05, 0.02, 2.0);
  EXPECT_NEAR(fit.slope, -2.1, 0.08);
  EXPECT_NEAR(fit.psd_m3(1.0) / 4.4e-6, 1.0, 0.2);
}

TEST(RoadRandomProfile, VarianceOverAWholePeriodIsTheBandIntegral) {
  const PowerLawSpectrum spectrum = iso8608_spectrum(Iso8608Class::kC);
  const double spacing = 0.05;
  const RandomProfile profile = random_profile([&](double n) { return spectrum.psd_m3(n); },
                                               SpatialBand{}, 32767 * spacing, spacing, 11);
  ASSERT_EQ(profile.elevation_m.size(), 32768u);
  ASSERT_DOUBLE_EQ(profile.period_m, 32768 * spacing);
  EXPECT_DOUBLE_EQ(profile.harmonic_spacing_cycles_per_m, 1.0 / profile.period_m);
  // Σ a_k²/2 is the midpoint rule for ∫ G dn: exact to O(Δn²).
  EXPECT_NEAR(mean_square(profile.elevation_m) / spectrum.band_variance_m2(SpatialBand{}), 1.0,
              2e-3);
}

TEST(RoadRandomProfile, MeanSquareOverManySeedsIsTheBandIntegral) {
  // E[h(x)²] = Σ a_k²/2 at every x, so the stretch's mean square averaged over seeds is
  // unbiased; one 833 m stretch scatters by ~20 %, 24 seeds by ~4 %.
  const PowerLawSpectrum spectrum = iso8608_spectrum(Iso8608Class::kB);
  double sum = 0.0;
  const int seeds = 24;
  for (int seed = 100; seed < 100 + seeds; ++seed) {
    sum += mean_square(random_profile([&](double n) { return spectrum.psd_m3(n); }, SpatialBand{},
                                      kDriveLength_m, 0.05, static_cast<std::uint64_t>(seed))
                           .elevation_m);
  }
  EXPECT_NEAR(sum / seeds / spectrum.band_variance_m2(SpatialBand{}), 1.0, 0.12);
}

TEST(RoadRandomProfile, SameSeedSameProfileOtherSeedAnotherOne) {
  const PowerLawSpectrum spectrum = iso8608_spectrum(Iso8608Class::kA);
  auto psd = [&](double n) { return spectrum.psd_m3(n); };
  const auto a = random_profile(psd, SpatialBand{}, 500.0, 0.05, 42).elevation_m;
  const auto b = random_profile(psd, SpatialBand{}, 500.0, 0.05, 42).elevation_m;
  const auto c = random_profile(psd, SpatialBand{}, 500.0, 0.05, 43).elevation_m;
  EXPECT_EQ(a, b);
  std::vector<double> difference(a.size());
  for (std::size_t k = 0; k < a.size(); ++k) difference[k] = a[k] - c[k];
  // Independent profiles: the difference has about √2 times the RMS of either.
  EXPECT_GT(mean_square(difference), 0.5 * mean_square(a));
}

TEST(RoadRandomProfile, BandEdgesAndSpacingAreChecked) {
  auto psd = [](double n) { return 1e-6 / (n * n); };
  EXPECT_THROW(random_profile(psd, SpatialBand{0.0, 2.83}, 100.0, 0.05, 1), InputError);
  EXPECT_THROW(random_profile(psd, SpatialBand{1.0, 0.5}, 100.0, 0.05, 1), InputError);
  EXPECT_THROW(random_profile(psd, SpatialBand{}, 100.0, 0.1, 1), InputError);  // > 1/(4·2.83)
  EXPECT_THROW(random_profile(psd, SpatialBand{}, 0.0, 0.05, 1), InputError);
  // No harmonic outside the band: over a whole period the spectrum is zero outside it.
  const RandomProfile narrow = random_profile(psd, SpatialBand{0.5, 0.6}, 65535 * 0.05, 0.05, 5);
  ASSERT_EQ(narrow.elevation_m.size(), 65536u);
  ASSERT_DOUBLE_EQ(narrow.period_m, 65536 * 0.05);
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, narrow.elevation_m);
  const double dn = narrow.harmonic_spacing_cycles_per_m;
  double inside = 0.0, outside = 0.0;
  for (std::size_t k = 1; k < narrow.elevation_m.size() / 2; ++k) {
    const double n = static_cast<double>(k) * dn;
    (n >= 0.5 - dn && n <= 0.6 + dn ? inside : outside) += std::norm(spectrum[k]);
  }
  EXPECT_LT(outside, 1e-20 * inside);
}

}  // namespace
}  // namespace ridefit::road
