#pragma once

#include <filesystem>
#include <span>

#include "ridefit/road/spatial_profile_road.h"

namespace ridefit::road {

// How a measured spatial profile is driven. Field names are the YAML keys.
struct ProfileRoadParameters {
  double speed_m_per_s = 50.0 / 3.6;
  // Where the tyre is at t = 0, relative to the profile's first point (a rear wheel a
  // wheelbase behind: −wheelbase); see SpatialProfileRoad.
  double offset_m = 0.0;
};

// A profile h(x) given at strictly increasing distances (any spacing, at least 5 points),
// driven from its first point at the speed until the tyre reaches its last point.
// Uniformly spaced data is used as is; otherwise it is first resampled by PCHIP at the
// median spacing (resample.h). Then a C2 cubic B-spline (UniformSpline, end slopes estimated
// from the data) gives h and dh/dx; before and after the profile the road holds its first
// and last elevation. A profile that does not start at h = 0 starts the car with a step:
// subtract the first elevation in the data if the car should start at rest.
//
// InputErrors: elevations beyond ±10 km, speed beyond 150 m/s, more than 2e7 points after
// resampling or 2e7 samples of run (a far negative offset_m), a run shorter than 1 ms
// (road_limits.h).
SpatialProfileRoad make_profile_road(std::span<const double> distance_m,
                                     std::span<const double> elevation_m,
                                     const ProfileRoadParameters& parameters);

// The same from a CSV with columns `distance[<length unit>]` and `elevation[<length unit>]`
// (m or mm; other columns are ignored). A non-increasing distance names its row; too few
// rows, a missing column, a non-length unit, a directory or other non-regular file are
// InputErrors naming the file.
SpatialProfileRoad load_profile_road(const std::filesystem::path& csv_file,
                                     const ProfileRoadParameters& parameters);

}  // namespace ridefit::road
