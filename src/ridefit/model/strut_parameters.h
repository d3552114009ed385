#pragma once

#include "ridefit/model/strut_damper_path.h"

namespace ridefit::model {

// The strut's damper path, declared once: top mount, damper, Dahl friction, free play and a
// controlled damper's command law. The quarter car (QuarterCarParameters), a half-car axle
// (HalfCarAxle) and the strut on the rig (StrutTestParameters) each are a StrutParameters plus
// what they add around it (masses and tyre; the rig's gas spring and load cell), so an effect of
// the path exists once and a damper fitted on the rig runs in either car as it is. Names are the
// model files' keys (design.md); every effect is off at its default.
//
// Not an aggregate (the defaulted constructor is user-declared): a derived struct's positional
// braces then cannot fill these fields by brace elision, which would silently shift every value.
template <typename T>
struct StrutParameters {
  StrutParameters() = default;

  T top_mount_stiffness_N_per_m{0.0};  // k_tm, damper path
  T damping_Ns_per_m{0.0};             // rebound (extension) coefficient c_r
  T dahl_sigma0_N_per_m{0.0};
  T coulomb_force_N{0.0};
  T dahl_exponent{1.0};
  // Compression coefficient over rebound coefficient, c_c = r·c_r (asymmetric_damper.h).
  T compression_to_rebound_ratio{1.0};
  // Blow-off knee (asymmetric_damper.h); v_k = 0 off.
  T damper_knee_velocity_m_per_s{0.0};
  T damping_above_knee_Ns_per_m{0.0};
  // The force above the knee grows as a power n of the speed (asymmetric_damper.h); 1 straight.
  T damping_above_knee_exponent{1.0};
  // Top mount stiffer at small amplitude (amplitude_stiffening_spring.h); δ0 = 0 off.
  T top_mount_small_amplitude_stiffness_N_per_m{0.0};
  T top_mount_transition_deflection_m{0.0};
  // Stribeck level of the Dahl element (stribeck_curve.h); v_s = 0 off.
  T static_friction_force_N{0.0};
  T stribeck_velocity_m_per_s{0.0};
  // Dry-friction devices: the Dahl level in compression over that in rebound (dahl_friction.h;
  // 1 symmetric) and free play in series with the path (free_play.h; 0 none).
  T friction_compression_to_rebound_ratio{1.0};
  T free_play_m{0.0};
  // The free play's resistance while its slack is crossed (strut_damper_path.h; 0 a dry play).
  T free_play_damping_Ns_per_m{0.0};
  // A controlled (semi-active) damper: damping and friction level affine in the shaped, lagged
  // command (commanded_levels): c(ū) = c + c_b·ū^p, Fc(ū) = Fc + Fc_b·ū^p, dū/dt = (u − ū)/τ.
  // The slopes are per unit of the command's SI unit (A or V); both 0 is a passive damper.
  T damping_per_command_Ns_per_m{0.0};  // c_b
  T coulomb_force_per_command_N{0.0};   // Fc_b
  T command_lag_s{0.0};                 // τ; 0 = none
  T command_exponent{1.0};              // p; 1 = affine in ū

  bool commanded() const {
    return damping_per_command_Ns_per_m != 0.0 || coulomb_force_per_command_N != 0.0;
  }
  bool has_lag() const { return command_lag_s > 0.0; }

  // The path at a filtered command ū (0 for a passive damper; limits in commanded_levels). The
  // command moves the rebound coefficient and the friction level; the compression ratio, the
  // knee's share of the damping and the Stribeck excess over Fc stay as they are.
  StrutDamperPath<T> damper_path(const T& command = T(0.0)) const {
    T c = damping_Ns_per_m;
    T fc = coulomb_force_N;
    T above_knee = damping_above_knee_Ns_per_m;
    if (commanded()) {
      const CommandedLevels<T> levels =
          commanded_levels(damping_Ns_per_m, coulomb_force_N, damping_per_command_Ns_per_m,
                           coulomb_force_per_command_N, command, command_exponent);
      if (damper_knee_velocity_m_per_s > 0.0) {
        above_knee = above_knee * (levels.damping_Ns_per_m / c);
      }
      c = levels.damping_Ns_per_m;
      fc = levels.coulomb_force_N;
    }
    return {
        {top_mount_stiffness_N_per_m, top_mount_small_amplitude_stiffness_N_per_m,
         top_mount_transition_deflection_m},
        {c, compression_to_rebound_ratio, damper_knee_velocity_m_per_s, above_knee,
         damping_above_knee_exponent},
        {dahl_sigma0_N_per_m, fc, dahl_exponent, static_friction_force_N + (fc - coulomb_force_N),
         stribeck_velocity_m_per_s, friction_compression_to_rebound_ratio},
        free_play_m,
        free_play_damping_Ns_per_m};
  }

  // The strut part of a model (a slice of QuarterCarParameters, HalfCarAxle, StrutTestParameters).
  const StrutParameters& strut() const { return *this; }
  StrutParameters& strut() { return *this; }

  // The same parameters in another scalar (Jets for a Jacobian).
  template <typename U>
  StrutParameters<U> strut_cast() const {
    StrutParameters<U> s;
    s.top_mount_stiffness_N_per_m = U(top_mount_stiffness_N_per_m);
    s.damping_Ns_per_m = U(damping_Ns_per_m);
    s.dahl_sigma0_N_per_m = U(dahl_sigma0_N_per_m);
    s.coulomb_force_N = U(coulomb_force_N);
    s.dahl_exponent = U(dahl_exponent);
    s.compression_to_rebound_ratio = U(compression_to_rebound_ratio);
    s.damper_knee_velocity_m_per_s = U(damper_knee_velocity_m_per_s);
    s.damping_above_knee_Ns_per_m = U(damping_above_knee_Ns_per_m);
    s.damping_above_knee_exponent = U(damping_above_knee_exponent);
    s.top_mount_small_amplitude_stiffness_N_per_m = U(top_mount_small_amplitude_stiffness_N_per_m);
    s.top_mount_transition_deflection_m = U(top_mount_transition_deflection_m);
    s.static_friction_force_N = U(static_friction_force_N);
    s.stribeck_velocity_m_per_s = U(stribeck_velocity_m_per_s);
    s.friction_compression_to_rebound_ratio = U(friction_compression_to_rebound_ratio);
    s.free_play_m = U(free_play_m);
    s.free_play_damping_Ns_per_m = U(free_play_damping_Ns_per_m);
    s.damping_per_command_Ns_per_m = U(damping_per_command_Ns_per_m);
    s.coulomb_force_per_command_N = U(coulomb_force_per_command_N);
    s.command_lag_s = U(command_lag_s);
    s.command_exponent = U(command_exponent);
    return s;
  }
};

}  // namespace ridefit::model
