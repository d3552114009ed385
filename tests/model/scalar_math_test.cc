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

}  // namespace
}  // namespace ridefit::model
