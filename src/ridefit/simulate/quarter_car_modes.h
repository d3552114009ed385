#pragma once

#include <Eigen/Core>

#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/modal_analysis.h"

namespace ridefit::simulate {

// The state matrix A = ∂f/∂x of a linear quarter car (slip or stick) about rest, taken
// from the same templated model by forward-mode autodiff: exact, never hand-typed.
Eigen::MatrixXd quarter_car_state_matrix(const model::QuarterCar& car);

// Modes of the linear slip or stick quarter car, named "body" and "wheel" by which mass
// holds most of the mode's kinetic energy. A stick/slip car, and a slip car whose damper is
// asymmetric (compression_to_rebound_ratio ≠ 1), is nonlinear: InputError.
ModalAnalysis quarter_car_modes(const model::QuarterCar& car);

}  // namespace ridefit::simulate
