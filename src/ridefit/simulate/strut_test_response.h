#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "ridefit/common/errors.h"
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
  // A run in doubles records its steps here (may be null), each stage converged as for a replay:
  // a fit keeps them for the Jacobian at the same point (hysteresis_fit.cc).
  EsdirkStepHistory* record_steps = nullptr;
};

// The state a strut test starts from: at rest at the first sample (z_c = x₀, F_f = 0) and, with a
// lagged command, the fluid settled at the first command (ū = u₀).
inline std::vector<double> strut_test_start(const model::StrutTestParameters<double>& values,
                                            double displacement_m, double command) {
  std::vector<double> y0 = {displacement_m, 0.0};
  if (model::StrutTest::state_count(values) == 3) y0.push_back(command);
  return y0;
}

// The load cell's reading of a force history (model::StrutTestParameters' measurement chain):
// gain × the force delayed by force_delay_s (a cubic between samples; the force
// before the first sample is the first) and low-passed at force_sensor_cutoff_Hz (first order,
// or two first-order stages for order 2, each discretised exactly for a force linear between
// samples, started settled). The load-cell offset is not scaled. Identity for an ideal sensor.
template <typename T>
void apply_force_sensor(std::span<const double> time_s, const model::StrutTestParameters<T>& p,
                        std::vector<T>& force) {
  using std::exp;
  const bool delayed = p.force_delay_s > 0.0;
  const bool filtered = p.force_sensor_cutoff_Hz > 0.0;
  // (with derivatives the gain is applied even at 1: its tangent is the force itself)
  if (!delayed && !filtered && std::is_same_v<T, double> && p.force_gain == 1.0) return;
  const std::size_t n = force.size();
  std::vector<T> physical(n);
  for (std::size_t k = 0; k < n; ++k) physical[k] = force[k] - p.force_offset_N;
  if (delayed) {
    std::vector<T> shifted(n);
    std::size_t i = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const T t = T(time_s[k]) - p.force_delay_s;
      if (t <= time_s[0]) {
        shifted[k] = physical[0];
        continue;
      }
      while (i + 1 < n && t > time_s[i + 1]) ++i;
      // F(t_k − δ) on the segment [t_i, t_i+1] by a Catmull-Rom cubic (continuous slope, so the
      // cost is smooth in δ across samples); its weight carries δ's derivative.
      const double h = time_s[i + 1] - time_s[i];
      const T w = (t - time_s[i]) / h;
      const T& f0 = physical[i > 0 ? i - 1 : 0];
      const T& f1 = physical[i];
      const T& f2 = physical[i + 1];
      const T& f3 = physical[i + 2 < n ? i + 2 : n - 1];
      shifted[k] = f1 + T(0.5) * w *
                            ((f2 - f0) + w * ((T(2.0) * f0 - T(5.0) * f1 + T(4.0) * f2 - f3) +
                                              w * (T(3.0) * (f1 - f2) + f3 - f0)));
    }
    physical = std::move(shifted);
  }
  if (filtered) {
    const T tau = T(1.0) / (T(2.0 * 3.14159265358979323846) * p.force_sensor_cutoff_Hz);
    const int stages = p.force_sensor_order == 2 ? 2 : 1;
    for (int stage = 0; stage < stages; ++stage) {
      T y = physical[0];
      T previous = physical[0];
      for (std::size_t k = 1; k < n; ++k) {
        const double h = time_s[k] - time_s[k - 1];
        const T a = exp(-h / tau);
        const T b1 = tau / h * (T(1.0) - a) - a;  // first-order hold: exact for a ramp
        const T b0 = T(1.0) - a - b1;
        y = a * y + b0 * physical[k] + b1 * previous;
        previous = physical[k];
        physical[k] = y;
      }
    }
  }
  for (std::size_t k = 0; k < n; ++k) force[k] = p.force_gain * physical[k] + p.force_offset_N;
}

