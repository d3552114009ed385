#include "ridefit/simulate/quarter_car_simulation.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/io/input_error.h"
#include "ridefit/simulate/quarter_car_system.h"

namespace ridefit::simulate {

QuarterCarResponse simulate(const model::QuarterCar& car, const road::RoadInput& road,
                            const SimulationOptions& options) {
  if (!(options.output_rate_Hz > 0.0) || !std::isfinite(options.output_rate_Hz)) {
    throw InputError(
        fmt::format("output rate {} Hz: expected a finite rate > 0", options.output_rate_Hz));
  }
  if (!(options.duration_s >= 0.0) || !std::isfinite(options.duration_s)) {
    throw InputError(
        fmt::format("duration {} s: expected a finite duration > 0 (or 0 for the "
                    "excitation's own)",
                    options.duration_s));
  }
  if (options.duration_s > road.duration_s() * (1.0 + 1e-12)) {
    throw InputError(fmt::format(
        "duration {} s is longer than the excitation ({} s); the road is not defined beyond it",
        options.duration_s, road.duration_s()));
  }
  const double duration = options.duration_s > 0.0 ? options.duration_s : road.duration_s();
  if (!(duration > 0.0)) throw InputError("simulation duration must be > 0 s");
  const double sample_count = std::floor(duration * options.output_rate_Hz) + 1.0;
  if (sample_count > kMaxOutputSamples) {
    throw InputError(fmt::format(
        "{} s at {} Hz is {:.3g} output samples, more than the {:g} this tool keeps in memory; "
        "lower the output rate or the duration",
        duration, options.output_rate_Hz, sample_count, kMaxOutputSamples));
  }
  const auto samples = static_cast<std::size_t>(sample_count);
  std::vector<double> times(samples);
  for (std::size_t k = 0; k < samples; ++k) {
    times[k] = static_cast<double>(k) / options.output_rate_Hz;
  }

  const QuarterCarSystem system(car, road);
  const std::vector<double> x0(static_cast<std::size_t>(car.state_size()), 0.0);
  const Trajectory trajectory = integrate(system, x0, times, options.integrator);

  QuarterCarResponse response;
  response.statistics = trajectory.statistics;
  response.time_s = times;
  auto reserve = [samples](std::vector<double>& v) { v.reserve(samples); };
  for (auto* channel :
       {&response.road_m, &response.body_acc_m_per_s2, &response.wheel_acc_m_per_s2,
        &response.travel_m, &response.tyre_force_N, &response.damper_force_N,
        &response.friction_force_N, &response.top_mount_deflection_m, &response.stuck}) {
    reserve(*channel);
  }
  for (std::size_t k = 0; k < samples; ++k) {
    const model::QuarterCarOutputs out = car.outputs(trajectory.state_at(k), road.at(times[k]));
    response.road_m.push_back(out.road_m);
    response.body_acc_m_per_s2.push_back(out.body_acc_m_per_s2);
    response.wheel_acc_m_per_s2.push_back(out.wheel_acc_m_per_s2);
    response.travel_m.push_back(out.travel_m);
    response.tyre_force_N.push_back(out.tyre_force_N);
    response.damper_force_N.push_back(out.damper_force_N);
    response.friction_force_N.push_back(out.friction_force_N);
    response.top_mount_deflection_m.push_back(out.top_mount_deflection_m);
    response.stuck.push_back(out.stuck);
  }
  return response;
}

}  // namespace ridefit::simulate
