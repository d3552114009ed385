#pragma once

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <utility>

#include "ridefit/road/road_input.h"

namespace ridefit::testing {

// h(t) = A·sin(2πft) with a controlled damper's command u(t) given as a function: closed-form
// roads for the commanded quarter car, independent of the measured road's interpolation.
class CommandedSineRoad : public road::RoadInput {
 public:
  CommandedSineRoad(double amplitude_m, double frequency_Hz, double duration_s,
                    std::function<double(double)> command)
      : amplitude_m_(amplitude_m),
        omega_(2.0 * std::numbers::pi * frequency_Hz),
        duration_s_(duration_s),
        command_(std::move(command)) {}
  road::RoadSample at(double t) const override {
    return {amplitude_m_ * std::sin(omega_ * t), amplitude_m_ * omega_ * std::cos(omega_ * t),
            command_(t)};
  }
  double duration_s() const override { return duration_s_; }
  double max_step_s() const override { return 0.25 * 2.0 * std::numbers::pi / omega_; }
  bool has_command() const override { return true; }
  std::string command_unit() const override { return "A"; }

 private:
  double amplitude_m_;
  double omega_;
  double duration_s_;
  std::function<double(double)> command_;
};

}  // namespace ridefit::testing