// The rig's acceleration at its samples, for the inertia force of the mass the load cell carries
// (moving_mass_kg): the three-point derivative (uneven steps allowed; one-sided at the ends) of
// the measured velocity where the record has one, else of the interpolant's slope at the samples.
// Not a second difference of the displacement: a quantised record would give q/h² of noise at
// every step (3 m/s² for 3 µm at 1 kHz).
inline std::vector<double> rig_acceleration_at_samples(std::span<const double> time_s,
                                                       const RigDisplacement& x,
                                                       std::span<const double> velocity_m_per_s) {
  const std::size_t n = time_s.size();
  std::vector<double> v(n);
  for (std::size_t k = 0; k < n; ++k) {
    v[k] = velocity_m_per_s.size() == n ? velocity_m_per_s[k] : x.rate_at(time_s[k]);
  }
  std::vector<double> a(n, 0.0);
  if (n < 2) return a;
  a[0] = (v[1] - v[0]) / (time_s[1] - time_s[0]);
  a[n - 1] = (v[n - 1] - v[n - 2]) / (time_s[n - 1] - time_s[n - 2]);
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const double h1 = time_s[k] - time_s[k - 1];
    const double h2 = time_s[k + 1] - time_s[k];
    a[k] = (-h2 / (h1 * (h1 + h2))) * v[k - 1] + ((h2 - h1) / (h1 * h2)) * v[k] +
           (h1 / (h2 * (h1 + h2))) * v[k + 1];
  }
  return a;
}

// The integrator's options for a record: the solver's, with steps ending on the samples where
// the inputs kink there (RigDisplacement::kinks_at_samples, or a command that changes, taken
// as straight lines between samples, for a controlled damper).
inline IntegratorOptions rig_integrator_options(const StrutTestSolverOptions& options,
                                                const RigDisplacement& x,
                                                const model::StrutTestParameters<double>& values,
                                                std::span<const double> command) {
  IntegratorOptions integrator = esdirk_options(options);
  const bool command_changes =
      values.commanded() && !command.empty() &&
      std::any_of(command.begin(), command.end(), [&](double u) { return u != command[0]; });
  // Behind a compliant top mount (a path that is not quasi-static) the force is k_tm·(x − z_c),
  // the small difference of a stiff state and the displacement it follows. Its error between step
  // ends is neither controlled nor small: the embedded estimate filters the stiff component
  // through G and the outputs interpolate its stage slopes, and steps of 10–100 relaxation times
  // left the force 0.15 N RMS off at rtol 1e-6 behind 1.2e6 N/m (365 N behind 5e7), against a
  // rig's 0.3 N noise. Steps that end on the samples keep it within 0.01 N at rtol 1e-4–1e-6, for
  // two to four times the steps of a slip damper (friction's kinks take as many already).
  integrator.steps_end_on_outputs =
      x.kinks_at_samples() || command_changes || !model::StrutTest::quasi_static(values);
  return integrator;
}

// The steps the adaptive run takes for this record and strut: to freeze them
// (StrutTestSolverOptions::frozen_steps) when checking the tangents by finite differences.
inline EsdirkStepHistory strut_test_steps(std::span<const double> time_s,
                                          std::span<const double> displacement_m,
                                          const model::StrutTestParameters<double>& values,
                                          const StrutTestSolverOptions& options = {},
                                          std::span<const double> command = {},
                                          std::span<const double> velocity_m_per_s = {}) {
  const RigDisplacement x(time_s, displacement_m, options.interpolation, velocity_m_per_s);
  const RigDisplacement u(time_s, command.empty() ? displacement_m : command,
                          RigInterpolation::kLinear);
  EsdirkStepHistory history;
  integrate_esdirk(StrutTestSystem(values, x, command.empty() ? nullptr : &u),
                   strut_test_start(values, displacement_m[0], command.empty() ? 0.0 : command[0]),
                   std::vector<double>(time_s.begin(), time_s.end()),
                   rig_integrator_options(options, x, values, command), &history);
  return history;
}

