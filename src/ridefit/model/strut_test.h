#pragma once

#include "ridefit/model/strut_damper_path.h"

namespace ridefit::model {

// Parameters of a strut on a test rig (seed 000, Section 2.2): the displacement x(t) is
// imposed across the whole assembly, the rig measures the force. Names are the YAML keys.
template <typename T>
struct StrutTestParameters {
  T dahl_sigma0_N_per_m;
  T coulomb_force_N;
  T dahl_exponent;
  T top_mount_stiffness_N_per_m;
  T damping_Ns_per_m;
  T gas_force_N;            // gas spring preload at x = 0 (compression positive: pushes out)
  T gas_stiffness_N_per_m;  // its rate
  T force_offset_N;         // load-cell offset
  // Optional Stribeck level of the Dahl element (stribeck_curve.h): Fs and v_s; v_s = 0 is off.
  // Last, with defaults, so an initialiser without them keeps the classic Dahl law.
  T static_friction_force_N{0.0};
  T stribeck_velocity_m_per_s{0.0};
  // A controlled (semi-active) damper: damping and friction level affine in the command u (the
  // record's current in A or voltage in V) after a first-order lag, the fluid's response time:
  //   c(ū) = c + c_b·ū,  Fc(ū) = Fc + Fc_b·ū,  dū/dt = (u − ū)/τ  (τ = 0: ū = u).
  // The slopes are per unit of the command's SI unit; both 0 is a passive damper.
  T damping_per_command_Ns_per_m{0.0};  // c_b [N·s/m per A or V]
  T coulomb_force_per_command_N{0.0};   // Fc_b [N per A or V]
  T command_lag_s{0.0};                 // τ
  // The measurement chain (rig-only): the load cell reads gain × the force, delayed by a time
  // and passed through a low-pass of the given order (1 or 2, critically damped) at a cutoff
  // (0 = none). A gain of 1, no delay and no cutoff is an ideal sensor.
  T force_gain{1.0};
  T force_delay_s{0.0};
  T force_sensor_cutoff_Hz{0.0};
  int force_sensor_order = 1;

  bool commanded() const {
    return damping_per_command_Ns_per_m != 0.0 || coulomb_force_per_command_N != 0.0;
  }
  bool has_lag() const { return command_lag_s > 0.0; }

  // The path at a filtered command ū (ū = 0 for a passive damper; limits in commanded_levels).
  StrutDamperPath<T> damper_path(const T& command = T(0.0)) const {
    T c = damping_Ns_per_m;
    T fc = coulomb_force_N;
    if (commanded()) {
      const CommandedLevels<T> levels =
          commanded_levels(damping_Ns_per_m, coulomb_force_N, damping_per_command_Ns_per_m,
                           coulomb_force_per_command_N, command);
      c = levels.damping_Ns_per_m;
      fc = levels.coulomb_force_N;
    }
    return {{top_mount_stiffness_N_per_m},
            {c, T(1.0)},
            {dahl_sigma0_N_per_m, fc, dahl_exponent,
             static_friction_force_N + (fc - coulomb_force_N), stribeck_velocity_m_per_s}};
  }
};

// The strut assembly on the rig: top mount k_tm in series with (damper c ∥ Dahl friction), the
// displacement x imposed across it (extension positive), and in parallel an optional gas force
// F_g0 + k_g·x and a constant offset. States y = [z_c, F_f]: the damper's own deflection and the
// Dahl force (StrutDamperPath). The rig force, tension positive, is
//   F = k_tm·(x − z_c) + F_g0 + k_g·x + F_0,
// and y' = f(y, x) with z_c' = (k_tm·(x − z_c) − F_f)/c, F_f' = Dahl(F_f, z_c') (with the Stribeck
// level Fc(z_c') when stribeck_velocity_m_per_s > 0).
//
// A controlled damper (StrutTestParameters::commanded) reads the command u(t) and, with a lag
// τ > 0, carries the filtered command ū as a third state: y = [z_c, F_f, ū], ū' = (u − ū)/τ.
struct StrutTest {
  // States for these parameters: 3 with a lagged command, else 2.
  template <typename T>
  static int state_count(const StrutTestParameters<T>& p) {
    return p.commanded() && p.has_lag() ? 3 : 2;
  }

  template <typename T>
  static void derivatives(const T* y, const T& x, const T& command, const StrutTestParameters<T>& p,
                          T* ydot) {
    const bool lagged = p.commanded() && p.has_lag();
    const StrutDamperPath<T> path = p.damper_path(lagged ? y[2] : command);
    const T path_force = path.path_force_N(x, y[0]);
    const T rate = path.damper_rate_m_per_s(path_force, y[1]);
    ydot[0] = rate;
    ydot[1] = path.friction.force_rate_N_per_s(y[1], rate);
    if (lagged) ydot[2] = (command - y[2]) / p.command_lag_s;
  }

  template <typename T>
  static T force_N(const T* y, const T& x, const StrutTestParameters<T>& p) {
    return p.top_mount_stiffness_N_per_m * (x - y[0]) + p.gas_force_N +
           p.gas_stiffness_N_per_m * x + p.force_offset_N;
  }
};

}  // namespace ridefit::model
