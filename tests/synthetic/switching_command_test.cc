// The random switching command: levels in range, holds as documented, smooth edges, seeded.
#include "ridefit/synthetic/switching_command.h"

#include <gtest/gtest.h>

namespace ridefit::synthetic {
namespace {

TEST(SyntheticSwitchingCommand, HoldsRandomLevelsForAQuarterToHalfASecond) {
  std::mt19937_64 rng(22), again(22);
  const SwitchingCommand u(30.0, 2.0, rng);
  const SwitchingCommand same(30.0, 2.0, again);
  const auto& s = u.switch_times_s();
  const auto& level = u.levels();
  ASSERT_EQ(level.size(), s.size() + 1);
  ASSERT_GT(s.size(), 60u);  // 30 s of 0.15–0.5 s holds
  EXPECT_EQ(level, same.levels());
  for (double v : level) {
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 2.0);
  }
  EXPECT_GE(s.front(), 0.15);
  EXPECT_LT(s.back(), 30.0);
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_GE(s[i] - s[i - 1], 0.15);
    EXPECT_LE(s[i] - s[i - 1], 0.5);
    // Midway between two switches the command is the level held there (edges of 2 ms).
    EXPECT_NEAR(u(0.5 * (s[i - 1] + s[i])), level[i], 1e-9);
  }
  // Halfway up an edge at the switch instant itself.
  EXPECT_NEAR(u(s[3]), 0.5 * (level[3] + level[4]), 1e-9);
}

}  // namespace
}  // namespace ridefit::synthetic
