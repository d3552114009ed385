// `ridefit simulate` for a half-car model file: every channel to CSV, ride figures to stdout.
#include <fmt/core.h>

#include <chrono>
#include <iostream>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/study/half_car_metrics.h"
#include "simulate_flags.h"

namespace ridefit::cli {
namespace {

io::CsvTable to_table(const simulate::HalfCarResponse& r) {
  using O = model::HalfCarOutputs;
  io::CsvTable table;
  table.add("time", "s", r.time_s);
  const std::vector<std::tuple<const char*, const char*, double O::*>> channels = {
      {"road_front", "m", &O::front_road_m},
      {"road_rear", "m", &O::rear_road_m},
      {"body_acc", "m/s^2", &O::body_acc_m_per_s2},
      {"pitch_acc", "rad/s^2", &O::pitch_acc_rad_per_s2},
      {"seat_acc", "m/s^2", &O::seat_acc_m_per_s2},
      {"lower_body_acc", "m/s^2", &O::lower_body_acc_m_per_s2},
      {"upper_body_acc", "m/s^2", &O::upper_body_acc_m_per_s2},
      {"front_wheel_acc", "m/s^2", &O::front_wheel_acc_m_per_s2},
      {"rear_wheel_acc", "m/s^2", &O::rear_wheel_acc_m_per_s2},
      {"front_travel", "m", &O::front_travel_m},
      {"rear_travel", "m", &O::rear_travel_m},
      {"front_tyre_force", "N", &O::front_tyre_force_N},
      {"rear_tyre_force", "N", &O::rear_tyre_force_N},
      {"front_damper_force", "N", &O::front_damper_force_N},
      {"rear_damper_force", "N", &O::rear_damper_force_N},
      {"front_friction_force", "N", &O::front_friction_force_N},
      {"rear_friction_force", "N", &O::rear_friction_force_N},
      {"front_damping", "Ns/m", &O::front_damping_Ns_per_m},
      {"rear_damping", "Ns/m", &O::rear_damping_Ns_per_m},
      {"front_stuck", "1", &O::front_stuck},
      {"rear_stuck", "1", &O::rear_stuck}};
  for (const auto& [name, unit, member] : channels) table.add(name, unit, r.channel(member));
  return table;
}

}  // namespace

void simulate_half_car(const SimulateFlags& flags) {
  io::RunOutputs({flags.model_file, flags.excitation_file}).add_file(flags.output_file, "-o");
  if (!flags.damper_state.empty()) {
    throw InputError(
        "--damper-state: a half car has a damper state per axle; use --set "
        "front.damper_state=stick_slip (and front.suspension=strut)");
  }
  const auto file = io::load_half_car(flags.model_file, parse_key_values(flags.overrides), "--set");
  const model::HalfCar car = file.make_model();
  const auto road = road::load_excitation(flags.excitation_file);
  check_output_rate(flags.output_rate_Hz,
                    flags.duration_s > 0.0 ? flags.duration_s : road->duration_s(), flags.solver);
  simulate::HalfCarSimulationOptions options;
  options.output_rate_Hz = flags.output_rate_Hz;
  options.duration_s = flags.duration_s;
  options.integrator = flags.solver.options();
  if (flags.rear_delay_s >= 0.0) options.rear_delay_s = flags.rear_delay_s;
  ProgressReporter progress("simulate",
                            options.duration_s > 0.0 ? options.duration_s : road->duration_s());
  options.integrator.progress = [&progress](double t) { progress(t); };
  const auto start = std::chrono::steady_clock::now();
  const auto response = simulate::simulate(car, *road, options);
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  const auto metrics = flags.output_rate_Hz >= 500.0
                           ? std::optional(study::half_car_metrics(response, file.parameters))
                           : std::nullopt;
  if (!flags.output_file.empty()) to_table(response).write(flags.output_file);
  if (flags.json) {
    nlohmann::json summary = {{"model", flags.model_file},
                              {"excitation", flags.excitation_file},
                              {"output", flags.output_file},
                              {"samples", response.time_s.size()},
                              {"rear_delay_s", response.rear_delay_s},
                              {"wall_time_s", elapsed_s},
                              {"solver", to_json(response.statistics)}};
    if (metrics) {
      for (const auto& [name, value] : metrics->named()) summary["metrics"][name] = value;
    }
    std::cout << summary.dump(2) << "\n";
    return;
  }
  std::cout << fmt::format("half car over {}: {} samples, {} steps ({}), rear delay {:.4g} s{}\n",
                           flags.excitation_file, response.time_s.size(), response.statistics.steps,
                           response.statistics.method, response.rear_delay_s,
                           flags.output_file.empty() ? "" : ", written to " + flags.output_file);
  if (metrics) {
    std::cout << fmt::format(
        "  Wk-weighted RMS: seat {:.4g}, lower body {:.4g}, upper body {:.4g} m/s^2; We pitch "
        "{:.4g} rad/s^2\n  travel RMS front {:.4g} m, rear {:.4g} m; dynamic tyre load RMS "
        "front {:.3f}, rear {:.3f} of static\n",
        metrics->seat_acc_wk_rms_m_per_s2, metrics->lower_body_acc_wk_rms_m_per_s2,
        metrics->upper_body_acc_wk_rms_m_per_s2, metrics->pitch_acc_we_rms_rad_per_s2,
        metrics->front_travel_rms_m, metrics->rear_travel_rms_m, metrics->front_dynamic_load_ratio,
        metrics->rear_dynamic_load_ratio);
  } else {
    std::cout << "  (ISO 2631 figures need --rate 500 or more)\n";
  }
}

}  // namespace ridefit::cli
