#pragma once

#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "ridefit/fitting/psd_fit.h"
#include "ridefit/road/commanded_road.h"
#include "ridefit/road/iso8608.h"
#include "ridefit/road/measured_road.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/study/sensor_model.h"

namespace ridefit::testing {

// A "measurement" of `truth` on an ISO 8608 road at 50 km/h (CVODE), its accelerations through
// the sensor model (study/sensor_model.h: 0.1 Hz high-pass, 0.4·fs low-pass, seeded Gaussian
// noise of `noise` times each channel's RMS): what the diagnosis tests feed their baselines.
// Each seed is another road realisation and other noise. With a `command` (a controlled
// damper's current in A over time), the truth follows it (DamperCommand::kFromRoad) and the
// record carries it sampled like the other channels.
inline fitting::PsdMeasurement hidden_effect_record(
    const model::QuarterCar& truth, road::Iso8608Class road_class, unsigned seed,
    double duration_s = 20.0, double sample_rate_Hz = 200.0, double noise = 0.005,
    const std::function<double(double)>& command = {}) {
  road::Iso8608RoadParameters r;
  r.road_class = road_class;
  r.random.speed_m_per_s = 50.0 / 3.6;
  r.random.duration_s = duration_s;
  r.random.seed = seed;
  const auto iso_road = road::make_iso8608_road(r);
  const road::CommandedRoad commanded_road(iso_road, command, "A");
  const road::RoadInput& road =
      command ? static_cast<const road::RoadInput&>(commanded_road) : iso_road;
  simulate::SimulationOptions options;
  options.output_rate_Hz = sample_rate_Hz;
  // CVODE, not the ESDIRK that the fits and the diagnosis run (no inverse crime).
  options.integrator.method = simulate::Method::kCvodeBdf;
  options.integrator.relative_tolerance = 1e-8;
  const auto run = simulate::simulate(truth.with_command_from_road(bool(command)), road, options);
  fitting::PsdMeasurement m;
  m.source = "record " + std::to_string(seed);
  m.time_s = run.time_s;
  m.sample_rate_Hz = sample_rate_Hz;
  if (command) {
    std::vector<double> u;
    for (double t : run.time_s) u.push_back(command(t));
    m.road = std::make_shared<road::MeasuredRoad>(run.time_s, run.road_m, u, "A");
  } else {
    m.road = std::make_shared<road::MeasuredRoad>(run.time_s, run.road_m);
  }
  std::mt19937_64 rng(1000 + seed);
  study::SensorModel sensor;
  sensor.noise_fraction = noise;
  m.body_acc_m_per_s2 = study::measure(run.body_acc_m_per_s2, sample_rate_Hz, sensor, rng);
  m.wheel_acc_m_per_s2 = study::measure(run.wheel_acc_m_per_s2, sample_rate_Hz, sensor, rng);
  return m;
}

// The record as a vehicle CSV a user would hand to `ridefit diagnose` or `fit psd` (time, road
// elevation, both accelerations), printed to 10 significant digits.
inline void write_vehicle_record(const std::filesystem::path& csv_file,
                                 const fitting::PsdMeasurement& m) {
  std::ofstream out(csv_file);
  out << "time[s],road[m],body_acc[m/s^2],wheel_acc[m/s^2]\n";
  out.precision(10);
  for (std::size_t k = 0; k < m.time_s.size(); ++k) {
    out << m.time_s[k] << ',' << m.road->at(m.time_s[k]).elevation_m << ','
        << m.body_acc_m_per_s2[k] << ',' << m.wheel_acc_m_per_s2[k] << '\n';
  }
}

}  // namespace ridefit::testing
