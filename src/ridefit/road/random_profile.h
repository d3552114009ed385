#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "ridefit/road/power_law_spectrum.h"
#include "ridefit/road/spatial_profile_road.h"

namespace ridefit::road {

// A random road profile on a uniform grid x_k = k·spacing_m, k = 0 … n−1.
struct RandomProfile {
  std::vector<double> elevation_m;
  double spacing_m = 0.0;
  double harmonic_spacing_cycles_per_m = 0.0;  // Δn = 1/period
  double period_m = 0.0;                       // the profile repeats after this distance
};

// The usual sum of harmonics with random phases (as in the road-simulation programs seed 001
// cites):
//
//   h(x) = Σ_k a_k·cos(2π n_k x + φ_k),   n_k = k·Δn in the band,
//   a_k = sqrt(2·G(n_k)·Δn),   φ_k uniform in [0, 2π),
//
// so that the variance Σ a_k²/2 = Σ G(n_k)Δn ≈ ∫ G dn over the band (the two edge harmonics
// use the part of their bin Δn inside the band, so the sum has no O(Δn) edge bias). The
// amplitudes are deterministic and only the phases are random, the usual choice for road
// profiles: the spectrum over a whole period is exactly G, a stretch of it scatters around G.
//
// Evaluated with one inverse real FFT of size N (a power of two, at least length/spacing + 1
// and at least 8/(n_low·spacing) so that the lowest octave holds at least 8 harmonics): Δn =
// 1/(N·spacing), O(N log N). Phases come from std::mt19937_64(seed), converted to [0, 1)
// from the top 53 bits so the same seed gives the same profile with every standard library.
// `psd_m3(n)` is the one-sided displacement PSD in m^3 with n in cycles/m.
// Requires spacing_m <= 1/(4·n_high) (at least 4 samples per shortest wave, all harmonics
// well below Nyquist).
RandomProfile random_profile(const std::function<double(double)>& psd_m3, const SpatialBand& band,
                             double length_m, double spacing_m, std::uint64_t seed);

// Settings shared by every random road (ISO 8608, seed 001's power law). Field names are
// the YAML keys.
struct RandomRoadParameters {
  double speed_m_per_s = 50.0 / 3.6;
  double duration_s = 60.0;
  std::uint64_t seed = 1;
  SpatialBand band;  // band_low_cycles_per_m, band_high_cycles_per_m
  // 0.05 m puts 7 samples on the shortest (0.35 m) wave: the spline then misses its
  // amplitude by 0.2 % and its slope by 0.7 %; at the limit of 4 samples, 2.5 % and 5 %.
  double sample_spacing_m = 0.05;
  // The profile is faded in from h = 0 over this distance with the quintic smoothstep
  // 6s^5 − 15s^4 + 10s^3 (value, slope and curvature 0 at x = 0), so a car starting at rest
  // at static equilibrium on h = 0 is not kicked by a step, and a rear wheel that starts
  // behind the profile (offset_m < 0) sees a smooth entry too. 0 disables it.
  double fade_in_m = 5.0;

  // Throws InputError naming the field (as a YAML key) of the first invalid value. Besides
  // signs and the spacing rule: speed <= 150 m/s, duration >= 1 ms, at least 5 and at most
  // 2e7 samples over speed·duration, fade_in_m no longer than the road, and an FFT of at most
  // 2e7 points for the band's lowest octave (road_limits.h).
  void validate() const;
};

// The profile over speed·duration metres from x = 0, faded in, sampled and splined
// (UniformSpline), driven at the speed.
SpatialProfileRoad make_random_road(const std::function<double(double)>& psd_m3,
                                    const RandomRoadParameters& parameters);

}  // namespace ridefit::road
