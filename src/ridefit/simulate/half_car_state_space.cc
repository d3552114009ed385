#include "ridefit/simulate/half_car_state_space.h"

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
  const int n = car.state_size();
  LinearStateSpace s;
  s.A.resize(n, n);
  s.B.resize(n, 4);
  s.C.resize(kHalfCarLinearOutputs, n);
  s.D.resize(kHalfCarLinearOutputs, 4);
  s.input_names = {"front_road", "front_road_rate", "rear_road", "rear_road_rate"};
  s.output_names = {"seat_acc",    "lower_body_acc",   "upper_body_acc",
                    "body_acc",    "pitch_acc",        "front_travel",
                    "rear_travel", "front_tyre_force", "rear_tyre_force"};
  std::vector<double> x(static_cast<std::size_t>(n), 0.0);
  std::vector<double> xdot(static_cast<std::size_t>(n));
  auto probe = [&](const model::AxleRoads& roads, auto&& column_of_a, auto&& column_of_c) {
    car.derivatives(x.data(), roads, xdot.data());
    for (int i = 0; i < n; ++i) column_of_a(i) = xdot[static_cast<std::size_t>(i)];
    const O out = car.outputs(x.data(), roads);
    for (int k = 0; k < kHalfCarLinearOutputs; ++k) column_of_c(k) = out.*kOutputs[k];
  };
  // The model is linear and measured from equilibrium, so f(0, 0) = 0 and each unit probe
  // returns a column.
  for (int j = 0; j < n; ++j) {
    x[static_cast<std::size_t>(j)] = 1.0;
    probe(
        model::AxleRoads{}, [&](int i) -> double& { return s.A(i, j); },
        [&](int k) -> double& { return s.C(k, j); });
    x[static_cast<std::size_t>(j)] = 0.0;
  }
  for (int j = 0; j < 4; ++j) {
    probe(
        unit_road(j), [&](int i) -> double& { return s.B(i, j); },
        [&](int k) -> double& { return s.D(k, j); });
  }
  return s;
}

}  // namespace ridefit::simulate
