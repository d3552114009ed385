#include "ridefit/model/quarter_car.h"

#include <cmath>

namespace ridefit::model {

QuarterCar::QuarterCar(DamperState state, const QuarterCarParameters<double>& parameters)
    : state_(state), parameters_(parameters) {}

bool QuarterCar::is_linear() const {
  switch (state_) {
    case DamperState::kStick:
      return true;
    case DamperState::kSlip:
      return parameters_.damper_path().damper.symmetric();
    case DamperState::kStickSlip:
      return false;
  }
  return false;
}

std::array<const char*, QuarterCar::kMaxStates> QuarterCar::state_names() const {
  return {"body_displacement", "wheel_displacement", "body_velocity",
          "wheel_velocity",    "damper_deflection",  "friction_force"};
}

QuarterCarOutputs QuarterCar::outputs(const double* x, const road::RoadSample& road) const {
  double xdot[kMaxStates] = {};
  derivatives(x, road, xdot);
  const auto& p = parameters_;
  QuarterCarOutputs out;
  out.road_m = road.elevation_m;
  out.body_acc_m_per_s2 = xdot[2];
  out.wheel_acc_m_per_s2 = xdot[3];
  out.travel_m = x[0] - x[1];
  out.tyre_force_N = p.tyre_stiffness_N_per_m * (road.elevation_m - x[1]) +
                     p.tyre_damping_Ns_per_m * (road.rate_m_per_s - x[3]);
  const double damper_deflection = state_ == DamperState::kStick ? 0.0 : x[4];
  out.top_mount_deflection_m = out.travel_m - damper_deflection;
  out.damper_force_N =
      state_ == DamperState::kStick ? 0.0 : p.damper_path().damper.force_N(xdot[4]);
  switch (state_) {
    case DamperState::kSlip:
      out.stuck = 0.0;
      break;
    case DamperState::kStick:
      out.stuck = 1.0;
      // The locked damper carries the whole damper-path force.
      out.friction_force_N = p.top_mount_stiffness_N_per_m * out.top_mount_deflection_m;
      break;
    case DamperState::kStickSlip:
      out.friction_force_N = x[5];
      out.stuck = (p.coulomb_force_N > 0.0 && std::abs(x[5]) < kStuckForceShare * p.coulomb_force_N)
                      ? 1.0
                      : 0.0;
      break;
  }
  return out;
}

const char* to_string(DamperState state) {
  switch (state) {
    case DamperState::kSlip:
      return "slip";
    case DamperState::kStick:
      return "stick";
    case DamperState::kStickSlip:
      return "stick_slip";
  }
  return "?";
}

}  // namespace ridefit::model
