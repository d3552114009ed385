// A semi-active law driving a controlled damper on the half car: the law's coefficient becomes
// the command u = (c_law − c)/c_b, which the damper follows through its lag (HalfCarAxle).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ridefit/io/half_car_file.h"
#include "ridefit/model/half_car.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/half_car_system.h"
#include "support/input_error_message.h"
#include "support/jacobian_check.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::model {
namespace {

io::HalfCarFile ajayi(const io::ModelOverrides& overrides) {
  return io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"), overrides);
}

TEST(CommandedHalfCar, TheLawsRequestReachesTheDamperThroughTheLag) {
  // Skyhook (c_sky 3000 within 300–3000 N·s/m) on a front damper c = 1000 + 1000·ū N·s/m, τ = 20
  // ms.
  const HalfCar car = ajayi({{"control.law", "skyhook"},
                             {"front.damping_per_command_Ns_per_m", "1000"},
                             {"front.command_lag_s", "0.02"}})
                          .make_model();
  ASSERT_EQ(car.state_size(), 2 * kHalfCarDofs + 1);
  EXPECT_EQ(car.state_names().back(), "front_filtered_command");
  EXPECT_FALSE(car.is_linear());
  std::vector<double> x(static_cast<std::size_t>(car.state_size()), 0.0);
  x[kHalfCarDofs + kBodyHeave] = 0.1;  // body rising, wheel still: skyhook asks for c_sky = 3000
  x.back() = 0.5;                      // ū
  std::vector<double> xdot(x.size());
  car.derivatives(x.data(), AxleRoads{}, xdot.data());
  // u = (3000 − 1000)/1000 = 2, so ū' = (2 − 0.5)/0.02.
  EXPECT_NEAR(xdot.back(), 75.0, 1e-12);
  const HalfCarOutputs out = car.outputs(x.data(), AxleRoads{});
  EXPECT_NEAR(out.front_damping_Ns_per_m, 1500.0, 1e-9);  // the lagged coefficient, not 3000
  EXPECT_NEAR(out.rear_damping_Ns_per_m, 3000.0, 1e-9);   // the rear follows the law at once
}

TEST(CommandedHalfCar, FrictionLevelMovesWithTheCommand) {
  // A front strut in stick/slip with Fc = 60 + 40·ū N; the damper at ū = 1.5 → Fc = 120 N.
  const HalfCar car = ajayi({{"control.law", "skyhook"},
                             {"front.suspension", "strut"},
                             {"front.damping_per_command_Ns_per_m", "1000"},
                             {"front.coulomb_force_per_command_N", "40"},
                             {"front.command_lag_s", "0.02"}})
                          .make_model();
  ASSERT_EQ(car.state_size(), 2 * kHalfCarDofs + 3);
  std::vector<double> x(static_cast<std::size_t>(car.state_size()), 0.0);
  x[2 * kHalfCarDofs + 1] = 110.0;  // F_f: below 0.95·120, so the damper counts as stuck
  x.back() = 1.5;
  EXPECT_EQ(car.outputs(x.data(), AxleRoads{}).front_stuck, 1.0);
  x[2 * kHalfCarDofs + 1] = 118.0;  // above 0.95·120 = 114
  EXPECT_EQ(car.outputs(x.data(), AxleRoads{}).front_stuck, 0.0);
}

TEST(CommandedHalfCar, JacobianWithCommandStatesMatchesCentralDifferences) {
  // Both axles controlled with a lag, the front a stick/slip strut: 14 + (2 + 1) + 1 states. The
  // state keeps the skyhook request inside its limits (1500 N·s/m) and the strut's damper sliding,
  // away from every kink.
  const HalfCar car = ajayi({{"control.law", "skyhook"},
                             {"front.suspension", "strut"},
                             {"front.damping_per_command_Ns_per_m", "1000"},
                             {"front.coulomb_force_per_command_N", "40"},
                             {"front.command_lag_s", "0.02"},
                             {"rear.damping_per_command_Ns_per_m", "800"},
                             {"rear.command_lag_s", "0.03"}})
                          .make_model();
  ASSERT_EQ(car.state_size(), 2 * kHalfCarDofs + 4);
  const testing::SineRoad road(0.005, 2.0, 5.0);
  const simulate::AxleRoadInput roads(road, 0.2);
  const simulate::HalfCarSystem system(car, roads);
  std::vector<double> x(static_cast<std::size_t>(car.state_size()), 0.0);
  x[kBodyHeave] = 1e-3;
  x[kFrontWheel] = -2e-4;
  x[kSeat] = 5e-4;
  x[kHalfCarDofs + kBodyHeave] = 0.05;
  x[kHalfCarDofs + kFrontWheel] = -0.05;
  x[kHalfCarDofs + kRearWheel] = -0.05;
  x[2 * kHalfCarDofs] = 5e-4;      // front z_c
  x[2 * kHalfCarDofs + 1] = 20.0;  // front F_f
  x[2 * kHalfCarDofs + 2] = 0.5;   // front ū
  x[2 * kHalfCarDofs + 3] = 0.4;   // rear ū
  testing::expect_jacobian_matches_central_differences(system, 0.31, x, "commanded half car");
  const int n = system.size();
  std::vector<double> jacobian(static_cast<std::size_t>(n * n));
  ASSERT_TRUE(system.jacobian(0.31, x.data(), jacobian.data()));
  // ū' = (u − ū)/τ: the rear command's own column is −1/τ.
  const auto last = static_cast<std::size_t>(n - 1);
  EXPECT_DOUBLE_EQ(jacobian[last * static_cast<std::size_t>(n) + last], -1.0 / 0.03);
}

TEST(CommandedHalfCar, AVeryShortLagFollowsTheInstantLaw) {
  // c = 1000 + 1000·ū with τ = 0.1 ms reaches the law's coefficient as the passive axle does.
  const testing::SineRoad road(0.01, 1.5, 4.0);
  simulate::HalfCarSimulationOptions options;
  options.rear_delay_s = 0.2;
  options.output_rate_Hz = 500.0;
  auto seat_rms = [&](const HalfCar& car) {
    return signal::rms(
        simulate::simulate(car, road, options).channel(&HalfCarOutputs::seat_acc_m_per_s2));
  };
  const double instant = seat_rms(ajayi({{"control.law", "skyhook"}}).make_model());
  const double lagged = seat_rms(ajayi({{"control.law", "skyhook"},
                                        {"front.damping_per_command_Ns_per_m", "1000"},
                                        {"front.command_lag_s", "1e-4"},
                                        {"rear.damping_per_command_Ns_per_m", "1000"},
                                        {"rear.command_lag_s", "1e-4"}})
                                     .make_model());
  EXPECT_GT(instant, 0.1);
  EXPECT_NEAR(lagged, instant, 0.005 * instant);
  // A 100 ms lag is a different damper: the body's 1.5 Hz motion meets a late coefficient.
  const double slow = seat_rms(ajayi({{"control.law", "skyhook"},
                                      {"front.damping_per_command_Ns_per_m", "1000"},
                                      {"front.command_lag_s", "0.1"},
                                      {"rear.damping_per_command_Ns_per_m", "1000"},
                                      {"rear.command_lag_s", "0.1"}})
                                   .make_model());
  EXPECT_GT(std::abs(slow - instant), 0.02 * instant);
}

TEST(CommandedHalfCar, AFrictionSlopeWithoutADampingSlopeUnderALawIsRefused) {
  const std::string message = testing::input_error_message([] {
    ajayi({{"control.law", "skyhook"}, {"front.coulomb_force_per_command_N", "40"}});
  });
  EXPECT_NE(message.find("ajayi_half_car.yaml"), std::string::npos) << message;
  EXPECT_NE(message.find("front.damping_per_command_Ns_per_m"), std::string::npos) << message;
  // Under the passive law the command is 0 and the slope harmless.
  EXPECT_NO_THROW(ajayi({{"front.coulomb_force_per_command_N", "40"}}));
}

}  // namespace
}  // namespace ridefit::model
