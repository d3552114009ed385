#pragma once

namespace ridefit::model {

// A viscous damper with a rebound/compression split and an optional blow-off knee: one place for
// the law, used by the quarter car's strut and by both kinds of half-car axle.
//
// The deflection rate v [m/s] is positive in extension (rebound) and the force [N] positive in
// tension. Below the knee (and always without one) the damper is linear on each side,
//
//   F = c_r·v        for v ≥ 0 (rebound, extension)
//   F = r·c_r·v      for v < 0 (compression),   r = compression_to_rebound_ratio > 0.
//
// The force is continuous (zero at v = 0) and its slope jumps from r·c_r to c_r there; at
// v = 0 exactly c_r is used (either side gives the same force). r = 1 is the linear damper
// F = c_r·v, bit for bit.
//
// Digressive valving (blow-off knee): with a knee velocity v_k > 0 [m/s]
// (damper_knee_velocity_m_per_s) the slope drops above |v| = v_k to c_h [Ns/m]
// (damping_above_knee_Ns_per_m, 0 < c_h ≤ c_r):
//
//   F = c_r·v_k + c_h·(v − v_k)          for v > v_k
//   F = r·(−c_r·v_k + c_h·(v + v_k))     for v < −v_k
//
// The knee sits at the same |v| on both sides and the compression ratio r scales both slopes
// (compression is the rebound law times r). F stays continuous, odd up to r, and strictly
// monotone (every slope > 0), so it has an explicit piecewise-linear inverse: the branch follows
// from the force (the knee forces are ±c_r·v_k, times r in compression). v_k = 0 (the default)
// means no knee, bit for bit the law above.
//
// Comparisons on a Jet or AutoDiffScalar compare the value part, so the branch follows the
// value and the derivative is that of the branch taken (one-sided at v = 0 and at the knees).
template <typename T>
struct AsymmetricDamper {
  T rebound_damping_Ns_per_m;           // c_r, the model key damping_Ns_per_m
  T compression_to_rebound_ratio{1.0};  // r, dimensionless
  T knee_velocity_m_per_s{0.0};         // v_k; 0 = no knee
  T damping_above_knee_Ns_per_m{0.0};   // c_h, read only when v_k > 0

  bool has_knee() const { return knee_velocity_m_per_s > 0.0; }

  // c(v): the low-speed (below-knee) coefficient of the side v is on.
  T damping_Ns_per_m(const T& rate_m_per_s) const {
    return rate_m_per_s < T(0.0) ? compression_to_rebound_ratio * rebound_damping_Ns_per_m
                                 : rebound_damping_Ns_per_m;
  }
  T force_N(const T& rate_m_per_s) const {
    if (!has_knee() ||
        !(rate_m_per_s > knee_velocity_m_per_s || rate_m_per_s < -knee_velocity_m_per_s)) {
      return damping_Ns_per_m(rate_m_per_s) * rate_m_per_s;
    }
    const T knee_force = rebound_damping_Ns_per_m * knee_velocity_m_per_s;
    if (rate_m_per_s > 0.0) {
      return knee_force + damping_above_knee_Ns_per_m * (rate_m_per_s - knee_velocity_m_per_s);
    }
    return compression_to_rebound_ratio *
           (-knee_force + damping_above_knee_Ns_per_m * (rate_m_per_s + knee_velocity_m_per_s));
  }
  // The rate at which the damper carries `force_N`: the inverse of force_N. Every branch has a
  // slope > 0, so the force and the rate have the same sign and the branch can be chosen from
  // the force: the inverse is explicit.
  //
  // With `parallel_Ns_per_m` c_q > 0 it is the rate u at which the damper and a dashpot c_q
  // moving with it carry `force` together, force_N(u) + c_q·u = force: every slope grows by c_q
  // and the knees' forces by c_q·v_k, so the branch still follows from the force (a free play's
  // damping, which resists the damper's rate as well as the rig's; strut_damper_path.h). c_q = 0
  // is the plain inverse, bit for bit (0 is added to each slope and knee force).
  T rate_m_per_s(const T& force, const T& parallel_Ns_per_m = T(0.0)) const {
    const T& c_q = parallel_Ns_per_m;
    if (has_knee()) {
      const T knee_force = rebound_damping_Ns_per_m * knee_velocity_m_per_s;
      const T rebound_knee = knee_force + c_q * knee_velocity_m_per_s;
      if (force > rebound_knee) {
        return knee_velocity_m_per_s + (force - rebound_knee) / (damping_above_knee_Ns_per_m + c_q);
      }
      const T compression_knee =
          compression_to_rebound_ratio * knee_force + c_q * knee_velocity_m_per_s;
      if (force < -compression_knee) {
        return -knee_velocity_m_per_s +
               (force + compression_knee) /
                   (compression_to_rebound_ratio * damping_above_knee_Ns_per_m + c_q);
      }
    }
    return force / ((force < T(0.0) ? compression_to_rebound_ratio * rebound_damping_Ns_per_m
                                    : rebound_damping_Ns_per_m) +
                    c_q);
  }
  bool symmetric() const { return compression_to_rebound_ratio == T(1.0); }
  // F proportional to v: symmetric, and without a knee or with one that keeps the slope.
  bool linear() const {
    return symmetric() && (!has_knee() || damping_above_knee_Ns_per_m == rebound_damping_Ns_per_m);
  }
};

}  // namespace ridefit::model
