#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <optional>
#include <span>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "ridefit/model/strut_test.h"

namespace ridefit::simulate {

// The rig force of a strut test (model::StrutTest) at every sample of an imposed displacement
// history, templated on the scalar so that Ceres' Jets flow through it.
//
// Why implicit: the Dahl element's pre-sliding stiffness σ0 in parallel with the damper gives a
// time constant c/σ0 (0.2 ms for the Passat strut) far below any sample interval, so an explicit
// step would need ~0.1 ms and millions of steps per fit. Backward Euler is L-stable and follows
// the fast dynamics' slow manifold at any step: each sample interval is split into `substeps`
// steps (x linear in between) and each step solves y = y_n + h·f(y, x) by Newton.
//
// Exact derivatives at the cost of one extra residual: Newton runs on the double values only;
// then one Newton step is taken in T from the converged point. Its value part is zero (the
// residual vanishes there) and its derivative part is −G⁻¹·∂r/∂p, the implicit-function
// derivative of the discrete scheme, so Jets carry d(force)/d(parameters) of exactly the
// discretisation whose values are returned. The model starts at rest at the first sample
// (z_c = x_0, F_f = 0).
//
// Returns no value when Newton fails to converge in a step (a parameter set the scheme cannot
// follow); the caller reports it (RunError, or `false` to Ceres).
struct StrutTestSolverOptions {
  int substeps = 4;
  int max_newton_iterations = 30;
  double tolerance = 1e-10;  // on the Newton update, relative to (|z_c| + 1 µm, |F_f| + 1 mN)
};

namespace strut_test_detail {

using Gradient2 = Eigen::Matrix<double, 2, 1>;
using AutoDiff2 = Eigen::AutoDiffScalar<Gradient2>;

// r(y) = y − y_n − h·f(y, x) and G = ∂r/∂y, in doubles.
inline void residual_and_jacobian(const Eigen::Vector2d& y, const Eigen::Vector2d& y_old, double x,
                                  double h, const model::StrutTestParameters<AutoDiff2>& p,
                                  Eigen::Vector2d& r, Eigen::Matrix2d& g) {
  AutoDiff2 ya[2] = {AutoDiff2(y[0], 2, 0), AutoDiff2(y[1], 2, 1)};
  AutoDiff2 f[2];
  model::StrutTest::derivatives(ya, AutoDiff2(x), p, f);
  for (int i = 0; i < 2; ++i) {
    r[i] = y[i] - y_old[i] - h * f[i].value();
    for (int j = 0; j < 2; ++j) {
      const double dfdy = f[i].derivatives().size() == 2 ? f[i].derivatives()[j] : 0.0;
      g(i, j) = (i == j ? 1.0 : 0.0) - h * dfdy;
    }
  }
}

inline model::StrutTestParameters<AutoDiff2> constant(const model::StrutTestParameters<double>& p) {
  return {AutoDiff2(p.dahl_sigma0_N_per_m),   AutoDiff2(p.coulomb_force_N),
          AutoDiff2(p.dahl_exponent),         AutoDiff2(p.top_mount_stiffness_N_per_m),
          AutoDiff2(p.damping_Ns_per_m),      AutoDiff2(p.gas_force_N),
          AutoDiff2(p.gas_stiffness_N_per_m), AutoDiff2(p.force_offset_N)};
}

}  // namespace strut_test_detail

// `parameters` and `values` hold the same numbers: `values` as doubles for the Newton solves
// (for T = double pass the same struct twice).
template <typename T>
std::optional<std::vector<T>> strut_test_force(std::span<const double> time_s,
                                               std::span<const double> displacement_m,
                                               const model::StrutTestParameters<T>& parameters,
                                               const model::StrutTestParameters<double>& values,
                                               const StrutTestSolverOptions& options = {}) {
  using strut_test_detail::residual_and_jacobian;
  const std::size_t n = time_s.size();
  std::vector<T> force;
  force.reserve(n);
  if (n == 0) return force;
  const auto p_values = strut_test_detail::constant(values);
  Eigen::Vector2d y_value(displacement_m[0], 0.0);
  T y[2] = {T(displacement_m[0]), T(0.0)};
  force.push_back(model::StrutTest::force_N(y, T(displacement_m[0]), parameters));
  const Eigen::Vector2d scale(1e-6, 1e-3);
  for (std::size_t k = 1; k < n; ++k) {
    const double h = (time_s[k] - time_s[k - 1]) / options.substeps;
    for (int s = 1; s <= options.substeps; ++s) {
      const double w = static_cast<double>(s) / options.substeps;
      const double x = (1.0 - w) * displacement_m[k - 1] + w * displacement_m[k];
      const Eigen::Vector2d y_old = y_value;
      Eigen::Vector2d r;
      Eigen::Matrix2d g;
      bool converged = false;
      for (int it = 0; it < options.max_newton_iterations; ++it) {
        residual_and_jacobian(y_value, y_old, x, h, p_values, r, g);
        const Eigen::Vector2d step = g.partialPivLu().solve(r);
        if (!step.allFinite()) return std::nullopt;
        y_value -= step;
        if ((step.array().abs() / (y_value.array().abs() + scale.array())).maxCoeff() <
            options.tolerance) {
          converged = true;
          break;
        }
      }
      if (!converged) return std::nullopt;
      // One Newton step in T from the converged point: exact tangents (see above).
      residual_and_jacobian(y_value, y_old, x, h, p_values, r, g);
      const Eigen::Matrix2d g_inverse = g.inverse();
      T y_new[2] = {T(y_value[0]), T(y_value[1])};
      T f[2];
      model::StrutTest::derivatives(y_new, T(x), parameters, f);
      const T r0 = y_new[0] - y[0] - T(h) * f[0];
      const T r1 = y_new[1] - y[1] - T(h) * f[1];
      y[0] = y_new[0] - (T(g_inverse(0, 0)) * r0 + T(g_inverse(0, 1)) * r1);
      y[1] = y_new[1] - (T(g_inverse(1, 0)) * r0 + T(g_inverse(1, 1)) * r1);
    }
    force.push_back(model::StrutTest::force_N(y, T(displacement_m[k]), parameters));
  }
  return force;
}

}  // namespace ridefit::simulate
