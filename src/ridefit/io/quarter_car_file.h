#pragma once

#include <filesystem>
#include <string>

#include "ridefit/io/model_overrides.h"
#include "ridefit/io/yaml_map.h"
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
// Optional physical effects, each off when its keys are absent (results then bit for bit as
// without them); the laws are in the model headers named:
//
//   # Top mount (damper path) stiffer at small amplitude, amplitude_stiffening_spring.h:
//   #   F = k_l·δ + (k_s − k_l)·δ0·tanh(δ/δ0), k_l = top_mount_stiffness_N_per_m. Both keys.
//   top_mount_small_amplitude_stiffness_N_per_m: 707000   # k_s, >= k_l
//   top_mount_transition_deflection_m: 0.0002              # δ0, in (0, 1]
//   # Bump stop beyond a compression clearance c0, bump_stop.h: with compression c = −travel,
//   #   F = k_bs·c0·((c − c0)/c0)^n for c > c0 (k_bs in N/m for every n). Stiffness and clearance.
//   bump_stop_stiffness_N_per_m: 200000    # k_bs, in (0, 1e10]
//   bump_stop_clearance_m: 0.03            # c0, in (0, 1]
//   bump_stop_exponent: 2                  # n, in [1, 10], default 2
//   # Unilateral tyre, tyre_lift_off.h: dynamic tyre force max(F, −(ms + mu)·g).
//   tyre_lift_off: true                    # true | false | 1 | 0, default false
//   # Damper blow-off knee, asymmetric_damper.h: slope c_h above |v| = v_k (times the
//   # compression ratio in compression). Both keys.
//   damper_knee_velocity_m_per_s: 0.1      # v_k, in (0, 10]
//   damping_above_knee_Ns_per_m: 300       # c_h, in (0, damping_Ns_per_m]
//   damping_above_knee_exponent: 0.4       # n, in (0, 5], default 1: F grows as |v|^n above
//   # Stribeck level of the Dahl element, stribeck_curve.h (needs coulomb_force_N > 0):
//   #   Fc(v) = Fc + (Fs − Fc)·exp(−(v/v_s)²).
//   stribeck_velocity_m_per_s: 0.01        # v_s, in (0, 10]; switches it on
//   static_friction_force_N: 90            # Fs, in [coulomb_force_N, 1e5], default Fc
//   # Controlled (semi-active) damper, strut_test.h: c(ū) = c + c_b·ū, Fc(ū) = Fc + Fc_b·ū,
//   # ū' = (u − ū)/τ with u the record's command (current[A] or voltage[V]); each optional.
//   # Rig tests and vehicle records read u from their current or voltage column (a measured
//   # excitation's too); without one the damper runs at u = 0.
//   damping_per_command_Ns_per_m: 2000     # c_b per A or V, in [-1e5, 1e6]
//   coulomb_force_per_command_N: 200       # Fc_b per A or V, in [-1e4, 1e4]
//   command_lag_s: 0.01                    # τ, in [0, 1]; 0 = ū follows u at once
//   command_exponent: 1.2                  # p: levels affine in ū^p, in (0, 10], default 1
//   # Dry-friction devices and slack, dahl_friction.h, free_play.h, strut_damper_path.h:
//   friction_compression_to_rebound_ratio: 0.85   # Dahl level in compression over rebound
//   free_play_m: 0.0002                    # b, total width of the slack, in [0, 1]; 0 = none
//   free_play_damping_Ns_per_m: 60000      # c_p while the slack is crossed; needs free_play_m
//
// Optional measuring chain of the accelerometers (acceleration_sensors.h): not physics, what the
// spectral comparisons (fit psd, diagnose) apply to the simulated PSDs, g²·|H(f)|²·P_sim.
//   body_acc_gain: 0.9                     # measured over true body_acc, in (0, 10], default 1
//   wheel_acc_gain: 1                      # the same for wheel_acc
//   acc_sensor_cutoff_Hz: 15               # low-pass corner f_c, in [0, 1e5]; 0 = none (default)
//   acc_sensor_order: 2                    # 1: |H|² = 1/(1 + (f/f_c)²); 2: its square (two
//                                          # first-order stages); default 1, needs the cutoff key
//
// Every numeric key can be given by `--set key=value` (tyre_lift_off=1 or 0 included).
// Unknown keys, missing keys, non-numbers and out-of-range values are InputErrors naming
// the file and the key.
struct QuarterCarFile {
  model::DamperState damper_state;
  model::QuarterCarParameters<double> parameters;

  model::QuarterCar make_model() const { return {damper_state, parameters}; }
};

// The strut's optional effects (top-mount stiffening, blow-off knee, Stribeck level, dry
// friction's direction ratio and free play, the controlled damper's command law), each off when
// its keys are absent: the keys and rules above, for a quarter-car file and each half-car axle
// alike.
void read_strut_effects(const YamlMap& file, model::StrutParameters<double>& p);

// `overrides` (model_overrides.h) replace or add keys before the file is checked, and may
// replace its damper state; "model" and "damper_state" are not keys an override may set.
QuarterCarFile load_quarter_car(const std::filesystem::path& path,
                                const ModelOverrides& overrides = {});

model::DamperState parse_damper_state(const std::string& text, const std::string& where);

}  // namespace ridefit::io
