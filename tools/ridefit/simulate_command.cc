// ridefit simulate MODEL.yaml EXCITATION.yaml -o out.csv [--json]
#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/model_kind.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/signal/statistics.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "simulate_flags.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

io::CsvTable to_table(const simulate::QuarterCarResponse& r, const std::string& command_unit) {
  io::CsvTable table;
  table.add("time", "s", r.time_s);
  table.add("road", "m", r.road_m);
  table.add("body_acc", "m/s^2", r.body_acc_m_per_s2);
  table.add("wheel_acc", "m/s^2", r.wheel_acc_m_per_s2);
  table.add("travel", "m", r.travel_m);
  table.add("tyre_force", "N", r.tyre_force_N);
  table.add("damper_force", "N", r.damper_force_N);
  table.add("friction_force", "N", r.friction_force_N);
  table.add("top_mount_deflection", "m", r.top_mount_deflection_m);
  table.add("stuck", "1", r.stuck);
  if (!r.damper_command.empty()) table.add("damper_command", command_unit, r.damper_command);
  return table;
}

void run(const SimulateFlags& flags) {
  if (io::model_kind(flags.model_file) == "half_car") {
    simulate_half_car(flags);
    return;
  }
  if (flags.rear_delay_s >= 0.0) {
    throw InputError("--rear-delay: a quarter car has one wheel; the flag is for half cars");
  }
  io::RunOutputs({flags.model_file, flags.excitation_file}).add_file(flags.output_file, "-o");
  const auto model_file = load_quarter_car_with_set(flags.model_file, flags.overrides,
                                                    flags.damper_state, "--damper-state");
  const auto road = road::load_excitation(flags.excitation_file);
  // A controlled damper follows the record's command (a current or voltage column of a measured
  // excitation); say when one of the two is there without the other.
  const model::QuarterCar car = model_file.make_model().with_command_from_road(road->has_command());
  if (road->has_command() && !car.follows_command()) {
    std::cerr << fmt::format(
        "note: {} carries a damper command ({}), but {} has no damping_per_command_Ns_per_m or "
        "coulomb_force_per_command_N: the damper stays passive\n",
        flags.excitation_file, road->command_unit(), flags.model_file);
  } else if (!road->has_command() && model_file.parameters.commanded()) {
    std::cerr << fmt::format(
        "note: {} describes a controlled damper, but {} carries no command (a current or voltage "
        "column of a measured excitation): the damper runs at command 0\n",
        flags.model_file, flags.excitation_file);
  }

  check_output_rate(flags.output_rate_Hz,
                    flags.duration_s > 0.0 ? flags.duration_s : road->duration_s(), flags.solver);
  simulate::SimulationOptions options;
  options.output_rate_Hz = flags.output_rate_Hz;
  options.duration_s = flags.duration_s;
  options.integrator = flags.solver.options();
  ProgressReporter progress("simulate",
                            options.duration_s > 0.0 ? options.duration_s : road->duration_s());
  options.integrator.progress = [&progress](double t) { progress(t); };
  const auto start = std::chrono::steady_clock::now();
  const auto response = simulate::simulate(car, *road, options);
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();

  if (!flags.output_file.empty()) {
    to_table(response, road->command_unit()).write(flags.output_file);
  }

  double stuck_share = 0.0;
  for (double s : response.stuck) stuck_share += s;
  stuck_share /= static_cast<double>(response.stuck.size());
  double travel_peak = 0.0;
  for (double t : response.travel_m) travel_peak = std::max(travel_peak, std::abs(t));

  if (flags.json) {
    nlohmann::json summary = {{"model", flags.model_file},
                              {"excitation", flags.excitation_file},
                              {"damper_state", model::to_string(car.damper_state())},
                              {"output", flags.output_file},
                              {"duration_s", response.time_s.back()},
                              {"samples", response.time_s.size()},
                              {"output_rate_Hz", flags.output_rate_Hz},
                              {"wall_time_s", elapsed_s},
                              {"solver", to_json(response.statistics)},
                              {"rms",
                               {{"body_acc_m_per_s2", signal::rms(response.body_acc_m_per_s2)},
                                {"wheel_acc_m_per_s2", signal::rms(response.wheel_acc_m_per_s2)},
                                {"travel_m", signal::rms(response.travel_m)},
                                {"tyre_force_N", signal::rms(response.tyre_force_N)},
                                {"friction_force_N", signal::rms(response.friction_force_N)}}},
                              {"travel_peak_m", travel_peak},
                              {"stuck_share", stuck_share}};
    std::cout << summary.dump(2) << "\n";
  } else {
    std::cout << fmt::format(
        "{} over {}: {} samples, {} steps ({}), body_acc RMS {:.4g} m/s^2, wheel_acc RMS "
        "{:.4g} m/s^2, stuck {:.1f} % of the time{}\n",
        model::to_string(car.damper_state()), flags.excitation_file, response.time_s.size(),
        response.statistics.steps, response.statistics.method,
        signal::rms(response.body_acc_m_per_s2), signal::rms(response.wheel_acc_m_per_s2),
        100.0 * stuck_share, flags.output_file.empty() ? "" : ", written to " + flags.output_file);
  }
}

}  // namespace

void register_simulate(CLI::App& app) {
  auto flags = std::make_shared<SimulateFlags>();
  CLI::App* command = app.add_subcommand(
      "simulate", "Simulate a quarter car over an excitation and write every channel to CSV");
  command->add_option("model", flags->model_file, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("excitation", flags->excitation_file, "Excitation file (YAML with `type`)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", flags->output_file, "Output CSV (written atomically)");
  command->add_option("--rate", flags->output_rate_Hz, "Output sample rate [Hz]")
      ->check(positive_number("Hz"))
      ->capture_default_str();
  command
      ->add_option("--duration", flags->duration_s,
                   "Simulated time [s] (default: the excitation's duration)")
      ->check(positive_number("s"));
  command
      ->add_option("--damper-state", flags->damper_state,
                   "Override the model's damper_state: slip, stick or stick_slip")
      ->check(CLI::IsMember({"slip", "stick", "stick_slip"}));
  command->add_option("--set", flags->overrides,
                      "Override a model key, e.g. --set coulomb_force_N=30 (repeatable)");
  command->add_flag("--json", flags->json, "Print a JSON summary (solver statistics, RMS values)");
  command
      ->add_option("--rear-delay", flags->rear_delay_s,
                   "Half car on an excitation given over time: the rear wheel's delay [s] (0 for a "
                   "rig shaking both axles together)")
      ->check(CLI::Range(0.0, 100.0));
  flags->solver.add_to(*command);
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
