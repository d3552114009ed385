#pragma once

#include <filesystem>

#include "ridefit/road/opencrg_file.h"
#include "ridefit/road/spatial_profile_road.h"

namespace ridefit::road {

// How a wheel track is taken from an OpenCRG road and driven. Field names are the YAML keys.
struct OpenCrgRoadParameters {
  double speed_m_per_s = 50.0 / 3.6;
  // The track's lateral position v (m, > 0 left of the reference line), between the outermost
  // long sections; the elevation is interpolated linearly between the two sections around it.
  double lateral_offset_m = 0.0;
  // Where the tyre is at t = 0 along u, relative to the grid's first row (as for the profile
  // road: a rear wheel a wheelbase behind uses −wheelbase).
  double offset_m = 0.0;
};

// The elevation along one track of the grid, over u, as a SpatialProfileRoad (profile_road.h:
// the same spline, limits and half-car wheelbase delay as `type: profile`). Missing points are
// filled as crg_track() says (linear along u, ends held).
//
// The reference line: ridefit takes z of the grid, the elevation relative to the reference
// line, and ignores the reference line's own geometry: its curvature (x, y, phi) does not
// change the elevation along u, and its longitudinal slope and banking are left out. For a
// vertical-dynamics run the road's unevenness is the input; a grade or cross slope changes it
// only over tens of metres (far below the body's 1 Hz at driving speeds) and would add a
// large quasi-static drift (the integral of the slope) to the road, the body and the travel
// outputs. OpenCRG's own evaluation adds them; a run that needs them (a crest, a sag) can
// add the slope channel to a profile CSV instead.
//
// InputErrors: lateral_offset_m outside [v_right, v_left] (names the key and the range), a
// track section without a valid point, and the profile road's own (speed, offset, length).
SpatialProfileRoad make_opencrg_road(const CrgGrid& grid, const OpenCrgRoadParameters& parameters,
                                     const std::string& source);
SpatialProfileRoad load_opencrg_road(const std::filesystem::path& crg_file,
                                     const OpenCrgRoadParameters& parameters);

}  // namespace ridefit::road
