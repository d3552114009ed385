#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <span>
#include <vector>

#include "ridefit/simulate/esdirk_integrator.h"

namespace ridefit::simulate {

// The ESDIRK run again, in a scalar T that carries derivatives (ceres::Jet, Eigen's
// AutoDiffScalar), over the steps an adaptive run in doubles took (EsdirkStepHistory): the
// derivative of exactly what that run computed, for Ceres.
//
// Frozen steps: the step sequence of an adaptive run depends on the parameters through its
// error control, so the computed solution is only piecewise smooth in them. Like internal
// numerical differentiation (Bock), the tangent is taken of the scheme with the step sequence
// held fixed: the derivative of the discrete map the run applied, which converges to the true
// sensitivity as the tolerance tightens and carries no step-selection noise.
//
// Each implicit stage Z_i = base_i + γh·f(t_i, Z_i) was solved by Newton in doubles (to 1e-5 of
// the tolerance when the run records its steps: at the run's usual 5 % the tangent, taken at a
// point off the stage's solution, was off by up to 1e-4 on stiff stretches); here one Newton step
// in T is taken from it with G =
// I − γh·∂f/∂y(t_i, Z_i), the exact Jacobian there: its value part is (almost) zero and its
// derivative part is −G⁻¹·∂r/∂p, the implicit-function derivative of the stage equation, including
// the dependence of base_i on the earlier stages' and steps' tangents. The stage slopes are k_i =
// (Z_i − base_i)/(γh), as in the run, and the output is the same cubic Hermite interpolation.
//
// `rhs(t, y, ydot)` evaluates f in T (the model's parameters as T); `output(k, t, y)` receives the
// state at output_times_s[k] for every k ≥ 1 (k = 0 is y0). Returns false when the double
// Jacobian at a stage is not finite.
template <typename T, int MaxN = 24, typename Rhs, typename Output>
bool replay_esdirk(const EsdirkStepHistory& history, const OdeSystem& system, std::span<const T> y0,
                   std::span<const double> output_times_s, Rhs&& rhs, Output&& output) {
  using Tab = EsdirkTableau;
  constexpr int kS = Tab::kStages;
  using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, MaxN, MaxN>;
  const int n = history.state_size;
  std::vector<T> y(y0.begin(), y0.end()), base(n), f(n), z(n);
  std::vector<std::vector<T>> k(kS, std::vector<T>(n));
  std::vector<std::vector<T>> stages(kS, std::vector<T>(n));
  Matrix jacobian(n, n), g_inverse(n, n);
  std::vector<T> z_constant(n);
  std::size_t next_output = 1;
  const std::size_t steps = history.step_count();
  for (std::size_t step = 0; step < steps; ++step) {
    const double t = history.start_s[step], h = history.length_s[step];
    const double t_new = step + 1 == steps ? output_times_s.back() : t + h;
    if (step == 0) rhs(t, y.data(), k[0].data());
    for (int i = 1; i < kS; ++i) {
      const double t_stage = t + Tab::c[i] * h;
      for (int r = 0; r < n; ++r) {
        base[r] = y[r];
        for (int j = 0; j < i; ++j) base[r] += T(h * Tab::a[i][j]) * k[j][r];
      }
      const double* zd = history.stage(step, i - 1);
      if (!system.jacobian(t_stage, zd, jacobian.data())) return false;
      g_inverse = (Matrix::Identity(n, n) - (Tab::kGamma * h) * jacobian).partialPivLu().inverse();
      for (int r = 0; r < n; ++r) z_constant[r] = T(zd[r]);
      rhs(t_stage, z_constant.data(), f.data());
      for (int r = 0; r < n; ++r) f[r] = z_constant[r] - base[r] - T(Tab::kGamma * h) * f[r];
      for (int r = 0; r < n; ++r) {
        T correction(0.0);
        for (int c = 0; c < n; ++c) correction += T(g_inverse(r, c)) * f[c];
        stages[i][r] = z_constant[r] - correction;
      }
      for (int r = 0; r < n; ++r) k[i][r] = (stages[i][r] - base[r]) / T(Tab::kGamma * h);
    }
    const std::vector<T>& y_new = stages[kS - 1];
    while (next_output < output_times_s.size() && output_times_s[next_output] <= t_new) {
      const double theta = (output_times_s[next_output] - t) / h;
      const double t2 = theta * theta, t3 = t2 * theta;
      const double h00 = 2 * t3 - 3 * t2 + 1, h10 = (t3 - 2 * t2 + theta) * h,
                   h01 = -2 * t3 + 3 * t2, h11 = (t3 - t2) * h;
      for (int r = 0; r < n; ++r) {
        z[r] = T(h00) * y[r] + T(h10) * k[0][r] + T(h01) * y_new[r] + T(h11) * k[kS - 1][r];
      }
      output(next_output, output_times_s[next_output], z.data());
      ++next_output;
    }
    y = y_new;
    k[0] = k[kS - 1];
  }
  return true;
}

}  // namespace ridefit::simulate
