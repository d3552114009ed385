#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/io/model_overrides.h"
#include "ridefit/model/half_car.h"

namespace ridefit::io {

// A half-car model file (YAML; datasets/vehicles/ajayi_half_car.yaml has every key but the
// optional compression_to_rebound_ratio):
//
//   model: half_car
//   body_mass_kg: 575
//   pitch_inertia_kg_m2: 769
//   front_axle_distance_m: 1.4      # a1, ahead of the centre of gravity
//   rear_axle_distance_m: 1.4       # a2, behind it
//   seat_distance_m: 0.65           # a3, ahead of it (negative: behind)
//   front:                          # and rear:, the same keys
//     suspension: passive           # passive (spring ∥ damper) | strut (MacPherson)
//     damper_state: stick_slip      # strut: slip | stick | stick_slip
//     unsprung_mass_kg: 60
//     tyre_stiffness_N_per_m: 190000
//     tyre_damping_Ns_per_m: 350
//     spring_stiffness_N_per_m: 16812
//     damping_Ns_per_m: 1000          # rebound (extension) coefficient c_r
//     compression_to_rebound_ratio: 1 # optional, default 1 (symmetric), in (0, 10]: the
//                                     # compression coefficient is this times c_r
//     top_mount_stiffness_N_per_m: 488000   # required for a strut, checked if present
//     dahl_sigma0_N_per_m: 5.0e6            # required for stick_slip, checked if present
//     coulomb_force_N: 60
//     dahl_exponent: 1
//     # A controlled damper under the control law (each optional, as the quarter car's):
//     # c(ū) = c + c_b·ū, Fc(ū) = Fc + Fc_b·ū, ū' = (u − ū)/τ with the law's command
//     # u = (c_law − c)/c_b (so a friction slope under a law needs a damping slope).
//     damping_per_command_Ns_per_m: 1000    # c_b per A or V, in [-1e5, 1e6]
//     coulomb_force_per_command_N: 40       # Fc_b per A or V, in [-1e4, 1e4]
//     command_lag_s: 0.015                  # τ, in [0, 1]
//     # Every other optional effect of the strut's damper path, with the quarter car's keys and
//     # rules (quarter_car_file.h: top-mount stiffening, blow-off knee, Stribeck level,
//     # friction_compression_to_rebound_ratio, free_play_m, free_play_damping_Ns_per_m,
//     # command_exponent). The top mount,
//     # friction and free play act on a strut axle only; a passive axle's damper keeps its knee.
//   seat:       {mass_kg: …, stiffness_N_per_m: …, damping_Ns_per_m: …}
//   lower_body: {mass_kg: …, stiffness_N_per_m: …, damping_Ns_per_m: …}
//   upper_body: {mass_kg: …, stiffness_N_per_m: …, damping_Ns_per_m: …,
//                supported_by: seat}  # seat (seed 001) | lower_body
//   control:                        # optional; default passive
//     law: skyhook                  # passive | skyhook | groundhook | hybrid
//     min_damping_Ns_per_m: 300     # c_min <= c_max, both required unless passive
//     max_damping_Ns_per_m: 4000
//     skyhook_damping_Ns_per_m: 2500    # skyhook and hybrid
//     groundhook_damping_Ns_per_m: 2500 # groundhook and hybrid
//     skyhook_share: 0.5                # hybrid, in [0, 1]
//
// Unknown keys, missing keys, non-numbers and out-of-range values are InputErrors naming the
// file and the dotted key (e.g. 'front.damping_Ns_per_m').
struct HalfCarFile {
  model::HalfCarTopology topology;
  model::HalfCarParameters<double> parameters;

  model::HalfCar make_model() const { return {topology, parameters}; }
};

// `overrides` (model_overrides.h) replace keys by dotted path before the file is checked:
// {"front.damping_Ns_per_m", "1500"}, {"front.suspension", "strut"}. The key must exist in the
// file (an unknown one is an InputError naming it and the overrides' origin), so a typo never
// adds a key that nothing reads. The exceptions are the optional keys that stand alone with a
// default, front.compression_to_rebound_ratio and rear.compression_to_rebound_ratio (and the
// controlled damper's three keys under front and rear): an override sets them whether or not
// the file has them. The damper states are per axle (front.damper_state): a whole-car
// overrides.damper_state is refused.
HalfCarFile load_half_car(const std::filesystem::path& path, const ModelOverrides& overrides = {});

// True when `dotted_key` names a scalar of the file, or one of the optional keys an override
// may add (for checking a study before it runs).
bool half_car_has_key(const std::filesystem::path& path, const std::string& dotted_key);

}  // namespace ridefit::io
