// Asserts that a call throws an InputError whose message holds given words:
//   EXPECT_TRUE(throws_input_error([&] { f(bad); }, "sample 3 is nan"));
// On failure gtest prints the message the call threw (or "no error").
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <utility>

#include "support/input_error_message.h"

namespace ridefit::testing {

template <class Call>
::testing::AssertionResult throws_input_error(Call&& call, std::string_view words) {
  const std::string message = input_error_message(std::forward<Call>(call));
  if (message != "no error" && message.find(words) != std::string::npos) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "expected an InputError saying '" << words << "', got: " << message;
}

}  // namespace ridefit::testing
