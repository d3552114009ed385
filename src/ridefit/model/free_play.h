#pragma once

namespace ridefit::model {

// Free play (backlash) of total width b [m] in series with a strut's damper path: a mechanism
// (rack and pinion, a worn joint, a loose rod end) that transmits no force until its slack is
// taken up. The deflection δ across the path is passed on as the dead zone
//
//   D(δ) = δ − b/2 (δ > b/2),  0 (|δ| ≤ b/2),  δ + b/2 (δ < −b/2),
//
// so the path carries no force while the slack is being crossed after a reversal, then its full
// stiffness. The corners are rounded over ±r about ±b/2 (r = b/100) by a quadratic that joins
// value and slope: D is C1 with D' from 0 to 1, so an implicit integrator's Newton iteration and
// a fit's derivatives see no jump, and the force is exactly zero in the middle of the slack
// (a smooth approximation that leaks force everywhere would, with a stiff path, put newtons
// where a real free play has none; wider rounding also made the dry-friction damper's records fit
// worse and its runs slower). b = 0 means none: D(δ) = δ, bit for bit.
inline constexpr double kFreePlayRoundingShare = 0.01;  // r / b

template <typename T>
T free_play_deflection_m(const T& deflection_m, const T& free_play_m) {
  if (!(free_play_m > 0.0)) return deflection_m;
  const T half = 0.5 * free_play_m;
  const T r = kFreePlayRoundingShare * free_play_m;
  const bool negative = deflection_m < 0.0;
  const T magnitude = negative ? T(-deflection_m) : deflection_m;
  T out;
  if (magnitude <= half - r) {
    out = T(0.0) * deflection_m;  // (keeps the derivative lanes, all zero)
  } else if (magnitude < half + r) {
    const T u = magnitude - half + r;
    out = u * u / (4.0 * r);
  } else {
    out = magnitude - half;
  }
  return negative ? T(-out) : out;
}

// D'(δ): 0 inside the slack, 1 beyond it, linear across the rounded corners.
template <typename T>
T free_play_slope(const T& deflection_m, const T& free_play_m) {
  if (!(free_play_m > 0.0)) return T(1.0);
  const T half = 0.5 * free_play_m;
  const T r = kFreePlayRoundingShare * free_play_m;
  const T magnitude = deflection_m < 0.0 ? T(-deflection_m) : deflection_m;
  if (magnitude <= half - r) return T(0.0) * deflection_m;
  if (magnitude < half + r) return (magnitude - half + r) / (2.0 * r);
  return T(1.0) + T(0.0) * deflection_m;
}

}  // namespace ridefit::model
