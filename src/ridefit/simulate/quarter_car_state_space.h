#pragma once

#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/linear_state_space.h"

namespace ridefit::simulate {

// Rows of C and D of the quarter car's linear outputs; columns of B and D are the road's
// elevation (0) and rate (1).
enum QuarterCarLinearOutput : int {
  kQuarterBodyAcc = 0,
  kQuarterWheelAcc,
  kQuarterTravel,
  kQuarterTyreForce,
  kQuarterCarLinearOutputs
};

// The slip or stick quarter car with a symmetric damper (QuarterCar::is_linear()) as x' = A·x +
// B·u, y = C·x + D·u with u = (road elevation, road rate), read off the model's own derivatives and
// outputs one unit input at a time, exactly as half_car_state_space does. std::invalid_argument for
// a car that is not linear.
LinearStateSpace quarter_car_state_space(const model::QuarterCar& car);

}  // namespace ridefit::simulate
