#pragma once

#include <string>
#include <vector>

#include "ridefit/model/half_car.h"
#include "ridefit/simulate/modal_analysis.h"

namespace ridefit::simulate {

// Modes of the linear half car (HalfCar::is_linear: passive symmetric dampers, struts in slip or
// stick) from its state matrix (half_car_state_space.h, read off the model's own derivatives),
// each named by the coordinate that holds most of its kinetic energy: "body" (heave), "pitch"
// (its share weighted by the pitch inertia), "front_wheel", "rear_wheel", "seat", "lower_body",
// "upper_body". A stick/slip strut, a semi-active law or an asymmetric damper makes the car
// nonlinear: InputError naming what to change.
ModalAnalysis half_car_modes(const model::HalfCar& car);

// The half car's modes with its strut axles in each `state` ("slip", "stick"; both when empty),
// the file's stick/slip state replaced. A car of passive axles is one linear model, named
// "passive"; asking it for a state is an InputError naming `model_name`.
struct StateModes {
  std::string state;
  ModalAnalysis modes;
};
std::vector<StateModes> half_car_modes_by_state(const model::HalfCarTopology& topology,
                                                const model::HalfCarParameters<double>& parameters,
                                                const std::string& state,
                                                const std::string& model_name);

}  // namespace ridefit::simulate
