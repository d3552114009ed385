#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/road/road_input.h"
#include "ridefit/simulate/esdirk_integrator.h"
#include "ridefit/simulate/esdirk_tangents.h"
#include "ridefit/simulate/quarter_car_system.h"

namespace ridefit::simulate {

// The quarter car's body and wheel acceleration at given output times, templated on the scalar
// so that Ceres' Jets carry their derivatives with respect to the model's parameters (the PSD
// fit, the diagnosis of vehicle spectra).
//
// The car runs on ridefit's adaptive ESDIRK (esdirk_integrator.h) over QuarterCarSystem, the
// same run as `simulate`: the accelerations are the model's to the tolerance, not a fixed-step
// scheme's (SDIRK2 at 1 ms steps shifted the wheel-hop mode enough to fit the top
// mount's transition deflection 18 % low: 0.41 mm for 0.5). With T a Jet, the run in doubles
// records its steps and replay_esdirk (esdirk_tangents.h) carries the derivatives through exactly
// those steps: the derivative of what was computed, the step sequence frozen. Starts at rest at
// static equilibrium (every state 0). Accelerations are the model's f(t, y) at the interpolated
// state.
//
// Returns no value when the integrator gives up (RunError: Newton failing, a step below its
// floor, more than max_steps_per_s steps per simulated second).
template <typename T>
struct AccelerationSeries {
  std::vector<T> body;   // body acceleration [m/s²] at each output time
  std::vector<T> wheel;  // wheel acceleration
};

struct AccelerationSolverOptions {
  // The integrator's relative tolerance (IntegratorOptions). A log-PSD compared over 10 s Welch
  // segments scatters by ±30 % per bin; at 1e-4 the stick/slip corner's acceleration RMS over
  // 60 s of class A road is within 0.02 % of CVODE at 1e-10 (body 0.005 %, wheel 0.018 %), far
  // inside it.
  double relative_tolerance = 1e-4;
  // A parameter set that makes the car this stiff is given up (no value) rather than followed
  // for minutes: ordinary cars on roads take 500–5 000 steps per second at 1e-4.
  double max_steps_per_s = 50'000;
  // Run on these steps (another run's history, quarter_car_steps) instead of choosing them:
  // the discrete map with its step sequence frozen, for checking tangents by finite differences.
  const EsdirkStepHistory* frozen_steps = nullptr;
};

// The steps the adaptive run takes for this car and road (to freeze them, frozen_steps).
inline EsdirkStepHistory quarter_car_steps(const model::QuarterCar& car,
                                           const road::RoadInput& road,
                                           std::span<const double> output_times_s,
                                           const AccelerationSolverOptions& options = {}) {
  EsdirkStepHistory history;
  integrate_esdirk(QuarterCarSystem(car, road),
                   std::vector<double>(static_cast<std::size_t>(car.state_size()), 0.0),
                   std::vector<double>(output_times_s.begin(), output_times_s.end()),
                   esdirk_options(options), &history);
  return history;
}

// `parameters` holds car.parameters()'s numbers as T (for T = double pass car.parameters()).
template <typename T>
std::optional<AccelerationSeries<T>> quarter_car_accelerations(
    const model::QuarterCar& car, const model::QuarterCarParameters<T>& parameters,
    const road::RoadInput& road, std::span<const double> output_times_s,
    const AccelerationSolverOptions& options = {}) {
  AccelerationSeries<T> out;
  if (output_times_s.empty()) return out;
  const int n = car.state_size();
  const auto un = static_cast<std::size_t>(n);
  const QuarterCarSystem system(car, road);
  const IntegratorOptions integrator = esdirk_options(options);
  const std::vector<double> times(output_times_s.begin(), output_times_s.end());
  const std::vector<double> y0(un, 0.0);
  out.body.reserve(times.size());
  out.wheel.reserve(times.size());
  try {
    if constexpr (std::is_same_v<T, double>) {
      const Trajectory trajectory =
          integrate_esdirk_or_frozen(system, y0, times, integrator, options.frozen_steps);
      double rate[model::QuarterCar::kMaxStates];
      for (std::size_t k = 0; k < times.size(); ++k) {
        car.derivatives(trajectory.state_at(k), road.at(times[k]), rate);
        out.body.push_back(rate[2]);
        out.wheel.push_back(rate[3]);
      }
    } else {
      EsdirkStepHistory own_history;
      const EsdirkStepHistory& history =
          esdirk_steps_or_frozen(system, y0, times, integrator, options.frozen_steps, own_history);
      // The replay asks for the road at each stage time once per evaluation in T.
      double cached_time = -1e300;
      road::RoadSample cached_road;
      auto road_at = [&](double t) {
        if (t != cached_time) {
          cached_road = road.at(t);
          cached_time = t;
        }
        return cached_road;
      };
      T rate[model::QuarterCar::kMaxStates];
      auto record = [&](double t, const T* y) {
        car.derivatives(y, road_at(t), parameters, rate);
        out.body.push_back(rate[2]);
        out.wheel.push_back(rate[3]);
      };
      const std::vector<T> y0_t(un, T(0.0));
      record(times[0], y0_t.data());
      const bool ok = replay_esdirk<T, model::QuarterCar::kMaxStates>(
          history, system, std::span<const T>(y0_t), output_times_s,
          [&](double t, const T* y, T* ydot) { car.derivatives(y, road_at(t), parameters, ydot); },
          [&](std::size_t, double t, const T* y) { record(t, y); });
      if (!ok) return std::nullopt;
    }
  } catch (const RunError&) {
    return std::nullopt;
  }
  if (out.body.size() != times.size()) return std::nullopt;
  return out;
}

}  // namespace ridefit::simulate
