#pragma once

#include <cmath>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "ridefit/io/input_error.h"
#include "ridefit/model/strut_test.h"
#include "ridefit/simulate/esdirk_integrator.h"
#include "ridefit/simulate/esdirk_tangents.h"
#include "ridefit/simulate/strut_test_system.h"

namespace ridefit::simulate {

// The rig force of a strut test (model::StrutTest) at every sample of an imposed displacement
// history, templated on the scalar so that Ceres' Jets flow through it.
//
// The strut is integrated by ridefit's adaptive ESDIRK (esdirk_integrator.h) over the
// displacement interpolated between samples (RigDisplacement: a C2 spline for uniform records),
// so the force is the model's, not a discretisation's: the Dahl element's pre-sliding time
// constant c/σ0 (0.2–0.75 ms) is far below a sample interval, and a fixed-step first-order
// scheme at a few substeps per sample biased σ0 by a quarter in a five-parameter fit. The kink at
// every reversal ends a step (the sliding velocity is the switching function).
//
// Exact derivatives (T a Jet): the run in doubles records its steps, then replay_esdirk
// (esdirk_tangents.h) carries d(force)/d(parameters) through exactly those steps: the derivative
// of what was computed, step sequence frozen. The model starts at rest at the first sample
// (z_c = x_0, F_f = 0).
//
// Returns no value when the integrator fails (a parameter set the model cannot follow: the
// caller reports it, a RunError, or `false` to Ceres).
struct StrutTestSolverOptions {
  // The integrator's relative tolerance (IntegratorOptions): at 1e-6 the force of a 1 kHz
  // random-displacement record is within 0.003 % (RMS) of CVODE at 1e-10 (a test asks 0.05 %).
  double relative_tolerance = 1e-6;
  RigInterpolation interpolation = RigInterpolation::kSpline;
  // A run that needs more steps than this per simulated second is given up (no value): a fit
  // exploring an extreme corner (a Stribeck velocity of micrometres per second, say) would
  // otherwise spend minutes on one evaluation. Ordinary records take 1 000–3 000.
  double max_steps_per_s = 10'000;
  // Run on these steps (another run's history: the discrete map with its step sequence frozen,
  // for checking the tangents by finite differences) instead of choosing them; may be null.
  const EsdirkStepHistory* frozen_steps = nullptr;
};

// The steps the adaptive run takes for this record and strut: to freeze them
// (StrutTestSolverOptions::frozen_steps) when checking the tangents by finite differences.
inline EsdirkStepHistory strut_test_steps(std::span<const double> time_s,
                                          std::span<const double> displacement_m,
                                          const model::StrutTestParameters<double>& values,
                                          const StrutTestSolverOptions& options = {}) {
  const RigDisplacement x(time_s, displacement_m, options.interpolation);
  EsdirkStepHistory history;
  integrate_esdirk(StrutTestSystem(values, x), {displacement_m[0], 0.0},
                   std::vector<double>(time_s.begin(), time_s.end()), esdirk_options(options),
                   &history);
  return history;
}

// `parameters` and `values` hold the same numbers: `values` as doubles for the run in doubles
// (for T = double pass the same struct twice).
template <typename T>
std::optional<std::vector<T>> strut_test_force(std::span<const double> time_s,
                                               std::span<const double> displacement_m,
                                               const model::StrutTestParameters<T>& parameters,
                                               const model::StrutTestParameters<double>& values,
                                               const StrutTestSolverOptions& options = {}) {
  const std::size_t n = time_s.size();
  std::vector<T> force;
  if (n == 0) return force;
  force.reserve(n);
  const RigDisplacement x(time_s, displacement_m, options.interpolation);
  const StrutTestSystem system(values, x);
  const IntegratorOptions integrator = esdirk_options(options);
  const std::vector<double> times(time_s.begin(), time_s.end());
  const std::vector<double> y0 = {displacement_m[0], 0.0};
  try {
    if constexpr (std::is_same_v<T, double>) {
      const Trajectory trajectory =
          integrate_esdirk_or_frozen(system, y0, times, integrator, options.frozen_steps);
      for (std::size_t k = 0; k < n; ++k) {
        force.push_back(
            model::StrutTest::force_N(trajectory.state_at(k), displacement_m[k], parameters));
      }
    } else {
      EsdirkStepHistory own_history;
      const EsdirkStepHistory& history =
          esdirk_steps_or_frozen(system, y0, times, integrator, options.frozen_steps, own_history);
      const T y0_t[2] = {T(y0[0]), T(y0[1])};
      force.push_back(model::StrutTest::force_N(y0_t, T(displacement_m[0]), parameters));
      const bool ok = replay_esdirk<T, 2>(
          history, system, std::span<const T>(y0_t, 2), time_s,
          [&](double t, const T* y, T* ydot) {
            model::StrutTest::derivatives(y, T(x.at(t)), parameters, ydot);
          },
          [&](std::size_t k, double, const T* y) {
            force.push_back(model::StrutTest::force_N(y, T(displacement_m[k]), parameters));
          });
      if (!ok) return std::nullopt;
    }
  } catch (const RunError&) {
    return std::nullopt;
  }
  if (force.size() != n) return std::nullopt;
  return force;
}

}  // namespace ridefit::simulate
