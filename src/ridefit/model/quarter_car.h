#pragma once

#include <array>
#include <string>

#include "ridefit/model/acceleration_sensors.h"
#include "ridefit/model/bump_stop.h"
#include "ridefit/model/kelvin_voigt.h"
#include "ridefit/model/linear_spring.h"
#include "ridefit/model/standard_gravity.h"
#include "ridefit/model/strut_parameters.h"
#include "ridefit/model/tyre_lift_off.h"
#include "ridefit/road/road_input.h"

namespace ridefit::model {

// Parameters of a MacPherson-strut quarter car, templated so Ceres can differentiate
// with respect to them. Names follow design.md's table.
template <typename T>
struct QuarterCarParameters : StrutParameters<T> {
  T sprung_mass_kg{0.0};
  T unsprung_mass_kg{0.0};
  T tyre_stiffness_N_per_m{0.0};
  T tyre_damping_Ns_per_m{0.0};
  T spring_stiffness_N_per_m{0.0};                 // coil spring
  T top_mount_spring_path_stiffness_N_per_m{0.0};  // top mount, in series with the coil
  // Optional physical effects outside the damper path, each off at its default (the keys are
  // absent; quarter_car_file.h). Progressive bump stop, bump_stop.h; k_bs = 0 off.
  T bump_stop_stiffness_N_per_m{0.0};
  T bump_stop_clearance_m{0.0};
  T bump_stop_exponent{2.0};
  // Unilateral tyre contact, tyre_lift_off.h.
  bool tyre_lift_off = false;
  // The accelerometers' measuring chain (acceleration_sensors.h): gains and a low-pass that the
  // spectral comparisons apply to the simulated PSDs; the motion never depends on them. Ideal by
  // default.
  AccelerationSensors<T> sensors{};
  // The damper path (StrutParameters) is the strut's: on the road a controlled damper's command
  // comes from the record (RoadSample::command) when the car follows it
  // (DamperCommand::kFromRoad); otherwise it is 0 (c and Fc).

  template <typename U>
  QuarterCarParameters<U> cast() const {
    QuarterCarParameters<U> q;
    q.strut() = this->template strut_cast<U>();
    q.sprung_mass_kg = U(sprung_mass_kg);
    q.unsprung_mass_kg = U(unsprung_mass_kg);
    q.tyre_stiffness_N_per_m = U(tyre_stiffness_N_per_m);
    q.tyre_damping_Ns_per_m = U(tyre_damping_Ns_per_m);
    q.spring_stiffness_N_per_m = U(spring_stiffness_N_per_m);
    q.top_mount_spring_path_stiffness_N_per_m = U(top_mount_spring_path_stiffness_N_per_m);
    q.bump_stop_stiffness_N_per_m = U(bump_stop_stiffness_N_per_m);
    q.bump_stop_clearance_m = U(bump_stop_clearance_m);
    q.bump_stop_exponent = U(bump_stop_exponent);
    q.tyre_lift_off = tyre_lift_off;
    q.sensors = sensors.template cast<U>();
    return q;
  }

