#pragma once

#include <stdexcept>
#include <string>

namespace ridefit {

// Bad input from a user: a model or excitation file, a data file or a command-line flag.
// The message names the file, key or row, what was wrong and what would be right.
// The command line maps it to exit code 2.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

// A run that was set up correctly but failed (solver failure, non-convergence).
// The command line maps it to exit code 1.
class RunError : public std::runtime_error {
 public:
  explicit RunError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace ridefit
