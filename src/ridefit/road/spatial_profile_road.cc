#include "ridefit/road/spatial_profile_road.h"

#include <fmt/core.h>

#include <cmath>
#include <utility>

#include "ridefit/common/errors.h"
#include "ridefit/road/road_limits.h"

namespace ridefit::road {

SpatialProfileRoad::SpatialProfileRoad(UniformSpline profile, double speed_m_per_s,
                                       double duration_s, double origin_m, double offset_m)
    : profile_(std::move(profile)),
      speed_m_per_s_(speed_m_per_s),
      duration_s_(duration_s),
      origin_m_(origin_m),
      offset_m_(offset_m) {
  check_speed_m_per_s(speed_m_per_s);
  if (!(duration_s > 0.0) || !std::isfinite(duration_s)) {
    throw InputError(fmt::format("key 'duration_s' is {}, expected a value > 0", duration_s));
  }
  const double steps = duration_s / max_step_s();
  if (!(steps <= kMaxRoadSamples)) {
    throw InputError(fmt::format(
        "key 'duration_s' is {:g} s: at speed_m_per_s = {:g} over a road sampled every {:g} m "
        "that is {:.3g} steps of {:g} s, more than {:g}; shorten duration_s or lower the speed",
        duration_s, speed_m_per_s, profile_.step(), steps, max_step_s(), kMaxRoadSamples));
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
