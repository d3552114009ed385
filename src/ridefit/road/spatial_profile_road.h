#pragma once

#include "ridefit/road/road_input.h"
#include "ridefit/road/uniform_spline.h"

namespace ridefit::road {

// A road profile h(x) over distance x, driven at a constant speed v:
//
//   x(t) = origin_m + offset_m + v·t,   h(t) = h(x(t)),   dh/dt = h'(x(t))·v
//
// `origin_m` is the road coordinate under the tyre at t = 0 (the first point of a measured
// profile, 0 for generated roads); `offset_m` shifts one wheel along the road, so a rear
// wheel a wheelbase L behind the front one uses offset_m = −L and sees the front wheel's
// input delayed by L/v. The profile is interpolated by UniformSpline (C2 cubic B-spline;
// outside the profile the road holds its end elevation, flat).
//
// The constructor checks the speed (road_limits.h), a duration > 0 and that the run needs at
// most kMaxRoadSamples steps of max_step_s(); the builders check their own keys first, so
// these are a last line of defence that names speed_m_per_s or duration_s.
class SpatialProfileRoad : public RoadInput {
 public:
  SpatialProfileRoad(UniformSpline profile, double speed_m_per_s, double duration_s,
                     double origin_m = 0.0, double offset_m = 0.0);

  RoadSample at(double time_s) const override;
  double duration_s() const override { return duration_s_; }
  // The profile's sample interval in time, spacing/speed.
  double max_step_s() const override { return profile_.step() / speed_m_per_s_; }

  double distance_m(double time_s) const { return origin_m_ + offset_m_ + speed_m_per_s_ * time_s; }
  // The same road for a wheel `offset_m` along it (the profile is shared, not copied).
  SpatialProfileRoad with_offset(double offset_m) const;

  const UniformSpline& profile() const { return profile_; }
  std::optional<double> speed_m_per_s() const override { return speed_m_per_s_; }
  double origin_m() const { return origin_m_; }
  double offset_m() const { return offset_m_; }

 private:
  UniformSpline profile_;
  double speed_m_per_s_;
  double duration_s_;
  double origin_m_;
  double offset_m_;
};

}  // namespace ridefit::road
