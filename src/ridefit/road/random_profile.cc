#include "ridefit/road/random_profile.h"

#include <fmt/core.h>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <bit>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <random>

#include "ridefit/common/errors.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {
namespace {

void check_spacing(const SpatialBand& band, double spacing_m) {
  if (!(band.low_cycles_per_m > 0.0) || !(band.high_cycles_per_m > band.low_cycles_per_m) ||
      !std::isfinite(band.high_cycles_per_m)) {
    throw InputError(
        fmt::format("keys 'band_low_cycles_per_m' ({}) and 'band_high_cycles_per_m' ({}): expected "
                    "0 < low < high",
                    band.low_cycles_per_m, band.high_cycles_per_m));
  }
  if (!(spacing_m > 0.0) || spacing_m > 0.25 / band.high_cycles_per_m) {
    throw InputError(fmt::format(
        "key 'sample_spacing_m' is {}, expected 0 < spacing <= 1/(4·band_high_cycles_per_m) = {} "
        "(at least 4 samples per shortest wave)",
        spacing_m, 0.25 / band.high_cycles_per_m));
  }
}

// The FFT must hold 8 harmonics in the band's lowest octave: 8/(n_low·spacing) points.
void check_fft_size(const SpatialBand& band, double spacing_m) {
  const double points = 8.0 / (band.low_cycles_per_m * spacing_m);
  if (!(points <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "key 'band_low_cycles_per_m' is {:g}: 8 harmonics in its octave at sample_spacing_m = "
        "{:g} m take an FFT of 8/(low·spacing) = {:.3g} points, more than {:g}; expected "
        "band_low_cycles_per_m >= {:g} (a wavelength of at most {:g} m)",
        band.low_cycles_per_m, spacing_m, points, kMaxRoadSamples,
        8.0 / (kMaxRoadSamples * spacing_m), kMaxRoadSamples * spacing_m / 8.0));
  }
}

// The quintic smoothstep: 0 at s = 0 and 1 at s = 1 with zero slope and curvature at both.
double smoothstep5(double s) { return s * s * s * (s * (6.0 * s - 15.0) + 10.0); }

}  // namespace

RandomProfile random_profile(const std::function<double(double)>& psd_m3, const SpatialBand& band,
                             double length_m, double spacing_m, std::uint64_t seed) {
  check_spacing(band, spacing_m);
  if (!(length_m > 0.0) || !std::isfinite(length_m)) {
    throw InputError(fmt::format("profile length {} m, expected > 0", length_m));
  }
  if (!(length_m / spacing_m + 1.0 <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "profile length {:g} m at sample_spacing_m = {:g} m is {:.3g} samples, more than {:g}",
        length_m, spacing_m, length_m / spacing_m + 1.0, kMaxRoadSamples));
  }
  check_fft_size(band, spacing_m);
  const auto samples = static_cast<std::size_t>(std::ceil(length_m / spacing_m)) + 1;
  const auto lowest_octave =
      static_cast<std::size_t>(std::ceil(8.0 / (band.low_cycles_per_m * spacing_m)));
  const std::size_t n_fft = std::bit_ceil(std::max({samples, lowest_octave, std::size_t{16}}));
  const double period_m = static_cast<double>(n_fft) * spacing_m;
  const double dn = 1.0 / period_m;

  // Harmonic k stands for the bin [n_k − Δn/2, n_k + Δn/2] clipped to the band (midpoint
  // rule): interior bins have width Δn, the two edge bins less, so that Σ a_k²/2 equals
  // ∫ G dn over the band up to O(Δn²) instead of an O(Δn) edge bias. Every bin lies below
  // Nyquist because spacing <= 1/(4·n_high).
  const auto k_low =
      static_cast<std::size_t>(std::max(1.0, std::ceil(band.low_cycles_per_m / dn - 0.5)));
  const auto k_high = static_cast<std::size_t>(std::floor(band.high_cycles_per_m / dn + 0.5));

  // Half spectrum X_k = (N/2)·a_k·e^{iφ_k}; the inverse FFT's 1/N and the Hermitian mirror
  // turn it into Σ a_k cos(2π k j/N + φ_k).
  std::vector<std::complex<double>> spectrum(n_fft / 2 + 1, {0.0, 0.0});
  std::mt19937_64 rng(seed);
  const double half_n = 0.5 * static_cast<double>(n_fft);
  for (std::size_t k = k_low; k <= k_high; ++k) {
    const double n = static_cast<double>(k) * dn;
    const double bin_low = std::max(n - 0.5 * dn, band.low_cycles_per_m);
    const double bin_high = std::min(n + 0.5 * dn, band.high_cycles_per_m);
    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;  // draw for every k
    if (!(bin_high > bin_low)) continue;
    const double amplitude = std::sqrt(2.0 * psd_m3(n) * (bin_high - bin_low));
    spectrum[k] = std::polar(half_n * amplitude, 2.0 * std::numbers::pi * u);
  }
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<double> elevation;
  fft.inv(elevation, spectrum, static_cast<Eigen::Index>(n_fft));
  elevation.resize(samples);
  elevation.shrink_to_fit();  // the FFT's tail beyond the road is up to half of it
  return {std::move(elevation), spacing_m, dn, period_m};
}

