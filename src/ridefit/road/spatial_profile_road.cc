#include "ridefit/road/spatial_profile_road.h"

#include <fmt/core.h>

#include <cmath>
#include <utility>

#include "ridefit/io/input_error.h"

namespace ridefit::road {

SpatialProfileRoad::SpatialProfileRoad(UniformSpline profile, double speed_m_per_s,
                                       double duration_s, double origin_m, double offset_m)
    : profile_(std::move(profile)),
      speed_m_per_s_(speed_m_per_s),
      duration_s_(duration_s),
      origin_m_(origin_m),
      offset_m_(offset_m) {
  if (!(speed_m_per_s > 0.0) || !std::isfinite(speed_m_per_s)) {
    throw InputError(fmt::format("key 'speed_m_per_s' is {}, expected a value > 0", speed_m_per_s));
  }
  if (!(duration_s > 0.0) || !std::isfinite(duration_s)) {
    throw InputError(fmt::format("key 'duration_s' is {}, expected a value > 0", duration_s));
  }
  if (!std::isfinite(origin_m) || !std::isfinite(offset_m)) {
    throw InputError(fmt::format("key 'offset_m' is {}, expected a finite number", offset_m));
  }
}

RoadSample SpatialProfileRoad::at(double time_s) const {
  const double x = distance_m(time_s);
  return {profile_.value(x), profile_.derivative(x) * speed_m_per_s_};
}

SpatialProfileRoad SpatialProfileRoad::with_offset(double offset_m) const {
  return SpatialProfileRoad(profile_, speed_m_per_s_, duration_s_, origin_m_, offset_m);
}

}  // namespace ridefit::road
