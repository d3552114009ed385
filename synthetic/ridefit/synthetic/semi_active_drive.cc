#include "ridefit/synthetic/semi_active_drive.h"

#include <fmt/core.h>

#include <ostream>

#include "ridefit/io/atomic_file.h"
#include "ridefit/model/quarter_car.h"
#include "ridefit/road/commanded_road.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/synthetic/gaussian_noise.h"
#include "ridefit/synthetic/lab_truth.h"
#include "ridefit/synthetic/switching_command.h"

namespace ridefit::synthetic {

void write_semi_active_drive(const std::filesystem::path& path, std::mt19937_64& rng) {
  constexpr double kDuration_s = 120.0, kRate_Hz = 200.0;
  road::Iso8608RoadParameters r;
  r.road_class = road::Iso8608Class::kB;
  r.random.speed_m_per_s = 50.0 / 3.6;
  r.random.duration_s = kDuration_s;
  r.random.seed = static_cast<unsigned>(rng() % 100000);
  const auto iso_road = road::make_iso8608_road(r);
  const SwitchingCommand current(kDuration_s, 2.0, rng);
  const road::CommandedRoad road(
      iso_road, [&](double t) { return current(t); }, "A");
  simulate::SimulationOptions options;
  options.output_rate_Hz = kRate_Hz;
  options.integrator.method = simulate::Method::kCvodeBdf;
  options.integrator.relative_tolerance = 1e-10;
  const model::QuarterCar car(model::DamperState::kSlip, lab_mr_car(),
                              model::DamperCommand::kFromRoad);
  const auto run = simulate::simulate(car, road, options);
  // One draw for both channels, body and wheel alternating sample by sample.
  const auto unit = gaussian_noise(2 * run.time_s.size(), 1.0, rng);
  const double body_noise = 0.01 * signal::rms(run.body_acc_m_per_s2);
  const double wheel_noise = 0.01 * signal::rms(run.wheel_acc_m_per_s2);
  io::write_atomically(path, [&](std::ostream& out) {
    out << "time[s],road[mm],body_acc[m/s^2],wheel_acc[m/s^2],current[A]\n";
    for (std::size_t k = 0; k < run.time_s.size(); ++k) {
      const double body = run.body_acc_m_per_s2[k] + body_noise * unit[2 * k];
      const double wheel = run.wheel_acc_m_per_s2[k] + wheel_noise * unit[2 * k + 1];
      out << fmt::format("{:.3f},{:.5f},{:.6f},{:.5f},{:.5f}\n", run.time_s[k], 1e3 * run.road_m[k],
                         body, wheel, current(run.time_s[k]));
    }
  });
}

}  // namespace ridefit::synthetic
