#pragma once

#include <string>

#include "ridefit/road/power_law_spectrum.h"
#include "ridefit/road/random_profile.h"
#include "ridefit/road/spatial_profile_road.h"

namespace ridefit::road {

// ISO 8608 road roughness classes, from A (very good) to H (very poor).
enum class Iso8608Class { kA, kB, kC, kD, kE, kF, kG, kH };

// "A" … "H"; anything else is an InputError listing the classes.
Iso8608Class parse_iso8608_class(const std::string& text);
char to_char(Iso8608Class road_class);

// ISO 8608 displacement PSD at n0 = 0.1 cycles/m, the geometric mean of the class:
// 16e-6 m^3 for class A, ×4 per class up to 262144e-6 m^3 for class H (each class spans a
// factor of 4 in Gd(n0), so a factor of 2 in RMS elevation).
constexpr double kIso8608ReferenceCyclesPerM = 0.1;
double iso8608_reference_psd_m3(Iso8608Class road_class);

// Gd(n) = Gd(n0)·(n/n0)^(−2): the standard's waviness w = 2.
PowerLawSpectrum iso8608_spectrum(Iso8608Class road_class);

struct Iso8608RoadParameters {
  Iso8608Class road_class = Iso8608Class::kA;  // YAML key `class`
  RandomRoadParameters random;
};

// A random profile of the class's spectrum over the band (random_profile.h), faded in,
// splined (C2 cubic B-spline, UniformSpline) and driven at the speed. The RMS elevation of the
// band, before the fade-in, is iso8608_spectrum(c).band_rms_m(band) up to the scatter of a
// finite stretch (3.81 mm for class A in the default band 0.011–2.83 cycles/m).
SpatialProfileRoad make_iso8608_road(const Iso8608RoadParameters& parameters);

}  // namespace ridefit::road
