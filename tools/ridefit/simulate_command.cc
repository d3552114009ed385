// ridefit simulate MODEL.yaml EXCITATION.yaml -o out.csv|out.mat [--json]
// One subcommand for both models: the model file's kind picks the quarter car or the half car;
// the tables and summaries of each are in the library (study/response_table,
// study/simulation_summary).
#include <fmt/core.h>

#include <chrono>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/io/model_kind.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/simulate/half_car_simulation.h"
#include "ridefit/simulate/quarter_car_simulation.h"
#include "ridefit/study/damper_command_note.h"
#include "ridefit/study/half_car_metrics.h"
#include "ridefit/study/response_table.h"
#include "ridefit/study/simulation_summary.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct SimulateFlags {
  std::string model_file;
  std::string excitation_file;
  std::string output_file;
  std::string damper_state;
  std::vector<std::string> overrides;
  double output_rate_Hz = 1000.0;
  double duration_s = 0.0;
  bool json = false;
  double rear_delay_s = -1.0;  // half car on a road given over time; < 0 = not given
  SolverFlags solver;
};

// The run's options from the flags, checked against the road's duration.
template <typename Options>
Options options_from(const SimulateFlags& flags, const road::RoadInput& road) {
  check_output_rate(flags.output_rate_Hz,
                    flags.duration_s > 0.0 ? flags.duration_s : road.duration_s());
  Options options;
  options.output_rate_Hz = flags.output_rate_Hz;
  options.duration_s = flags.duration_s;
  options.integrator = flags.solver.options();
  return options;
}

// Runs the car with progress on stderr (for runs longer than a second); the response and the
// wall time it took.
template <typename Car, typename Options>
auto timed_simulation(const Car& car, const road::RoadInput& road, Options options) {
  ProgressReporter progress("simulate",
                            options.duration_s > 0.0 ? options.duration_s : road.duration_s());
  options.integrator.progress = [&progress](double t) { progress(t); };
  const auto start = std::chrono::steady_clock::now();
  auto response = simulate::simulate(car, road, options);
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  progress.finish();
  return std::make_pair(std::move(response), elapsed_s);
}

// No output may replace an input.
void check_outputs(const SimulateFlags& flags) {
  io::RunOutputs({flags.model_file, flags.excitation_file}).add_file(flags.output_file, "-o");
}

study::SimulationRun run_of(const SimulateFlags& flags, double wall_time_s) {
  return {flags.model_file, flags.excitation_file, flags.output_file, flags.output_rate_Hz,
          wall_time_s};
}

void simulate_quarter_car(const SimulateFlags& flags) {
  if (flags.rear_delay_s >= 0.0) {
    throw InputError("--rear-delay: a quarter car has one wheel; the flag is for half cars");
  }
  check_outputs(flags);
  const auto file = load_quarter_car_with_set(flags.model_file, flags.overrides, flags.damper_state,
                                              "--damper-state");
  const auto road = road::load_excitation(flags.excitation_file);
  const model::QuarterCar car = file.make_model().with_command_from_road(road->has_command());
  if (const auto note =
          study::damper_command_note(car, *road, flags.model_file, flags.excitation_file)) {
    std::cerr << "note: " << *note << "\n";
  }
  const auto options = options_from<simulate::SimulationOptions>(flags, *road);
  const auto [response, wall_time_s] = timed_simulation(car, *road, options);
  if (!flags.output_file.empty()) {
    io::write_measurement_table(study::response_table(response, road->command_unit()),
                                flags.output_file);
  }
  const study::SimulationRun run = run_of(flags, wall_time_s);
  if (flags.json) {
    std::cout << study::summary_json(run, car, response).dump(2) << "\n";
  } else {
    std::cout << study::summary_text(run, car, response);
  }
}

void simulate_half_car(const SimulateFlags& flags) {
  check_outputs(flags);
  if (!flags.damper_state.empty()) {
    throw InputError(
        "--damper-state: a half car has a damper state per axle; use --set "
        "front.damper_state=stick_slip (and front.suspension=strut)");
  }
  const auto file = io::load_half_car(flags.model_file, half_car_set(flags.overrides));
  const model::HalfCar car = file.make_model();
  const auto road = road::load_excitation(flags.excitation_file);
  auto options = options_from<simulate::HalfCarSimulationOptions>(flags, *road);
  if (flags.rear_delay_s >= 0.0) options.rear_delay_s = flags.rear_delay_s;
  options.rear_delay_name = "--rear-delay S";
  const auto [response, wall_time_s] = timed_simulation(car, *road, options);
  // The ISO 2631-1 weightings need 500 Hz (Wk); a slower run reports what it can.
  const auto metrics = flags.output_rate_Hz >= 500.0
                           ? std::optional(study::half_car_metrics(response, file.parameters))
                           : std::nullopt;
  if (!flags.output_file.empty()) {
    io::write_measurement_table(study::response_table(response), flags.output_file);
  }
  const study::SimulationRun run = run_of(flags, wall_time_s);
  if (flags.json) {
    std::cout << study::summary_json(run, response, metrics).dump(2) << "\n";
    return;
  }
  std::cout << study::summary_text(run, response, metrics);
  if (!metrics) std::cout << "  (ISO 2631 figures need --rate 500 or more)\n";
}

void run(const SimulateFlags& flags) {
  if (io::model_kind(flags.model_file) == "half_car") {
    simulate_half_car(flags);
  } else {
    simulate_quarter_car(flags);
  }
}

}  // namespace

void register_simulate(CLI::App& app) {
  auto flags = std::make_shared<SimulateFlags>();
  CLI::App* command = app.add_subcommand(
      "simulate",
      "Simulate a quarter car over an excitation and write every channel to CSV or .mat");
  command->add_option("model", flags->model_file, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("excitation", flags->excitation_file, "Excitation file (YAML with `type`)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", flags->output_file,
                      "Output file: CSV, or MATLAB v5 if it ends in .mat (written atomically)");
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
