#include "ridefit/model/half_car.h"

#include <cmath>
#include <stdexcept>
#include <tuple>

#include "ridefit/model/quarter_car.h"

namespace ridefit::model {

const char* to_string(ControlLaw law) {
  switch (law) {
    case ControlLaw::kPassive:
      return "passive";
    case ControlLaw::kSkyhook:
      return "skyhook";
    case ControlLaw::kGroundhook:
      return "groundhook";
    case ControlLaw::kHybrid:
      return "hybrid";
  }
  return "?";
}

HalfCar::HalfCar(const HalfCarTopology& topology, const HalfCarParameters<double>& parameters)
    : topology_(topology), parameters_(parameters) {}

bool HalfCar::is_linear() const {
  auto linear = [](const AxleTopology& axle, const HalfCarAxle<double>& p) {
    const StrutDamperPath<double> path = p.damper_path();
    if (axle.suspension == AxleSuspension::kStrut) {
      if (axle.damper_state == DamperState::kStickSlip) return false;
      // A stiffening top mount or free play bends the path's force law.
      if (path.top_mount.stiffening() || path.free_play_m > 0.0) return false;
      if (axle.damper_state == DamperState::kStick) return true;  // the damper never moves
    }
    return path.damper.linear();
  };
  return linear(topology_.front, parameters_.front) && linear(topology_.rear, parameters_.rear) &&
         topology_.control.law == ControlLaw::kPassive;
}

std::vector<std::string> HalfCar::state_names() const {
  std::vector<std::string> names = {"z_body", "pitch",        "z_front_wheel", "z_rear_wheel",
                                    "z_seat", "z_lower_body", "z_upper_body"};
  for (int i = 0; i < kHalfCarDofs; ++i) names.push_back("d/dt " + names[i]);
  for (const auto& [name, axle, values] : {std::tuple{"front", topology_.front, parameters_.front},
                                           std::tuple{"rear", topology_.rear, parameters_.rear}}) {
    const int count = axle.internal_state_count();
    if (count >= 1) names.push_back(std::string(name) + "_damper_deflection");
    if (count >= 2) names.push_back(std::string(name) + "_friction_force");
    if (axle_state_count(axle, values) > count) {
      names.push_back(std::string(name) + "_filtered_command");
    }
  }
  return names;
}

HalfCarOutputs HalfCar::outputs(const double* x, const AxleRoads& roads) const {
  std::vector<double> xdot(static_cast<std::size_t>(state_size()));
  derivatives(x, roads, xdot.data());
  const double* q = x;
  const double* v = x + kHalfCarDofs;
  const double* a = xdot.data() + kHalfCarDofs;
  HalfCarOutputs out;
  out.front_road_m = roads.front.elevation_m;
  out.rear_road_m = roads.rear.elevation_m;
  out.body_acc_m_per_s2 = a[kBodyHeave];
  out.pitch_acc_rad_per_s2 = a[kBodyPitch];
  out.seat_acc_m_per_s2 = a[kSeat];
  out.lower_body_acc_m_per_s2 = a[kLowerBody];
  out.upper_body_acc_m_per_s2 = a[kUpperBody];
  out.front_wheel_acc_m_per_s2 = a[kFrontWheel];
  out.rear_wheel_acc_m_per_s2 = a[kRearWheel];

  std::vector<double> scratch(8, 0.0);
  const double* internal = x + 2 * kHalfCarDofs;
  auto axle = [&](const AxleTopology& top, const HalfCarAxle<double>& ax, double arm, int wheel,
                  const road::RoadSample& road, const double* states, double& travel, double& tyre,
                  double& damper, double& friction, double& damping, double& stuck) {
    const double body_velocity = v[kBodyHeave] + arm * v[kBodyPitch];
    travel = q[kBodyHeave] + arm * q[kBodyPitch] - q[wheel];
    const AxleForces<double> f =
        axle_forces(top, ax, ax, travel, body_velocity - v[wheel], body_velocity, v[wheel],
                    q[wheel], road, states, scratch.data());
    tyre = f.tyre_N;
    damper = f.damper_N;
    friction = f.friction_N;
    damping = f.damping_Ns_per_m;
    stuck = 0.0;
    if (top.suspension == AxleSuspension::kStrut) {
      if (top.damper_state == DamperState::kStick) stuck = 1.0;
      if (top.damper_state == DamperState::kStickSlip &&
          std::abs(f.friction_N) < QuarterCar::kStuckForceShare * f.friction_level_N) {
        stuck = 1.0;
      }
    }
  };
  const HalfCarParameters<double>& p = parameters_;
  axle(topology_.front, p.front, p.front_axle_distance_m, kFrontWheel, roads.front, internal,
       out.front_travel_m, out.front_tyre_force_N, out.front_damper_force_N,
       out.front_friction_force_N, out.front_damping_Ns_per_m, out.front_stuck);
  axle(topology_.rear, p.rear, -p.rear_axle_distance_m, kRearWheel, roads.rear,
       internal + front_state_count(), out.rear_travel_m, out.rear_tyre_force_N,
       out.rear_damper_force_N, out.rear_friction_force_N, out.rear_damping_Ns_per_m,
       out.rear_stuck);
  return out;
}

MassDampingStiffness assemble_mass_damping_stiffness(const HalfCarTopology& topology,
                                                     const HalfCarParameters<double>& p) {
  if (topology.front.suspension != AxleSuspension::kPassive ||
      topology.rear.suspension != AxleSuspension::kPassive) {
    throw std::invalid_argument(
        "assemble_mass_damping_stiffness: a strut's damper path adds states; use the state-space "
        "form");
  }
  if (!p.front.damper_path().damper.linear() || !p.rear.damper_path().damper.linear()) {
    throw std::invalid_argument(
        "assemble_mass_damping_stiffness: an asymmetric damper (compression_to_rebound_ratio != 1) "
        "or one with a knee has no single damping matrix");
  }
  using Vector = Eigen::Matrix<double, kHalfCarDofs, 1>;
  MassDampingStiffness m;
  m.mass.setZero();
  m.damping.setZero();
  m.stiffness.setZero();
  m.mass.diagonal() << p.body_mass_kg, p.pitch_inertia_kg_m2, p.front.unsprung_mass_kg,
      p.rear.unsprung_mass_kg, p.seat.mass_kg, p.lower_body.mass_kg, p.upper_body.mass_kg;
  // Each element adds k·g·gᵀ and c·g·gᵀ with g = g_above − g_below.
  auto add = [&](const Vector& g, double k, double c) {
    m.stiffness += k * g * g.transpose();
    m.damping += c * g * g.transpose();
  };
  auto point = [](double arm) {
    Vector g = Vector::Zero();
    g[kBodyHeave] = 1.0;
    g[kBodyPitch] = arm;
    return g;
  };
  auto dof = [](int i) { return Vector::Unit(i); };
  add(point(p.front_axle_distance_m) - dof(kFrontWheel), p.front.spring_stiffness_N_per_m,
      p.front.damping_Ns_per_m);
  add(point(-p.rear_axle_distance_m) - dof(kRearWheel), p.rear.spring_stiffness_N_per_m,
      p.rear.damping_Ns_per_m);
  add(dof(kFrontWheel), p.front.tyre_stiffness_N_per_m, p.front.tyre_damping_Ns_per_m);
  add(dof(kRearWheel), p.rear.tyre_stiffness_N_per_m, p.rear.tyre_damping_Ns_per_m);
  add(dof(kSeat) - point(p.seat_distance_m), p.seat.stiffness_N_per_m, p.seat.damping_Ns_per_m);
  add(dof(kLowerBody) - dof(kSeat), p.lower_body.stiffness_N_per_m, p.lower_body.damping_Ns_per_m);
  const int support = topology.upper_body_support == UpperBodySupport::kSeat ? kSeat : kLowerBody;
  add(dof(kUpperBody) - dof(support), p.upper_body.stiffness_N_per_m,
      p.upper_body.damping_Ns_per_m);
  return m;
}

}  // namespace ridefit::model
