// A single cleat after a flat run-up: the adaptive solver must not step over it (the road's
// max_step_s bounds its step), so CVODE and RK4 see the same impact.
#include <gtest/gtest.h>

#include "ridefit/road/cleat.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"

namespace ridefit::simulate {
namespace {

TEST(CleatResponse, CvodeDoesNotStepOverTheCleatAndAgreesWithRk4) {
  road::CleatParameters cleat;
  cleat.shape = road::CleatShape::kSemicircular;
  cleat.height_m = 0.02;
  cleat.length_m = 0.04;
  cleat.speed_m_per_s = 40.0 / 3.6;
  const auto road = road::make_cleat_road(cleat);
  const model::QuarterCar car(model::DamperState::kStickSlip, testing::passat_corner().parameters);
  SimulationOptions options;
  const auto cvode = simulate(car, road, options);
  options.integrator.method = Method::kArkodeRk4;
  options.integrator.fixed_step_s = 2e-5;
  const auto rk4 = simulate(car, road, options);
  const double a = signal::rms(cvode.body_acc_m_per_s2);
  const double b = signal::rms(rk4.body_acc_m_per_s2);
  EXPECT_GT(a, 0.01);  // the body does move
  EXPECT_NEAR(a, b, 0.01 * b);
  EXPECT_GT(cvode.statistics.steps, 100);
}

}  // namespace
}  // namespace ridefit::simulate
