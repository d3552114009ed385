#include "ridefit/simulate/strut_test_reference.h"

#include "ridefit/simulate/integrator.h"
#include "ridefit/simulate/strut_test_system.h"

namespace ridefit::simulate {

std::vector<double> reference_strut_test_force(
    std::span<const double> time_s, const std::function<double(double)>& displacement_m,
    const model::StrutTestParameters<double>& parameters) {
  std::vector<double> force;
  if (time_s.empty()) return force;
  const RigDisplacement x(displacement_m);
  const StrutTestSystem system(parameters, x);
  IntegratorOptions options;
  options.method = Method::kCvodeBdf;
  options.relative_tolerance = 1e-10;
  options.max_steps_per_s = 1e7;
  const std::vector<double> times(time_s.begin(), time_s.end());
  const Trajectory trajectory =
      integrate(system, {displacement_m(times.front()), 0.0}, times, options);
  force.reserve(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    force.push_back(
        model::StrutTest::force_N(trajectory.state_at(k), displacement_m(times[k]), parameters));
  }
  return force;
}

}  // namespace ridefit::simulate
