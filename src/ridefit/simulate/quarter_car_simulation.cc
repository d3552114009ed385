#include "ridefit/simulate/quarter_car_simulation.h"

#include "ridefit/simulate/quarter_car_system.h"

namespace ridefit::simulate {

QuarterCarResponse simulate(const model::QuarterCar& car, const road::RoadInput& road,
                            const SimulationOptions& options) {
  const std::vector<double> times = output_times(options, road.duration_s());
  const std::size_t samples = times.size();

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
    if (car.follows_command()) response.damper_command.push_back(out.damper_command);
  }
  return response;
}

}  // namespace ridefit::simulate
