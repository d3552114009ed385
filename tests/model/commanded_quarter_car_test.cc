// A controlled damper on the road: the quarter car follows the record's command through the
// fluid's lag (QuarterCar with DamperCommand::kFromRoad), checked against closed forms and
// against the passive car at the command's levels.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/simulate/quarter_car_system.h"
#include "support/commanded_road.h"
#include "support/jacobian_check.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::model {
namespace {

QuarterCarParameters<double> commanded(double lag_s) {
  auto p = testing::passat_corner().parameters;
  p.damping_Ns_per_m = 600.0;
  p.damping_per_command_Ns_per_m = 400.0;
  p.coulomb_force_per_command_N = 20.0;
  p.command_lag_s = lag_s;
  return p;
}

simulate::QuarterCarResponse run(const QuarterCar& car, const road::RoadInput& road) {
  simulate::SimulationOptions options;
  options.output_rate_Hz = 1000.0;
  options.integrator.relative_tolerance = 1e-8;
  return simulate::simulate(car, road, options);
}

TEST(CommandedQuarterCar, FilteredCommandIsAFirstOrderLagOfAStep) {
  // u = 2 A from t = 0: ū(t) = 2·(1 − exp(−t/τ)), whatever the car does.
  const double lag_s = 0.02;
  const testing::CommandedSineRoad road(2e-3, 3.0, 0.2, [](double) { return 2.0; });
  const QuarterCar car(DamperState::kStickSlip, commanded(lag_s), DamperCommand::kFromRoad);
  EXPECT_EQ(car.state_size(), 7);
  EXPECT_EQ(car.command_state_index(), 6);
  const auto r = run(car, road);
  ASSERT_EQ(r.damper_command.size(), r.time_s.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < r.time_s.size(); ++k) {
    const double exact = 2.0 * (1.0 - std::exp(-r.time_s[k] / lag_s));
    worst = std::max(worst, std::abs(r.damper_command[k] - exact));
  }
  EXPECT_LT(worst, 1e-5);
}

TEST(CommandedQuarterCar, ConstantCommandWithoutLagIsThePassiveDamperAtItsLevels) {
  // 1.5 A held: c = 600 + 400·1.5 = 1200 N·s/m and Fc = 60 + 20·1.5 = 90 N, as a passive car.
  const testing::CommandedSineRoad road(5e-3, 4.0, 2.0, [](double) { return 1.5; });
  const QuarterCar controlled(DamperState::kStickSlip, commanded(0.0), DamperCommand::kFromRoad);
  EXPECT_EQ(controlled.state_size(), 6);
  auto passive = testing::passat_corner().parameters;
  passive.damping_Ns_per_m = 1200.0;
  passive.coulomb_force_N = 90.0;
  const auto a = run(controlled, road);
  const auto b = run(QuarterCar(DamperState::kStickSlip, passive), road);
  ASSERT_EQ(a.body_acc_m_per_s2.size(), b.body_acc_m_per_s2.size());
  std::vector<double> difference(a.body_acc_m_per_s2.size());
  for (std::size_t k = 0; k < difference.size(); ++k) {
    difference[k] = a.body_acc_m_per_s2[k] - b.body_acc_m_per_s2[k];
  }
  EXPECT_LT(signal::rms(difference), 1e-5 * signal::rms(b.body_acc_m_per_s2));
  EXPECT_GT(signal::rms(b.body_acc_m_per_s2), 0.1);
}

TEST(CommandedQuarterCar, WithoutTheRoadsCommandTheDamperStaysAtItsBaseLevels) {
  const testing::CommandedSineRoad road(5e-3, 4.0, 1.0, [](double) { return 1.5; });
  const QuarterCar ignoring(DamperState::kSlip, commanded(0.02));
  EXPECT_FALSE(ignoring.follows_command());
  EXPECT_EQ(ignoring.state_size(), 5);
  EXPECT_TRUE(ignoring.is_linear());
  const QuarterCar following = ignoring.with_command_from_road(true);
  EXPECT_TRUE(following.follows_command());
  EXPECT_FALSE(following.is_linear());
  EXPECT_NE(following.nonlinearity().find("command"), std::string::npos);
  auto base = commanded(0.02);
  base.damping_per_command_Ns_per_m = base.coulomb_force_per_command_N = 0.0;
  const auto a = run(ignoring, road);
  const auto b = run(QuarterCar(DamperState::kSlip, base), road);
  EXPECT_TRUE(a.damper_command.empty());
  EXPECT_NEAR(signal::rms(a.body_acc_m_per_s2), signal::rms(b.body_acc_m_per_s2),
              1e-9 * signal::rms(b.body_acc_m_per_s2));
}

TEST(CommandedQuarterCar, JacobianWithTheCommandStateMatchesCentralDifferences) {
  const testing::CommandedSineRoad road(2e-3, 3.0, 10.0,
                                        [](double t) { return 1.0 + 0.5 * std::sin(9.0 * t); });
  for (const DamperState state : {DamperState::kSlip, DamperState::kStickSlip}) {
    const QuarterCar car(state, commanded(0.015), DamperCommand::kFromRoad);
    const simulate::QuarterCarSystem system(car, road);
    std::vector<double> x = {1e-3, -2e-4, 0.03, -0.1, 5e-4};
    if (state == DamperState::kStickSlip) x.push_back(20.0);
    x.push_back(0.7);  // ū
    testing::expect_jacobian_matches_central_differences(system, 0.37, x, to_string(state));
    const int n = system.size();
    std::vector<double> jacobian(static_cast<std::size_t>(n * n));
    ASSERT_TRUE(system.jacobian(0.37, x.data(), jacobian.data()));
    // The command's row: ū' = (u − ū)/τ, so ∂ū'/∂ū = −1/τ exactly.
    const auto last = static_cast<std::size_t>(n - 1);
    EXPECT_DOUBLE_EQ(jacobian[last * static_cast<std::size_t>(n) + last], -1.0 / 0.015);
  }
}

}  // namespace
}  // namespace ridefit::model
