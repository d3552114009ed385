#pragma once

#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <optional>
#include <span>
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
  double tolerance = 1e-8;  // on the Newton update, relative to (|z_c| + 1 µm, |F_f| + 1 mN)
};

namespace strut_test_detail {

// r(y) = y − y_n − h·f(y, x) and G = ∂r/∂y, in doubles, with f's partial derivatives written
// out (this is the inner loop of every fit: a generic autodiff here spent most of its time in
// exp/log for the Dahl power, which is the identity for the common d = 1). Equal to the
// templated StrutTest::derivatives (the tests compare the solver with CVODE on those).
inline void residual_and_jacobian(const Eigen::Vector2d& y, const Eigen::Vector2d& y_old, double x,
                                  double h, const model::StrutTestParameters<double>& p,
                                  Eigen::Vector2d& r, Eigen::Matrix2d& g) {
  const double c = p.damping_Ns_per_m;
  const double v = (p.top_mount_stiffness_N_per_m * (x - y[0]) - y[1]) / c;
  const double dv_dz = -p.top_mount_stiffness_N_per_m / c;
  const double dv_df = -1.0 / c;
  double force_rate = 0.0, dr_dz = 0.0, dr_df = 0.0;
  if (p.coulomb_force_N > 0.0) {
    const double sign = v < 0.0 ? -1.0 : 1.0;
    // The sliding level L(v) and dL/dv: Fc and 0 without the Stribeck curve.
    double level = p.coulomb_force_N, dlevel_dv = 0.0;
    if (p.stribeck_velocity_m_per_s > 0.0) {
      const double u = v / p.stribeck_velocity_m_per_s;
      const double excess = (p.static_friction_force_N - p.coulomb_force_N) * std::exp(-u * u);
      level = p.coulomb_force_N + excess;
      dlevel_dv = -2.0 * u / p.stribeck_velocity_m_per_s * excess;
    }
    const double s = 1.0 - y[1] / level * sign;
    double power = s, slope = 1.0;  // sgn(s)|s|^d and d|s|^(d−1)
    if (p.dahl_exponent != 1.0) {
      const double magnitude = s == 0.0 ? 0.0 : std::pow(std::abs(s), p.dahl_exponent);
      power = s < 0.0 ? -magnitude : magnitude;
      slope = s == 0.0 ? 0.0 : p.dahl_exponent * magnitude / std::abs(s);
    }
    const double ds_df = -sign / level;  // at fixed v
    force_rate = p.dahl_sigma0_N_per_m * v * power;
    if (dlevel_dv == 0.0) {
      dr_dz = p.dahl_sigma0_N_per_m * power * dv_dz;
      dr_df = p.dahl_sigma0_N_per_m * (power * dv_df + v * slope * ds_df);
    } else {
      // s also moves with v through the level: ds/dv = (F·sgn v / L²)·dL/dv.
      const double ds_dv = y[1] * sign / (level * level) * dlevel_dv;
      dr_dz = p.dahl_sigma0_N_per_m * (power + v * slope * ds_dv) * dv_dz;
      dr_df = p.dahl_sigma0_N_per_m * (power * dv_df + v * slope * (ds_df + ds_dv * dv_df));
    }
  }
  r[0] = y[0] - y_old[0] - h * v;
  r[1] = y[1] - y_old[1] - h * force_rate;
  g << 1.0 - h * dv_dz, -h * dv_df, -h * dr_dz, 1.0 - h * dr_df;
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
  const auto& p_values = values;
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
