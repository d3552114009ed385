// The integrators' Jacobian (forward-mode autodiff of the templated model) against central
// differences, on every topology and on both sides of the friction kink.
#include "ridefit/simulate/quarter_car_system.h"

#include <gtest/gtest.h>

#include <vector>

#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::simulate {
namespace {

void expect_jacobian_matches_central_differences(const model::QuarterCar& car,
                                                 const std::vector<double>& x) {
  const testing::SineRoad road(2e-3, 3.0, 10.0);
  const QuarterCarSystem system(car, road);
  const int n = system.size();
  const double t = 0.37;
  std::vector<double> jacobian(static_cast<std::size_t>(n * n));
  ASSERT_TRUE(system.jacobian(t, x.data(), jacobian.data()));
  for (int col = 0; col < n; ++col) {
    const double h = 1e-6 * system.typical_magnitude(col);
    std::vector<double> plus = x, minus = x, f_plus(n), f_minus(n);
    plus[col] += h;
    minus[col] -= h;
    ASSERT_TRUE(system.derivatives(t, plus.data(), f_plus.data()));
    ASSERT_TRUE(system.derivatives(t, minus.data(), f_minus.data()));
    for (int row = 0; row < n; ++row) {
      const double fd = (f_plus[row] - f_minus[row]) / (2.0 * h);
      const double exact = jacobian[static_cast<std::size_t>(col * n + row)];
      EXPECT_NEAR(exact, fd, 1e-6 * std::max(1.0, std::abs(fd)))
          << "d f" << row << " / d x" << col << " (" << model::to_string(car.damper_state()) << ")";
    }
  }
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
