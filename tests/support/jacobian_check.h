#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ridefit/simulate/ode_system.h"

namespace ridefit::testing {

// An integrator system's Jacobian at (t, x) against central differences of its derivatives, each
// state stepped by 1e-6 of its typical magnitude; `what` names the case in failures.
inline void expect_jacobian_matches_central_differences(const simulate::OdeSystem& system, double t,
                                                        const std::vector<double>& x,
                                                        const std::string& what = "") {
  const int n = system.size();
  ASSERT_EQ(n, static_cast<int>(x.size())) << what;
  std::vector<double> jacobian(static_cast<std::size_t>(n * n));
  ASSERT_TRUE(system.jacobian(t, x.data(), jacobian.data())) << what;
  for (int col = 0; col < n; ++col) {
    const double h = 1e-6 * system.typical_magnitude(col);
    std::vector<double> plus = x, minus = x, f_plus(x.size()), f_minus(x.size());
    plus[static_cast<std::size_t>(col)] += h;
    minus[static_cast<std::size_t>(col)] -= h;
    ASSERT_TRUE(system.derivatives(t, plus.data(), f_plus.data())) << what;
    ASSERT_TRUE(system.derivatives(t, minus.data(), f_minus.data())) << what;
    for (int row = 0; row < n; ++row) {
      const auto r = static_cast<std::size_t>(row);
      const double fd = (f_plus[r] - f_minus[r]) / (2.0 * h);
      EXPECT_NEAR(jacobian[static_cast<std::size_t>(col * n + row)], fd,
                  1e-6 * std::max(1.0, std::abs(fd)))
          << "d f" << row << " / d x" << col << " (" << what << ")";
    }
  }
}

}  // namespace ridefit::testing
