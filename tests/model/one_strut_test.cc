// The strut is declared once (model/strut_parameters.h): the quarter car, each half-car axle and
// the rig carry the same StrutParameters, so every effect of the damper path reaches all three
// and a damper moves between them as it is.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ridefit/io/half_car_file.h"
#include "ridefit/model/half_car.h"
#include "ridefit/model/half_car_parameter_table.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/model/strut_test.h"
#include "support/input_error_message.h"
#include "support/passat.h"

namespace ridefit::model {
namespace {

// Every effect of the path switched on, each value distinct from its default.
StrutParameters<double> every_effect() {
  StrutParameters<double> s;
  s.top_mount_stiffness_N_per_m = 450000.0;
  s.damping_Ns_per_m = 1200.0;
  s.dahl_sigma0_N_per_m = 3e6;
  s.coulomb_force_N = 80.0;
  s.dahl_exponent = 1.3;
  s.compression_to_rebound_ratio = 0.6;
  s.damper_knee_velocity_m_per_s = 0.05;
  s.damping_above_knee_Ns_per_m = 400.0;
  s.damping_above_knee_exponent = 0.6;
  s.top_mount_small_amplitude_stiffness_N_per_m = 900000.0;
  s.top_mount_transition_deflection_m = 2e-4;
  s.static_friction_force_N = 110.0;
  s.stribeck_velocity_m_per_s = 0.01;
  s.friction_compression_to_rebound_ratio = 0.8;
  s.free_play_m = 1e-3;
  s.free_play_damping_Ns_per_m = 5000.0;
  return s;
}

TEST(OneStrut, EachStrutRowIsItsOwnFieldInEveryModel) {
  StrutParameters<double> s;
  for (std::size_t i = 0; i < kStrutRows.size(); ++i)
    strut_field(s, i) = 100.0 + static_cast<double>(i);
  QuarterCarParameters<double> q{};
  q.strut() = s;
  HalfCarParameters<double> h{};
  h.rear.strut() = s;
  SemiActiveControl control;
  const auto rig = StrutTestParameters<double>::on_rig(s);
  for (std::size_t i = 0; i < kStrutRows.size(); ++i) {
    const double expected = 100.0 + static_cast<double>(i);
    const ParameterInfo& row = kQuarterCarParameters[kStrutRows[i]];
    SCOPED_TRACE(std::string(row.key));
    EXPECT_EQ(strut_row(row), i);
    EXPECT_EQ(quarter_car_parameter(q, kStrutRows[i]), expected);
    const auto field = half_car_field(h, control, "rear." + std::string(row.key));
    ASSERT_TRUE(field.has_value());
    EXPECT_EQ(*field->value, expected);
    EXPECT_EQ(strut_field(const_cast<StrutTestParameters<double>&>(rig).strut(), i), expected);
  }
  // Rows the strut does not have are none of its fields.
  EXPECT_FALSE(strut_row(quarter_car_rows::sprung_mass_kg).has_value());
  EXPECT_FALSE(strut_row(quarter_car_rows::bump_stop_stiffness_N_per_m).has_value());
}

TEST(OneStrut, TheHalfCarsStrutMovesAsTheQuarterCarsWithEveryEffect) {
  const StrutParameters<double> s = every_effect();
  QuarterCarParameters<double> q = testing::passat_corner().parameters;
  q.strut() = s;
  const QuarterCar quarter(DamperState::kStickSlip, q);
  auto file = io::load_half_car(testing::dataset("vehicles/ajayi_half_car.yaml"),
                                {{"front.suspension", "strut"}});
  file.parameters.front.strut() = s;
  const HalfCar half = file.make_model();
  ASSERT_EQ(half.state_size(), 2 * kHalfCarDofs + 2);
  // Travel, its rate, the damper's deflection and the friction force: sliding in compression
  // above the knee; inside the free play's slack; near the breakaway in rebound.
  const double cases[][4] = {
      {-0.004, -0.3, -0.0025, -60.0}, {0.0002, 0.02, 0.0001, 20.0}, {0.003, 0.4, 0.0016, 100.0}};
  for (const auto& c : cases) {
    std::vector<double> xq = {c[0], 0.0, c[1], 0.0, c[2], c[3]};
    std::vector<double> dq(xq.size());
    quarter.derivatives(xq.data(), road::RoadSample{}, dq.data());
    std::vector<double> xh(static_cast<std::size_t>(half.state_size()), 0.0);
    // Travel at the front axle: body point over the axle minus the wheel.
    xh[kBodyHeave] = c[0];
    xh[kHalfCarDofs + kBodyHeave] = c[1];
    xh[2 * kHalfCarDofs] = c[2];
    xh[2 * kHalfCarDofs + 1] = c[3];
    std::vector<double> dh(xh.size());
    half.derivatives(xh.data(), AxleRoads{}, dh.data());
    SCOPED_TRACE(::testing::Message() << "travel " << c[0] << ", rate " << c[1]);
    EXPECT_NEAR(dh[2 * kHalfCarDofs], dq[4], 1e-12 * (1.0 + std::abs(dq[4])));
    EXPECT_NEAR(dh[2 * kHalfCarDofs + 1], dq[5], 1e-9 * (1.0 + std::abs(dq[5])));
    // And the effects act: without them the rates differ.
    QuarterCarParameters<double> plain = q;
    plain.strut() = StrutParameters<double>{};
    plain.top_mount_stiffness_N_per_m = s.top_mount_stiffness_N_per_m;
    plain.damping_Ns_per_m = s.damping_Ns_per_m;
    plain.dahl_sigma0_N_per_m = s.dahl_sigma0_N_per_m;
    plain.coulomb_force_N = s.coulomb_force_N;
    plain.dahl_exponent = s.dahl_exponent;
    std::vector<double> dp(xq.size());
    QuarterCar(DamperState::kStickSlip, plain)
        .derivatives(xq.data(), road::RoadSample{}, dp.data());
    EXPECT_GT(std::abs(dp[4] - dq[4]), 1e-3 * std::abs(dq[4]));
  }
}

TEST(OneStrut, AHalfCarFileTakesEveryStrutKeyWithTheQuarterCarsRules) {
  const auto path = testing::dataset("vehicles/ajayi_half_car.yaml");
  const auto file = io::load_half_car(path, {{"front.suspension", "strut"},
                                             {"front.free_play_m", "0.002"},
                                             {"front.friction_compression_to_rebound_ratio", "0.9"},
                                             {"front.command_exponent", "0.5"},
                                             {"front.free_play_damping_Ns_per_m", "3000"}});
  EXPECT_EQ(file.parameters.front.free_play_m, 0.002);
  EXPECT_EQ(file.parameters.front.free_play_damping_Ns_per_m, 3000.0);
  EXPECT_EQ(file.parameters.front.friction_compression_to_rebound_ratio, 0.9);
  EXPECT_EQ(file.parameters.front.command_exponent, 0.5);
  EXPECT_EQ(file.parameters.rear.free_play_m, 0.0);
  // A passive axle's damper keeps its knee: the model is no longer linear.
  const auto knee = io::load_half_car(path, {{"rear.damper_knee_velocity_m_per_s", "0.1"},
                                             {"rear.damping_above_knee_Ns_per_m", "300"}});
  EXPECT_EQ(knee.parameters.rear.damper_knee_velocity_m_per_s, 0.1);
  EXPECT_FALSE(knee.make_model().is_linear());
  EXPECT_TRUE(io::load_half_car(path).make_model().is_linear());
  // The pair's rule, named with its axle.
  const std::string message = testing::input_error_message([&] {
    io::load_half_car(path, {{"rear.damper_knee_velocity_m_per_s", "0.1"}});
  });
  EXPECT_NE(message.find("rear"), std::string::npos) << message;
  EXPECT_NE(message.find("damping_above_knee_Ns_per_m"), std::string::npos) << message;
  // validate() on a model edited in memory names the axle's key.
  auto edited = file.parameters;
  edited.rear.damper_knee_velocity_m_per_s = 0.1;
  const auto error = validate(edited, file.topology);
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->key, "rear.damper_knee_velocity_m_per_s");
  // A free play's damping without free play: named with its axle, in the file and in memory.
  const std::string play = testing::input_error_message([&] {
    io::load_half_car(path, {{"rear.free_play_damping_Ns_per_m", "3000"}});
  });
  EXPECT_NE(play.find("rear.free_play_damping_Ns_per_m"), std::string::npos) << play;
  EXPECT_NE(play.find("free_play_m"), std::string::npos) << play;
  auto damped = file.parameters;
  damped.rear.free_play_damping_Ns_per_m = 3000.0;
  const auto damped_error = validate(damped, file.topology);
  ASSERT_TRUE(damped_error.has_value());
  EXPECT_EQ(damped_error->key, "rear.free_play_damping_Ns_per_m");
}

}  // namespace
}  // namespace ridefit::model
