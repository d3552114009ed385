#include "ridefit/simulate/half_car_state_space.h"

#include "ridefit/simulate/probe_state_space.h"

#include <stdexcept>
#include <vector>

namespace ridefit::simulate {
namespace {

using O = model::HalfCarOutputs;

constexpr double O::*kOutputs[kHalfCarLinearOutputs] = {
    &O::seat_acc_m_per_s2, &O::lower_body_acc_m_per_s2, &O::upper_body_acc_m_per_s2,
    &O::body_acc_m_per_s2, &O::pitch_acc_rad_per_s2,    &O::front_travel_m,
    &O::rear_travel_m,     &O::front_tyre_force_N,      &O::rear_tyre_force_N};

model::AxleRoads unit_road(int input) {
  model::AxleRoads roads{};
  switch (input) {
    case kFrontRoad:
      roads.front.elevation_m = 1.0;
      break;
    case kFrontRoadRate:
      roads.front.rate_m_per_s = 1.0;
      break;
    case kRearRoad:
      roads.rear.elevation_m = 1.0;
      break;
    case kRearRoadRate:
      roads.rear.rate_m_per_s = 1.0;
      break;
    default:
      break;
  }
  return roads;
}

}  // namespace

LinearStateSpace half_car_state_space(const model::HalfCar& car) {
  if (!car.is_linear()) {
    throw std::invalid_argument(
        "half_car_state_space: the car has Dahl friction, a semi-active law or an asymmetric "
        "damper; it is not linear");
  }
  LinearStateSpace s = probe_state_space<2 * model::kHalfCarDofs + 2 * 2>(
      car.state_size(), 4, kHalfCarLinearOutputs,
      [&](const double* x, int input, double* xdot) { car.derivatives(x, unit_road(input), xdot); },
      [&](const double* x, int input, double* y) {
        const O out = car.outputs(x, unit_road(input));
        for (int k = 0; k < kHalfCarLinearOutputs; ++k) y[k] = out.*kOutputs[k];
      });
  s.input_names = {"front_road", "front_road_rate", "rear_road", "rear_road_rate"};
  s.output_names = {"seat_acc",    "lower_body_acc",   "upper_body_acc",
                    "body_acc",    "pitch_acc",        "front_travel",
                    "rear_travel", "front_tyre_force", "rear_tyre_force"};
  return s;
}

}  // namespace ridefit::simulate
