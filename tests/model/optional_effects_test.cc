// The quarter car's optional effects switched off (their keys absent) leave the model exactly as
// it was: the derivatives equal the original equations written out here, bit for bit, in every
// topology; and each effect, switched on, makes the model nonlinear.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/scalar_math.h"
#include "support/passat.h"

namespace ridefit::model {
namespace {

// The quarter car's equations as they were before the optional effects (linear top mount, no
// bump stop, bilateral tyre, damper without a knee, Dahl with a constant level).
void reference_derivatives(DamperState state, const QuarterCarParameters<double>& p,
                           const double* x, const road::RoadSample& road, double* xdot) {
  const double travel = x[0] - x[1];
  const double c_r = p.damping_Ns_per_m;
  const double r = p.compression_to_rebound_ratio;
  const auto rate = [&](double force) { return force / (force < 0.0 ? r * c_r : c_r); };
  double path = 0.0;
  switch (state) {
    case DamperState::kStick:
      path = p.top_mount_stiffness_N_per_m * (travel - 0.0);
      break;
    case DamperState::kSlip:
      path = p.top_mount_stiffness_N_per_m * (travel - x[4]);
      xdot[4] = rate(path - 0.0);
      break;
    case DamperState::kStickSlip: {
      path = p.top_mount_stiffness_N_per_m * (travel - x[4]);
      const double v = rate(path - x[5]);
      xdot[4] = v;
      const double s = 1.0 - x[5] / p.coulomb_force_N * (v < 0.0 ? -1.0 : 1.0);
      xdot[5] = p.dahl_sigma0_N_per_m * v * signed_power(s, p.dahl_exponent);
      break;
    }
  }
  const double spring = p.spring_path_stiffness_N_per_m() * travel;
  const double tyre = p.tyre_stiffness_N_per_m * (x[1] - road.elevation_m) +
                      p.tyre_damping_Ns_per_m * (x[3] - road.rate_m_per_s);
  xdot[0] = x[2];
  xdot[1] = x[3];
  xdot[2] = -(spring + path) / p.sprung_mass_kg;
  xdot[3] = (spring + path - tyre) / p.unsprung_mass_kg;
}

TEST(OptionalEffects, AbsentKeysGiveTheOriginalDerivativesBitForBit) {
  const QuarterCarParameters<double> passat = testing::passat_corner().parameters;
  ASSERT_EQ(passat.dahl_exponent, 1.0);
  // Without the keys every effect is at its off value.
  EXPECT_EQ(passat.top_mount_transition_deflection_m, 0.0);
  EXPECT_EQ(passat.bump_stop_stiffness_N_per_m, 0.0);
  EXPECT_FALSE(passat.tyre_lift_off);
  EXPECT_EQ(passat.damper_knee_velocity_m_per_s, 0.0);
  EXPECT_EQ(passat.stribeck_velocity_m_per_s, 0.0);
  EXPECT_EQ(passat.static_friction_force_N, passat.coulomb_force_N);  // read only when v_s > 0
  for (const double ratio : {1.0, 0.45}) {
    QuarterCarParameters<double> p = passat;
    p.compression_to_rebound_ratio = ratio;
    // Large states on purpose: 60 mm compression (where a bump stop would touch), the wheel
    // 50 mm above the road (where a unilateral tyre would lift), the damper fast (beyond a knee)
    // and the friction at rest (where a Stribeck level would differ).
    const std::array<std::array<double, 6>, 4> states{{
        {1e-3, -2e-4, 0.03, -0.1, 2e-4, 20.0},
        {-0.04, 0.02, -0.8, 1.2, -3e-4, -59.0},
        {0.05, 0.0, 0.5, -1.5, 1e-3, 0.0},
        {-0.01, 0.05, 0.0, 2.0, -2e-3, 45.0},
    }};
    const road::RoadSample road{-0.002, 0.3};
    for (const DamperState state :
         {DamperState::kStick, DamperState::kSlip, DamperState::kStickSlip}) {
      const QuarterCar car(state, p);
      for (const auto& x : states) {
        double expected[6] = {}, actual[6] = {};
        reference_derivatives(state, p, x.data(), road, expected);
        car.derivatives(x.data(), road, actual);
        for (int i = 0; i < car.state_size(); ++i) {
          EXPECT_EQ(actual[i], expected[i]) << to_string(state) << " state " << i;
        }
        // The tyre force channel is the bilateral one (compression positive).
        EXPECT_EQ(car.outputs(x.data(), road).tyre_force_N,
                  p.tyre_stiffness_N_per_m * (road.elevation_m - x[1]) +
                      p.tyre_damping_Ns_per_m * (road.rate_m_per_s - x[3]));
      }
    }
  }
}

TEST(OptionalEffects, EachEffectMakesTheModelNonlinear) {
  const QuarterCarParameters<double> passat = testing::passat_corner().parameters;
  ASSERT_TRUE(QuarterCar(DamperState::kSlip, passat).is_linear());
  ASSERT_TRUE(QuarterCar(DamperState::kStick, passat).is_linear());
  EXPECT_EQ(QuarterCar(DamperState::kSlip, passat).nonlinearity(), "");

  auto stiffening = passat;
  stiffening.top_mount_small_amplitude_stiffness_N_per_m = 707000.0;
  stiffening.top_mount_transition_deflection_m = 2e-4;
  auto bump = passat;
  bump.bump_stop_stiffness_N_per_m = 2e5;
  bump.bump_stop_clearance_m = 0.03;
  auto lift = passat;
  lift.tyre_lift_off = true;
  for (const auto* p : {&stiffening, &bump, &lift}) {
    EXPECT_FALSE(QuarterCar(DamperState::kSlip, *p).is_linear());
    EXPECT_FALSE(QuarterCar(DamperState::kStick, *p).is_linear());
  }
  EXPECT_EQ(QuarterCar(DamperState::kStick, bump).nonlinearity(), "the bump stop");
  EXPECT_EQ(QuarterCar(DamperState::kStick, lift).nonlinearity(), "tyre lift-off");
  // k_s = k_l: the tanh term vanishes, the spring is linear.
  stiffening.top_mount_small_amplitude_stiffness_N_per_m = passat.top_mount_stiffness_N_per_m;
  EXPECT_TRUE(QuarterCar(DamperState::kStick, stiffening).is_linear());

  auto knee = passat;
  knee.damper_knee_velocity_m_per_s = 0.1;
  knee.damping_above_knee_Ns_per_m = 300.0;
  EXPECT_FALSE(QuarterCar(DamperState::kSlip, knee).is_linear());
  EXPECT_EQ(QuarterCar(DamperState::kSlip, knee).nonlinearity(), "the damper's knee at 0.1 m/s");
  // The locked damper of stick never reaches its knee.
  EXPECT_TRUE(QuarterCar(DamperState::kStick, knee).is_linear());
  // A knee that keeps the slope is the linear damper.
  knee.damping_above_knee_Ns_per_m = passat.damping_Ns_per_m;
  EXPECT_TRUE(QuarterCar(DamperState::kSlip, knee).is_linear());

  auto stribeck = passat;
  stribeck.stribeck_velocity_m_per_s = 0.01;
  stribeck.static_friction_force_N = 90.0;
  EXPECT_FALSE(QuarterCar(DamperState::kStickSlip, stribeck).is_linear());
}

}  // namespace
}  // namespace ridefit::model
