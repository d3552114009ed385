#pragma once

#include <Eigen/Core>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

namespace ridefit::simulate {

// The dense Jacobian ∂f/∂x (column-major, n×n, SUNDIALS' layout) of a templated right-hand side
// by Eigen's forward-mode AutoDiffScalar; `derivatives(x, xdot)` is called once with AutoDiff
// scalars. Derivative vectors live on the stack (fixed capacity MaxStates). False when an entry
// is not finite.
template <int MaxStates, typename Derivatives>
bool autodiff_jacobian(int n, const double* x, Derivatives&& derivatives,
                       double* jacobian_column_major) {
  using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, MaxStates, 1>;
  using AutoDiff = Eigen::AutoDiffScalar<Gradient>;
  AutoDiff xa[MaxStates];
  AutoDiff fa[MaxStates];
  for (int i = 0; i < n; ++i) xa[i] = AutoDiff(x[i], n, i);
  derivatives(xa, fa);
  for (int row = 0; row < n; ++row) {
    const Gradient& g = fa[row].derivatives();
    for (int col = 0; col < n; ++col) {
      // A constant output (e.g. z' = v) may carry an empty derivative vector.
      const double value = g.size() == n ? g[col] : 0.0;
      if (!std::isfinite(value)) return false;
      jacobian_column_major[col * n + row] = value;
    }
  }
  return true;
}

}  // namespace ridefit::simulate
