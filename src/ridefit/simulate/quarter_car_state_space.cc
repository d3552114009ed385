#include "ridefit/simulate/quarter_car_state_space.h"

#include <array>
#include <stdexcept>

namespace ridefit::simulate {

LinearStateSpace quarter_car_state_space(const model::QuarterCar& car) {
  if (car.damper_state() == model::DamperState::kStickSlip) {
    throw std::invalid_argument(
        "quarter_car_state_space: a stick/slip car has Dahl friction; it is not linear");
  }
  const int n = car.state_size();
  LinearStateSpace s;
  s.A.resize(n, n);
  s.B.resize(n, 2);
  s.C.resize(kQuarterCarLinearOutputs, n);
  s.D.resize(kQuarterCarLinearOutputs, 2);
  s.input_names = {"road", "road_rate"};
  s.output_names = {"body_acc", "wheel_acc", "travel", "tyre_force"};
  // Sized for the largest state so that no branch of derivatives() can read past the end.
  std::array<double, model::QuarterCar::kMaxStates> x{}, xdot{};
  auto probe = [&](const road::RoadSample& road, auto&& column_of_a, auto&& column_of_c) {
    car.derivatives(x.data(), road, xdot.data());
    for (int i = 0; i < n; ++i) column_of_a(i) = xdot[static_cast<std::size_t>(i)];
    const model::QuarterCarOutputs out = car.outputs(x.data(), road);
    const double values[kQuarterCarLinearOutputs] = {out.body_acc_m_per_s2, out.wheel_acc_m_per_s2,
                                                     out.travel_m, out.tyre_force_N};
    for (int k = 0; k < kQuarterCarLinearOutputs; ++k) column_of_c(k) = values[k];
  };
  // Linear and measured from equilibrium: f(0, 0) = 0, so each unit probe gives a column.
  for (int j = 0; j < n; ++j) {
    x[static_cast<std::size_t>(j)] = 1.0;
    probe(
        road::RoadSample{}, [&](int i) -> double& { return s.A(i, j); },
        [&](int k) -> double& { return s.C(k, j); });
    x[static_cast<std::size_t>(j)] = 0.0;
  }
  for (int j = 0; j < 2; ++j) {
    road::RoadSample unit;
    (j == 0 ? unit.elevation_m : unit.rate_m_per_s) = 1.0;
    probe(
        unit, [&](int i) -> double& { return s.B(i, j); },
        [&](int k) -> double& { return s.D(k, j); });
  }
  return s;
}

}  // namespace ridefit::simulate
