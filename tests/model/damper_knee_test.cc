// The damper's blow-off knee (AsymmetricDamper with damper_knee_velocity_m_per_s and
// damping_above_knee_Ns_per_m): the piecewise-linear law and its explicit inverse at closed-form
// points, Jet derivatives, and the lower peak force of a digressive damper on a large sine.
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ridefit/model/asymmetric_damper.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "support/passat.h"
#include "support/sine_road.h"

namespace ridefit::model {
namespace {

// c_r 2000 Ns/m, r 0.5, knee at 0.1 m/s, 500 Ns/m above it.
const AsymmetricDamper<double> kDamper{2000.0, 0.5, 0.1, 500.0};

TEST(DamperKnee, LawAtClosedFormPoints) {
  EXPECT_EQ(kDamper.force_N(0.0), 0.0);
  EXPECT_DOUBLE_EQ(kDamper.force_N(0.05), 100.0);   // below the knee: c_r·v
  EXPECT_DOUBLE_EQ(kDamper.force_N(0.1), 200.0);    // at the knee
  EXPECT_DOUBLE_EQ(kDamper.force_N(0.3), 300.0);    // 200 + 500·0.2
  EXPECT_DOUBLE_EQ(kDamper.force_N(-0.05), -50.0);  // compression: r·c_r·v
  EXPECT_DOUBLE_EQ(kDamper.force_N(-0.1), -100.0);
  EXPECT_DOUBLE_EQ(kDamper.force_N(-0.3), -150.0);  // r·(−200 + 500·(−0.2))
  // Continuous at both knees.
  for (const double knee : {0.1, -0.1}) {
    EXPECT_NEAR(kDamper.force_N(knee * (1.0 + 1e-12)), kDamper.force_N(knee), 1e-9);
  }
  // The explicit inverse undoes the law on every branch.
  for (const double v : {-1.0, -0.3, -0.1, -0.02, 0.0, 0.04, 0.1, 0.25, 2.0}) {
    EXPECT_NEAR(kDamper.rate_m_per_s(kDamper.force_N(v)), v, 1e-15) << v;
  }
  EXPECT_DOUBLE_EQ(kDamper.rate_m_per_s(300.0), 0.3);
  EXPECT_DOUBLE_EQ(kDamper.rate_m_per_s(-150.0), -0.3);
  // Monotone.
  double previous = kDamper.force_N(-1.0);
  for (int i = -99; i <= 100; ++i) {
    const double f = kDamper.force_N(0.01 * i);
    EXPECT_GT(f, previous);
    previous = f;
  }
  // Without a knee (the default) the law is the linear split, bit for bit, however fast.
  const AsymmetricDamper<double> plain{2000.0, 0.5};
  EXPECT_EQ(plain.force_N(3.0), 6000.0);
  EXPECT_EQ(plain.rate_m_per_s(-3000.0), -3.0);
  EXPECT_FALSE(plain.has_knee());
  EXPECT_TRUE((AsymmetricDamper<double>{2000.0}.linear()));
  EXPECT_FALSE((AsymmetricDamper<double>{2000.0, 1.0, 0.1, 500.0}.linear()));
}

TEST(DamperKnee, JetDerivativesMatchCentralDifferences) {
  using Jet = ceres::Jet<double, 4>;  // d/dc_r, d/dr, d/dv_k, d/dc_h
  const double values[4] = {2000.0, 0.5, 0.1, 500.0};
  for (const double v : {0.05, 0.3, -0.04, -0.6}) {
    const AsymmetricDamper<Jet> damper{Jet(values[0], 0), Jet(values[1], 1), Jet(values[2], 2),
                                       Jet(values[3], 3)};
    const Jet force = damper.force_N(Jet(v));
    const double target = kDamper.force_N(v);
    const Jet rate = damper.rate_m_per_s(Jet(target));
    for (int j = 0; j < 4; ++j) {
      double up[4] = {values[0], values[1], values[2], values[3]};
      double down[4] = {values[0], values[1], values[2], values[3]};
      const double h = 1e-6 * values[j];
      up[j] += h;
      down[j] -= h;
      const AsymmetricDamper<double> u{up[0], up[1], up[2], up[3]};
      const AsymmetricDamper<double> d{down[0], down[1], down[2], down[3]};
      const double fd_force = (u.force_N(v) - d.force_N(v)) / (2.0 * h);
      const double fd_rate = (u.rate_m_per_s(target) - d.rate_m_per_s(target)) / (2.0 * h);
      EXPECT_NEAR(force.v[j], fd_force, 1e-6 * std::max(1.0, std::abs(fd_force)))
          << "force, parameter " << j << " at " << v;
      EXPECT_NEAR(rate.v[j], fd_rate, 1e-6 * std::max(1e-3, std::abs(fd_rate)))
          << "rate, parameter " << j << " at " << v;
    }
  }
  // Above the rebound knee: ∂F/∂c_h = v − v_k, ∂F/∂v_k = c_r − c_h.
  const AsymmetricDamper<Jet> damper{Jet(values[0], 0), Jet(values[1], 1), Jet(values[2], 2),
                                     Jet(values[3], 3)};
  const Jet above = damper.force_N(Jet(0.3));
  EXPECT_DOUBLE_EQ(above.v[3], 0.2);
  EXPECT_DOUBLE_EQ(above.v[2], 1500.0);
}

QuarterCarParameters<double> with_knee(QuarterCarParameters<double> p) {
  p.damper_knee_velocity_m_per_s = 0.1;
  p.damping_above_knee_Ns_per_m = 300.0;
  return p;
}

// The strut's damper rate comes from the explicit inverse: a path force beyond the knee force
// (886.9 Ns/m · 0.1 m/s = 88.69 N) drives the damper faster than c_r would.
TEST(DamperKnee, StrutDamperRateUsesTheInverse) {
  const QuarterCarParameters<double> p = with_knee(testing::passat_corner().parameters);
  const double path = 200.0;  // N
  const double x[6] = {0.0, 0.0, 0.0, 0.0, -path / p.top_mount_stiffness_N_per_m, 20.0};
  double xdot[6] = {};
  QuarterCar(DamperState::kSlip, p).derivatives(x, {}, xdot);
  EXPECT_NEAR(xdot[4], 0.1 + (200.0 - 88.69) / 300.0, 1e-12);  // 0.471 m/s
  QuarterCar(DamperState::kStickSlip, p).derivatives(x, {}, xdot);
  EXPECT_NEAR(xdot[4], 0.1 + (180.0 - 88.69) / 300.0, 1e-12);
  EXPECT_NEAR(QuarterCar(DamperState::kStickSlip, p).outputs(x, {}).damper_force_N, 180.0, 1e-9);
}

// A 30 mm, 3 Hz road sine drives the slip Passat damper past 0.1 m/s: the digressive damper's
// peak force is lower, and it still exceeds the knee force.
TEST(DamperKnee, LowersThePeakDamperForceOnALargeSine) {
  const QuarterCarParameters<double> plain = testing::passat_corner().parameters;
  const testing::SineRoad road(0.03, 3.0, 4.0);
  simulate::SimulationOptions options;
  options.output_rate_Hz = 1000.0;
  const auto peak = [&](const QuarterCarParameters<double>& p) {
    const auto r = simulate::simulate(QuarterCar(DamperState::kSlip, p), road, options);
    double f = 0.0;
    for (double d : r.damper_force_N) f = std::max(f, std::abs(d));
    return f;
  };
  const double linear = peak(plain);
  const double digressive = peak(with_knee(plain));
  EXPECT_GT(linear, 3.0 * 88.69);
  EXPECT_LT(digressive, 0.8 * linear);
  EXPECT_GT(digressive, 88.69);
}

}  // namespace
}  // namespace ridefit::model
