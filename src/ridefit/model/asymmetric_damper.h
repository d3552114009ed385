#pragma once

namespace ridefit::model {

// A viscous damper with a rebound/compression split: one place for the law, used by the
// quarter car's strut and by both kinds of half-car axle.
//
// The deflection rate v is positive in extension (rebound) and the force c(v)·v positive in
// tension, with
//
//   c(v) = c_r       for v > 0 (rebound, extension)
//   c(v) = r · c_r   for v < 0 (compression),   r = compression_to_rebound_ratio > 0.
//
// The force is continuous (zero at v = 0) and its slope jumps from r·c_r to c_r there; at
// v = 0 exactly c_r is used (either side gives the same force). r = 1 is the linear damper
// F = c_r·v, bit for bit.
//
// Comparisons on a Jet or AutoDiffScalar compare the value part, so the branch follows the
// value and the derivative is that of the branch taken (one-sided at v = 0).
template <typename T>
struct AsymmetricDamper {
  T rebound_damping_Ns_per_m;           // c_r, the model key damping_Ns_per_m
  T compression_to_rebound_ratio{1.0};  // r, dimensionless

  // c(v): the coefficient acting at deflection rate v.
  T damping_Ns_per_m(const T& rate_m_per_s) const {
    return rate_m_per_s < T(0.0) ? compression_to_rebound_ratio * rebound_damping_Ns_per_m
                                 : rebound_damping_Ns_per_m;
  }
  T force_N(const T& rate_m_per_s) const { return damping_Ns_per_m(rate_m_per_s) * rate_m_per_s; }
  // The rate at which the damper carries `force_N`: the inverse of force_N. Both branches
  // have c > 0, so the force and the rate have the same sign and the branch can be chosen
  // from the force: the inverse is explicit.
  T rate_m_per_s(const T& force) const {
    return force / (force < T(0.0) ? compression_to_rebound_ratio * rebound_damping_Ns_per_m
                                   : rebound_damping_Ns_per_m);
  }
  bool symmetric() const { return compression_to_rebound_ratio == T(1.0); }
};

}  // namespace ridefit::model
