// A vehicle dataset of hidden_datasets.h.
#include <fmt/core.h>

#include <ostream>

#include <unistd.h>

#include "ridefit/io/atomic_file.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/synthetic/hidden_datasets.h"
#include "ridefit/synthetic/road_realisation.h"
#include "ridefit/synthetic/truth_file.h"

namespace ridefit::synthetic {

void write_vehicle_dataset(const HiddenDataset& d, const model::QuarterCar& car,
                           const std::filesystem::path& dir, const std::filesystem::path& out_dir,
                           long seed_offset, const RecordWritten& written) {
  YAML::Node truth = truth_header(d, dir);
  truth["excitation"] = std::filesystem::relative(d.excitation, dir).string();
  truth["sample_rate_Hz"] = d.sample_rate_Hz;
  truth["noise_fraction"] = d.sensor.noise_fraction;
  truth["high_pass_Hz"] = d.sensor.high_pass_Hz;
  truth["low_pass_Hz"] = d.sensor.low_pass_Hz > 0 ? d.sensor.low_pass_Hz : 0.4 * d.sample_rate_Hz;
  if (d.sensor.mount) {
    truth["mount"]["channel"] = d.mount_channel;
    truth["mount"]["frequency_Hz"] = d.sensor.mount->frequency_Hz;
    truth["mount"]["damping_ratio"] = d.sensor.mount->damping_ratio;
  }
  // The mount sits under one accelerometer; the other reads through the plain chain.
  study::SensorModel plain = d.sensor;
  plain.mount.reset();
  const study::SensorModel& body_sensor = d.mount_channel == "body_acc" ? d.sensor : plain;
  const study::SensorModel& wheel_sensor = d.mount_channel == "wheel_acc" ? d.sensor : plain;
  for (int k = 1; k <= d.records; ++k) {
    const auto road = load_road_realisation(
        d.excitation, k,
        out_dir / fmt::format(".road_{}.yaml.tmp{}", d.name, static_cast<long>(getpid())));
    simulate::SimulationOptions options;
    options.output_rate_Hz = d.sample_rate_Hz;
    options.duration_s = d.duration_s;
    // CVODE, not the ESDIRK that `diagnose` fits with (no inverse crime), at the tolerance the
    // shipped records were made with (bit for bit); its error is far below the sensor noise.
    options.integrator.method = simulate::Method::kCvodeBdf;
    options.integrator.relative_tolerance = 1e-6;
    const auto run = simulate::simulate(car, *road, options);
    std::mt19937_64 rng = record_generator(d, seed_offset, k);
    const auto body = study::measure(run.body_acc_m_per_s2, d.sample_rate_Hz, body_sensor, rng);
    const auto wheel = study::measure(run.wheel_acc_m_per_s2, d.sample_rate_Hz, wheel_sensor, rng);
    const std::string file = record_file_name(d, k);
    io::write_atomically(out_dir / file, [&](std::ostream& out) {
      out << "time[s],road[m],body_acc[m/s^2],wheel_acc[m/s^2]\n";
      for (std::size_t n = 0; n < run.time_s.size(); ++n) {
        out << fmt::format("{:.6g},{:.6g},{:.6g},{:.6g}\n", run.time_s[n], run.road_m[n], body[n],
                           wheel[n]);
      }
    });
    truth["records"].push_back(file);
    if (written) written(dir / file, run.time_s.back(), d.sample_rate_Hz);
  }
  write_truth_file(d, truth, out_dir);
}

}  // namespace ridefit::synthetic
