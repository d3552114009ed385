#pragma once

#include <vector>

#include "ridefit/road/road_profile.h"

namespace ridefit::road {

// The golden quarter car of the IRI (ASTM E1926, Sayers 1995), per unit sprung mass.
struct GoldenQuarterCar {
  double tyre_stiffness = 653.0;       // k1/ms, 1/s^2
  double suspension_stiffness = 63.3;  // k2/ms, 1/s^2
  double damping = 6.0;                // c/ms, 1/s
  double unsprung_mass_ratio = 0.15;   // mu = mu/ms
  double speed_m_per_s = 80.0 / 3.6;
};

struct IriOptions {
  double segment_length_m = 100.0;  // reporting segments; the whole length is reported too
  double moving_average_m = 0.25;   // the standard's smoothing base length
};

struct IriSegment {
  double start_m = 0.0;  // distances along the profile, from its first sample
  double end_m = 0.0;
  double iri_m_per_km = 0.0;  // = mm/m
};

struct InternationalRoughnessIndex {
  double iri_m_per_km = 0.0;  // over the whole profile
  // Consecutive segments of segment_length_m from the profile's start; the last one is shorter
  // when the length is not a multiple (a tail under half a segment joins the one before).
  std::vector<IriSegment> segments;
  double spacing_m = 0.0;  // the spacing simulated
};

// The IRI per ASTM E1926: the profile, on a uniform grid whose spacing divides the 250 mm
// base (the input's own spacing when it does, else linear resampling to 0.25/m m, m =
// ceil(0.25/median spacing), never coarser than 0.25 m), is smoothed by the 250 mm moving
// average (slopes s_i = (y_{i+b} − y_i)/(b·dx)), and the golden car is driven over the slope
// profile at 80 km/h with the exact discrete state transition for a slope held over each
// step (zero-order hold; matrix exponential). The states start at z_s' = z_u' = (y(11 m) −
// y(0))/11, accelerations 0. IRI = mean |z_s' − z_u'|/V·1000 in m/km.
// Throws InputError for a bad profile (check_road_profile), a profile shorter than 11 m or
// than one segment, or a non-positive segment length.
InternationalRoughnessIndex international_roughness_index(const RoadProfile& profile,
                                                          const IriOptions& options = {});

}  // namespace ridefit::road
