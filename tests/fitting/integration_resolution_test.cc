// The stop that ends a fit at the integrator's resolution: when it stops, when it must not, and
// that it measures the scatter again before stopping at a new iterate.
#include "ridefit/fitting/integration_resolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ridefit::fitting {
namespace {

ceres::IterationSummary iterate(int iteration, double cost, bool successful,
                                double cost_change = 0.0, double relative_decrease = 0.0) {
  ceres::IterationSummary s;
  s.iteration = iteration;
  s.cost = cost;
  s.step_is_successful = successful;
  s.step_is_valid = true;
  s.cost_change = cost_change;
  s.relative_decrease = relative_decrease;
  return s;
}

TEST(IntegrationResolution, FloorIsHalfTheSquaredDifferenceOfTheTwoRuns) {
  const std::vector<double> r = {1.0, 2.0, 3.0}, coarse = {1.5, 2.0, 1.0};
  EXPECT_DOUBLE_EQ(integration_cost_floor(r, coarse), 0.5 * (0.25 + 0.0 + 4.0));
  EXPECT_DOUBLE_EQ(coarser_tolerance(1e-6), 4e-6);
  EXPECT_DOUBLE_EQ(coarser_tolerance(0.05), 0.1);  // the integrators' largest tolerance
}

// Like with like: under a robust loss Ceres' cost is ½Σρ(r²), so the floor is ½Σρ(δ²) (Cauchy
// with scale a: ρ(s) = a²·log(1 + s/a²)), below ½Σδ² where the differences pass the scale.
TEST(IntegrationResolution, FloorCarriesTheFitsRobustLoss) {
  const std::vector<double> fine = {1.0, -2.0, 30.0};
  const std::vector<double> coarse = {0.0, 0.0, 0.0};
  const ceres::CauchyLoss loss(5.0);
  const double expected =
      0.5 * 25.0 * (std::log1p(1.0 / 25.0) + std::log1p(4.0 / 25.0) + std::log1p(900.0 / 25.0));
  EXPECT_NEAR(integration_cost_floor(fine, coarse, &loss), expected, 1e-12 * expected);
  EXPECT_LT(integration_cost_floor(fine, coarse, &loss),
            0.2 * integration_cost_floor(fine, coarse));
  EXPECT_DOUBLE_EQ(integration_cost_floor(fine, coarse, nullptr), 0.5 * (1.0 + 4.0 + 900.0));
}

TEST(IntegrationResolution, StopsOnlyOnceTheCostIsAtTheScatterMeasuredThere) {
  int measurements = 0;
  double floor = 1.0;
  StopAtIntegrationResolution stop(
      [&] {
        ++measurements;
        return floor;
      },
      10000);
  // Far from the optimum: large cost, large predicted decrease.
  EXPECT_EQ(stop(iterate(0, 1e6, true)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(measurements, 1);  // measured at the start
  EXPECT_EQ(stop(iterate(1, 1e3, true, 1e6 - 1e3, 1.0)), ceres::SOLVER_CONTINUE);
  // A trial point the model could not be solved at: never a reason to stop.
  auto failed = iterate(2, 1.797e308, false, -1.797e308, -1.797e308);
  failed.step_is_valid = false;
  EXPECT_EQ(stop(failed), ceres::SOLVER_CONTINUE);
  // Below the start's floor at a new iterate: measured again there; here the integration is
  // finer (floor 0.01), so the fit goes on.
  floor = 0.01;
  EXPECT_EQ(stop(iterate(3, 0.5, true, 999.5, 1.0)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(measurements, 2);
  EXPECT_FALSE(stop.reached());
  // A rejected step leaves the iterate where it was: its measurement still holds.
  EXPECT_EQ(stop(iterate(4, 0.6, false, -0.1, -1.0)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(measurements, 2);
  // Below that floor at the next iterate: measured there once more, and it stops.
  EXPECT_EQ(stop(iterate(5, 0.008, true, 0.492, 1.0)), ceres::SOLVER_TERMINATE_SUCCESSFULLY);
  EXPECT_EQ(measurements, 3);
  EXPECT_TRUE(stop.reached());
  EXPECT_DOUBLE_EQ(stop.floor(), 0.01);
}

TEST(IntegrationResolution, StopsWhenThePredictedDecreaseIsBelowTheScatter) {
  StopAtIntegrationResolution stop([] { return 0.1; }, 10000);
  EXPECT_EQ(stop(iterate(0, 500.0, true)), ceres::SOLVER_CONTINUE);
  // A small accepted step is progress (along a flat valley): the fit goes on.
  EXPECT_EQ(stop(iterate(1, 499.96, true, 0.04, 0.8)), ceres::SOLVER_CONTINUE);
  // Noisy data at their optimum: cost 500 (the noise's), a step predicting a decrease of 0.05
  // (cost change −0.04, ratio −0.8) rejected, below the scatter 0.1 + √1000·√(0.2/10000) ≈ 0.24.
  // Once is not enough (a shorter step may still be accepted)...
  EXPECT_EQ(stop(iterate(2, 500.0, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  EXPECT_FALSE(stop.reached());
  // ...and an accepted step in between starts the count again...
  EXPECT_EQ(stop(iterate(3, 499.99, true, 0.01, 0.5)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(4, 499.99, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  // ...but a second such rejection in a row ends the fit.
  EXPECT_EQ(stop(iterate(5, 499.99, false, -0.02, -0.8)), ceres::SOLVER_TERMINATE_SUCCESSFULLY);
  EXPECT_TRUE(stop.reached());
  // A rejected step that had predicted a decrease of 50 is the model's failure, not the scatter's.
  StopAtIntegrationResolution go_on([] { return 0.1; }, 10000);
  EXPECT_EQ(go_on(iterate(0, 500.0, true)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(go_on(iterate(1, 500.0, false, -40.0, -0.8)), ceres::SOLVER_CONTINUE);
}

// The gradient condition: two rejections the scatter decided end the fit only if the whole
// Gauss-Newton step promises less than the scatter too. A trust region shrunk partway along a flat
// valley promises 0.05 for its own step while the step to the valley's floor promises 5.
TEST(IntegrationResolution, RejectionsStopOnlyWhenTheWholeStepPromisesLittleToo) {
  double promise = 5.0;
  int asked = 0;
  StopAtIntegrationResolution stop([] { return 0.1; }, 10000,
                                   [&] {
                                     ++asked;
                                     return promise;
                                   });
  EXPECT_EQ(stop(iterate(0, 500.0, true)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(1, 500.0, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(2, 500.0, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(asked, 1);  // asked only when the rejections would end the fit
  EXPECT_FALSE(stop.reached());
  // At the valley's floor the whole step promises 0.01, below the scatter of about 0.24.
  promise = 0.01;
  EXPECT_EQ(stop(iterate(3, 499.0, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(4, 499.0, false, -0.04, -0.8)), ceres::SOLVER_TERMINATE_SUCCESSFULLY);
  EXPECT_EQ(asked, 2);
  EXPECT_TRUE(stop.reached());
}

// And, with the number of fitted values known, only if the whole step would move them by less
// than a fifth of their standard errors: cost 500 over 10000 residuals and 4 values is a residual
// variance σ̂² = 1000/9996 ≈ 0.1, so the step may promise at most ½·0.04·σ̂² ≈ 0.002. A promise of
// 0.01 is below the scatter (0.24) but half a standard error of movement: the fit goes on.
TEST(IntegrationResolution, RejectionsStopOnlyWhenTheWholeStepIsWithinAFifthOfTheErrors) {
  double promise = 0.01;
  StopAtIntegrationResolution stop([] { return 0.1; }, 10000, [&] { return promise; }, 4);
  EXPECT_EQ(stop(iterate(0, 500.0, true)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(1, 500.0, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(2, 500.0, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  EXPECT_FALSE(stop.reached());
  promise = 0.0015;
  EXPECT_EQ(stop(iterate(3, 500.0, false, -0.04, -0.8)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(4, 500.0, false, -0.04, -0.8)), ceres::SOLVER_TERMINATE_SUCCESSFULLY);
  EXPECT_TRUE(stop.reached());
}

TEST(IntegrationResolution, NoFloorNoStop) {
  StopAtIntegrationResolution stop([] { return 0.0; }, 100);  // frozen steps, or a failed run
  EXPECT_EQ(stop(iterate(0, 0.0, true)), ceres::SOLVER_CONTINUE);
  EXPECT_EQ(stop(iterate(1, 0.0, true, 1e-30, 1.0)), ceres::SOLVER_CONTINUE);
}

}  // namespace
}  // namespace ridefit::fitting
