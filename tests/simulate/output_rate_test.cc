#include <gtest/gtest.h>

#include "ridefit/simulate/simulation_options.h"
#include "support/throws_input_error.h"

namespace ridefit::simulate {
namespace {

using testing::throws_input_error;

// The library's message starts with the rate and names no flag: the command line adds its own.
TEST(OutputRate, TooFastOrTooFewSamplesAreInputErrorsThatBeginWithTheRate) {
  EXPECT_NO_THROW(check_output_rate(1000.0, 10.0));
  EXPECT_NO_THROW(check_output_rate(kMaxOutputRate_Hz, 0.01));
  EXPECT_TRUE(throws_input_error([] { check_output_rate(1e6, 1.0); },
                                 "1e+06 Hz: output samples more than 100000 per second"));
  EXPECT_TRUE(throws_input_error([] { check_output_rate(0.1, 2.0); },
                                 "0.1 Hz over 2 s gives 1 output sample; give at least two"));
  // Exactly two samples at the rate that just gives them.
  EXPECT_NO_THROW(check_output_rate(0.5, 2.0));
}

}  // namespace
}  // namespace ridefit::simulate
