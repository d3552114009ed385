#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "ridefit/model/parameter_info.h"

namespace ridefit::model {

// The rows of a strut on the test rig that a vehicle model does not have (strut_test.h): the gas
// spring, the load cell's chain and the mass it carries. The strut's damper-path parameters are
// quarter-car rows (quarter_car_parameter_table.h). Not read from a model file: these come from a
// fit.
inline constexpr std::array<ParameterInfo, 7> kStrutRigParameters{{
    {"gas_force_N", "N", -1e4, 1e4, false, false,
     "gas spring preload at zero travel (compression positive: pushes out)"},
    {"gas_stiffness_N_per_m", "N/m", -1e6, 1e6, false, false, "the gas spring's rate"},
    {"force_offset_N", "N", -1e4, 1e4, false, false, "load-cell offset"},
    {"force_gain", "1", 0.0, 10.0, true, false, "load cell's measured over true force"},
    {"force_delay_s", "s", 0.0, 1.0, false, false, "load cell's delay behind the displacement"},
    {"force_sensor_cutoff_Hz", "Hz", 0.0, 1e5, false, false,
     "load cell's first-order low-pass corner; 0 = none"},
    {"moving_mass_kg", "kg", 0.0, 1e5, false, false,
     "mass moving between the load cell and the damper (rod, fixture, a friction device's "
     "drum as the rod sees it): the load cell also reads its inertia force"},
}};

// The rig-only rows by name (as model::quarter_car_rows).
namespace strut_rig_rows {
inline constexpr const ParameterInfo& gas_force_N = kStrutRigParameters[0];
inline constexpr const ParameterInfo& gas_stiffness_N_per_m = kStrutRigParameters[1];
inline constexpr const ParameterInfo& force_offset_N = kStrutRigParameters[2];
inline constexpr const ParameterInfo& force_gain = kStrutRigParameters[3];
inline constexpr const ParameterInfo& force_delay_s = kStrutRigParameters[4];
inline constexpr const ParameterInfo& force_sensor_cutoff_Hz = kStrutRigParameters[5];
inline constexpr const ParameterInfo& moving_mass_kg = kStrutRigParameters[6];
}  // namespace strut_rig_rows

}  // namespace ridefit::model
