// ridefit friction-study MODEL.yaml EXCITATION.yaml... [--coulomb-forces LIST] [-o DIR]
// The seed's Section 3.2 study: the stick/slip quarter car at several Coulomb forces.
#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/output_paths.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/io/staged_folder.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/road/excitation_file.h"
#include "ridefit/simulate/solver_statistics_json.h"
#include "ridefit/study/friction_study.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct FrictionStudyFlags {
  std::string model_file;
  std::vector<std::string> excitation_files;
  std::vector<double> coulomb_forces_N = {0.0, 12.0, 30.0, 60.0, 120.0};
  std::string output_dir;
  bool force = false;
  std::vector<std::string> overrides;
  double output_rate_Hz = 1000.0;
  bool json = false;
  SolverFlags solver;
};

nlohmann::json optional_json(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json();
}

std::string force_label(double force_N) { return fmt::format("Fc{:g}N", force_N); }

void write_psds(const study::FrictionStudyResult& result, const std::filesystem::path& path) {
  io::CsvTable table;
  table.add("frequency", "Hz", result.frequency_Hz);
  for (const auto& c : result.cases) {
    table.add("body_acc_psd_" + force_label(c.coulomb_force_N), "(m/s^2)^2/Hz", c.body_psd);
  }
  for (const auto& c : result.cases) {
    table.add("wheel_acc_psd_" + force_label(c.coulomb_force_N), "(m/s^2)^2/Hz", c.wheel_psd);
  }
  table.write(path);
}

