#include "ridefit/simulate/quarter_car_state_space.h"

#include "ridefit/simulate/probe_state_space.h"

#include <stdexcept>

namespace ridefit::simulate {

LinearStateSpace quarter_car_state_space(const model::QuarterCar& car) {
  if (!car.is_linear()) {
    throw std::invalid_argument("quarter_car_state_space: the car is not linear: " +
                                car.nonlinearity());
  }
  auto unit_road = [](int input) {
    road::RoadSample road;
    if (input == 0) road.elevation_m = 1.0;
    if (input == 1) road.rate_m_per_s = 1.0;
    return road;
  };
  LinearStateSpace s = probe_state_space<model::QuarterCar::kMaxStates>(
      car.state_size(), 2, kQuarterCarLinearOutputs,
      [&](const double* x, int input, double* xdot) { car.derivatives(x, unit_road(input), xdot); },
      [&](const double* x, int input, double* y) {
        const model::QuarterCarOutputs out = car.outputs(x, unit_road(input));
        y[kQuarterBodyAcc] = out.body_acc_m_per_s2;
        y[kQuarterWheelAcc] = out.wheel_acc_m_per_s2;
        y[kQuarterTravel] = out.travel_m;
        y[kQuarterTyreForce] = out.tyre_force_N;
      });
  s.input_names = {"road", "road_rate"};
  s.output_names = {"body_acc", "wheel_acc", "travel", "tyre_force"};
  return s;
}

}  // namespace ridefit::simulate
