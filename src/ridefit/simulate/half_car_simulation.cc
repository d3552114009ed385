#include "ridefit/simulate/half_car_simulation.h"

#include "ridefit/simulate/half_car_system.h"

namespace ridefit::simulate {

std::vector<double> HalfCarResponse::channel(double model::HalfCarOutputs::*member) const {
  std::vector<double> values;
  values.reserve(samples.size());
  for (const auto& s : samples) values.push_back(s.*member);
  return values;
}

HalfCarResponse simulate(const model::HalfCar& car, const road::RoadInput& road,
                         const HalfCarSimulationOptions& options) {
  const std::vector<double> times = output_times(options, road.duration_s());
  const AxleRoadInput roads(road, rear_delay_s(road, car.parameters().wheelbase_m(),
                                               options.rear_delay_s, options.rear_delay_name));
  const HalfCarSystem system(car, roads);
  const std::vector<double> x0(static_cast<std::size_t>(car.state_size()), 0.0);
  const Trajectory trajectory = integrate(system, x0, times, options.integrator);
  HalfCarResponse response;
  response.time_s = times;
  response.rear_delay_s = roads.rear_delay_s();
  response.statistics = trajectory.statistics;
  response.samples.reserve(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    response.samples.push_back(car.outputs(trajectory.state_at(k), roads.at(times[k])));
  }
  return response;
}

}  // namespace ridefit::simulate
