#include "ridefit/fitting/diagnose/damper_speed.h"

#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/simulate/quarter_car_simulation.h"

namespace ridefit::fitting::diagnose {
namespace {

// Σv² and the count of central-difference speeds of x over t.
void add_central_speeds(const std::vector<double>& t, const std::vector<double>& x, double& squares,
                        std::size_t& count) {
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const double v = (x[k + 1] - x[k - 1]) / (t[k + 1] - t[k - 1]);
    squares += v * v;
    ++count;
  }
}

}  // namespace

double damper_speed_rms_m_per_s(const std::vector<HysteresisRecord>& records) {
  double squares = 0.0;
  std::size_t count = 0;
  for (const auto& r : records) {
    if (!r.velocity_m_per_s.empty()) {
      for (double v : r.velocity_m_per_s) squares += v * v;
      count += r.velocity_m_per_s.size();
    } else {
      add_central_speeds(r.time_s, r.displacement_m, squares, count);
    }
  }
  return count == 0 ? 0.0 : std::sqrt(squares / static_cast<double>(count));
}

double damper_speed_rms_m_per_s(const model::QuarterCar& car, const PsdMeasurement& record) {
  if (record.road == nullptr || record.time_s.size() < 3 || !(record.sample_rate_Hz > 0.0)) {
    return 0.0;
  }
  simulate::SimulationOptions options;
  options.output_rate_Hz = record.sample_rate_Hz;
  options.duration_s = std::min(record.time_s.back(), record.road->duration_s());
  try {
    const simulate::QuarterCarResponse run = simulate::simulate(car, *record.road, options);
    double squares = 0.0;
    std::size_t count = 0;
    add_central_speeds(run.time_s, run.travel_m, squares, count);
    return count == 0 ? 0.0 : std::sqrt(squares / static_cast<double>(count));
  } catch (const RunError&) {
    return 0.0;
  } catch (const InputError&) {
    return 0.0;
  }
}

}  // namespace ridefit::fitting::diagnose
