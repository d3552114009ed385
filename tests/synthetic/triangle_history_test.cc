// The quasi-static triangle: its corners, stroke speed and period, and what it refuses.
#include "ridefit/synthetic/triangle_history.h"

#include <gtest/gtest.h>

#include "support/throws_input_error.h"

namespace ridefit::synthetic {
namespace {

TEST(SyntheticTriangle, ThreeMillimetresAtOneMillimetrePerSecond) {
  const TriangleHistory x(0.003, 0.001);
  EXPECT_EQ(x.period_s(), 12.0);
  EXPECT_EQ(x(0.0), 0.0);
  EXPECT_NEAR(x(3.0), 0.003, 1e-15);
  EXPECT_NEAR(x(6.0), 0.0, 1e-15);
  EXPECT_NEAR(x(9.0), -0.003, 1e-15);
  EXPECT_NEAR(x(12.0 + 3.0), 0.003, 1e-15);  // periodic
  // Constant stroke speed between corners, reversing at them.
  EXPECT_NEAR((x(2.5) - x(0.5)) / 2.0, 0.001, 1e-15);
  EXPECT_NEAR((x(7.5) - x(4.5)) / 3.0, -0.001, 1e-15);
  EXPECT_NEAR((x(11.5) - x(9.5)) / 2.0, 0.001, 1e-15);
}

TEST(SyntheticTriangle, RefusesANonPositiveAmplitudeOrSpeed) {
  EXPECT_TRUE(testing::throws_input_error([] { TriangleHistory(0.003, 0.0); }, "speed > 0"));
  EXPECT_TRUE(testing::throws_input_error([] { TriangleHistory(-0.003, 0.001); }, "amplitude"));
}

}  // namespace
}  // namespace ridefit::synthetic
