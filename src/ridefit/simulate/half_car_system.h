#pragma once

#include <optional>
#include <string_view>
#include <vector>

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
// road given over time, `rear_delay_s` must be given (>= 0), else InputError asking for it by
// `name` (the caller's name for the option: the CLI gives its flag).
double rear_delay_s(const road::RoadInput& road, double wheelbase_m,
                    std::optional<double> rear_delay_s = std::nullopt,
                    std::string_view name = "rear_delay_s");

// A half car on its roads as a first-order system; the Jacobian comes from the templated model
// by forward-mode autodiff (Eigen's AutoDiffScalar), as for the quarter car.
class HalfCarSystem : public OdeSystem {
 public:
  HalfCarSystem(const model::HalfCar& car, const AxleRoadInput& roads);

  int size() const override { return car_.state_size(); }
  bool derivatives(double t_s, const double* x, double* xdot) const override;
  bool jacobian(double t_s, const double* x, double* jacobian_column_major) const override;
  double typical_magnitude(int state_index) const override;
  double max_step_s() const override { return roads_.road().max_step_s(); }
  // The kinks: each strut damper's own rate where it has Dahl friction or a compression/rebound
  // split, each passive damper's travel rate where it has the split.
  int switching_count() const override { return static_cast<int>(switches_.size()); }
  void switching(double t_s, const double* x, double* g) const override;

 private:
  // A switching function: the rate of state `state` (a strut's damper deflection), or with
  // state < 0 the travel rate of the passive axle at `arm` over wheel `wheel`.
  struct Switch {
    int state = -1;
    double arm_m = 0.0;
    int wheel = 0;
  };
  std::vector<Switch> switches_;
  const model::HalfCar& car_;
  const AxleRoadInput& roads_;
};

}  // namespace ridefit::simulate
