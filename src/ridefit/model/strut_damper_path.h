#pragma once

#include "ridefit/model/amplitude_stiffening_spring.h"
#include "ridefit/model/asymmetric_damper.h"
#include "ridefit/model/dahl_friction.h"
#include "ridefit/model/free_play.h"

namespace ridefit::model {

// How the damper of a MacPherson strut behaves (seed 000, Figure 7).
enum class DamperState {
  kSlip,       // top mount in series with the damper: a Maxwell element
  kStick,      // damper locked: the top mount alone carries the damper path
  kStickSlip,  // top mount in series with (damper ∥ Dahl friction): a Bingham-Hooke element
};

// The damper path of a strut: top-mount spring k_tm in series with the damper c, which is
// in parallel with Dahl friction. With the suspension deflection z (travel, extension
// positive) and the damper's own deflection z_c (rod against housing), the top mount
// deflects by z − z_c and one force runs through the path:
//
//   F_path = k_tm · (z − z_c) = c · z_c' + F_f
//
// so z_c' = (k_tm·(z − z_c) − F_f) / c is explicit: no algebraic loop. z_c is a state in
// kSlip and kStickSlip, F_f a state in kStickSlip. In kStick, z_c ≡ 0 and F_path = k_tm·z.
//
// The damper may be asymmetric (AsymmetricDamper: c = c_r in rebound, z_c' > 0, and r·c_r in
// compression). Both coefficients are > 0, so z_c' has the sign of F_path − F_f: the branch is
// chosen from that known force and z_c' stays explicit, still without an algebraic loop. The same
// holds with the damper's blow-off knee (its inverse is explicit, asymmetric_damper.h).
//
// The top mount may stiffen at small amplitude (AmplitudeStiffeningSpring): F_path = F_tm(z − z_c)
// is then a smooth monotone function of the top-mount deflection instead of k_tm·(z − z_c). It is
// still computed from the states first, in every topology (stick: F_tm(z); slip and stick/slip:
// F_tm(z − z_c)), and z_c' follows from it explicitly as before.
//
// The path may have free play (free_play.h) in series: the top mount then deflects by
// D(z − z_c), the dead zone of the path's deflection, and carries no force while the slack is
// crossed. The slack may resist being crossed (free_play_damping_Ns_per_m c_p: a clevis or
// joint whose gap is filled with oil or grease, a fluid column that must flow before the
// damper's piston bears): a dashpot across the play that acts while it is open,
// c_q = c_p·(1 − D'(δ)), δ = z − z_c, so that
//
//   F_path = F_tm(D(δ)) + c_q·(z' − z_c') = c(z_c')·z_c' + F_f
//
// and z_c' = damper.rate_m_per_s(F_tm + c_q·z' − F_f, c_q), still explicit. Inside the slack
// the path then carries the damper and c_p in series (c·c_p/(c + c_p)·z' for a linear damper),
// the velocity-dependent plateau after each reversal that an MR damper on a press shows; once
// the play is taken up (D' = 1) c_q is 0 and the path is as without it. c_p = 0 (the default)
// is a dry play, bit for bit.
template <typename T>
struct StrutDamperPath {
  AmplitudeStiffeningSpring<T> top_mount;
  AsymmetricDamper<T> damper;
  DahlFriction<T> friction;
  T free_play_m{0.0};                 // b; 0 = none
  T free_play_damping_Ns_per_m{0.0};  // c_p, read only when b > 0

  // Internal states this path adds to a model.
  static int state_count(DamperState state) {
    switch (state) {
      case DamperState::kSlip:
        return 1;
      case DamperState::kStick:
        return 0;
      case DamperState::kStickSlip:
        return 2;
    }
    return 0;
  }

  T path_force_N(const T& travel_m, const T& damper_deflection_m) const {
    return top_mount.force_N(
        free_play_deflection_m(T(travel_m - damper_deflection_m), free_play_m));
  }

  // Damper deflection rate z_c' for a given path force and friction force.
  T damper_rate_m_per_s(const T& path_force_N, const T& friction_force_N) const {
    return damper.rate_m_per_s(path_force_N - friction_force_N);
  }

  // c_q: the free play's damping at the path's deflection δ (0 without it, and once the play
  // is taken up).
  T slack_damping_Ns_per_m(const T& deflection_m) const {
    if (!(free_play_m > 0.0) || !(free_play_damping_Ns_per_m > 0.0)) return T(0.0);
    return free_play_damping_Ns_per_m * (T(1.0) - free_play_slope(deflection_m, free_play_m));
  }

  // The path's force and the damper's rate z_c' at travel z, travel rate z', damper deflection
  // z_c and friction force F_f (0 for a path without friction), as above.
  struct Flow {
    T force_N;
    T damper_rate_m_per_s;
  };
  Flow flow(const T& travel_m, const T& travel_rate_m_per_s, const T& damper_deflection_m,
            const T& friction_force_N) const {
    const T deflection = travel_m - damper_deflection_m;
    const T spring = top_mount.force_N(free_play_deflection_m(deflection, free_play_m));
    const T c_q = slack_damping_Ns_per_m(deflection);
    if (!(c_q > 0.0)) return {spring, damper.rate_m_per_s(spring - friction_force_N)};
    const T rate = damper.rate_m_per_s(spring + c_q * travel_rate_m_per_s - friction_force_N, c_q);
    return {spring + c_q * (travel_rate_m_per_s - rate), rate};
  }

  // The force of a locked damper's path (z_c ≡ 0): the top mount, and the slack's damping at
  // the travel rate.
  T stuck_force_N(const T& travel_m, const T& travel_rate_m_per_s) const {
    const T spring = top_mount.force_N(free_play_deflection_m(travel_m, free_play_m));
    const T c_q = slack_damping_Ns_per_m(travel_m);
    return c_q > 0.0 ? T(spring + c_q * travel_rate_m_per_s) : spring;
  }
};

// A controlled (semi-active) damper's levels at the filtered command ū: damping and friction
// level affine in the command's shape ū^p (p = command_exponent; 1, the default, is affine in ū:
// an MR damper's yield force saturates with its coil's field, p < 1, or grows faster than the
// current at low currents, p > 1), c = c_a + c_b·ū^p and Fc = Fc_a + Fc_b·ū^p (sgn ū·|ū|^p for a
// negative command). The damping is kept at least 1 % of c_a and the friction level at least 0,
// so that a fit exploring a steep negative slope (or a command beyond the data sheet's range)
// cannot make the damper's law singular.
template <typename T>
struct CommandedLevels {
  T damping_Ns_per_m;
  T coulomb_force_N;
};

template <typename T>
CommandedLevels<T> commanded_levels(const T& damping_Ns_per_m, const T& coulomb_force_N,
                                    const T& damping_per_command_Ns_per_m,
                                    const T& coulomb_force_per_command_N, const T& command,
                                    const T& command_exponent = T(1.0)) {
  const T shaped = command_exponent == 1.0 ? command : signed_power(command, command_exponent);
  T c = damping_Ns_per_m + damping_per_command_Ns_per_m * shaped;
  if (c < 0.01 * damping_Ns_per_m) c = T(0.01) * damping_Ns_per_m;
  T fc = coulomb_force_N + coulomb_force_per_command_N * shaped;
  if (fc < 0.0) fc = T(0.0);
  return {c, fc};
}

}  // namespace ridefit::model
