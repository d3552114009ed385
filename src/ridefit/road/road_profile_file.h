#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "ridefit/common/errors.h"
#include "ridefit/road/road_profile.h"

namespace ridefit::road {

// How a file becomes one longitudinal profile.
struct RoadProfileSource {
  // OpenCRG: the track's lateral position v (unset: the reference line, v = 0).
  std::optional<double> lateral_offset_m;
  // A vehicle record over time: the speed it was driven at, which maps time to distance.
  std::optional<double> speed_m_per_s;
  // A vehicle record: the road channel (empty: `road`, else `road_front` when the record has
  // no `road`, as a half car's has).
  std::string channel;
};

// A vehicle record over time was given without the speed it was driven at. Callers that
// know how the user gives a speed add that to the message.
class MissingDrivingSpeed : public InputError {
 public:
  using InputError::InputError;
};

// A longitudinal profile read from a file, for road evaluation (`ridefit road`):
// - a CSV with columns distance and elevation in lengths (distance[m],elevation[mm], …),
//   distance strictly increasing;
// - an OpenCRG file (.crg, any case; opencrg_file.h): the track at `lateral_offset_m` (default
//   0: the reference line) over the reference line's u, missing points filled along u;
// - a vehicle record over time (time[s],road[m],body_acc[m/s^2],…): its road channel over
//   the distance driven at a given speed.
// InputError naming the file (and row, key, column or long section) for anything else.
// The CSV form alone (also `type: profile`'s file, profile_road.h): the columns distance and
// elevation in lengths, distance strictly increasing (the row named otherwise); the values are
// not checked further here.
RoadProfile read_profile_csv(const std::filesystem::path& path);

// Any of the three: an OpenCRG file (by its extension .crg), a profile CSV (a `distance`
// column) or a vehicle record (a `time` column, strictly increasing, and a road channel in
// lengths; distance = speed·(t − t0)). A setting that does not apply to the file (a lateral
// offset for a CSV, a speed or a channel for a profile over distance) is an InputError, and a
// record without a speed is a MissingDrivingSpeed. The profile is checked
// (check_road_profile, at least 4 samples).
RoadProfile load_road_profile(const std::filesystem::path& path,
                              const RoadProfileSource& source = {});

}  // namespace ridefit::road
