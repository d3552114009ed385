#pragma once

#include "ridefit/model/strut_parameters.h"

namespace ridefit::model {

// Parameters of a strut on a test rig (seed 000, Section 2.2): the displacement x(t) is
// imposed across the whole assembly, the rig measures the force. The strut is StrutParameters
// (the cars' own); the rig adds its gas spring and the load cell. Names are the YAML keys.
template <typename T>
struct StrutTestParameters : StrutParameters<T> {
  T gas_force_N{0.0};            // gas spring preload at x = 0 (compression positive: pushes out)
  T gas_stiffness_N_per_m{0.0};  // its rate
  T force_offset_N{0.0};         // load-cell offset
  // The measurement chain (rig-only): the load cell reads gain × the force, delayed by a time
  // and passed through a low-pass of the given order (1 or 2, critically damped) at a cutoff
  // (0 = none). A gain of 1, no delay and no cutoff is an ideal sensor.
  T force_gain{1.0};
  T force_delay_s{0.0};
  T force_sensor_cutoff_Hz{0.0};
  int force_sensor_order = 1;
  // The mass between the load cell and the damper: the cell reads m·ẍ beside the strut's force
  // (a rig's "inertia compensation" subtracts it; a record that was not compensated carries it).
  T moving_mass_kg{0.0};

  // The strut's damper path on the rig, with no gas spring, no offset and an ideal load cell
  // (rig-only, zero until fitted): a damper from a car runs on the rig as it is.
  static StrutTestParameters on_rig(const StrutParameters<T>& strut) {
    StrutTestParameters p;
    p.strut() = strut;
    return p;
  }

  // The same parameters in another scalar (Jets for a Jacobian).
  template <typename U>
  StrutTestParameters<U> cast() const {
    StrutTestParameters<U> p;
    p.strut() = this->template strut_cast<U>();
    p.gas_force_N = U(gas_force_N);
    p.gas_stiffness_N_per_m = U(gas_stiffness_N_per_m);
    p.force_offset_N = U(force_offset_N);
    p.force_gain = U(force_gain);
    p.force_delay_s = U(force_delay_s);
    p.force_sensor_cutoff_Hz = U(force_sensor_cutoff_Hz);
    p.force_sensor_order = force_sensor_order;
    p.moving_mass_kg = U(moving_mass_kg);
    return p;
  }
};

// The seed's Dahl strut on the rig (σ0, Fc, d, k_tm, c), every other effect off, no gas spring,
// no offset and an ideal load cell.
template <typename T>
StrutTestParameters<T> dahl_strut_on_rig(const T& sigma0_N_per_m, const T& coulomb_force_N,
                                         const T& dahl_exponent, const T& top_mount_N_per_m,
                                         const T& damping_Ns_per_m) {
  StrutTestParameters<T> p;
  p.dahl_sigma0_N_per_m = sigma0_N_per_m;
  p.coulomb_force_N = coulomb_force_N;
  p.dahl_exponent = dahl_exponent;
  p.top_mount_stiffness_N_per_m = top_mount_N_per_m;
  p.damping_Ns_per_m = damping_Ns_per_m;
  return p;
}

// A damper path whose relaxation time c/k_tm is below this [s] (a rigid mount: 1e9 N/m against
// 1e4 N·s/m; a dry-friction device with next to no viscous damping) runs in its quasi-static
// limit on the rig (StrutTest): resolving a relaxation of microseconds took the implicit solver
// tens of thousands of failed Newton iterations per second of record, and it is far faster than
// anything a rig record samples.
inline constexpr double kQuasiStaticPathTime_s = 1e-5;
// τ: how fast a quasi-static path returns to its equilibrium when a step has left it (below).
inline constexpr double kQuasiStaticRecovery_s = 1e-4;

// The strut assembly on the rig: top mount k_tm in series with (damper c ∥ Dahl friction), the
// displacement x imposed across it (extension positive), and in parallel an optional gas force
// F_g0 + k_g·x and a constant offset. States y = [z_c, F_f]: the damper's own deflection and the
// Dahl force (StrutDamperPath). The rig force, tension positive, is
//   F = F_tm(D(x − z_c)) + F_g0 + k_g·x + F_0
// (D the free play's dead zone, identity without it), and y' = f(y, x) with
// z_c' = (F_tm − F_f)/c, F_f' = Dahl(F_f, z_c') (with the Stribeck level Fc(z_c') when
// stribeck_velocity_m_per_s > 0).
//
// Quasi-static path (c/k_tm < kQuasiStaticPathTime_s): the path force is in equilibrium with the
// damper and the friction at every instant, F_tm = F_f + c·z_c'. Differentiating it and dropping
// c·z_c'' (a term of relative size c/k_tm times the record's rates) gives the damper rate
// explicitly from the rig's velocity x':
//   z_c' = k·x' / (k + σ0·s),   k = k_tm·D'(x − z_c),  s = |1 − F_f/L·sgn x'|^d ≥ 0,
// the share of the motion the friction element takes (all of it while sliding, s = 0; none
// inside the free play, D' = 0), and the force F = F_f + c·z_c' + F_g0 + k_g·x + F_0. With a
// rigid mount this is the classic F = c·x' + F_f(x). The states stay [z_c, F_f], so the output
// and the derivatives read them as before. The equilibrium's residual R = F_tm − F_f − c·z_c'
// decays with τ = kQuasiStaticRecovery_s (R' = −R/τ) rather than being assumed to stay zero:
//   z_c' = (k·x' + (F_tm − F_f)/τ) / (k + σ0·s + c/τ),
// the same rate as above while R = 0, and inside the slack (k = 0, F_tm = 0) a friction force
// left from before the reversal unloads, as the real element does, instead of staying frozen.
// A damped free play (free_play_damping_Ns_per_m c_p) adds c_q·(x' − z_c') to F_tm in R,
// c_q = c_p·(1 − D'), so c becomes c + c_q and F_tm becomes F_tm + c_q·x' above: inside the
// slack the damper and c_q then carry the rig's motion in series.
//
// A controlled damper (StrutTestParameters::commanded) reads the command u(t) and, with a lag
// τ > 0, carries the filtered command ū as a third state: y = [z_c, F_f, ū], ū' = (u − ū)/τ.
struct StrutTest {
  // States for these parameters: 3 with a lagged command, else 2.
  template <typename T>
  static int state_count(const StrutTestParameters<T>& p) {
    return p.commanded() && p.has_lag() ? 3 : 2;
  }

