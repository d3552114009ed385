#pragma once

#include "ridefit/model/scalar_math.h"
#include "ridefit/model/stribeck_curve.h"

namespace ridefit::model {

// Dahl friction (seed 000, Section 3.1). The friction force F is a state:
//
//   dF/dt = σ0 · v · |1 − (F/Fc)·sgn v|^d · sgn(1 − (F/Fc)·sgn v)
//
// with sliding velocity v, pre-sliding (contact) stiffness σ0, Coulomb force Fc and shape
// exponent d. From rest with d = 1 and constant-sign motion, F(x) = Fc(1 − exp(−σ0 x / Fc)).
//
// The kink at v = 0: the right-hand side is continuous there, because every branch is
// multiplied by v and so vanishes; only its slope ∂(dF/dt)/∂v jumps, from
// σ0·|1 + F/Fc|^d·sgn(1 + F/Fc) (v < 0) to σ0·|1 − F/Fc|^d·sgn(1 − F/Fc) (v > 0). We take
// sgn 0 = +1, i.e. the v > 0 branch's slope at exactly v = 0 (a one-sided derivative, which
// Newton iterations and Ceres tolerate; exact zeros of v are rare in floating point).
//
// Fc = 0 means no friction: the force stays at zero (the formula would divide by zero).
//
// Optional velocity dependence (Stribeck, stribeck_curve.h): with stribeck_velocity_m_per_s
// v_s > 0, Fc in the law above becomes the level Fc(v) = Fc + (Fs − Fc)·exp(−(v/v_s)²) at the
// same sliding velocity v, so gross sliding settles at F = Fc(v)·sgn v: the breakaway force
// Fs near rest, Fc at speed. Fc(v) ≥ Fc > 0 keeps the division safe; the right-hand side stays
// continuous at v = 0 (still multiplied by v). v_s = 0 (the default) is the classic law, bit for
// bit. The element is active only with Fc > 0.
//
// Optional asymmetry: the level in compression (v < 0) is r times the level in rebound (v > 0),
// r = compression_to_rebound_ratio (a dry-friction device whose sliding force differs with the
// direction; 1, the default, is symmetric). The law is still multiplied by v, so the right-hand
// side stays continuous at v = 0.
template <typename T>
struct DahlFriction {
  T sigma0_N_per_m;
  T coulomb_force_N;
  T exponent;
  T static_friction_force_N{0.0};       // Fs, read only when v_s > 0
  T stribeck_velocity_m_per_s{0.0};     // v_s; 0 = no velocity dependence
  T compression_to_rebound_ratio{1.0};  // r: compression level over rebound level

  bool active() const { return coulomb_force_N > 0.0; }

  // The sliding level Fc(v) [N] (Fc without the Stribeck keys).
  T level_N(const T& velocity_m_per_s) const {
    const T level = stribeck_level_N(coulomb_force_N, static_friction_force_N,
                                     stribeck_velocity_m_per_s, velocity_m_per_s);
    return velocity_m_per_s < 0.0 ? T(level * compression_to_rebound_ratio) : level;
  }

  T force_rate_N_per_s(const T& force_N, const T& velocity_m_per_s) const {
    if (!active()) return T(0.0);
    const T s =
        T(1.0) - force_N / level_N(velocity_m_per_s) * sign_positive_at_zero(velocity_m_per_s);
    return sigma0_N_per_m * velocity_m_per_s * dahl_power(s, exponent);
  }
};

}  // namespace ridefit::model
