// The PSD fit recovers the top-mount stiffness of the stick/slip quarter car from its spectra
// (seed 000 Section 4.2.2: 488 and 707 N/mm), the "measurement" simulated with CVODE.
#include "ridefit/fitting/psd_fit.h"

#include <gtest/gtest.h>

#include <ceres/cost_function.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ridefit/io/input_error.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/simulate/quarter_car_sensitivity.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"

namespace ridefit::fitting {
namespace {

PsdMeasurement measure(double top_mount_N_per_m) {
  auto p = testing::passat_corner().parameters;
  p.top_mount_stiffness_N_per_m = top_mount_N_per_m;
  const model::QuarterCar car(model::DamperState::kStickSlip, p);
  road::Iso8608RoadParameters r;
  r.road_class = road::Iso8608Class::kA;
  r.random.speed_m_per_s = 50.0 / 3.6;
  r.random.duration_s = 30.0;
  r.random.seed = 5;
  const auto road = road::make_iso8608_road(r);
  simulate::SimulationOptions options;
  options.output_rate_Hz = 1000.0;
  // CVODE, not the ESDIRK that the fit runs (no inverse crime).
  options.integrator.method = simulate::Method::kCvodeBdf;
  options.integrator.relative_tolerance = 1e-8;
  const auto run = simulate::simulate(car, road, options);
  PsdMeasurement m;
  m.source = "simulated";
  m.time_s = run.time_s;
  m.sample_rate_Hz = 1000.0;
  m.road = std::make_shared<road::MeasuredRoad>(run.time_s, run.road_m);
  m.body_acc_m_per_s2 = run.body_acc_m_per_s2;
  m.wheel_acc_m_per_s2 = run.wheel_acc_m_per_s2;
  return m;
}

void expect_recovered(double truth, double start) {
  const auto m = measure(truth);
  auto p = testing::passat_corner().parameters;
  p.top_mount_stiffness_N_per_m = start;
  const model::QuarterCar car(model::DamperState::kStickSlip, p);
  PsdFitOptions options;
  options.free = {"top_mount_stiffness_N_per_m"};
  options.band_low_Hz = 8.0;
  options.band_high_Hz = 30.0;
  options.segment_s = 5.0;
  const auto fit = fit_psd(m, car, options);
  EXPECT_TRUE(fit.converged) << fit.termination;
  EXPECT_NEAR(fit.values[0], truth, 0.03 * truth) << "start " << start;
}

TEST(PsdFit, RecoversA488NPerMmTopMount) { expect_recovered(488000.0, 600000.0); }
TEST(PsdFit, RecoversA707NPerMmTopMount) { expect_recovered(707000.0, 560000.0); }

// The log-PSD residuals' Jacobian (tangents through the ESDIRK steps and the FFT) against
// central differences of the same residuals on the same steps (frozen: the adaptive run's step
// sequence moves with the parameters, so differences of re-chosen steps measure the error
// control, not the tangent), both parameters, every bin. (The Coulomb-force column is the one
// that caught signed_power dropping the tangent at s = 0, where a sliding Dahl element sits;
// scalar_math.h.)
TEST(PsdFit, GradientCheckAgainstCentralDifferences) {
  auto m = measure(488000.0);
  m.time_s.resize(10001);  // 10 s are enough for the check
  m.body_acc_m_per_s2.resize(10001);
  m.wheel_acc_m_per_s2.resize(10001);
  auto at = testing::passat_corner().parameters;
  at.top_mount_stiffness_N_per_m *= 1.1;  // off the truth, so residuals are not zero
  at.coulomb_force_N *= 0.9;
  const model::QuarterCar car(model::DamperState::kStickSlip, at);
  PsdFitOptions options;
  options.free = {"top_mount_stiffness_N_per_m", "coulomb_force_N"};
  options.segment_s = 2.0;
  const auto steps = simulate::quarter_car_steps(
      car, *m.road, m.time_s, {.relative_tolerance = options.relative_tolerance});
  options.frozen_steps = &steps;
  std::unique_ptr<ceres::CostFunction> cost(make_psd_cost(m, car, options));
  double x[2] = {1.0, 1.0};
  const double* blocks[2] = {&x[0], &x[1]};
  const auto rows = static_cast<std::size_t>(cost->num_residuals());
  std::vector<double> residuals(rows), j0(rows), j1(rows);
  double* jacobians[2] = {j0.data(), j1.data()};
  ASSERT_TRUE(cost->Evaluate(blocks, residuals.data(), jacobians));
  for (int p = 0; p < 2; ++p) {
    const double saved = x[p], step = 1e-6;
    std::vector<double> up(rows), down(rows);
    x[p] = saved + step;
    ASSERT_TRUE(cost->Evaluate(blocks, up.data(), nullptr));
    x[p] = saved - step;
    ASSERT_TRUE(cost->Evaluate(blocks, down.data(), nullptr));
    x[p] = saved;
    const auto& exact = p == 0 ? j0 : j1;
    double scale = 0.0, worst = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
      scale = std::max(scale, std::abs(exact[r]));
      worst = std::max(worst, std::abs((up[r] - down[r]) / (2.0 * step) - exact[r]));
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LT(worst, 1e-4 * scale) << options.free[static_cast<std::size_t>(p)];
  }
}

TEST(PsdFit, BadRequestsAreInputErrors) {
  const auto m = measure(488000.0);
  const model::QuarterCar car(model::DamperState::kStickSlip, testing::passat_corner().parameters);
  PsdFitOptions options;
  options.free = {"top_mount_stiffnes"};
  EXPECT_THROW(fit_psd(m, car, options), InputError);
  options.free = {"top_mount_stiffness_N_per_m"};
  options.segment_s = 1000.0;
  EXPECT_THROW(fit_psd(m, car, options), InputError);
  options.segment_s = 5.0;
  options.bounds["top_mount_stiffness_N_per_m"] = {1e6, 2e6};  // start outside
  EXPECT_THROW(fit_psd(m, car, options), InputError);
}

}  // namespace
}  // namespace ridefit::fitting
