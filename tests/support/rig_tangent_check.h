#pragma once

#include <gtest/gtest.h>

#include <ceres/jet.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::testing {

// The strut solver's tangents (Jets through the recorded steps, as a fit's Jacobian) of three
// parameters, by their names, against central differences of the same discrete scheme, its steps
// frozen: each within 1e-4 of its largest value, and not all zero (the parameter acts). The
// differences step each parameter by `relative_step` of its value: where a step of the run ends
// on a kink it located (a free play's corner, the knee), the next step's first stage sits on it
// to the location's accuracy, and a difference wider than that straddles the kink and measures
// its jump in slope, not the tangent (behind a compliant mount 1e-6 did at two samples; 1e-8
// does not, and still lies far above rounding).
inline void expect_rig_tangents_match_frozen_differences(
    const std::vector<double>& t, const std::vector<double>& x,
    const model::StrutTestParameters<double>& p, const std::array<std::string, 3>& names,
    double relative_step = 1e-6) {
  const simulate::StrutTestSolverOptions options;
  using Jet = ceres::Jet<double, 3>;
  std::array<std::size_t, 3> index{};
  model::StrutTestParameters<Jet> pj = p.cast<Jet>();
  for (int j = 0; j < 3; ++j) {
    index[j] = fitting::strut_parameter_index(names[j]);
    fitting::strut_parameter(pj, index[j]).v[j] = 1.0;
  }
  const auto jets = simulate::strut_test_force<Jet>(t, x, pj, p, options);
  ASSERT_TRUE(jets.has_value()) << "no derivatives: the recorded run failed";
  simulate::StrutTestSolverOptions frozen = options;
  const auto steps = simulate::strut_test_steps(t, x, p, frozen);
  frozen.frozen_steps = &steps;
  for (int j = 0; j < 3; ++j) {
    auto plus = p, minus = p;
    const double step = relative_step * fitting::strut_parameter(p, index[j]);
    fitting::strut_parameter(plus, index[j]) += step;
    fitting::strut_parameter(minus, index[j]) -= step;
    const auto up = simulate::strut_test_force<double>(t, x, plus, plus, frozen);
    const auto down = simulate::strut_test_force<double>(t, x, minus, minus, frozen);
    ASSERT_TRUE(up && down);
    double scale = 0.0, worst = 0.0;
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double fd = ((*up)[k] - (*down)[k]) / (2.0 * step);
      scale = std::max(scale, std::abs((*jets)[k].v[j]));
      worst = std::max(worst, std::abs(fd - (*jets)[k].v[j]));
    }
    EXPECT_GT(scale, 0.0) << names[j];
    EXPECT_LT(worst, 1e-4 * scale) << names[j];
  }
}

}  // namespace ridefit::testing
