// The SDIRK quarter car with tangents: its accelerations against CVODE, its derivatives against
// central differences of itself.
#include "ridefit/simulate/quarter_car_sensitivity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "ridefit/road/log_sweep.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"

namespace ridefit::simulate {
namespace {

road::LogSweep short_sweep() {
  road::LogSweepParameters p;
  p.initial_amplitude_m = 0.002;
  p.duration_s = 8.0;
  return road::LogSweep(p);
}

TEST(QuarterCarSensitivity, AccelerationsFollowCvode) {
  const auto file = testing::passat_corner();
  const model::QuarterCar car(model::DamperState::kStickSlip, file.parameters);
  const auto road = short_sweep();
  SimulationOptions options;
  options.output_rate_Hz = 1000.0;
  options.integrator.relative_tolerance = 1e-8;
  const auto reference = simulate(car, road, options);
  const auto sdirk = quarter_car_accelerations<double>(car, file.parameters, file.parameters, road,
                                                       reference.time_s);
  ASSERT_TRUE(sdirk.has_value());
  const double body_ref = signal::rms(reference.body_acc_m_per_s2);
  const double wheel_ref = signal::rms(reference.wheel_acc_m_per_s2);
  EXPECT_NEAR(signal::rms(sdirk->body), body_ref, 0.01 * body_ref);
  EXPECT_NEAR(signal::rms(sdirk->wheel), wheel_ref, 0.01 * wheel_ref);
}

TEST(QuarterCarSensitivity, DerivativesMatchCentralDifferences) {
  using AD = Eigen::AutoDiffScalar<Eigen::Vector2d>;
  const auto file = testing::passat_corner();
  const model::QuarterCar car(model::DamperState::kStickSlip, file.parameters);
  const auto road = short_sweep();
  std::vector<double> times;
  for (int k = 0; k <= 2000; ++k) times.push_back(k * 1e-3);
  auto p_ad = file.parameters.cast<AD>();
  p_ad.top_mount_stiffness_N_per_m = AD(file.parameters.top_mount_stiffness_N_per_m, 2, 0);
  p_ad.coulomb_force_N = AD(file.parameters.coulomb_force_N, 2, 1);
  const auto jets = quarter_car_accelerations<AD>(car, p_ad, file.parameters, road, times);
  ASSERT_TRUE(jets.has_value());
  for (int j = 0; j < 2; ++j) {
    auto up = file.parameters, down = file.parameters;
    double& u = j == 0 ? up.top_mount_stiffness_N_per_m : up.coulomb_force_N;
    double& d = j == 0 ? down.top_mount_stiffness_N_per_m : down.coulomb_force_N;
    const double step = 1e-5 * u;
    u += step;
    d -= step;
    const model::QuarterCar car_up(model::DamperState::kStickSlip, up);
    const model::QuarterCar car_down(model::DamperState::kStickSlip, down);
    const auto a = quarter_car_accelerations<double>(car_up, up, up, road, times);
    const auto b = quarter_car_accelerations<double>(car_down, down, down, road, times);
    double scale = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < times.size(); ++k) {
      const double numeric = (a->body[k] - b->body[k]) / (2.0 * step);
      const double exact =
          jets->body[k].derivatives().size() == 2 ? jets->body[k].derivatives()[j] : 0.0;
      scale = std::max(scale, std::abs(exact));
      worst = std::max(worst, std::abs(numeric - exact));
    }
    EXPECT_GT(scale, 0.0);
    EXPECT_LT(worst, 1e-4 * scale) << "parameter " << j;
  }
}

}  // namespace
}  // namespace ridefit::simulate
