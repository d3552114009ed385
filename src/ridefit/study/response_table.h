#pragma once

#include <string>

#include "ridefit/io/csv_table.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace ridefit::study {

// Every channel of a quarter-car run as a CSV table, with the units and signs README documents:
// time, road, body_acc, wheel_acc, travel, tyre_force, damper_force, friction_force,
// top_mount_deflection, stuck; and damper_command in `command_unit` (the record's: A or V) when
// the damper followed a command.
io::CsvTable response_table(const simulate::QuarterCarResponse& response,
                            const std::string& command_unit);

// Every channel of a half-car run: the two roads, the body, pitch, seat and occupant
// accelerations, and per axle the wheel acceleration, travel, tyre, damper and friction forces,
// the damping coefficient in use (it varies with a semi-active law) and whether the strut is stuck.
io::CsvTable response_table(const simulate::HalfCarResponse& response);

}  // namespace ridefit::study
