#pragma once

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::simulate {

// The quarter car's parameters as Eigen AutoDiffScalars whose derivative vectors are zeros of
// the state's size n, not empty. Eigen's AutoDiffScalar makes an empty and a sized derivative
// vector coherent in some operators but not when the sized one is an expression (e.g.
// `-knee_velocity + (force + r·knee_force)/(r·c_h)` in AsymmetricDamper): the sizes then
// mismatch, an assertion in debug builds and wrong Jacobian entries in release builds (the
// blow-off knee's Jacobian was wrong this way). Sized zeros keep every operation coherent.
template <typename AutoDiff>
model::QuarterCarParameters<AutoDiff> autodiff_parameters(
    const model::QuarterCarParameters<double>& values, int n) {
  model::QuarterCarParameters<AutoDiff> p = values.template cast<AutoDiff>();
  for (std::size_t i = 0; i < model::kQuarterCarParameters.size(); ++i) {
    model::quarter_car_parameter(p, i).derivatives().setZero(n);
  }
  return p;
}

}  // namespace ridefit::simulate
