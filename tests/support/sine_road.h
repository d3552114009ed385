#pragma once

#include <cmath>
#include <numbers>

#include "ridefit/road/road_input.h"

namespace ridefit::testing {

// h(t) = A·sin(2πft), for closed-form comparisons without depending on the road module.
class SineRoad : public road::RoadInput {
 public:
  SineRoad(double amplitude_m, double frequency_Hz, double duration_s)
      : amplitude_m_(amplitude_m),
        omega_(2.0 * std::numbers::pi * frequency_Hz),
        duration_s_(duration_s) {}
  road::RoadSample at(double t) const override {
    return {amplitude_m_ * std::sin(omega_ * t), amplitude_m_ * omega_ * std::cos(omega_ * t)};
  }
  double duration_s() const override { return duration_s_; }
  double max_step_s() const override { return 0.25 * 2.0 * std::numbers::pi / omega_; }

 private:
  double amplitude_m_;
  double omega_;
  double duration_s_;
};

}  // namespace ridefit::testing
