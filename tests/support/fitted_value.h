#pragma once

#include <gtest/gtest.h>

#include <string>

#include "ridefit/fitting/hysteresis_fit.h"

namespace ridefit::testing {

// A free parameter's fitted value (a test failure when it was not fitted).
inline double fitted_value(const fitting::HysteresisFitResult& fit, const std::string& name) {
  for (const auto& p : fit.parameters) {
    if (p.name == name) return p.value;
  }
  ADD_FAILURE() << name << " was not fitted";
  return 0.0;
}

}  // namespace ridefit::testing
