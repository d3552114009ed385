#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "ridefit/model/kelvin_voigt.h"
#include "ridefit/model/semi_active_control.h"
#include "ridefit/model/strut_parameters.h"
#include "ridefit/road/road_input.h"

namespace ridefit::model {

// Generalised coordinates of the half car with seat and occupant (seed 001, Figure 1), in
// this order. Displacements are vertical, positive upwards, from static equilibrium; pitch θ
// is positive nose up, so a body point a distance x ahead of the centre of gravity moves by
// z_b + x·θ (the front axle is at x = a1, the rear axle at x = −a2, the seat at x = a3).
enum HalfCarDof : int {
  kBodyHeave = 0,
  kBodyPitch,
  kFrontWheel,
  kRearWheel,
  kSeat,
  kLowerBody,
  kUpperBody,
  kHalfCarDofs
};

// One axle: wheel, tyre and suspension. The damper is the strut's (StrutParameters, the quarter
// car's and the rig's own, every effect of the path included); its top mount, friction and free
// play act only when the axle is a strut. A passive axle's damper is the path's damper alone
// (AsymmetricDamper: damping_Ns_per_m in rebound, compression_to_rebound_ratio times it in
// compression, with its knee). A controlled damper follows the command that asks for a
// semi-active law's coefficient (HalfCar), u = (c_law − c)/c_b; with the passive law u = 0.
template <typename T>
struct HalfCarAxle : StrutParameters<T> {
  T unsprung_mass_kg{0.0};
  T tyre_stiffness_N_per_m{0.0};
  T tyre_damping_Ns_per_m{0.0};
  T spring_stiffness_N_per_m{0.0};

  template <typename U>
  HalfCarAxle<U> cast() const {
    HalfCarAxle<U> a;
    a.strut() = this->template strut_cast<U>();
    a.unsprung_mass_kg = U(unsprung_mass_kg);
    a.tyre_stiffness_N_per_m = U(tyre_stiffness_N_per_m);
    a.tyre_damping_Ns_per_m = U(tyre_damping_Ns_per_m);
    a.spring_stiffness_N_per_m = U(spring_stiffness_N_per_m);
    return a;
  }
};

// A mass on a spring ∥ damper (the seat on the body, a body segment on the seat).
template <typename T>
struct SuspendedMass {
  T mass_kg;
  T stiffness_N_per_m;
  T damping_Ns_per_m;

  template <typename U>
  SuspendedMass<U> cast() const {
    return {U(mass_kg), U(stiffness_N_per_m), U(damping_Ns_per_m)};
  }
};

template <typename T>
struct HalfCarParameters {
  T body_mass_kg;
  T pitch_inertia_kg_m2;
  T front_axle_distance_m;  // a1, ahead of the centre of gravity
  T rear_axle_distance_m;   // a2, behind it
  T seat_distance_m;        // a3, ahead of it (negative: behind)
  HalfCarAxle<T> front;
  HalfCarAxle<T> rear;
  SuspendedMass<T> seat;
  SuspendedMass<T> lower_body;
  SuspendedMass<T> upper_body;

  template <typename U>
  HalfCarParameters<U> cast() const {
    return {U(body_mass_kg),
            U(pitch_inertia_kg_m2),
            U(front_axle_distance_m),
            U(rear_axle_distance_m),
            U(seat_distance_m),
            front.template cast<U>(),
            rear.template cast<U>(),
            seat.template cast<U>(),
            lower_body.template cast<U>(),
            upper_body.template cast<U>()};
  }
  T wheelbase_m() const { return front_axle_distance_m + rear_axle_distance_m; }
};

// How an axle's suspension is built. kPassive: coil spring ∥ damper between body and wheel
// (seed 001). kStrut: coil spring ∥ damper path of a MacPherson strut (top mount in series with
// the damper, and Dahl friction in stick/slip; seed 000), in `damper_state`.
enum class AxleSuspension { kPassive, kStrut };

struct AxleTopology {
  AxleSuspension suspension = AxleSuspension::kPassive;
  DamperState damper_state = DamperState::kStickSlip;  // read for a strut only

