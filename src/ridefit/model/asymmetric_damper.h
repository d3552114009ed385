#pragma once

#include <cmath>

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
// Above the knee the force may grow as a power of the speed (exponent_above_knee n > 0,
// damping_above_knee_exponent in the model files):
//
//   F = c_r·v_k + c_h·v_k·((v/v_k)^n − 1)/n          for v > v_k (times r, mirrored, for v < −v_k)
//
// with the slope c_h at the knee, c_h·(v/v_k)^(n−1) beyond it: n < 1 flattens with speed as the
// shear-thinning fluid of an MR damper does (its steady force grows about as ln v from 5 to
// 120 mm/s on the UTFSM records: n → 0 is c_h·v_k·ln(v/v_k)), n > 1 is progressive. Still
// continuous and strictly monotone; its inverse is explicit (below). n = 1 (the default) is the
// straight slope above, bit for bit.
//
// Comparisons on a Jet or AutoDiffScalar compare the value part, so the branch follows the
// value and the derivative is that of the branch taken (one-sided at v = 0 and at the knees).
template <typename T>
struct AsymmetricDamper {
  T rebound_damping_Ns_per_m;           // c_r, the model key damping_Ns_per_m
  T compression_to_rebound_ratio{1.0};  // r, dimensionless
  T knee_velocity_m_per_s{0.0};         // v_k; 0 = no knee
  T damping_above_knee_Ns_per_m{0.0};   // c_h, read only when v_k > 0
  T exponent_above_knee{1.0};           // n, read only when v_k > 0; 1 = a straight slope

  bool has_knee() const { return knee_velocity_m_per_s > 0.0; }
  // n = 1 and not differentiated in n (a Jet of a held exponent, any other scalar at 1): the
  // straight slope's own formulas, bit for bit as before the exponent; a fitted n keeps its
  // tangent through the general form.
  bool straight_above_knee() const {
    if constexpr (requires { exponent_above_knee.v.isZero(); }) {  // ceres::Jet
      return exponent_above_knee == 1.0 && exponent_above_knee.v.isZero();
    } else {
      return exponent_above_knee == 1.0;
    }
  }

  // The rebound law at a speed w > v_k above the knee, and its slope there.
  T above_knee_force_N(const T& speed_m_per_s) const {
    const T knee_force = rebound_damping_Ns_per_m * knee_velocity_m_per_s;
    if (straight_above_knee()) {
      return knee_force + damping_above_knee_Ns_per_m * (speed_m_per_s - knee_velocity_m_per_s);
    }
    using std::exp;
    using std::log;
    const T power = exp(exponent_above_knee * log(speed_m_per_s / knee_velocity_m_per_s));
    return knee_force + damping_above_knee_Ns_per_m * knee_velocity_m_per_s * (power - 1.0) /
                            exponent_above_knee;
  }
  T above_knee_slope_Ns_per_m(const T& speed_m_per_s) const {
    if (straight_above_knee()) return damping_above_knee_Ns_per_m;
    using std::exp;
    using std::log;
    return damping_above_knee_Ns_per_m *
           exp((exponent_above_knee - 1.0) * log(speed_m_per_s / knee_velocity_m_per_s));
  }

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
    if (!straight_above_knee()) {
      return rate_m_per_s > 0.0
                 ? above_knee_force_N(rate_m_per_s)
                 : T(-compression_to_rebound_ratio * above_knee_force_N(T(-rate_m_per_s)));
    }
    const T knee_force = rebound_damping_Ns_per_m * knee_velocity_m_per_s;
    if (rate_m_per_s > 0.0) {
      return knee_force + damping_above_knee_Ns_per_m * (rate_m_per_s - knee_velocity_m_per_s);
    }
    return compression_to_rebound_ratio *
           (-knee_force + damping_above_knee_Ns_per_m * (rate_m_per_s + knee_velocity_m_per_s));
  }

  // The speed w > v_k above the knee at which scale·F_above(w) + c_q·w = target (scale 1 in
  // rebound, r in compression, target above the knee's own): closed form without c_q; with it,
  // Newton's method from the side where the tangent never overshoots (φ is concave for n < 1 and
  // convex for n > 1, and φ(w) ≥ φ(v_k) + c_q·(w − v_k) bounds the root), in T so that Jets
  // carry the derivative of the converged root.
  T above_knee_speed_m_per_s(const T& target, const T& scale, const T& c_q) const {
    using std::abs;
    using std::exp;
    using std::log;
    const T& v_k = knee_velocity_m_per_s;
    const T& n = exponent_above_knee;
    const T knee_force = rebound_damping_Ns_per_m * v_k;
    if (!(c_q > 0.0)) {
      const T base = 1.0 + n * (target / scale - knee_force) / (damping_above_knee_Ns_per_m * v_k);
      return v_k * exp(log(base) / n);
    }
    // (-> T: an AutoDiffScalar expression would outlive the temporaries it refers to.)
    const auto phi = [&](const T& w) -> T { return scale * above_knee_force_N(w) + c_q * w; };
    T w = n < 1.0 ? v_k : T(v_k + (target - phi(v_k)) / c_q);
    for (int iteration = 0; iteration < 60; ++iteration) {
      const T step = (target - phi(w)) / (scale * above_knee_slope_Ns_per_m(w) + c_q);
      w += step;
      if (!(w > v_k)) w = v_k;
      if (!(abs(step) > 1e-13 * w)) break;
    }
    return w;
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
    if (has_knee() && !straight_above_knee()) {
      const T knee_force = rebound_damping_Ns_per_m * knee_velocity_m_per_s;
      if (force > knee_force + c_q * knee_velocity_m_per_s) {
        return above_knee_speed_m_per_s(force, T(1.0), c_q);
      }
      if (force < -(compression_to_rebound_ratio * knee_force + c_q * knee_velocity_m_per_s)) {
        return -above_knee_speed_m_per_s(T(-force), compression_to_rebound_ratio, c_q);
      }
    } else if (has_knee()) {
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
    return symmetric() &&
           (!has_knee() || (damping_above_knee_Ns_per_m == rebound_damping_Ns_per_m &&
                            exponent_above_knee == 1.0));
  }
};

}  // namespace ridefit::model
