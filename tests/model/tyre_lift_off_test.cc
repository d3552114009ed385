// Unilateral tyre contact (tyre_lift_off): the law, its place in the quarter car's equations and
// output, and a ride over a road that throws the wheel into the air.
#include "ridefit/model/tyre_lift_off.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "ridefit/comfort/tyre_load_metrics.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::model {
namespace {

TEST(TyreLiftOff, LawAtClosedFormPoints) {
  EXPECT_EQ(lifted_off_tyre_force_N(250.0, 4000.0), 250.0);
  EXPECT_EQ(lifted_off_tyre_force_N(-3999.0, 4000.0), -3999.0);
  EXPECT_EQ(lifted_off_tyre_force_N(-4000.0, 4000.0), -4000.0);
  EXPECT_EQ(lifted_off_tyre_force_N(-6500.0, 4000.0), -4000.0);  // total load 0, not −2500 N
}

// The Passat corner's static load: (385.40 + 46.761) kg · 9.80665 m/s² = 4238.05 N, one value
// for the model and the comfort metrics.
TEST(TyreLiftOff, StaticLoadIsBothMassesTimesStandardGravity) {
  const QuarterCarParameters<double> p = testing::passat_corner().parameters;
  EXPECT_NEAR(p.static_tyre_load_N(), 4238.05, 0.01);
  EXPECT_EQ(p.static_tyre_load_N(), comfort::static_tyre_load_N(p));
  EXPECT_EQ(comfort::kStandardGravity_m_per_s2, 9.80665);
}

// While airborne the clipped force depends on the masses only: ∂F/∂ms = ∂F/∂mu = −g, and not on
// the tyre's stiffness; in contact the other way round.
TEST(TyreLiftOff, JetDerivativesFollowTheBranch) {
  using Jet = ceres::Jet<double, 3>;  // d/dms, d/dmu, d/dkt
  QuarterCarParameters<Jet> p = testing::passat_corner().parameters.cast<Jet>();
  p.sprung_mass_kg.v[0] = 1.0;
  p.unsprung_mass_kg.v[1] = 1.0;
  p.tyre_stiffness_N_per_m.v[2] = 1.0;
  p.tyre_lift_off = true;
  for (const double wheel_m : {0.03, -0.01}) {  // 30 mm above the road: airborne
    const Jet dynamic = p.tyre_stiffness_N_per_m * Jet(-wheel_m);
    const Jet clipped = lifted_off_tyre_force_N(dynamic, p.static_tyre_load_N());
    if (wheel_m > 0.0) {
      EXPECT_NEAR(clipped.a, -4238.05, 0.01);
      EXPECT_DOUBLE_EQ(clipped.v[0], -kStandardGravity_m_per_s2);
      EXPECT_DOUBLE_EQ(clipped.v[1], -kStandardGravity_m_per_s2);
      EXPECT_EQ(clipped.v[2], 0.0);
    } else {
      EXPECT_NEAR(clipped.a, 2881.8, 1e-9);
      EXPECT_EQ(clipped.v[0], 0.0);
      EXPECT_DOUBLE_EQ(clipped.v[2], 0.01);
    }
  }
}

// The wheel 30 mm above its static position on a flat road: the bilateral tyre would pull it
// down with kt·0.03 = 8645 N; the unilateral one only lets gravity act, −F_static.
TEST(TyreLiftOff, ClipsTheTyreForceInTheQuarterCar) {
  QuarterCarParameters<double> p = testing::passat_corner().parameters;
  p.tyre_lift_off = true;
  const QuarterCar car(DamperState::kStick, p);
  double x[4] = {0.03, 0.03, 0.0, 0.0};  // no travel: only the tyre acts on the wheel
  double xdot[4] = {};
  car.derivatives(x, {}, xdot);
  EXPECT_NEAR(xdot[3], -p.static_tyre_load_N() / p.unsprung_mass_kg, 1e-12);  // −90.6 m/s²
  EXPECT_NEAR(car.outputs(x, {}).tyre_force_N, -p.static_tyre_load_N(), 1e-12);
  // In contact it changes nothing.
  x[1] = -0.01;
  double bilateral[4] = {};
  car.derivatives(x, {}, xdot);
  QuarterCar(DamperState::kStick, testing::passat_corner().parameters)
      .derivatives(x, {}, bilateral);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(xdot[i], bilateral[i]);
}

// A 25 mm road sine at the wheel-hop mode (13 Hz) throws the wheel: without lift-off the tyre
// "pulls" down to far below −F_static; with it the total load stays ≥ 0 and the wheel flies.
TEST(TyreLiftOff, TotalWheelLoadNeverGoesNegativeOverAWheelHopSine) {
  QuarterCarParameters<double> p = testing::passat_corner().parameters;
  const testing::SineRoad road(0.025, 13.3, 2.0);
  simulate::SimulationOptions options;
  options.output_rate_Hz = 2000.0;
  const auto min_force = [&](const QuarterCarParameters<double>& q) {
    const auto r = simulate::simulate(QuarterCar(DamperState::kSlip, q), road, options);
    return *std::min_element(r.tyre_force_N.begin(), r.tyre_force_N.end());
  };
  const double load = p.static_tyre_load_N();
  EXPECT_LT(min_force(p), -1.3 * load);
  p.tyre_lift_off = true;
  const auto r = simulate::simulate(QuarterCar(DamperState::kSlip, p), road, options);
  const double lowest = *std::min_element(r.tyre_force_N.begin(), r.tyre_force_N.end());
  EXPECT_GE(lowest, -load);
  EXPECT_EQ(lowest, -load);  // it does lift off
  const auto metrics = comfort::tyre_load_metrics(r.tyre_force_N, load);
  EXPECT_GT(metrics.lift_off_share, 0.05);
  EXPECT_EQ(metrics.min_total_load_N, 0.0);
}

}  // namespace
}  // namespace ridefit::model
