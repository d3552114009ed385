// ridefit modes MODEL.yaml [--state slip|stick] [--json]
#include <fmt/core.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command_options.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/simulate/quarter_car_modes.h"
#include "subcommands.h"

namespace ridefit::cli {
namespace {

struct ModesFlags {
  std::string model_file;
  std::string state;  // "" = both
  std::vector<std::string> overrides;
  bool json = false;
};

void run(const ModesFlags& flags) {
  const std::vector<std::string> states = flags.state.empty()
                                              ? std::vector<std::string>{"slip", "stick"}
                                              : std::vector<std::string>{flags.state};
  nlohmann::json summary = {{"model", flags.model_file}, {"states", nlohmann::json::object()}};
  // Every state's model is read and solved before anything is printed: bad input prints nothing.
  std::vector<simulate::ModalAnalysis> all_modes;
  for (const auto& state : states) {
    const auto file =
        load_quarter_car_with_set(flags.model_file, flags.overrides, state, "--state");
    all_modes.push_back(simulate::quarter_car_modes(file.make_model()));
  }
  if (!flags.json) {
    std::cout << fmt::format("{:<6} {:<6} {:>12} {:>12} {:>9}\n", "state", "mode", "natural[Hz]",
                             "damped[Hz]", "damping");
  }
  for (std::size_t s = 0; s < states.size(); ++s) {
    const std::string& state = states[s];
    const auto& modes = all_modes[s];
    nlohmann::json list = nlohmann::json::array();
    for (const auto& mode : modes.oscillatory) {
      list.push_back({{"mode", mode.dominant_dof},
                      {"natural_frequency_Hz", mode.natural_frequency_Hz},
                      {"damped_frequency_Hz", mode.damped_frequency_Hz},
                      {"damping_ratio", mode.damping_ratio},
                      {"energy_share", mode.energy_share}});
      if (!flags.json) {
        std::cout << fmt::format("{:<6} {:<6} {:>12.3f} {:>12.3f} {:>9.4f}\n", state,
                                 mode.dominant_dof, mode.natural_frequency_Hz,
                                 mode.damped_frequency_Hz, mode.damping_ratio);
      }
    }
    nlohmann::json first_order = nlohmann::json::array();
    for (const auto& mode : modes.real) {
      first_order.push_back(
          {{"eigenvalue_per_s", mode.eigenvalue_per_s}, {"time_constant_s", mode.time_constant_s}});
      if (!flags.json) {
        std::cout << fmt::format("{:<6} {:<6} first-order, time constant {:.4g} s\n", state,
                                 "damper", mode.time_constant_s);
      }
    }
    summary["states"][state] = {{"modes", list}, {"first_order", first_order}};
  }
  if (flags.json) std::cout << summary.dump(2) << "\n";
}

}  // namespace

void register_modes(CLI::App& app) {
  auto flags = std::make_shared<ModesFlags>();
  CLI::App* command = app.add_subcommand(
      "modes", "Eigenfrequencies and damping ratios of the linear slip and stick models");
  command->add_option("model", flags->model_file, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--state", flags->state, "slip or stick (default: both)")
      ->check(CLI::IsMember({"slip", "stick"}));
  command->add_option("--set", flags->overrides,
                      "Override a model key, e.g. --set top_mount_stiffness_N_per_m=707e3");
  command->add_flag("--json", flags->json, "Print the modes as JSON");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
