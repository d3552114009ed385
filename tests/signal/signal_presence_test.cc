// signal::require_signal: zero or constant channels are refused, real signals pass.
#include "ridefit/signal/signal_presence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/throws_input_error.h"

namespace ridefit::signal {
namespace {

using testing::throws_input_error;

TEST(SignalPresence, ZerosAndConstantsWithRoundOffAreRefusedNamingFileAndChannel) {
  const std::vector<double> zeros(1000, 0.0);
  EXPECT_TRUE(
      throws_input_error([&] { require_signal(zeros, "a.csv", "body_acc", "m/s^2"); },
                         "a.csv: channel body_acc carries no signal: every sample is zero"));
  std::vector<double> offset(1000, 9.81);
  for (std::size_t k = 0; k < offset.size(); k += 7) offset[k] = std::nextafter(9.81, 10.0);
  EXPECT_TRUE(throws_input_error([&] { require_signal(offset, "b.csv", "body_acc", "m/s^2"); },
                                 "it is constant"));
  std::vector<double> tiny(1000);
  for (std::size_t k = 0; k < tiny.size(); ++k)
    tiny[k] = 1e-9 * std::sin(0.1 * static_cast<double>(k));
  EXPECT_TRUE(throws_input_error([&] { require_signal(tiny, "c.csv", "road", "m"); }, "road"));
}

TEST(SignalPresence, SmallRealSignalsPass) {
  std::vector<double> road(1000), force(1000);
  for (std::size_t k = 0; k < road.size(); ++k) {
    road[k] = 1e-5 * std::sin(0.1 * static_cast<double>(k));           // 10 µm of road
    force[k] = 500.0 + 0.05 * std::sin(0.1 * static_cast<double>(k));  // 50 mN on a 500 N preload
  }
  EXPECT_NO_THROW(require_signal(road, "r.csv", "road", "m"));
  EXPECT_NO_THROW(require_signal(force, "f.csv", "force", "N"));
}

}  // namespace
}  // namespace ridefit::signal