void RandomRoadParameters::validate() const {
  check_speed_m_per_s(speed_m_per_s);
  if (!(duration_s >= kMinRoadDuration_s) || !std::isfinite(duration_s)) {
    throw InputError(fmt::format("key 'duration_s' is {}, expected a finite value >= {:g} s",
                                 duration_s, kMinRoadDuration_s));
  }
  check_spacing(band, sample_spacing_m);
  if (!(fade_in_m >= 0.0) || !std::isfinite(fade_in_m)) {
    throw InputError(fmt::format("key 'fade_in_m' is {}, expected a value >= 0", fade_in_m));
  }
  const double length_m = speed_m_per_s * duration_s;
  const double samples = length_m / sample_spacing_m + 1.0;
  if (!(samples <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "keys 'duration_s', 'speed_m_per_s' and 'sample_spacing_m': {:g} s at {:g} m/s is {:g} m "
        "of road, {:.3g} samples {:g} m apart, more than {:g}; shorten duration_s, lower the "
        "speed or raise sample_spacing_m (up to 1/(4·band_high_cycles_per_m) = {:g} m)",
        duration_s, speed_m_per_s, length_m, samples, sample_spacing_m, kMaxRoadSamples,
        0.25 / band.high_cycles_per_m));
  }
  // UniformSpline needs 5 samples: 4 spacings of road.
  if (!(length_m >= 4.0 * sample_spacing_m)) {
    throw InputError(fmt::format(
        "keys 'speed_m_per_s' and 'duration_s': {:g} m/s for {:g} s is {:g} m of road, shorter "
        "than 4·sample_spacing_m = {:g} m (a profile needs at least 5 samples); raise the speed "
        "or duration_s to at least {:g} s",
        speed_m_per_s, duration_s, length_m, 4.0 * sample_spacing_m,
        4.0 * sample_spacing_m / speed_m_per_s));
  }
  if (!(fade_in_m <= length_m)) {
    throw InputError(fmt::format(
        "key 'fade_in_m' is {:g} m, longer than the road (speed_m_per_s·duration_s = {:g} m); "
        "expected 0 <= fade_in_m <= {:g}",
        fade_in_m, length_m, length_m));
  }
  check_fft_size(band, sample_spacing_m);
}

SpatialProfileRoad make_random_road(const std::function<double(double)>& psd_m3,
                                    const RandomRoadParameters& parameters) {
  parameters.validate();
  const double length_m = parameters.speed_m_per_s * parameters.duration_s;
  RandomProfile profile = random_profile(psd_m3, parameters.band, length_m,
                                         parameters.sample_spacing_m, parameters.seed);
  std::vector<double>& h = profile.elevation_m;
  // validate() bounds the sizes; a spectrum that overflows (a PSD near 1e308) is caught here.
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (!std::isfinite(h[k])) {
      throw InputError(fmt::format(
          "the random profile's elevation is {} at {:g} m: its spectrum is too large (check the "
          "roughness and the band)",
          h[k], static_cast<double>(k) * profile.spacing_m));
    }
  }
  double start_slope = std::numeric_limits<double>::quiet_NaN();
  if (parameters.fade_in_m > 0.0) {
    for (std::size_t k = 0; k < h.size(); ++k) {
      const double x = static_cast<double>(k) * profile.spacing_m;
      if (x >= parameters.fade_in_m) break;
      h[k] *= smoothstep5(x / parameters.fade_in_m);
    }
    start_slope = 0.0;
  }
  return SpatialProfileRoad(UniformSpline(h, 0.0, profile.spacing_m, start_slope),
                            parameters.speed_m_per_s, parameters.duration_s);
}

}  // namespace ridefit::road
