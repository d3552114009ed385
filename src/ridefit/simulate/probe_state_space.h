#pragma once

#include <array>
#include <stdexcept>

#include "ridefit/simulate/linear_state_space.h"

namespace ridefit::simulate {

// A, B, C and D of a linear model measured from equilibrium, read off its own right-hand side
// and outputs one unit state or unit input at a time: f(0, 0) = 0, so each probe returns a
// column, exactly (no step, no truncation), and the physics stays in one place.
//   rate(x, input, xdot):    x' at state x with input `input` set to 1 (−1: no input)
//   output(x, input, y):     the outputs there
// `kMaxStates` sizes the probe's state on the stack, so no branch of a model can read past it.
template <int kMaxStates, class Rate, class Output>
LinearStateSpace probe_state_space(int states, int inputs, int outputs, Rate&& rate,
                                   Output&& output) {
  if (states > kMaxStates) throw std::invalid_argument("probe_state_space: too many states");
  LinearStateSpace s;
  s.A.resize(states, states);
  s.B.resize(states, inputs);
  s.C.resize(outputs, states);
  s.D.resize(outputs, inputs);
  std::array<double, kMaxStates> x{}, xdot{};
  Eigen::VectorXd y(outputs);
  auto probe = [&](int input, auto column_of_a, auto column_of_c) {
    rate(x.data(), input, xdot.data());
    output(x.data(), input, y.data());
    for (int i = 0; i < states; ++i) column_of_a(i) = xdot[static_cast<std::size_t>(i)];
    for (int k = 0; k < outputs; ++k) column_of_c(k) = y[k];
  };
  for (int j = 0; j < states; ++j) {
    x[static_cast<std::size_t>(j)] = 1.0;
    probe(
        -1, [&](int i) -> double& { return s.A(i, j); },
        [&](int k) -> double& { return s.C(k, j); });
    x[static_cast<std::size_t>(j)] = 0.0;
  }
  for (int j = 0; j < inputs; ++j) {
    probe(
        j, [&](int i) -> double& { return s.B(i, j); },
        [&](int k) -> double& { return s.D(k, j); });
  }
  return s;
}

}  // namespace ridefit::simulate
