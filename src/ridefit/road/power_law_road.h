#pragma once

#include "ridefit/road/power_law_spectrum.h"
#include "ridefit/road/random_profile.h"
#include "ridefit/road/spatial_profile_road.h"

namespace ridefit::road {

// The road spectrum of seed 001 (Section 2.4, Eq. 3 and Table 3): PSD = Cr/ν^α in m^3/cycle.
//
// How we read it. ν is the spatial frequency n in cycles/m (the seed calls α the
// "wavenumber", but α is the exponent and ν the variable), so
//
//   S(n) = Cr·n^(−α)   [m^3 = m^2 per cycle/m],   n in cycles/m,
//
// i.e. Cr is the one-sided displacement PSD at n = 1 cycle/m, in m^3. This is the same
// quantity as ISO 8608's Gd(n) (a PowerLawSpectrum with n_ref = 1 cycle/m), and it puts the
// seed's roads where their names say: at n0 = 0.1 cycles/m the smooth highway gives
// 4.8e-7·0.1^(−2.1) = 6.0e-5 m^3 (ISO class B), gravel 5.5e-4 m^3 (class D) and the suburban
// road 1.0e-3 m^3 (class D/E). The same (Cr, α) pairs are tabulated for n in cycles/m in the
// vehicle-dynamics literature (e.g. Wong, Theory of Ground Vehicles; not re-checked here).
//
// The seed's Eq. 4 turns S(n) into a temporal PSD S(f) = Cr·U^(α−1)/f^α (n = f/U, S(f) =
// S(n)/U), which holds for U in m/s, although the seed writes km/h; which unit its results
// used is for a later issue. Here only the spatial PSD is implemented, so no speed unit
// enters the spectrum: the speed only maps distance to time (x = v·t, v in m/s).
//
// The seed gives no band; we use ISO 8608's 0.011–2.83 cycles/m by default (configurable).
struct PowerLawRoadParameters {
  double roughness_coefficient_m3 = 4.8e-7;  // Cr: S at n = 1 cycle/m
  double waviness = 2.1;                     // α
  RandomRoadParameters random;

  PowerLawSpectrum spectrum() const { return {1.0, roughness_coefficient_m3, waviness}; }
  // Throws InputError naming the field (as a YAML key) of the first invalid value; the band
  // RMS elevation must be at most 10 m (a mistyped Cr would overflow the profile).
  void validate() const;
};

// Seed 001, Table 3 (α = 2.1 for all three).
inline constexpr double kSeed001Waviness = 2.1;
inline constexpr double kSeed001SmoothHighwayCr_m3 = 4.8e-7;
inline constexpr double kSeed001GravelHighwayCr_m3 = 4.4e-6;
inline constexpr double kSeed001SuburbanRoadCr_m3 = 8.1e-6;

// Same harmonic machinery as ISO 8608 (random_profile.h): random phases, faded in, splined
// (C2 cubic B-spline, UniformSpline), driven at the speed.
SpatialProfileRoad make_power_law_road(const PowerLawRoadParameters& parameters);

}  // namespace ridefit::road
