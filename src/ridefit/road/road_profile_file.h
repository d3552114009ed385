#pragma once

#include <filesystem>
#include <optional>

#include "ridefit/road/road_profile.h"

namespace ridefit::road {

// A longitudinal profile read from a file, for road evaluation (`ridefit road`):
// - a CSV with columns distance and elevation in lengths (distance[m],elevation[mm], …),
//   distance strictly increasing; `lateral_offset_m` must be unset;
// - an OpenCRG file (.crg, any case; opencrg_file.h): the track at `lateral_offset_m` (default
//   0: the reference line) over the reference line's u, missing points filled along u.
// InputError naming the file (and row, key or long section) for anything else.
// The CSV form alone (also `type: profile`'s file, profile_road.h): the columns distance and
// elevation in lengths, distance strictly increasing (the row named otherwise); the values are
// not checked further here.
RoadProfile read_profile_csv(const std::filesystem::path& path);

RoadProfile load_road_profile(const std::filesystem::path& path,
                              std::optional<double> lateral_offset_m = std::nullopt);

}  // namespace ridefit::road
