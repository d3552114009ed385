#pragma once

#include "ridefit/model/half_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/ode_system.h"

namespace ridefit::simulate {

// The roads under a half car's two wheels: the front wheel on `road`, the rear wheel on the
// same profile `rear_delay_s` later (wheelbase over speed). Before the rear wheel reaches the
// profile's start it stands still at the profile's first elevation.
class AxleRoadInput {
 public:
  AxleRoadInput(const road::RoadInput& road, double rear_delay_s);
  model::AxleRoads at(double time_s) const;
  double rear_delay_s() const { return rear_delay_s_; }
  const road::RoadInput& road() const { return road_; }

 private:
  const road::RoadInput& road_;
  double rear_delay_s_;
};

// The rear delay of a road for a car: wheelbase / speed for a road driven at a speed; for a
// road given over time, `rear_delay_s` must be given (>= 0), else InputError.
double rear_delay_s(const road::RoadInput& road, double wheelbase_m,
                    std::optional<double> rear_delay_s = std::nullopt);

// A half car on its roads as a first-order system; the Jacobian comes from the templated model
// by forward-mode autodiff (Eigen's AutoDiffScalar), as for the quarter car.
class HalfCarSystem : public OdeSystem {
 public:
  HalfCarSystem(const model::HalfCar& car, const AxleRoadInput& roads) : car_(car), roads_(roads) {}

  int size() const override { return car_.state_size(); }
  bool derivatives(double t_s, const double* x, double* xdot) const override;
  bool jacobian(double t_s, const double* x, double* jacobian_column_major) const override;
  double typical_magnitude(int state_index) const override;
  double max_step_s() const override { return roads_.road().max_step_s(); }

 private:
  const model::HalfCar& car_;
  const AxleRoadInput& roads_;
};

}  // namespace ridefit::simulate
