#pragma once

#include <optional>
#include <string>

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"

namespace ridefit::study {

// A controlled damper follows the record's command (a current or voltage column of a measured
// excitation). When only one of the two is there, the run still goes ahead (passive, or at
// command 0), and this says so, naming both files; nothing when they agree.
std::optional<std::string> damper_command_note(const model::QuarterCar& car,
                                               const road::RoadInput& road,
                                               const std::string& model_file,
                                               const std::string& excitation_file);

}  // namespace ridefit::study