void run(const FrictionStudyFlags& flags) {
  const auto model_file =
      load_quarter_car_with_set(flags.model_file, flags.overrides, "stick_slip", "");
  std::set<std::string> labels;
  for (double f : flags.coulomb_forces_N) {
    if (!std::isfinite(f) || f < 0.0 || f > 1e5) {
      throw InputError(fmt::format(
          "--coulomb-forces: {} N; every force must be a finite number in [0, 1e5] N", f));
    }
    // Each force names its columns (body_acc_psd_Fc30N, ...): two alike would run twice and
    // collide.
    if (!labels.insert(force_label(f)).second) {
      throw InputError(fmt::format(
          "--coulomb-forces: {:g} N is given twice; give each force once (they name the PSD "
          "columns, e.g. body_acc_psd_{})",
          f, force_label(f)));
    }
  }
  for (const auto& [key, value] : parse_overrides(flags.overrides)) {
    if (key == model::quarter_car_rows::coulomb_force_N.key) {
      throw InputError("--set coulomb_force_N: the study sets Fc itself; use --coulomb-forces");
    }
  }
  // Every excitation is loaded and every output name checked before anything runs, so a
  // bad input never leaves part of the results behind.
  std::vector<std::unique_ptr<road::RoadInput>> roads;
  std::set<std::string> stems;
  std::vector<std::string> files;
  io::RunOutputs outputs({flags.model_file});
  for (const auto& excitation_file : flags.excitation_files) outputs.add_input(excitation_file);
  for (const auto& excitation_file : flags.excitation_files) {
    roads.push_back(road::load_excitation(excitation_file));
    check_output_rate(flags.output_rate_Hz, roads.back()->duration_s());
    const std::string stem = std::filesystem::path(excitation_file).stem().string();
    if (!stems.insert(stem).second) {
      throw InputError(
          fmt::format("{}: another excitation has the same name '{}', and both "
                      "would write {}_psd.csv; rename one",
                      excitation_file, stem, stem));
    }
    files.push_back(stem + "_psd.csv");
  }
  if (!flags.output_dir.empty()) {
    outputs.add_folder(flags.output_dir, "-o", files, flags.force, "--force");
    io::prepare_output_directory(flags.output_dir, "-o");
  }
  // Written into a staged copy of the folder, put in place as a whole once every case ran.
  std::optional<io::StagedFolder> staged;
  if (!flags.output_dir.empty()) staged.emplace(flags.output_dir, files);

  study::FrictionStudyOptions options;
  options.coulomb_forces_N = flags.coulomb_forces_N;
  options.simulation.output_rate_Hz = flags.output_rate_Hz;
  options.simulation.integrator = flags.solver.options();

  nlohmann::json summary = {{"model", flags.model_file}, {"excitations", nlohmann::json::array()}};
  const bool tty = isatty(fileno(stderr)) != 0;
  for (std::size_t e = 0; e < flags.excitation_files.size(); ++e) {
    const std::string& excitation_file = flags.excitation_files[e];
    const auto& road = roads[e];
    std::size_t done = 0;
    const auto result = study::run_friction_study(
        model_file.parameters, *road, options, [&](const study::FrictionCase& c) {
          // On a terminal the progress line rewrites itself; in a log, one line per case.
          std::cerr << fmt::format("{}{}: {}/{} cases (Fc = {:g} N done){}", tty ? "\r" : "",
                                   excitation_file, ++done, flags.coulomb_forces_N.size(),
                                   c.coulomb_force_N, tty ? "   " : "\n")
                    << std::flush;
        });
    if (tty) std::cerr << "\n";
    const std::string stem = std::filesystem::path(excitation_file).stem().string();
    std::string psd_file;
    if (!flags.output_dir.empty()) {
      psd_file = (std::filesystem::path(flags.output_dir) / (stem + "_psd.csv")).string();
      write_psds(result, (staged->path() / (stem + "_psd.csv")).string());
    }
    nlohmann::json cases = nlohmann::json::array();
    if (!flags.json) {
      std::cout << fmt::format("\n{} ({})\n", stem, excitation_file);
      std::cout << fmt::format("{:>7} {:>11} {:>12} {:>9} {:>9} {:>9} {:>12} {:>12} {:>8}\n",
                               "Fc[N]", "body_pk[Hz]", "wheel_pk[Hz]", "body_rms", "body_Wk",
                               "wheel_rms", "body_1.0-1.6", "body_2.8-4.2", "stuck[%]");
    }
    for (const auto& c : result.cases) {
      cases.push_back(
          {{model::quarter_car_rows::coulomb_force_N.key_string(), c.coulomb_force_N},
           {"body_peak_Hz", c.body_peak_Hz},
           {"wheel_peak_Hz", c.wheel_peak_Hz},
           {"body_acc_rms_m_per_s2", c.body_acc_rms_m_per_s2},
           {"wheel_acc_rms_m_per_s2", c.wheel_acc_rms_m_per_s2},
           {"body_acc_wk_rms_m_per_s2", optional_json(c.body_acc_wk_rms_m_per_s2)},
           {"body_acc_wk_vdv_m_per_s1_75", optional_json(c.body_acc_wk_vdv_m_per_s1_75)},
           {"body_slip_band_rms_m_per_s2", c.body_slip_band_rms_m_per_s2},
           {"body_stick_band_rms_m_per_s2", c.body_stick_band_rms_m_per_s2},
           {"stuck_share", c.stuck_share},
           {"solver", simulate::to_json(c.statistics)}});
      if (!flags.json) {
        std::cout << fmt::format(
            "{:>7g} {:>11.2f} {:>12.2f} {:>9.4f} {:>9} {:>9.4f} {:>12.4f} {:>12.4f} {:>8.1f}\n",
            c.coulomb_force_N, c.body_peak_Hz, c.wheel_peak_Hz, c.body_acc_rms_m_per_s2,
            c.body_acc_wk_rms_m_per_s2 ? fmt::format("{:.4f}", *c.body_acc_wk_rms_m_per_s2) : "-",
            c.wheel_acc_rms_m_per_s2, c.body_slip_band_rms_m_per_s2, c.body_stick_band_rms_m_per_s2,
            100.0 * c.stuck_share);
      }
    }
    if (!flags.json && !psd_file.empty()) std::cout << "PSDs: " << psd_file << "\n";
    summary["excitations"].push_back(
        {{"excitation", excitation_file}, {"psd_file", psd_file}, {"cases", cases}});
  }
  if (staged) staged->commit();
  if (!flags.json) {
    std::cout << "\nbody_pk: body-acceleration PSD peak in 0.5-6 Hz; wheel_pk: wheel PSD peak in "
                 "8-30 Hz;\nRMS in m/s^2; body_Wk: ISO 2631-1 Wk-weighted body RMS (needs --rate "
                 ">= 500 Hz); body_1.0-1.6 / "
                 "body_2.8-4.2: body RMS in the slip / "
                 "stick band; stuck: share "
                 "of time with |F_f| < 0.95 Fc.\n";
  }
  if (flags.json) std::cout << summary.dump(2) << "\n";
}

}  // namespace

void register_friction_study(CLI::App& app) {
  auto flags = std::make_shared<FrictionStudyFlags>();
  CLI::App* command = app.add_subcommand(
      "friction-study",
      "Seed 000 Section 3.2: the stick/slip quarter car at several Coulomb forces");
  command->add_option("model", flags->model_file, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("excitations", flags->excitation_files, "Excitation files (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--coulomb-forces", flags->coulomb_forces_N, "Coulomb forces [N]")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("-o,--output-dir", flags->output_dir,
                      "Directory for the PSD CSV files (one per excitation)");
  add_force_flag(*command, flags->force);
  command->add_option("--rate", flags->output_rate_Hz, "Output sample rate [Hz]")
      ->check(positive_number("Hz"))
      ->capture_default_str();
  command->add_option("--set", flags->overrides, "Override a model key (repeatable)");
  command->add_flag("--json", flags->json, "Print the results as JSON");
  flags->solver.add_to(*command);
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
