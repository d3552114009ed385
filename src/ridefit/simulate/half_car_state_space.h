#pragma once

#include "ridefit/model/half_car.h"
#include "ridefit/simulate/linear_state_space.h"

namespace ridefit::simulate {

// Indices of the half car's linear outputs (rows of C and D) and road inputs (columns of B, D).
enum HalfCarLinearOutput : int {
  kSeatAcc = 0,
  kLowerBodyAcc,
  kUpperBodyAcc,
  kBodyAcc,
  kPitchAcc,
  kFrontTravel,
  kRearTravel,
  kFrontTyreForce,
  kRearTyreForce,
  kHalfCarLinearOutputs
};
enum HalfCarRoadInput : int { kFrontRoad = 0, kFrontRoadRate, kRearRoad, kRearRoadRate };

// The linear half car (HalfCar::is_linear(): no Dahl friction, passive symmetric damping;
// struts in slip or stick are linear and keep their extra states) as x' = A·x + B·u,
// y = C·x + D·u, with u the elevation and rate under each wheel. The matrices are read off the
// model's own derivatives and outputs, one unit input at a time: for a linear model that is exact
// (no step, no truncation), and it keeps one source of physics. std::invalid_argument for a
// non-linear car.
LinearStateSpace half_car_state_space(const model::HalfCar& car);

}  // namespace ridefit::simulate