  // Coil spring in series with the top mount's spring path.
  T spring_path_stiffness_N_per_m() const {
    return series_stiffness(spring_stiffness_N_per_m, top_mount_spring_path_stiffness_N_per_m);
  }
  BumpStop<T> bump_stop() const {
    return {bump_stop_stiffness_N_per_m, bump_stop_clearance_m, bump_stop_exponent};
  }
  // The tyre carries both masses: (ms + mu)·g [N].
  T static_tyre_load_N() const {
    return (sprung_mass_kg + unsprung_mass_kg) * kStandardGravity_m_per_s2;
  }
};

// Everything a quarter-car state shows at one instant (SI, signs as in QuarterCar).
struct QuarterCarOutputs {
  double road_m = 0;
  double body_acc_m_per_s2 = 0;
  double wheel_acc_m_per_s2 = 0;
  double travel_m = 0;                // zs − zu, extension positive
  double tyre_force_N = 0;            // dynamic tyre load, compression positive (clipped at
                                      // −(ms + mu)·g with tyre_lift_off)
  double damper_force_N = 0;          // hydraulic damper force c(z_c')·z_c' (AsymmetricDamper)
  double friction_force_N = 0;        // Dahl friction F_f
  double top_mount_deflection_m = 0;  // damper path top mount, z − z_c
  double stuck = 0;                   // 1 while the damper sticks (rule in QuarterCar)
  double damper_command = 0;          // the filtered command ū the damper follows (A or V)
};

// Where a controlled damper's command comes from: nowhere (ū = 0, the damper at its base levels
// c and Fc), or the road's record (RoadSample::command), through the lag when command_lag_s > 0.
enum class DamperCommand { kNone, kFromRoad };

// Quarter car of a MacPherson strut (seed 000, Figure 7 and Equations 9–11).
//
// Frame and signs: vertical coordinates positive upwards, measured from static
// equilibrium (gravity and static preloads cancel for these linear springs); travel
// z = zs − zu is positive in extension; element forces are positive in tension.
//
// State order: [zs, zu, vs, vu, z_c, F_f] — body and wheel displacement [m], their
// velocities [m/s], then the damper's own deflection z_c [m] (slip and stick/slip) and the
// Dahl friction force F_f [N] (stick/slip only). Sizes: slip 5, stick 4, stick/slip 6.
//
// Equations:
//   ms·zs'' = −k_sp·z − F_path
//   mu·zu'' =  k_sp·z + F_path − kt·(zu − h) − ct·(zu' − h')
// with the spring path k_sp = coil in series with the top mount's spring path and F_path
// from StrutDamperPath. The damper's coefficient is damping_Ns_per_m in rebound (z_c' > 0) and
// compression_to_rebound_ratio times it in compression; with a ratio other than 1 the slip
// model is no longer linear (is_linear()).
//
// Optional effects (each off by default; the keys in quarter_car_file.h):
//   - the damper-path top mount stiffer at small amplitude (F_path nonlinear in z − z_c);
//   - a bump stop F_bs(−z) in parallel with the spring path, pushing body and wheel apart:
//       ms·zs'' = −k_sp·z − F_path + F_bs,   mu·zu'' = k_sp·z + F_path − F_bs − F_tyre,t;
//   - tyre lift-off: the tyre's tension force kt·(zu − h) + ct·(zu' − h') is capped at the
//     static load (ms + mu)·g, so the total wheel load never goes below zero;
//   - a blow-off knee in the damper law, and a Stribeck level in the Dahl element.
//
// A controlled damper following the road's command (DamperCommand::kFromRoad, with
// damping_per_command_Ns_per_m or coulomb_force_per_command_N non-zero): the damper's levels are
// commanded_levels at the filtered command ū; with command_lag_s τ > 0, ū is one more state, the
// last, with ū' = (u − ū)/τ (u the record's command); with τ = 0, ū = u.
//
// Stuck rule (the `stuck` output): in stick/slip the damper counts as stuck while the
// Dahl element is on its pre-sliding branch, |F_f| < 0.95·Fc (gross sliding drives |F_f|
// to Fc; at 0.95·Fc and d = 1 the element has slid 3·Fc/σ0 since the last reversal).
// The stick topology is always stuck, the slip topology never.
class QuarterCar {
 public:
  static constexpr int kMaxStates = 7;
  static constexpr double kStuckForceShare = 0.95;

  QuarterCar(DamperState state, const QuarterCarParameters<double>& parameters,
             DamperCommand command = DamperCommand::kNone);

