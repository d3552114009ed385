#include "ridefit/model/quarter_car.h"

#include <fmt/core.h>

#include <cmath>

namespace ridefit::model {

QuarterCar::QuarterCar(DamperState state, const QuarterCarParameters<double>& parameters,
                       DamperCommand command)
    : state_(state), parameters_(parameters), command_(command) {}

double QuarterCar::command_at(const double* x, const road::RoadSample& road) const {
  if (command_state()) return x[path_states()];
  return follows_command() ? road.command : 0.0;
}

std::string QuarterCar::nonlinearity() const {
  const auto& p = parameters_;
  std::string reasons;
  const auto add = [&](const std::string& reason) {
    reasons += (reasons.empty() ? "" : ", ") + reason;
  };
  if (state_ == DamperState::kStickSlip) add("the Dahl friction of stick_slip");
  const auto path = p.damper_path();
  // The locked damper of stick never moves: its split and knee do not act.
  if (state_ != DamperState::kStick) {
    if (!path.damper.symmetric()) {
      add(fmt::format("the damper's compression_to_rebound_ratio {}",
                      p.compression_to_rebound_ratio));
    }
    if (path.damper.has_knee() && (p.damping_above_knee_Ns_per_m != p.damping_Ns_per_m ||
                                   p.damping_above_knee_exponent != 1.0)) {
      add(fmt::format("the damper's knee at {} m/s", p.damper_knee_velocity_m_per_s));
    }
  }
  if (!path.top_mount.linear()) add("the top mount's amplitude stiffening");
  if (p.bump_stop().active()) add("the bump stop");
  if (p.tyre_lift_off) add("tyre lift-off");
  if (follows_command()) add("the damper's command from the record");
  return reasons;
}

std::array<const char*, QuarterCar::kMaxStates> QuarterCar::state_names() const {
  std::array<const char*, kMaxStates> names{"body_displacement",
                                            "wheel_displacement",
                                            "body_velocity",
                                            "wheel_velocity",
                                            "damper_deflection",
                                            "friction_force",
                                            ""};
  // Stick has no damper deflection, slip no friction force; the command follows the path's states.
  if (state_ == DamperState::kStick) names[4] = "";
  if (state_ != DamperState::kStickSlip) names[5] = "";
  if (command_state()) names[static_cast<std::size_t>(path_states())] = "filtered_command";
  return names;
}

QuarterCarOutputs QuarterCar::outputs(const double* x, const road::RoadSample& road) const {
  double xdot[kMaxStates] = {};
  derivatives(x, road, xdot);
  const auto& p = parameters_;
  const double command = command_at(x, road);
  const StrutDamperPath<double> path = p.damper_path(command);
  QuarterCarOutputs out;
  out.damper_command = command;
  out.road_m = road.elevation_m;
  out.body_acc_m_per_s2 = xdot[2];
  out.wheel_acc_m_per_s2 = xdot[3];
  out.travel_m = x[0] - x[1];
  out.tyre_force_N = p.tyre_stiffness_N_per_m * (road.elevation_m - x[1]) +
                     p.tyre_damping_Ns_per_m * (road.rate_m_per_s - x[3]);
  if (p.tyre_lift_off)
    out.tyre_force_N = lifted_off_tyre_force_N(out.tyre_force_N, p.static_tyre_load_N());
  const double damper_deflection = state_ == DamperState::kStick ? 0.0 : x[4];
  out.top_mount_deflection_m = out.travel_m - damper_deflection;
  out.damper_force_N = state_ == DamperState::kStick ? 0.0 : path.damper.force_N(xdot[4]);
  switch (state_) {
    case DamperState::kSlip:
      out.stuck = 0.0;
      break;
    case DamperState::kStick:
      out.stuck = 1.0;
      // The locked damper carries the whole damper-path force (its free play's too).
      out.friction_force_N = path.stuck_force_N(out.travel_m, x[2] - x[3]);
      break;
    case DamperState::kStickSlip:
      out.friction_force_N = x[5];
      // With a Stribeck curve the share is of the level at the damper's rate, Fc(z_c').
      out.stuck = (path.friction.coulomb_force_N > 0.0 &&
                   std::abs(x[5]) < kStuckForceShare * path.friction.level_N(xdot[4]))
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
