// ridefit simulate-rig MODEL.yaml TEST.yaml -o record.csv|.mat [--rig LIMITS.yaml] [--set k=v]
// A rig test (io/rig_test_file.h: sine, triangle or band-limited random) run on a model's strut
// (simulate/rig_test_run.h), written as the record a rig would give: a test can be tried on the
// model before it is run on the rig, and the record fitted or diagnosed like a measured one.
#include <fmt/core.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/io/model_kind.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/rig_test_file.h"
#include "ridefit/simulate/rig_test_run.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct SimulateRigFlags {
  std::string model_file;
  std::string test_file;
  std::string output_file;
  std::string rig_file;
  std::vector<std::string> overrides;
  double relative_tolerance = 1e-6;
  bool json = false;
};

// `--set NAME=VALUE` of the strut on the rig (fitting/strut_parameters.h names: the model's keys
// and the rig's own, such as force_offset_N or moving_mass_kg).
model::StrutTestParameters<double> with_set(const model::StrutTestParameters<double>& strut,
                                            const std::vector<std::string>& entries) {
  const std::map<std::string, double> values = parse_overrides(entries);
  for (const auto& [name, value] : values) {
    const std::string entry = fmt::format("--set {}={:g}", name, value);
    try {
      const fitting::StrutParameterInfo& info =
          fitting::kStrutParameters[fitting::strut_parameter_index(name)];
      if (value != 0.0 && (value < info.lower || value > info.upper)) {
        throw InputError(fmt::format("give 0 (off) or a value from {:g} to {:g} [{}]", info.lower,
                                     info.upper, info.row->unit));
      }
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", entry, e.what()));
    }
  }
  return fitting::with_strut_values(strut, values);
}

void run(const SimulateRigFlags& flags) {
  std::vector<std::filesystem::path> inputs = {flags.model_file, flags.test_file};
  if (!flags.rig_file.empty()) inputs.emplace_back(flags.rig_file);
  io::RunOutputs(inputs).add_file(flags.output_file, "-o");
  if (io::model_kind(flags.model_file) == "half_car") {
    throw InputError(fmt::format(
        "{}: a half car; simulate-rig puts one strut on the rig: give a quarter-car model",
        flags.model_file));
  }
  const road::RigLimits limits =
      flags.rig_file.empty() ? road::RigLimits{} : io::load_rig_limits(flags.rig_file);
  const io::RigTestFile test = io::load_rig_test(flags.test_file, limits);
  const auto strut = with_set(
      fitting::strut_on_rig(io::load_quarter_car(flags.model_file).make_model()), flags.overrides);
  simulate::StrutTestSolverOptions solver;
  solver.relative_tolerance = flags.relative_tolerance;
  simulate::RigTestRecord record;
  try {
    record = simulate::simulate_rig_test(strut, test.test, test.limits, solver);
  } catch (const InputError& e) {
    throw InputError(fmt::format("{}: {}", flags.test_file, e.what()));
  }

  if (!flags.output_file.empty()) {
    io::CsvTable table;
    table.add("time", "s", record.time_s);
    table.add("displacement", "m", record.displacement_m);
    table.add("velocity", "m/s", record.velocity_m_per_s);
    table.add("force", "N", record.force_N);
    io::write_measurement_table(table, flags.output_file);
  }
  if (flags.json) {
    nlohmann::json j = {{"test", flags.test_file},
                        {"waveform", road::waveform_name(test.test.waveform)},
                        {"samples", record.time_s.size()},
                        {"duration_s", test.test.duration_s},
                        {"peak_displacement_m", record.peak_displacement_m},
                        {"peak_velocity_m_per_s", record.peak_velocity_m_per_s},
                        {"highest_frequency_Hz", record.highest_frequency_Hz},
                        {"peak_force_N", record.peak_force_N},
                        {"peak_force_time_s", record.peak_time_s},
                        {"limits",
                         {{"stroke_m", test.limits.stroke_m},
                          {"velocity_m_per_s", test.limits.velocity_m_per_s},
                          {"force_N", test.limits.force_N},
                          {"frequency_Hz", test.limits.frequency_Hz}}},
                        {"output", flags.output_file}};
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << fmt::format(
      "{} test, {} samples over {:g} s: ±{:.3g} mm (rig ±{:.3g} mm), up to {:.3g} m/s (rig "
      "{:.3g} m/s), {:.3g} Hz (rig {:.3g} Hz), peak force {:.4g} N at {:.3g} s (rig {:.4g} kN)\n",
      road::waveform_name(test.test.waveform), record.time_s.size(), test.test.duration_s,
      1e3 * record.peak_displacement_m, 1e3 * test.limits.stroke_m, record.peak_velocity_m_per_s,
      test.limits.velocity_m_per_s, record.highest_frequency_Hz, test.limits.frequency_Hz,
      record.peak_force_N, record.peak_time_s, 1e-3 * test.limits.force_N);
  if (!flags.output_file.empty()) std::cout << "record written to " << flags.output_file << "\n";
}

}  // namespace

void register_simulate_rig(CLI::App& app) {
  auto flags = std::make_shared<SimulateRigFlags>();
  CLI::App* command = app.add_subcommand(
      "simulate-rig",
      "Run a rig test (sine, triangle or band-limited random) on a model's strut and write the "
      "record a rig would give (time, displacement, velocity, force)");
  command->add_option("model", flags->model_file, "Quarter-car model file (YAML): its strut")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("test", flags->test_file, "Rig test file (YAML with `waveform`)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("-o,--output", flags->output_file,
                      "Record: CSV, or MATLAB v5 if it ends in .mat (written atomically)");
  command
      ->add_option("--rig", flags->rig_file,
                   "The rig's limits (YAML: stroke_m, velocity_m_per_s, force_N, frequency_Hz; "
                   "default ±50 mm, 1.5 m/s, 20 kN, 30 Hz); a `rig:` block in the test file wins")
      ->check(CLI::ExistingFile);
  command->add_option("--set", flags->overrides,
                      "Set a strut parameter on the rig, e.g. --set force_offset_N=2.5 or --set "
                      "moving_mass_kg=3 (repeatable)");
  command->add_option("--rtol", flags->relative_tolerance, "The strut solver's relative tolerance")
      ->check(CLI::Range(1e-12, 1e-1))
      ->capture_default_str();
  command->add_flag("--json", flags->json, "Print a JSON summary");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