  DamperState damper_state() const { return state_; }
  const QuarterCarParameters<double>& parameters() const { return parameters_; }
  DamperCommand command_input() const { return command_; }
  // True when the damper's levels follow the road's command (a controlled damper, kFromRoad).
  bool follows_command() const {
    return command_ == DamperCommand::kFromRoad && parameters_.commanded();
  }
  // The same car with its command from the road when `road_has_command`, else none.
  QuarterCar with_command_from_road(bool road_has_command) const {
    return {state_, parameters_,
            road_has_command ? DamperCommand::kFromRoad : DamperCommand::kNone};
  }
  int state_size() const { return path_states() + (command_state() ? 1 : 0); }
  // True for the linear models: stick (the locked damper never moves, so its split does not
  // act), and slip with a symmetric damper (compression_to_rebound_ratio 1) without a knee.
  // Stick/slip has Dahl friction and is never linear. A bump stop, tyre lift-off or a top mount
  // that stiffens (k_s ≠ k_l) make every topology nonlinear.
  bool is_linear() const { return nonlinearity().empty(); }
  // What makes the model nonlinear, for messages ("" when it is linear), e.g. "the damper's
  // compression_to_rebound_ratio 0.5".
  std::string nonlinearity() const;
  // Names of the states in order, for messages and output.
  std::array<const char*, kMaxStates> state_names() const;

  // x' = f(t, x, road; p). Pure: the model object is never changed.
  template <typename T>
  void derivatives(const T* x, const road::RoadSample& road, const QuarterCarParameters<T>& p,
                   T* xdot) const {
    const T& zs = x[0];
    const T& zu = x[1];
    const T& vs = x[2];
    const T& vu = x[3];
    const T travel = zs - zu;
    T command(0.0);
    if (command_state()) {
      const int i = path_states();
      command = x[i];
      xdot[i] = (T(road.command) - command) / p.command_lag_s;
    } else if (follows_command()) {
      command = T(road.command);
    }
    const StrutDamperPath<T> path = p.damper_path(command);
    const T travel_rate = vs - vu;
    T path_force(0.0);
    switch (state_) {
      case DamperState::kStick:
        path_force = path.stuck_force_N(travel, travel_rate);
        break;
      case DamperState::kSlip: {
        const auto flow = path.flow(travel, travel_rate, x[4], T(0.0));
        path_force = flow.force_N;
        xdot[4] = flow.damper_rate_m_per_s;
        break;
      }
      case DamperState::kStickSlip: {
        const auto flow = path.flow(travel, travel_rate, x[4], x[5]);
        path_force = flow.force_N;
        xdot[4] = flow.damper_rate_m_per_s;
        xdot[5] = path.friction.force_rate_N_per_s(x[5], flow.damper_rate_m_per_s);
        break;
      }
    }
    T spring_force = p.spring_path_stiffness_N_per_m() * travel;
    if (p.bump_stop_stiffness_N_per_m > 0.0) spring_force -= p.bump_stop().force_N(-travel);
    const KelvinVoigt<T> tyre{p.tyre_stiffness_N_per_m, p.tyre_damping_Ns_per_m};
    T tyre_force = tyre.force_N(zu - road.elevation_m, vu - road.rate_m_per_s);
    if (p.tyre_lift_off)
      tyre_force = -lifted_off_tyre_force_N(T(-tyre_force), p.static_tyre_load_N());
    xdot[0] = vs;
    xdot[1] = vu;
    xdot[2] = -(spring_force + path_force) / p.sprung_mass_kg;
    xdot[3] = (spring_force + path_force - tyre_force) / p.unsprung_mass_kg;
  }

  template <typename T>
  void derivatives(const T* x, const road::RoadSample& road, T* xdot) const {
    derivatives(x, road, parameters_.cast<T>(), xdot);
  }

  // All output channels at one state.
  QuarterCarOutputs outputs(const double* x, const road::RoadSample& road) const;
  // The filtered command ū the damper follows at this state and road sample (0 when it follows
  // none).
  double command_at(const double* x, const road::RoadSample& road) const;
  // The index of the filtered command among the states, or -1 when it is not a state.
  int command_state_index() const { return command_state() ? path_states() : -1; }

 private:
  int path_states() const { return 4 + StrutDamperPath<double>::state_count(state_); }
  // The filtered command is a state (the last) when the car follows a lagged command.
  bool command_state() const { return follows_command() && parameters_.has_lag(); }
  DamperState state_;
  QuarterCarParameters<double> parameters_;
  DamperCommand command_ = DamperCommand::kNone;
};

// "slip" | "stick" | "stick_slip" and back.
const char* to_string(DamperState state);

}  // namespace ridefit::model
