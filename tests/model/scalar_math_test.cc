// signed_power on Jets: an exponent of 1 that the fit holds (no derivative) passes s through
// without exp and log, with s's tangents; a free exponent keeps its own derivative, s^d·ln|s|.
#include "ridefit/model/scalar_math.h"

#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <cmath>

namespace ridefit::model {
namespace {

using Jet = ceres::Jet<double, 2>;

TEST(SignedPower, AHeldExponentOfOnePassesTheValueAndItsTangentsThrough) {
  Jet s(-0.37, 0);  // d/dθ0 = 1
  s.v[1] = 2.5;
  const Jet held(1.0);  // no derivative
  const Jet out = signed_power(s, held);
  EXPECT_EQ(out.a, s.a);
  EXPECT_EQ(out.v[0], 1.0);
  EXPECT_EQ(out.v[1], 2.5);
}

TEST(SignedPower, AFreeExponentKeepsItsDerivative) {
  const Jet s(0.37);       // held
  const Jet free(1.0, 1);  // d/dθ1 = 1: the exponent is fitted
  const Jet out = signed_power(s, free);
  EXPECT_NEAR(out.a, 0.37, 1e-15);
  EXPECT_EQ(out.v[0], 0.0);
  EXPECT_NEAR(out.v[1], 0.37 * std::log(0.37), 1e-14);  // ∂(s^d)/∂d at d = 1
  // Negative s: sgn(s)·|s|^d.
  const Jet negative = signed_power(Jet(-0.37), Jet(2.0, 1));
  EXPECT_NEAR(negative.a, -0.37 * 0.37, 1e-15);
  EXPECT_NEAR(negative.v[1], -0.37 * 0.37 * std::log(0.37), 1e-14);
}

// The Dahl law's power at s = 0: the value is 0 for every d; the slope is 1 for d = 1, 0 above
// and, where it is unbounded (d < 1), the secant over one rounding step of s = 1 − F/Fc, ε^(d−1);
// the hand-written Jacobians' dahl_power_slope_at_zero says the same. signed_power itself (a
// command shaped by u^p) keeps the slope 0 below 1.
TEST(DahlPower, AtZeroTakesTheSlopeOfItsExponent) {
  const double epsilon = std::ldexp(1.0, -52);
  for (const double d : {0.9, 0.5, 1.0, 1.4}) {
    const Jet out = dahl_power(Jet(0.0, 0), d);
    EXPECT_EQ(out.a, 0.0) << d;
    const double expected = d < 1.0 ? std::pow(epsilon, d - 1.0) : d == 1.0 ? 1.0 : 0.0;
    EXPECT_NEAR(out.v[0], expected, 1e-12 * expected) << d;
    EXPECT_NEAR(dahl_power_slope_at_zero(d), expected, 1e-12 * expected) << d;
    EXPECT_EQ(signed_power(Jet(0.0, 0), d).v[0], d == 1.0 ? 1.0 : 0.0) << d;
  }
  // The secant meets the neighbouring slope d·|s|^(d−1) at s = ε within the factor d.
  const Jet next = dahl_power(Jet(epsilon, 0), 0.9);
  EXPECT_NEAR(next.v[0], 0.9 * dahl_power_slope_at_zero(0.9), 1e-9 * next.v[0]);
  // A free exponent has no derivative at s = 0 (the value is 0 for every d).
  EXPECT_EQ(dahl_power(Jet(0.0), Jet(0.9, 1)).v[1], 0.0);
}

}  // namespace
}  // namespace ridefit::model
