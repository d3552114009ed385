#pragma once

#include <type_traits>

#include <cmath>

namespace ridefit::model {

// Small helpers written once for every scalar the physics runs on: double, Eigen's
// AutoDiffScalar (the integrator's Jacobian) and ceres::Jet (fitting). Only operations
// that all three provide (comparison, abs, exp, log, arithmetic) are used; the functions
// are found by argument-dependent lookup.

// Sign with sgn(0) = +1. The physics only uses it where it multiplies a factor that
// vanishes at zero, so the choice affects one-sided derivatives only (see dahl_friction.h).
template <typename T>
T sign_positive_at_zero(const T& x) {
  return x < 0.0 ? T(-1.0) : T(1.0);
}

// True when `d` is exactly 1 and carries no derivative (a double, or a Jet of a value the fit
// holds): a law may then take its d = 1 form, whose tangents in d would be lost. Eigen's
// AutoDiffScalar (CVODE's Jacobian) always takes the general form: its d is never differentiated,
// and the shipped records CVODE writes follow that Jacobian's last digits (the drift test).
template <typename E>
bool held_at_one(const E& d) {
  if constexpr (std::is_arithmetic_v<E>) {
    return d == 1.0;
  } else if constexpr (requires { d.v.isZero(); }) {  // ceres::Jet
    return d == 1.0 && d.v.isZero();
  } else {
    return false;
  }
}

// sgn(s) * |s|^d for d > 0, with an exact zero at s = 0, where log|s| would be -inf. There the
// derivative with respect to d is 0 by continuity, and the one with respect to s is that of the
// power: 1 for d = 1 (s itself is returned, so tangents pass through: the Dahl element sits at
// exactly s = 0 while it slides, F = ±Fc, and the fits differentiate through it), 0 for d > 1
// and unbounded for d < 1 (0 is kept: a one-sided choice; the Dahl law takes its own,
// dahl_power below).
template <typename T, typename E>
T signed_power(const T& s, const E& d) {
  using std::abs;
  using std::exp;
  using std::log;
  if (s == 0.0) return d == 1.0 ? s : T(0.0);
  // The common d = 1 without exp and log, when d carries no derivative (a double, or a Jet of
  // an exponent the fit holds: the Dahl shape of every MR fit, evaluated at each stage).
  if (held_at_one(d)) return s;
  const T magnitude = exp(d * log(abs(s)));
  return s < 0.0 ? T(-magnitude) : magnitude;
}

// log(ε), ε = 2^-52: the smallest step s = 1 − F/Fc takes next to 0 in doubles is ε/2 … ε.
inline constexpr double kLogSignedPowerZeroStep = -36.04365338911715;

// signed_power for the Dahl law's s = 1 − (F/Fc)·sgn v, which differs at s = 0 for d < 1. There
// the slope is unbounded, and that matters: the element reaches its sliding level in finite time
// and sits at s = 0 exactly, F pinned to the level (∂F/∂Fc = 1). signed_power's zero slope froze
// the tangent of F at the value it had on arrival (0.51 where central differences give 1). The
// secant over the smallest step s takes next to 0, ε^(d−1) (36.8 for d = 0.9), stands for it:
// the tangent then follows the level's to within 1 %. A larger slope (1/ε) pins it exactly but
// makes the slope jump by 14 decades between s = 0 and the next double, and a stage whose s
// rounded differently in the Jacobian and in the residual then blew the tangent up. Only the Dahl
// law takes it: a command shaped by u^p is not a rounding of 1 − F/Fc, and at 0 A a slope of
// ε^(p−1) (3e12 at p = 0.2) would only load the Newton matrices.
template <typename T, typename E>
T dahl_power(const T& s, const E& d) {
  using std::exp;
  if (s == 0.0 && d < 1.0) return s * exp((d - 1.0) * kLogSignedPowerZeroStep);
  return signed_power(s, d);
}

// d/ds of dahl_power at s = 0 in doubles, with the same choice (1; 0 for d > 1; ε^(d−1) for
// d < 1): for Jacobians written out by hand, which must agree with the tangents the law gives in
// Jets.
inline double dahl_power_slope_at_zero(double d) {
  if (d == 1.0) return 1.0;
  return d > 1.0 ? 0.0 : std::exp((d - 1.0) * kLogSignedPowerZeroStep);
}

}  // namespace ridefit::model
