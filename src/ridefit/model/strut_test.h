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

  // The rig model's damper is symmetric (ratio 1): the hysteresis fit identifies one c, and
  // strut_test_response.h writes this law out by hand for its Newton solves.
  StrutDamperPath<T> damper_path() const {
    return {{top_mount_stiffness_N_per_m},
            {damping_Ns_per_m, T(1.0)},
            {dahl_sigma0_N_per_m, coulomb_force_N, dahl_exponent, static_friction_force_N,
             stribeck_velocity_m_per_s}};
  }
};

// The strut assembly on the rig: top mount k_tm in series with (damper c ∥ Dahl friction), the
// displacement x imposed across it (extension positive), and in parallel an optional gas force
// F_g0 + k_g·x and a constant offset. States y = [z_c, F_f]: the damper's own deflection and the
// Dahl force (StrutDamperPath). The rig force, tension positive, is
//   F = k_tm·(x − z_c) + F_g0 + k_g·x + F_0,
// and y' = f(y, x) with z_c' = (k_tm·(x − z_c) − F_f)/c, F_f' = Dahl(F_f, z_c') (with the Stribeck
// level Fc(z_c') when stribeck_velocity_m_per_s > 0).
struct StrutTest {
  template <typename T>
  static void derivatives(const T* y, const T& x, const StrutTestParameters<T>& p, T* ydot) {
    const StrutDamperPath<T> path = p.damper_path();
    const T path_force = path.path_force_N(x, y[0]);
    const T rate = path.damper_rate_m_per_s(path_force, y[1]);
    ydot[0] = rate;
    ydot[1] = path.friction.force_rate_N_per_s(y[1], rate);
  }

  template <typename T>
  static T force_N(const T* y, const T& x, const StrutTestParameters<T>& p) {
    return p.top_mount_stiffness_N_per_m * (x - y[0]) + p.gas_force_N +
           p.gas_stiffness_N_per_m * x + p.force_offset_N;
  }
};

}  // namespace ridefit::model
