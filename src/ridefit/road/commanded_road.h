#pragma once

#include <functional>
#include <string>
#include <utility>

#include "ridefit/road/road_input.h"

namespace ridefit::road {

// Another road with a controlled damper's command u(t) added to its samples (RoadSample::command):
// a known command signal, such as a synthetic coil current, over any road. `road` must outlive
// this object.
class CommandedRoad : public RoadInput {
 public:
  CommandedRoad(const RoadInput& road, std::function<double(double)> command,
                std::string command_unit)
      : road_(road), command_(std::move(command)), command_unit_(std::move(command_unit)) {}

  RoadSample at(double time_s) const override {
    RoadSample sample = road_.at(time_s);
    sample.command = command_(time_s);
    return sample;
  }
  double duration_s() const override { return road_.duration_s(); }
  double max_step_s() const override { return road_.max_step_s(); }
  std::optional<double> speed_m_per_s() const override { return road_.speed_m_per_s(); }
  bool has_command() const override { return true; }
  std::string command_unit() const override { return command_unit_; }

 private:
  const RoadInput& road_;
  std::function<double(double)> command_;
  std::string command_unit_;
};

}  // namespace ridefit::road
