#pragma once

#include <vector>

namespace ridefit::road {

// A measured or generated longitudinal road profile: elevation over distance, regularly or
// irregularly spaced.
struct RoadProfile {
  std::vector<double> distance_m;
  std::vector<double> elevation_m;
};

// Throws InputError, naming the sample index, unless the two vectors have equal length, at
// least `minimum_samples` (>= 2) samples, every value finite and distance strictly increasing.
void check_road_profile(const RoadProfile& profile, std::size_t minimum_samples = 2);

// The profile's length: last minus first distance.
double profile_length_m(const RoadProfile& profile);

// The median distance between neighbouring samples.
double median_spacing_m(const RoadProfile& profile);

// The spacing of a uniform profile as length/(samples − 1) (free of the rounding in the
// differences), else the median spacing.
double nominal_spacing_m(const RoadProfile& profile);

// True when every spacing is within 1e-6 (relative) of spacing_m.
bool is_uniform(const RoadProfile& profile, double spacing_m);

// The profile on the grid x_k = x_0 + k·spacing_m, k = 0 … floor(length/spacing (+1e-9)),
// elevations by linear interpolation. Checks the profile (check_road_profile) and throws
// InputError for a spacing that is not positive and finite or longer than the profile.
RoadProfile uniform(const RoadProfile& profile, double spacing_m);

// Linear interpolation of the profile's elevation at a distance inside [x_0, x_{n-1}]
// (clamped outside).
double elevation_at(const RoadProfile& profile, double distance_m);

}  // namespace ridefit::road
