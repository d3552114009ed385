// The integrators' Jacobian (forward-mode autodiff of the templated model) against central
// differences, on every topology and on both sides of the friction kink.
#include "ridefit/simulate/quarter_car_system.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/jacobian_check.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::simulate {
namespace {

void expect_jacobian_matches_central_differences(const model::QuarterCar& car,
                                                 const std::vector<double>& x) {
  const testing::SineRoad road(2e-3, 3.0, 10.0);
  testing::expect_jacobian_matches_central_differences(QuarterCarSystem(car, road), 0.37, x,
                                                       model::to_string(car.damper_state()));
}

TEST(QuarterCarSystem, JacobianMatchesCentralDifferencesForEveryTopology) {
  const auto file = testing::passat_corner();
  expect_jacobian_matches_central_differences(
      model::QuarterCar(model::DamperState::kSlip, file.parameters),
      {1e-3, -2e-4, 0.03, -0.1, 5e-4});
  expect_jacobian_matches_central_differences(
      model::QuarterCar(model::DamperState::kStick, file.parameters), {1e-3, -2e-4, 0.03, -0.1});
  // Damper sliding clearly in one direction, then clearly in the other (away from the kink,
  // where central differences are meaningful).
  const model::QuarterCar car(model::DamperState::kStickSlip, file.parameters);
  expect_jacobian_matches_central_differences(car, {1e-3, -2e-4, 0.03, -0.1, 5e-4, 20.0});
  expect_jacobian_matches_central_differences(car, {-1e-3, 2e-4, 0.03, -0.1, -5e-4, -20.0});
}

TEST(QuarterCarSystem, NonFiniteStateIsReportedNotPropagated) {
  const auto file = testing::passat_corner();
  const model::QuarterCar car(model::DamperState::kStickSlip, file.parameters);
  const testing::SineRoad road(2e-3, 3.0, 10.0);
  const QuarterCarSystem system(car, road);
  std::vector<double> x = {std::nan(""), 0, 0, 0, 0, 0}, xdot(6);
  EXPECT_FALSE(system.derivatives(0.0, x.data(), xdot.data()));
}

}  // namespace
}  // namespace ridefit::simulate
