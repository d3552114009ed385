#include "ridefit/signal/uniform_sample_rate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "support/input_error_message.h"

namespace ridefit::signal {
namespace {

TEST(UniformSampleRate, RecoversTheRateDespiteRoundedTimes) {
  std::vector<double> t;
  for (int i = 0; i < 5000; ++i) t.push_back(std::round(i * (1.0 / 512.0) * 1e5) / 1e5);
  EXPECT_NEAR(uniform_sample_rate_Hz(t, "x.csv"), 512.0, 1e-3);
}

TEST(UniformSampleRate, AGapOrATooShortSignalNamesTheRow) {
  std::vector<double> t = {0.0, 0.01, 0.02, 0.04, 0.05, 0.06};  // sample 4 dropped
  const std::string message =
      testing::input_error_message([&] { uniform_sample_rate_Hz(t, "meas.csv"); });
  EXPECT_NE(message.find("meas.csv: row 5"), std::string::npos) << message;
  EXPECT_NE(message.find("resample"), std::string::npos) << message;
  const std::vector<double> one = {0.0};
  EXPECT_NE(
      testing::input_error_message([&] { uniform_sample_rate_Hz(one, "x"); }).find("at least 2"),
      std::string::npos);
  const std::vector<double> jitter = {0.0, 0.01, 0.0205, 0.03, 0.04};  // 5 % jitter
  EXPECT_NE(testing::input_error_message([&] { uniform_sample_rate_Hz(jitter, "x"); }), "no error");
  EXPECT_NO_THROW(uniform_sample_rate_Hz(jitter, "x", 0.1));
}

}  // namespace
}  // namespace ridefit::signal