  template <typename T>
  static bool quasi_static(const StrutTestParameters<T>& p) {
    return p.damping_Ns_per_m < kQuasiStaticPathTime_s * p.top_mount_stiffness_N_per_m;
  }

  // The damper path at the state's command, its force and the damper's rate z_c'. `x_rate` is
  // the rig's velocity x' (read only on a quasi-static path).
  template <typename T>
  struct PathState {
    StrutDamperPath<T> path;
    T force_N;
    T rate_m_per_s;
  };
  template <typename T>
  static PathState<T> path_state(const T* y, const T& x, const T& x_rate, const T& command,
                                 const StrutTestParameters<T>& p) {
    const bool lagged = p.commanded() && p.has_lag();
    PathState<T> out{p.damper_path(lagged ? y[2] : command), T(0.0), T(0.0)};
    const auto& path = out.path;
    if (!quasi_static(p)) {
      const auto flow = path.flow(x, x_rate, y[0], y[1]);
      out.force_N = flow.force_N;
      out.rate_m_per_s = flow.damper_rate_m_per_s;
      return out;
    }
    const T delta = x - y[0];
    // k·D'(δ) by the dead zone's slope (1 without free play).
    const T k = p.top_mount_stiffness_N_per_m * free_play_slope(delta, p.free_play_m);
    // The equilibrium's residual R = F_tm − F_f − c·z_c' is made to decay, R' = −R/τ, instead of
    // being assumed zero (Baumgarte's stabilisation of a differentiated constraint): the
    // differentiated form alone has nothing that pulls a state back once a step has left the
    // equilibrium. A step across a reversal into the free play's slack then froze the friction
    // force at its sliding level for the rest of the run (a 9 kN force with nothing loading it).
    // Without free play nothing here reads z_c (k is k_tm): no equilibrium to keep, and z_c is a
    // passenger the error control leaves alone (StrutTestSystem::typical_magnitude).
    // The free play's damping c_q (strut_damper_path.h) joins the residual, R = F_tm +
    // c_q·(x' − z_c') − F_f − c·z_c', and so both the drive and the damper's share.
    const bool slack = p.free_play_m > 0.0;
    const T c_q = path.slack_damping_Ns_per_m(delta);
    const bool damped = c_q > 0.0;
    const T c_over_tau = slack ? T((damped ? T(path.damper.rebound_damping_Ns_per_m + c_q)
                                           : path.damper.rebound_damping_Ns_per_m) /
                                   kQuasiStaticRecovery_s)
                               : T(0.0);
    const T slack_force =
        damped ? T(path.path_force_N(x, y[0]) + c_q * x_rate) : path.path_force_N(x, y[0]);
    const T drive =
        k * x_rate + (slack ? T((slack_force - y[1]) / kQuasiStaticRecovery_s) : T(0.0));
    T share = T(0.0);  // σ0·s: how much of the motion the friction element resists, s in 0..1+
    if (path.friction.active()) {
      // The level at the rate the path would take while sliding (s = 0): Stribeck's curve and the
      // direction read it.
      const T sliding_rate = drive / (k + c_over_tau);
      const T s =
          T(1.0) - y[1] / path.friction.level_N(sliding_rate) * sign_positive_at_zero(sliding_rate);
      share = s > 0.0 ? signed_power(s, path.friction.exponent) : T(0.0);
      share = path.friction.sigma0_N_per_m * share;
    }
    const T denominator = k + share + c_over_tau;
    out.rate_m_per_s = denominator > 0.0 ? T(drive / denominator) : T(0.0);
    out.force_N = y[1] + path.damper.force_N(out.rate_m_per_s);
    return out;
  }

  template <typename T>
  static void derivatives(const T* y, const T& x, const T& x_rate, const T& command,
                          const StrutTestParameters<T>& p, T* ydot) {
    const PathState<T> state = path_state(y, x, x_rate, command, p);
    ydot[0] = state.rate_m_per_s;
    ydot[1] = state.path.friction.force_rate_N_per_s(y[1], state.rate_m_per_s);
    if (p.commanded() && p.has_lag()) ydot[2] = (command - y[2]) / p.command_lag_s;
  }

  template <typename T>
  static T force_N(const T* y, const T& x, const T& x_rate, const T& command,
                   const StrutTestParameters<T>& p) {
    return path_state(y, x, x_rate, command, p).force_N + p.gas_force_N +
           p.gas_stiffness_N_per_m * x + p.force_offset_N;
  }
};

}  // namespace ridefit::model
