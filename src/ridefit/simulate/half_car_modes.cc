#include "ridefit/simulate/half_car_modes.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"
#include "ridefit/simulate/half_car_state_space.h"

namespace ridefit::simulate {

ModalAnalysis half_car_modes(const model::HalfCar& car) {
  if (!car.is_linear()) {
    throw InputError(
        "modes are defined for a linear half car: struts in slip or stick (not stick_slip) "
        "without top-mount stiffening or free play, the passive control law, and linear dampers "
        "(compression_to_rebound_ratio 1, no knee) on both axles");
  }
  const auto& p = car.parameters();
  const LinearStateSpace linear = half_car_state_space(car);
  return analyse_modes(linear.A, {{"body", p.body_mass_kg, model::kBodyHeave},
                                  {"pitch", p.pitch_inertia_kg_m2, model::kBodyPitch},
                                  {"front_wheel", p.front.unsprung_mass_kg, model::kFrontWheel},
                                  {"rear_wheel", p.rear.unsprung_mass_kg, model::kRearWheel},
                                  {"seat", p.seat.mass_kg, model::kSeat},
                                  {"lower_body", p.lower_body.mass_kg, model::kLowerBody},
                                  {"upper_body", p.upper_body.mass_kg, model::kUpperBody}});
}

std::vector<StateModes> half_car_modes_by_state(const model::HalfCarTopology& topology,
                                                const model::HalfCarParameters<double>& parameters,
                                                const std::string& state,
                                                const std::string& model_name) {
  if (!state.empty() && state != "slip" && state != "stick") {
    throw InputError(fmt::format("state '{}': expected slip or stick", state));
  }
  const bool front = topology.front.suspension == model::AxleSuspension::kStrut;
  const bool rear = topology.rear.suspension == model::AxleSuspension::kStrut;
  if (!front && !rear) {
    if (!state.empty()) {
      throw InputError(fmt::format(
          "state {}: {} has passive axles only (no strut damper to put in slip or stick); "
          "leave the state out",
          state, model_name));
    }
    return {{"passive", half_car_modes(model::HalfCar(topology, parameters))}};
  }
  std::vector<StateModes> all;
  for (const std::string s : {"slip", "stick"}) {
    if (!state.empty() && s != state) continue;
    model::HalfCarTopology in_state = topology;
    const auto damper_state = s == "slip" ? model::DamperState::kSlip : model::DamperState::kStick;
    if (front) in_state.front.damper_state = damper_state;
    if (rear) in_state.rear.damper_state = damper_state;
    all.push_back({s, half_car_modes(model::HalfCar(in_state, parameters))});
  }
  return all;
}

}  // namespace ridefit::simulate
