// CVODE (BDF) and ARKODE RK4 on the nonlinear stick/slip quarter car: they agree, and each
// converges as its tolerance or step shrinks.
#include "ridefit/simulate/integrator.h"
#include "ridefit/signal/statistics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::simulate {
namespace {

// Largest difference between two body-acceleration histories relative to the RMS.
double relative_difference(const QuarterCarResponse& a, const QuarterCarResponse& b) {
  double worst = 0.0;
  for (std::size_t k = 0; k < a.time_s.size(); ++k) {
    worst = std::max(worst, std::abs(a.body_acc_m_per_s2[k] - b.body_acc_m_per_s2[k]));
  }
  return worst / signal::rms(b.body_acc_m_per_s2);
}

class StickSlipRun : public ::testing::Test {
 protected:
  // 2 mm at 2 Hz: the damper sticks and slips every cycle (Fc = 60 N).
  QuarterCarResponse run(Method method, double tolerance_or_step) const {
    const auto file = testing::passat_corner();
    const model::QuarterCar car(model::DamperState::kStickSlip, file.parameters);
    const testing::SineRoad road(2e-3, 2.0, 6.0);
    SimulationOptions options;
    options.output_rate_Hz = 500.0;
    options.integrator.method = method;
    if (method == Method::kCvodeBdf) {
      options.integrator.relative_tolerance = tolerance_or_step;
    } else {
      options.integrator.fixed_step_s = tolerance_or_step;
    }
    return simulate(car, road, options);
  }
};

TEST_F(StickSlipRun, CvodeAndRk4AgreeOnBodyAccelerationRms) {
  const auto cvode = run(Method::kCvodeBdf, 1e-6);
  const auto rk4 = run(Method::kArkodeRk4, 1e-4);
  const double a = signal::rms(cvode.body_acc_m_per_s2);
  const double b = signal::rms(rk4.body_acc_m_per_s2);
  EXPECT_NEAR(a, b, 5e-3 * b);
  // The run really sticks and slips.
  double stuck_share = 0.0;
  for (double s : cvode.stuck) stuck_share += s;
  stuck_share /= static_cast<double>(cvode.stuck.size());
  EXPECT_GT(stuck_share, 0.05);
  EXPECT_LT(stuck_share, 0.95);
  EXPECT_EQ(cvode.statistics.method, "cvode");
  EXPECT_GT(cvode.statistics.steps, 0);
  EXPECT_GT(cvode.statistics.jacobian_evaluations, 0);
  // 6 s at 0.1 ms (one more step may land the stop time after rounding); ARKODE reuses the
  // right-hand side at the end of a step as the first stage of the next.
  EXPECT_NEAR(static_cast<double>(rk4.statistics.steps), 60000.0, 1.0);
  EXPECT_GE(rk4.statistics.rhs_evaluations, 3 * rk4.statistics.steps);
  EXPECT_LE(rk4.statistics.rhs_evaluations, 4 * rk4.statistics.steps + 4);
}

TEST_F(StickSlipRun, CvodeConvergesAsToleranceShrinks) {
  const auto reference = run(Method::kCvodeBdf, 1e-10);
  const double coarse = relative_difference(run(Method::kCvodeBdf, 1e-4), reference);
  const double medium = relative_difference(run(Method::kCvodeBdf, 1e-6), reference);
  const double fine = relative_difference(run(Method::kCvodeBdf, 1e-8), reference);
  EXPECT_LT(medium, coarse);
  EXPECT_LT(fine, medium);
  EXPECT_LT(fine, 1e-3);
}

TEST_F(StickSlipRun, Rk4ConvergesAsStepShrinks) {
  const auto reference = run(Method::kCvodeBdf, 1e-10);
  const double coarse = relative_difference(run(Method::kArkodeRk4, 2e-4), reference);
  const double medium = relative_difference(run(Method::kArkodeRk4, 1e-4), reference);
  const double fine = relative_difference(run(Method::kArkodeRk4, 5e-5), reference);
  EXPECT_LT(medium, coarse);
  EXPECT_LT(fine, medium);
  EXPECT_LT(fine, 1e-2);
}

TEST(Integrator, UnstableFixedStepFailsWithTimeInMessage) {
  // RK4 far beyond its stability limit for σ0/c ≈ 5600 1/s blows up; the failure names
  // the time instead of returning NaN.
  const auto file = testing::passat_corner();
  const model::QuarterCar car(model::DamperState::kStickSlip, file.parameters);
  const testing::SineRoad road(2e-3, 2.0, 2.0);
  SimulationOptions options;
  options.output_rate_Hz = 100.0;
  options.integrator.method = Method::kArkodeRk4;
  options.integrator.fixed_step_s = 5e-3;
  try {
    simulate(car, road, options);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("failed at t ="), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ridefit::simulate
