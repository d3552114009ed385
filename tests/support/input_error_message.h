// The message of the InputError that a call throws, or "no error": tests assert on the words
// a user reads (the key, file or row named), not only on the exception type.
#pragma once

#include <string>
#include <utility>

#include "ridefit/common/errors.h"

namespace ridefit::testing {

template <class Call>
std::string input_error_message(Call&& call) {
  try {
    std::forward<Call>(call)();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace ridefit::testing
