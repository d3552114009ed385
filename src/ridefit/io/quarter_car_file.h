#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "ridefit/model/quarter_car.h"

namespace ridefit::io {

// A quarter-car model file (YAML):
//
//   model: quarter_car
//   damper_state: stick_slip          # slip | stick | stick_slip
//   sprung_mass_kg: 385.4
//   unsprung_mass_kg: 46.76
//   tyre_stiffness_N_per_m: 288180
//   tyre_damping_Ns_per_m: 100
//   spring_stiffness_N_per_m: 29000
//   top_mount_spring_path_stiffness_N_per_m: 800000
//   top_mount_stiffness_N_per_m: 488000
//   damping_Ns_per_m: 887             # rebound (extension) coefficient c_r
//   compression_to_rebound_ratio: 1   # optional, default 1 (symmetric), in (0, 10]: the
//                                     # compression coefficient is this times c_r
//   dahl_sigma0_N_per_m: 5.0e6        # required for stick_slip, optional otherwise
//   coulomb_force_N: 60
//   dahl_exponent: 1
//
// Unknown keys, missing keys, non-numbers and out-of-range values are InputErrors naming
// the file and the key.
struct QuarterCarFile {
  model::DamperState damper_state;
  model::QuarterCarParameters<double> parameters;

  model::QuarterCar make_model() const { return {damper_state, parameters}; }
};

// `overrides` replace (or add) numeric keys before validation, e.g. {"coulomb_force_N", 30};
// `damper_state` ("" = as in the file) replaces the file's topology.
QuarterCarFile load_quarter_car(const std::filesystem::path& path,
                                const std::map<std::string, double>& overrides = {},
                                const std::string& damper_state = "");

model::DamperState parse_damper_state(const std::string& text, const std::string& where);

}  // namespace ridefit::io
