#pragma once

#include <Eigen/Core>
#include <array>
#include <span>
#include <utility>

#include "ridefit/simulate/esdirk_integrator.h"
#include "ridefit/simulate/small_dense_solve.h"

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
// Jacobian at a stage is not finite or G is singular.
namespace esdirk_detail {

// The replay for a state size N known at compile time (or Eigen::Dynamic up to MaxN): the state,
// stage and slope vectors live in fixed arrays and G = I − γh·J is a fixed-size matrix, so the
// small loops unroll and nothing is allocated or copied per step (with std::vector<T> and a
// dynamic G, copies and the dynamic-size inverse took a third of a PSD fit).
template <typename T, int N, int MaxN, typename Rhs, typename Output>
bool replay_fixed(const EsdirkStepHistory& history, const OdeSystem& system, std::span<const T> y0,
                  std::span<const double> output_times_s, Rhs& rhs, Output& output) {
  using Tab = EsdirkTableau;
  constexpr int kS = Tab::kStages;
  constexpr int kCap = N == Eigen::Dynamic ? MaxN : N;
  using Matrix = Eigen::Matrix<double, N, N, 0, kCap, kCap>;
  using Vector = std::array<T, kCap>;
  const int n = N == Eigen::Dynamic ? history.state_size : N;
  Vector y{}, base{}, f{}, z{}, z_constant{};
  std::array<Vector, kS> k{};
  for (int r = 0; r < n; ++r) y[r] = y0[static_cast<std::size_t>(r)];
  Matrix jacobian(n, n), g(n, n);
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
      g = Matrix::Identity(n, n) - (Tab::kGamma * h) * jacobian;
      for (int r = 0; r < n; ++r) z_constant[r] = T(zd[r]);
      rhs(t_stage, z_constant.data(), f.data());
      for (int r = 0; r < n; ++r) f[r] = z_constant[r] - base[r] - T(Tab::kGamma * h) * f[r];
      if (!small_solve(g, f.data())) return false;  // f ← G⁻¹·residual
      // The stage in T, and its slope k_i = (Z_i − base_i)/(γh) as the run computed it.
      Vector& stage = i == kS - 1 ? z : k[i];
      for (int r = 0; r < n; ++r) stage[r] = z_constant[r] - f[r];
      if (i == kS - 1) {
        for (int r = 0; r < n; ++r) k[i][r] = (z[r] - base[r]) / T(Tab::kGamma * h);
      } else {
        for (int r = 0; r < n; ++r) k[i][r] = (k[i][r] - base[r]) / T(Tab::kGamma * h);
      }
    }
    // z: the step's end (the last stage: the method is stiffly accurate).
    while (next_output < output_times_s.size() && output_times_s[next_output] <= t_new) {
      const double theta = (output_times_s[next_output] - t) / h;
      const double t2 = theta * theta, t3 = t2 * theta;
      const double h00 = 2 * t3 - 3 * t2 + 1, h10 = (t3 - 2 * t2 + theta) * h,
                   h01 = -2 * t3 + 3 * t2, h11 = (t3 - t2) * h;
      Vector out{};
      for (int r = 0; r < n; ++r) {
        out[r] = T(h00) * y[r] + T(h10) * k[0][r] + T(h01) * z[r] + T(h11) * k[kS - 1][r];
      }
      output(next_output, output_times_s[next_output], out.data());
      ++next_output;
    }
    y = z;
    k[0] = k[kS - 1];
  }
  return true;
}

template <typename T, int MaxN, int... Sizes, typename Rhs, typename Output>
bool replay_dispatch(std::integer_sequence<int, Sizes...>, const EsdirkStepHistory& history,
                     const OdeSystem& system, std::span<const T> y0,
                     std::span<const double> output_times_s, Rhs& rhs, Output& output) {
  bool ok = false;
  const bool fixed =
      ((history.state_size == Sizes &&
        (ok = replay_fixed<T, Sizes, MaxN>(history, system, y0, output_times_s, rhs, output),
         true)) ||
       ...);
  if (fixed) return ok;
  return replay_fixed<T, Eigen::Dynamic, MaxN>(history, system, y0, output_times_s, rhs, output);
}

}  // namespace esdirk_detail

// MaxN: the largest state size the caller's system has (fixed-size code for 2–7 states).
template <typename T, int MaxN = 24, typename Rhs, typename Output>
bool replay_esdirk(const EsdirkStepHistory& history, const OdeSystem& system, std::span<const T> y0,
                   std::span<const double> output_times_s, Rhs&& rhs, Output&& output) {
  if (history.state_size > MaxN) return false;
  if constexpr (MaxN <= 7) {
    return esdirk_detail::replay_dispatch<T, MaxN>(std::integer_sequence<int, 2, 3, 4, 5, 6, 7>{},
                                                   history, system, y0, output_times_s, rhs,
                                                   output);
  } else {
    return esdirk_detail::replay_fixed<T, Eigen::Dynamic, MaxN>(history, system, y0, output_times_s,
                                                                rhs, output);
  }
}

}  // namespace ridefit::simulate