  int internal_state_count() const {
    return suspension == AxleSuspension::kStrut ? StrutDamperPath<double>::state_count(damper_state)
                                                : 0;
  }
};

// What the upper body rests on. Seed 001's matrices (Eq. 1) connect both body segments to the
// seat (their springs k2 and k3 each couple to x_se); kLowerBody chains them instead.
enum class UpperBodySupport { kSeat, kLowerBody };

struct HalfCarTopology {
  AxleTopology front;
  AxleTopology rear;
  UpperBodySupport upper_body_support = UpperBodySupport::kSeat;
  SemiActiveControl control;  // applies to both axles' dampers
};

// The road under both wheels at one instant.
struct AxleRoads {
  road::RoadSample front;
  road::RoadSample rear;
};

// Every output of one instant (SI; signs as in HalfCar).
struct HalfCarOutputs {
  double front_road_m = 0, rear_road_m = 0;
  double body_acc_m_per_s2 = 0;  // heave at the centre of gravity
  double pitch_acc_rad_per_s2 = 0;
  double seat_acc_m_per_s2 = 0, lower_body_acc_m_per_s2 = 0, upper_body_acc_m_per_s2 = 0;
  double front_wheel_acc_m_per_s2 = 0, rear_wheel_acc_m_per_s2 = 0;
  double front_travel_m = 0, rear_travel_m = 0;              // extension positive
  double front_tyre_force_N = 0, rear_tyre_force_N = 0;      // dynamic, compression positive
  double front_damper_force_N = 0, rear_damper_force_N = 0;  // hydraulic, tension positive
  double front_friction_force_N = 0, rear_friction_force_N = 0;
  // The damper's coefficient now: the controller's choice (the axle's own when passive) in
  // rebound, times compression_to_rebound_ratio in compression.
  double front_damping_Ns_per_m = 0, rear_damping_Ns_per_m = 0;
  double front_stuck = 0, rear_stuck = 0;  // QuarterCar's rule: |F_f| < 0.95·Fc
};

// The 7-DOF half car with seat and occupant of seed 001, assembled from elements: nothing is
// typed as a matrix. Each element joins a point "above" (attachment vector g_a over the
// coordinates) to a point "below" (g_b); its extension is e = (g_a − g_b)·q and its tension F
// pushes the two apart by −F·(g_a − g_b) on the generalised forces. The mass matrix is
// diag(m_b, J, m_uf, m_ur, m_se, m_2, m_3).
//
// Elements: per axle the coil spring and the damper (passive: c(ė)·ė, with the controller's c in
// rebound, ė > 0, and compression_to_rebound_ratio times it in compression, ė < 0; strut: the
// damper path of StrutDamperPath with the same split, whose internal states are the damper
// deflection z_c and the Dahl force F_f) between the body point over the axle and the wheel,
// and the tyre (Kelvin-Voigt, compression positive, point contact, never lifts off) between
// wheel and road; the seat between the body point at a3 and the seat mass; the lower body on
// the seat; the upper body on the seat (seed 001) or on the lower body.
//
// A controlled damper (HalfCarAxle::commanded) under a semi-active law follows the command that
// asks for the law's coefficient, through its lag: the coefficient and the friction level lag
// the law's request by the fluid's response time.
//
// State: [q (7), q' (7), front axle states (the strut's z_c, F_f as the damper state has them,
// then the filtered command ū when it lags), rear axle states]. Sizes: 14 for passive axles, up
// to 20 with two lagged stick/slip struts.
class HalfCar {
 public:
  HalfCar(const HalfCarTopology& topology, const HalfCarParameters<double>& parameters);

  const HalfCarTopology& topology() const { return topology_; }
  const HalfCarParameters<double>& parameters() const { return parameters_; }
  int state_size() const { return 2 * kHalfCarDofs + front_state_count() + rear_state_count(); }
  // Each axle's own states after the 14 of the masses: the strut's (AxleTopology), then the
  // filtered command when a semi-active law drives a controlled damper through a lag.
  int front_state_count() const { return axle_state_count(topology_.front, parameters_.front); }
  int rear_state_count() const { return axle_state_count(topology_.rear, parameters_.rear); }
  // The semi-active law drives this axle's damper through its command (HalfCarAxle::commanded).
  bool follows_command(const HalfCarAxle<double>& axle) const {
    return topology_.control.law != ControlLaw::kPassive && axle.commanded();
  }
  // True when the model is linear: no Dahl friction (no stick/slip strut), passive damping and
  // symmetric dampers (compression_to_rebound_ratio 1 on both axles; a stick strut's locked
  // damper never moves, so its split does not act).
  bool is_linear() const;
  std::vector<std::string> state_names() const;

  // x' = f(t, x, roads; p). Pure.
  template <typename T>
  void derivatives(const T* x, const AxleRoads& roads, const HalfCarParameters<T>& p,
                   T* xdot) const;
  template <typename T>
  void derivatives(const T* x, const AxleRoads& roads, T* xdot) const {
    derivatives(x, roads, parameters_.cast<T>(), xdot);
  }

