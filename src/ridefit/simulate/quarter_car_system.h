#pragma once

#include <Eigen/Core>

#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/ode_system.h"

namespace ridefit::simulate {

// A quarter car driven by a road, as a first-order system for the integrators. The
// Jacobian is exact: the same templated derivatives() run on Eigen's forward-mode
// AutoDiffScalar (core does not depend on Ceres).
class QuarterCarSystem : public OdeSystem {
 public:
  QuarterCarSystem(const model::QuarterCar& car, const road::RoadInput& road);

  int size() const override { return car_.state_size(); }
  bool derivatives(double t_s, const double* x, double* xdot) const override;
  bool jacobian(double t_s, const double* x, double* jacobian_column_major) const override;
  double typical_magnitude(int state_index) const override;
  double max_step_s() const override { return road_.max_step_s(); }
  // The kinks of the model's laws: the damper's rate (Dahl reversal, compression/rebound
  // split), the knee on either side, the bump stop's contact, the tyre's lift-off; only those
  // the model has.
  int switching_count() const override { return static_cast<int>(switches_.size()); }
  void switching(double t_s, const double* x, double* g) const override;

 private:
  enum class Switch { kDamperRate, kKneeRebound, kKneeCompression, kBumpStop, kLiftOff };
  // Newton iterations ask for the road at one stage time again and again. One system serves
  // one integration (not shared between threads).
  road::RoadSample road_at(double t_s) const;

  // The Jacobian's scalar (autodiff_jacobian's) and the parameters in it, made once: converting
  // them on every Jacobian cost as much as the Jacobian itself.
  using JacobianScalar = Eigen::AutoDiffScalar<
      Eigen::Matrix<double, Eigen::Dynamic, 1, 0, model::QuarterCar::kMaxStates, 1>>;

  const model::QuarterCar& car_;
  const road::RoadInput& road_;
  model::QuarterCarParameters<JacobianScalar> jacobian_parameters_;
  std::vector<Switch> switches_;
  mutable double cached_time_s_ = -1e300;
  mutable road::RoadSample cached_road_;
};

}  // namespace ridefit::simulate
