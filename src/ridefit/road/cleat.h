#pragma once

#include <string>

#include "ridefit/road/spatial_profile_road.h"

namespace ridefit::road {

enum class CleatShape { kSemicircular, kRectangular };

// "semicircular" | "rectangular"; anything else is an InputError listing both.
CleatShape parse_cleat_shape(const std::string& text);

// A single cleat (a short obstacle across the road) driven over at a constant speed. Field
// names are the YAML keys.
struct CleatParameters {
  CleatShape shape = CleatShape::kSemicircular;
  // Semicircular: h(s) = H·sqrt(1 − (2s/L − 1)^2) for 0 <= s <= L (a half ellipse; a
  // semicircle when L = 2H). Rectangular: h = H on 0 <= s <= L.
  double height_m = 0.02;
  double length_m = 0.04;
  double start_distance_m = 2.0;  // where the cleat begins; the tyre is at 0 at t = 0
  // The tyre does not follow the cleat's edges (a step has infinite slope): it envelops the
  // obstacle with its contact patch. Modelled as a moving average of the cleat over this
  // length (the "fixed footprint" model). 0.1 m is the static contact length of a
  // passenger-car tyre at nominal load and pressure (roughly 0.1–0.15 m); the shorter end
  // keeps the edges sharp. The average keeps the area under the cleat (so the impulse into
  // the tyre spring) and lowers the peak of cleats shorter than the patch: a 20 mm
  // semicircle (L = 40 mm) peaks at π·H·L/(4·0.1 m) = 6.3 mm. Set it from your tyre.
  double tyre_contact_length_m = 0.1;
  double speed_m_per_s = 20.0 / 3.6;
  // 0 = until the tyre has left the cleat plus kCleatSettleTime_s for the car to settle.
  double duration_s = 0.0;

  // Throws InputError naming the field (as a YAML key) of the first invalid value. Besides
  // signs: height_m <= 1 m, speed <= 150 m/s, a non-zero duration_s no shorter than the time
  // the contact patch takes to leave the cleat (nor than 1 ms), at most 2e7 samples across
  // cleat and patch and at most 2e7 samples of road over the run (road_limits.h).
  void validate() const;
};

// Time after the tyre leaves the enveloped cleat, by default: about three periods of a
// 1–1.5 Hz body mode, enough for a damped car to settle.
inline constexpr double kCleatSettleTime_s = 3.0;

// The enveloped (moving-averaged) cleat at road distance x, in closed form:
// h̄(x) = (F(x + l/2) − F(x − l/2))/l with F the integral of the cleat's shape.
double enveloped_cleat_elevation_m(const CleatParameters& parameters, double distance_m);

// h̄ sampled every min(L, l)/40 (at least 40 samples across the narrower of cleat and patch)
// from a flat stretch before to a flat stretch after, splined (C2 cubic B-spline with zero end
// slopes, UniformSpline): the kinks of h̄ (the corners of a rectangle's trapezoid) are
// rounded over about one sample, h and dh/dt are continuous, and the road is flat (h = 0,
// dh/dt = 0) before and after.
SpatialProfileRoad make_cleat_road(const CleatParameters& parameters);

}  // namespace ridefit::road
