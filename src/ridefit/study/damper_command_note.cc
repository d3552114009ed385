#include "ridefit/study/damper_command_note.h"

#include <fmt/core.h>

namespace ridefit::study {

std::optional<std::string> damper_command_note(const model::QuarterCar& car,
                                               const road::RoadInput& road,
                                               const std::string& model_file,
                                               const std::string& excitation_file) {
  if (road.has_command() && !car.follows_command()) {
    return fmt::format(
        "{} carries a damper command ({}), but {} has no damping_per_command_Ns_per_m or "
        "coulomb_force_per_command_N: the damper stays passive",
        excitation_file, road.command_unit(), model_file);
  }
  if (!road.has_command() && car.parameters().commanded()) {
    return fmt::format(
        "{} describes a controlled damper, but {} carries no command (a current or voltage "
        "column of a measured excitation): the damper runs at command 0",
        model_file, excitation_file);
  }
  return std::nullopt;
}

}  // namespace ridefit::study
