#pragma once

#include <CLI/CLI.hpp>

namespace ridefit::cli {

// Each subcommand lives in its own file and registers itself here; its callback runs the
// command and throws InputError / RunError for main() to map to exit codes.
void register_modes(CLI::App& app);
void register_simulate(CLI::App& app);
void register_simulate_rig(CLI::App& app);
void register_friction_study(CLI::App& app);
void register_analyse(CLI::App& app);
void register_sweep(CLI::App& app);
void register_fit(CLI::App& app);
void register_generate_lab(CLI::App& app);
void register_optimise(CLI::App& app);
void register_diagnose(CLI::App& app);
void register_generate_hidden(CLI::App& app);
void register_road(CLI::App& app);
void register_batch(CLI::App& app);

inline void register_subcommands(CLI::App& app) {
  register_modes(app);
  register_simulate(app);
  register_simulate_rig(app);
  register_friction_study(app);
  register_analyse(app);
  register_sweep(app);
  register_fit(app);
  register_generate_lab(app);
  register_optimise(app);
  register_diagnose(app);
  register_generate_hidden(app);
  register_road(app);
  register_batch(app);
}

}  // namespace ridefit::cli
