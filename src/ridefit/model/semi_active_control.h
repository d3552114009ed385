#pragma once

#include <algorithm>
#include <string>

namespace ridefit::model {

// Semi-active damping laws (seed 001's control forces u_f, u_r). A semi-active damper can only
// dissipate: it chooses its coefficient c within [c_min, c_max] at each instant, so its force
// is always c·v_rel with the sign of the suspension's extension rate v_rel. What the laws ask
// for, with v_b the absolute velocity of the body above the axle and v_u that of the wheel:
//
//   skyhook:    the force −c_sky·v_b of a damper to the sky on the body. Achievable when
//               v_b·v_rel > 0: c = c_sky·v_b/v_rel; otherwise the least, c_min.
//   groundhook: the force −c_gnd·v_u of a damper to the ground on the wheel (road holding).
//               Achievable when −v_u·v_rel > 0: c = −c_gnd·v_u/v_rel; otherwise c_min.
//   hybrid:     c = α·(skyhook request) + (1 − α)·(groundhook request), with each request 0
//               where it is not achievable; α = skyhook_share.
//   passive:    the axle's own damping_Ns_per_m, always.
//
// Every request is clipped to [c_min, c_max] (the "clipped continuous" form; the on-off form
// is c_sky → ∞). v_rel is the suspension's deflection rate, which a controller measures; in
// a strut the damper's own rate differs from it by the top mount's deflection rate, and using
// that instead would make c depend on itself. Friction (Dahl) stays in parallel with the
// controlled damper: the controller cannot remove it (seed 000, Section 1).
//
// An asymmetric damper (the axle's compression_to_rebound_ratio r ≠ 1, AsymmetricDamper): the
// law's c is the rebound setting, and in compression the damper gives r·c. The split is a
// property of the damper's valves, which the controller's command scales as a whole, so in
// compression the clipping range is r·[c_min, c_max] and the skyhook or groundhook force is r
// times the requested one. With r = 1 the law is as above.
enum class ControlLaw { kPassive, kSkyhook, kGroundhook, kHybrid };

struct SemiActiveControl {
  ControlLaw law = ControlLaw::kPassive;
  double min_damping_Ns_per_m = 0.0;
  double max_damping_Ns_per_m = 0.0;
  double skyhook_damping_Ns_per_m = 0.0;
  double groundhook_damping_Ns_per_m = 0.0;
  double skyhook_share = 0.5;  // α of the hybrid law

  // The damper coefficient now. `passive_damping` is the axle's damping_Ns_per_m.
  template <typename T>
  T damping(const T& body_velocity, const T& wheel_velocity, const T& passive_damping) const {
    if (law == ControlLaw::kPassive) return passive_damping;
    const T relative = body_velocity - wheel_velocity;
    const T zero(0.0);
    T sky = zero;
    if (body_velocity * relative > zero)
      sky = T(skyhook_damping_Ns_per_m) * body_velocity / relative;
    T ground = zero;
    if (-wheel_velocity * relative > zero) {
      ground = -T(groundhook_damping_Ns_per_m) * wheel_velocity / relative;
    }
    T request = zero;
    switch (law) {
      case ControlLaw::kSkyhook:
        request = sky;
        break;
      case ControlLaw::kGroundhook:
        request = ground;
        break;
      case ControlLaw::kHybrid:
        request = T(skyhook_share) * sky + T(1.0 - skyhook_share) * ground;
        break;
      case ControlLaw::kPassive:
        break;
    }
    if (request < T(min_damping_Ns_per_m)) return T(min_damping_Ns_per_m);
    if (request > T(max_damping_Ns_per_m)) return T(max_damping_Ns_per_m);
    return request;
  }
};

// "passive" | "skyhook" | "groundhook" | "hybrid" and back.
const char* to_string(ControlLaw law);

}  // namespace ridefit::model
