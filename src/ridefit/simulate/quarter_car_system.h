#pragma once

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/ode_system.h"

namespace ridefit::simulate {

// A quarter car driven by a road, as a first-order system for the integrators. The
// Jacobian is exact: the same templated derivatives() run on Eigen's forward-mode
// AutoDiffScalar (core does not depend on Ceres).
class QuarterCarSystem : public OdeSystem {
 public:
  QuarterCarSystem(const model::QuarterCar& car, const road::RoadInput& road)
      : car_(car), road_(road) {}

  int size() const override { return car_.state_size(); }
  bool derivatives(double t_s, const double* x, double* xdot) const override;
  bool jacobian(double t_s, const double* x, double* jacobian_column_major) const override;
  double typical_magnitude(int state_index) const override;
  double max_step_s() const override { return road_.max_step_s(); }

 private:
  const model::QuarterCar& car_;
  const road::RoadInput& road_;
};

}  // namespace ridefit::simulate
