#pragma once

#include <cmath>

namespace ridefit::model {

// Velocity-dependent friction level (a Stribeck curve): the force at which a friction element
// slides falls from the static (breakaway) force Fs at rest to the Coulomb force Fc at speed,
//
//   Fc(v) = Fc + (Fs − Fc) · exp(−(v/v_s)²)     [N]
//
// with sliding velocity v [m/s], coulomb_force_N = Fc [N], static_friction_force_N = Fs [N]
// (Fs ≥ Fc, the model files check it) and stribeck_velocity_m_per_s = v_s [m/s] (> 0). The
// curve is even and smooth (C∞) in v, equal to Fs at v = 0 and falling monotonically to Fc in
// |v| (for Fs ≥ Fc), so Fc(v) ≥ Fc > 0 whenever the Dahl element is active and its division by
// the level is safe. Used as the Coulomb level of DahlFriction (dahl_friction.h).
//
// v_s = 0 (or less) means no velocity dependence (the keys are absent): Fc(v) = Fc exactly, and Fs
// is not read.
template <typename T>
T stribeck_level_N(const T& coulomb_force_N, const T& static_friction_force_N,
                   const T& stribeck_velocity_m_per_s, const T& velocity_m_per_s) {
  if (!(stribeck_velocity_m_per_s > 0.0)) return coulomb_force_N;
  using std::exp;
  const T u = velocity_m_per_s / stribeck_velocity_m_per_s;
  return coulomb_force_N + (static_friction_force_N - coulomb_force_N) * exp(-(u * u));
}

}  // namespace ridefit::model