  HalfCarOutputs outputs(const double* x, const AxleRoads& roads) const;

 private:
  template <typename T>
  struct AxleForces {
    T suspension_N;  // spring + damper path, tension positive
    T damper_N;
    T friction_N;
    T damping_Ns_per_m;  // the damper's coefficient now (HalfCarOutputs)
    T tyre_N;            // compression positive
    T friction_level_N;  // the Dahl element's Fc now (the command moves it)
  };

  int axle_state_count(const AxleTopology& topology, const HalfCarAxle<double>& axle) const {
    return topology.internal_state_count() +
           (follows_command(axle) && axle.command_lag_s > 0.0 ? 1 : 0);
  }

  // `values` is the axle's parameters as numbers: they decide which states the axle has.
  template <typename T>
  AxleForces<T> axle_forces(const AxleTopology& topology, const HalfCarAxle<double>& values,
                            const HalfCarAxle<T>& axle, const T& travel, const T& travel_rate,
                            const T& body_velocity, const T& wheel_velocity, const T& wheel,
                            const road::RoadSample& road, const T* internal,
                            T* internal_rate) const;

  HalfCarTopology topology_;
  HalfCarParameters<double> parameters_;
};

// M, C and K of the linear model with both axles passive, assembled from the same elements
// (for the tests of symmetry and definiteness, and for modal analysis). With struts the damper
// path adds states, and an asymmetric damper has no single C, so these are an
// std::invalid_argument.
struct MassDampingStiffness {
  Eigen::Matrix<double, kHalfCarDofs, kHalfCarDofs> mass, damping, stiffness;
};
MassDampingStiffness assemble_mass_damping_stiffness(const HalfCarTopology& topology,
                                                     const HalfCarParameters<double>& p);

// --- implementation -------------------------------------------------------------------------

template <typename T>
HalfCar::AxleForces<T> HalfCar::axle_forces(
    const AxleTopology& topology, const HalfCarAxle<double>& values, const HalfCarAxle<T>& axle,
    const T& travel, const T& travel_rate, const T& body_velocity, const T& wheel_velocity,
    const T& wheel, const road::RoadSample& road, const T* internal, T* internal_rate) const {
  AxleForces<T> f;
  // The controller sets the rebound coefficient; the damper's compression valve gives
  // compression_to_rebound_ratio times it (SemiActiveControl).
  const T law = topology_.control.damping(body_velocity, wheel_velocity, axle.damping_Ns_per_m);
  StrutDamperPath<T> strut = axle.damper_path();
  if (follows_command(values)) {
    // A controlled damper reaches the law's coefficient through its command (c_b ≠ 0, checked
    // by the file reader), after the fluid's lag; the friction level moves with the command.
    const T command = (law - axle.damping_Ns_per_m) / axle.damping_per_command_Ns_per_m;
    T filtered = command;
    if (values.command_lag_s > 0.0) {
      const int i = topology.internal_state_count();
      filtered = internal[i];
      internal_rate[i] = (command - filtered) / axle.command_lag_s;
    }
    strut = axle.damper_path(filtered);
  } else if (topology_.control.law != ControlLaw::kPassive) {
    // An ideal semi-active damper: the law's coefficient directly, the knee's share kept.
    if (strut.damper.has_knee()) {
      strut.damper.damping_above_knee_Ns_per_m *= law / strut.damper.rebound_damping_Ns_per_m;
    }
    strut.damper.rebound_damping_Ns_per_m = law;
  }
  f.friction_level_N = strut.friction.coulomb_force_N;
  const AsymmetricDamper<T>& damper = strut.damper;
  f.friction_N = T(0.0);
  T path(0.0);
  if (topology.suspension == AxleSuspension::kPassive) {
    // The damper's own rate is the travel rate: its sign picks the branch.
    f.damping_Ns_per_m = damper.damping_Ns_per_m(travel_rate);
    path = damper.force_N(travel_rate);
    f.damper_N = path;
  } else {
    f.damping_Ns_per_m = damper.rebound_damping_Ns_per_m;
    switch (topology.damper_state) {
      case DamperState::kStick:
        path = strut.stuck_force_N(travel, travel_rate);
        f.damper_N = path;  // the locked damper carries the whole path force
        break;
      case DamperState::kSlip: {
        const auto flow = strut.flow(travel, travel_rate, internal[0], T(0.0));
        path = flow.force_N;
        const T damper_rate = flow.damper_rate_m_per_s;
        internal_rate[0] = damper_rate;
        f.damper_N = path;
        f.damping_Ns_per_m = damper.damping_Ns_per_m(damper_rate);
        break;
      }
      case DamperState::kStickSlip: {
        const auto flow = strut.flow(travel, travel_rate, internal[0], internal[1]);
        path = flow.force_N;
        const T damper_rate = flow.damper_rate_m_per_s;
        internal_rate[0] = damper_rate;
        internal_rate[1] = strut.friction.force_rate_N_per_s(internal[1], damper_rate);
        f.damper_N = path - internal[1];
        f.friction_N = internal[1];
        f.damping_Ns_per_m = damper.damping_Ns_per_m(damper_rate);
        break;
      }
    }
  }
  f.suspension_N = axle.spring_stiffness_N_per_m * travel + path;
  const KelvinVoigt<T> tyre{axle.tyre_stiffness_N_per_m, axle.tyre_damping_Ns_per_m};
  f.tyre_N = -tyre.force_N(wheel - road.elevation_m, wheel_velocity - road.rate_m_per_s);
  return f;
}

template <typename T>
void HalfCar::derivatives(const T* x, const AxleRoads& roads, const HalfCarParameters<T>& p,
                          T* xdot) const {
  const T* q = x;
  const T* v = x + kHalfCarDofs;
  const T* internal = x + 2 * kHalfCarDofs;
  T* internal_rate = xdot + 2 * kHalfCarDofs;
  const T a1 = p.front_axle_distance_m, a2 = p.rear_axle_distance_m, a3 = p.seat_distance_m;
  T force[kHalfCarDofs];
  for (T& f : force) f = T(0.0);

  // Axles: body point z_b + x·θ above the wheel.
  auto axle = [&](const AxleTopology& top, const HalfCarAxle<double>& values,
                  const HalfCarAxle<T>& ax, const T& arm, int wheel, const road::RoadSample& road,
                  const T* states, T* rates) {
    const T body = q[kBodyHeave] + arm * q[kBodyPitch];
    const T body_velocity = v[kBodyHeave] + arm * v[kBodyPitch];
    const T travel = body - q[wheel];
    const T travel_rate = body_velocity - v[wheel];
    const AxleForces<T> f = axle_forces(top, values, ax, travel, travel_rate, body_velocity,
                                        v[wheel], q[wheel], road, states, rates);
    force[kBodyHeave] -= f.suspension_N;
    force[kBodyPitch] -= arm * f.suspension_N;
    force[wheel] += f.suspension_N + f.tyre_N;
  };
  axle(topology_.front, parameters_.front, p.front, a1, kFrontWheel, roads.front, internal,
       internal_rate);
  const int front_states = front_state_count();
  axle(topology_.rear, parameters_.rear, p.rear, -a2, kRearWheel, roads.rear,
       internal + front_states, internal_rate + front_states);

  // Seat on the body point at a3, body segments on the seat (or chained).
  auto mount = [&](const SuspendedMass<T>& m, int top, const T& bottom, const T& bottom_rate,
                   auto&& apply_to_bottom) {
    const T tension =
        m.stiffness_N_per_m * (q[top] - bottom) + m.damping_Ns_per_m * (v[top] - bottom_rate);
    force[top] -= tension;
    apply_to_bottom(tension);
  };
  mount(p.seat, kSeat, q[kBodyHeave] + a3 * q[kBodyPitch], v[kBodyHeave] + a3 * v[kBodyPitch],
        [&](const T& tension) {
          force[kBodyHeave] += tension;
          force[kBodyPitch] += a3 * tension;
        });
  mount(p.lower_body, kLowerBody, q[kSeat], v[kSeat],
        [&](const T& tension) { force[kSeat] += tension; });
  const int support = topology_.upper_body_support == UpperBodySupport::kSeat ? kSeat : kLowerBody;
  mount(p.upper_body, kUpperBody, q[support], v[support],
        [&](const T& tension) { force[support] += tension; });

  const T mass[kHalfCarDofs] = {
      p.body_mass_kg, p.pitch_inertia_kg_m2, p.front.unsprung_mass_kg, p.rear.unsprung_mass_kg,
      p.seat.mass_kg, p.lower_body.mass_kg,  p.upper_body.mass_kg};
  for (int i = 0; i < kHalfCarDofs; ++i) {
    xdot[i] = v[i];
    xdot[kHalfCarDofs + i] = force[i] / mass[i];
  }
}

}  // namespace ridefit::model
