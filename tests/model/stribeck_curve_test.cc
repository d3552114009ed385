// The Stribeck level of the Dahl element (stribeck_curve.h, DahlFriction with
// static_friction_force_N and stribeck_velocity_m_per_s): the curve at closed-form points, the
// sliding level the Dahl law settles at, Jet derivatives, and the quarter car's use of it.
#include "ridefit/model/stribeck_curve.h"

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ridefit/model/dahl_friction.h"
#include "ridefit/model/quarter_car.h"
#include "support/passat.h"

namespace ridefit::model {
namespace {

TEST(StribeckCurve, LevelAtClosedFormPoints) {
  // Fc 60 N, Fs 90 N, v_s 10 mm/s.
  EXPECT_EQ(stribeck_level_N(60.0, 90.0, 0.01, 0.0), 90.0);
  EXPECT_NEAR(stribeck_level_N(60.0, 90.0, 0.01, 0.01), 60.0 + 30.0 / std::exp(1.0), 1e-12);
  EXPECT_NEAR(stribeck_level_N(60.0, 90.0, 0.01, -0.02), 60.0 + 30.0 * std::exp(-4.0), 1e-12);
  EXPECT_NEAR(stribeck_level_N(60.0, 90.0, 0.01, 0.1), 60.0, 1e-30 + 1e-12);
  // Even and falling in |v|.
  double previous = 91.0;
  for (int i = 0; i <= 50; ++i) {
    const double v = 1e-3 * i;
    const double level = stribeck_level_N(60.0, 90.0, 0.01, v);
    EXPECT_EQ(level, stribeck_level_N(60.0, 90.0, 0.01, -v));
    EXPECT_LT(level, previous);
    EXPECT_GE(level, 60.0);
    previous = level;
  }
  // v_s = 0 is off: Fc whatever Fs.
  EXPECT_EQ(stribeck_level_N(60.0, 90.0, 0.0, 0.0), 60.0);
}

// Gross sliding settles where dF/dt = 0: F = Fc(v)·sgn v.
TEST(StribeckCurve, DahlSlidesAtTheVelocityDependentLevel) {
  const DahlFriction<double> dahl{5e6, 60.0, 1.0, 90.0, 0.01};
  for (const double v : {0.002, 0.01, -0.005, 0.05}) {
    const double level = stribeck_level_N(60.0, 90.0, 0.01, v);
    EXPECT_NEAR(dahl.force_rate_N_per_s(std::copysign(level, v), v), 0.0, 1e-6) << v;
    // Below the level the force grows towards it, above it falls back.
    EXPECT_GT(dahl.force_rate_N_per_s(0.9 * std::copysign(level, v), v) * v, 0.0);
    EXPECT_LT(dahl.force_rate_N_per_s(1.1 * std::copysign(level, v), v) * v, 0.0);
  }
  // At 75 N and 2 mm/s the classic element (level 60 N) unloads, the Stribeck one still loads.
  const DahlFriction<double> classic{5e6, 60.0, 1.0};
  EXPECT_LT(classic.force_rate_N_per_s(75.0, 0.002), 0.0);
  EXPECT_GT(dahl.force_rate_N_per_s(75.0, 0.002), 0.0);
  // Off: the classic law bit for bit, Fs ignored.
  const DahlFriction<double> off{5e6, 60.0, 1.0, 90.0, 0.0};
  EXPECT_EQ(off.force_rate_N_per_s(30.0, 0.002), classic.force_rate_N_per_s(30.0, 0.002));
}

TEST(StribeckCurve, JetDerivativesMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 3>;  // d/dFc, d/dFs, d/dv_s
  const double values[3] = {60.0, 90.0, 0.01};
  for (const double v : {0.004, -0.012, 0.03}) {
    for (const double force : {20.0, -70.0}) {
      const DahlFriction<Jet> dahl{Jet(5e6), Jet(values[0], 0), Jet(1.0), Jet(values[1], 1),
                                   Jet(values[2], 2)};
      const Jet rate = dahl.force_rate_N_per_s(Jet(force), Jet(v));
      const Jet level = dahl.level_N(Jet(v));
      for (int j = 0; j < 3; ++j) {
        double up[3] = {values[0], values[1], values[2]};
        double down[3] = {values[0], values[1], values[2]};
        const double h = 1e-6 * values[j];
        up[j] += h;
        down[j] -= h;
        const DahlFriction<double> u{5e6, up[0], 1.0, up[1], up[2]};
        const DahlFriction<double> d{5e6, down[0], 1.0, down[1], down[2]};
        const double fd_rate =
            (u.force_rate_N_per_s(force, v) - d.force_rate_N_per_s(force, v)) / (2.0 * h);
        const double fd_level = (u.level_N(v) - d.level_N(v)) / (2.0 * h);
        EXPECT_NEAR(rate.v[j], fd_rate, 1e-6 * std::max(1.0, std::abs(fd_rate)))
            << "rate, parameter " << j << " at v " << v << ", F " << force;
        EXPECT_NEAR(level.v[j], fd_level, 1e-7 * std::max(1.0, std::abs(fd_level)));
      }
      // ∂Fc(v)/∂Fs = exp(−(v/v_s)²).
      EXPECT_NEAR(level.v[1], std::exp(-(v / 0.01) * (v / 0.01)), 1e-15);
    }
  }
}

// In the quarter car the friction state follows the level at the damper's own rate, and the
// stuck rule measures against that level.
TEST(StribeckCurve, QuarterCarFrictionUsesTheLevelAtTheDamperRate) {
  QuarterCarParameters<double> p = testing::passat_corner().parameters;
  p.static_friction_force_N = 90.0;
  p.stribeck_velocity_m_per_s = 0.01;
  const QuarterCar car(DamperState::kStickSlip, p);
  // Damper at rest, friction 80 N: 80 < 0.95·90, stuck (the classic rule, 0.95·60 = 57, says
  // sliding).
  double x[6] = {0.0, 0.0, 0.0, 0.0, -80.0 / p.top_mount_stiffness_N_per_m, 80.0};
  EXPECT_EQ(car.outputs(x, {}).stuck, 1.0);
  QuarterCarParameters<double> classic = testing::passat_corner().parameters;
  EXPECT_EQ(QuarterCar(DamperState::kStickSlip, classic).outputs(x, {}).stuck, 0.0);
  // The friction rate is the Dahl law at the damper rate (F_path − F_f)/c, with that level.
  x[4] = -150.0 / p.top_mount_stiffness_N_per_m;  // path 150 N, friction 80 N
  double xdot[6] = {};
  car.derivatives(x, {}, xdot);
  const double v = 70.0 / p.damping_Ns_per_m;
  EXPECT_NEAR(xdot[4], v, 1e-15);
  const double level = 60.0 + 30.0 * std::exp(-(v / 0.01) * (v / 0.01));
  EXPECT_NEAR(xdot[5], p.dahl_sigma0_N_per_m * v * (1.0 - 80.0 / level), 1e-6);
}

}  // namespace
}  // namespace ridefit::model