// `parameters` and `values` hold the same numbers: `values` as doubles for the run in doubles
// (for T = double pass the same struct twice). `command`: the record's command (current or
// voltage) at its samples, for a controlled damper; empty for none (a command of 0).
// `velocity_m_per_s`: the rig's measured velocity at its samples, when it has one (RigDisplacement
// then runs through the samples with those slopes). The result is what the load cell reads
// (apply_force_sensor) of the strut's force and the inertia force of the mass it carries.
template <typename T>
std::optional<std::vector<T>> strut_test_force(std::span<const double> time_s,
                                               std::span<const double> displacement_m,
                                               const model::StrutTestParameters<T>& parameters,
                                               const model::StrutTestParameters<double>& values,
                                               const StrutTestSolverOptions& options = {},
                                               std::span<const double> command = {},
                                               std::span<const double> velocity_m_per_s = {}) {
  const std::size_t n = time_s.size();
  std::vector<T> force;
  if (n == 0) return force;
  force.reserve(n);
  const RigDisplacement x(time_s, displacement_m, options.interpolation, velocity_m_per_s);
  // A command switches between levels: straight lines between samples, never an overshoot.
  const RigDisplacement u(time_s, command.empty() ? displacement_m : command,
                          RigInterpolation::kLinear);
  const RigDisplacement* u_or_none = command.empty() ? nullptr : &u;
  const StrutTestSystem system(values, x, u_or_none);
  const IntegratorOptions integrator = rig_integrator_options(options, x, values, command);
  const std::vector<double> times(time_s.begin(), time_s.end());
  const std::vector<double> y0 =
      strut_test_start(values, displacement_m[0], command.empty() ? 0.0 : command[0]);
  const auto command_at = [&](double t) { return u_or_none ? u.at(t) : 0.0; };
  try {
    if constexpr (std::is_same_v<T, double>) {
      const Trajectory trajectory =
          options.frozen_steps == nullptr
              ? integrate_esdirk(system, y0, times, integrator, options.record_steps)
              : integrate_esdirk_on_steps(system, y0, times, integrator, *options.frozen_steps);
      for (std::size_t k = 0; k < n; ++k) {
        force.push_back(model::StrutTest::force_N(trajectory.state_at(k), displacement_m[k],
                                                  x.rate_at(time_s[k]), command_at(time_s[k]),
                                                  parameters));
      }
    } else {
      EsdirkStepHistory own_history;
      const EsdirkStepHistory& history =
          esdirk_steps_or_frozen(system, y0, times, integrator, options.frozen_steps, own_history);
      T y0_t[3] = {T(y0[0]), T(y0[1]), T(0.0)};
      if (y0.size() == 3) y0_t[2] = T(y0[2]);
      force.push_back(model::StrutTest::force_N(y0_t, T(displacement_m[0]), T(x.rate_at(time_s[0])),
                                                T(command_at(time_s[0])), parameters));
      const bool ok = replay_esdirk<T, 3>(
          history, system, std::span<const T>(y0_t, y0.size()), time_s,
          [&](double t, const T* y, T* ydot) {
            model::StrutTest::derivatives(y, T(x.at(t)), T(x.rate_at(t)), T(command_at(t)),
                                          parameters, ydot);
          },
          [&](std::size_t k, double, const T* y) {
            force.push_back(model::StrutTest::force_N(y, T(displacement_m[k]),
                                                      T(x.rate_at(time_s[k])),
                                                      T(command_at(time_s[k])), parameters));
          });
      if (!ok) return std::nullopt;
    }
  } catch (const RunError&) {
    return std::nullopt;
  }
  if (force.size() != n) return std::nullopt;
  // (with derivatives even at 0 kg: its tangent is the acceleration)
  if (!std::is_same_v<T, double> || values.moving_mass_kg != 0.0) {
    const std::vector<double> a = rig_acceleration_at_samples(time_s, x, velocity_m_per_s);
    for (std::size_t k = 0; k < n; ++k) force[k] += parameters.moving_mass_kg * a[k];
  }
  apply_force_sensor(time_s, parameters, force);
  return force;
}

}  // namespace ridefit::simulate
