// ridefit modes MODEL.yaml [--state slip|stick] [--json]: the quarter car's modes, or the half
// car's (its strut axles in the state asked; a car of passive axles has one linear model).
#include <fmt/core.h>

#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command_options.h"
#include "ridefit/common/errors.h"
#include "ridefit/io/half_car_file.h"
#include "ridefit/io/model_kind.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/simulate/half_car_modes.h"
#include "ridefit/simulate/modes_json.h"
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
  // Every state's model is read and solved before anything is printed: bad input prints nothing.
  std::vector<simulate::StateModes> all;
  const bool half_car = io::model_kind(flags.model_file) == "half_car";
  if (half_car) {
    const io::HalfCarFile file = io::load_half_car(flags.model_file, half_car_set(flags.overrides));
    try {
      all = simulate::half_car_modes_by_state(file.topology, file.parameters, flags.state,
                                              flags.model_file);
    } catch (const InputError& e) {
      throw InputError(flags.state.empty() ? e.what() : fmt::format("--{}", e.what()));
    }
  } else {
    for (const std::string state : {"slip", "stick"}) {
      if (!flags.state.empty() && state != flags.state) continue;
      const auto file =
          load_quarter_car_with_set(flags.model_file, flags.overrides, state, "--state");
      all.push_back({state, simulate::quarter_car_modes(file.make_model())});
    }
  }
  if (flags.json) {
    std::cout << simulate::modes_json(flags.model_file, all).dump(2) << "\n";
    return;
  }
  // The half car's coordinates and its "passive" state have longer names.
  const int width = half_car ? 11 : 6, state_width = half_car ? 7 : 6;
  std::cout << fmt::format("{:<{}} {:<{}} {:>12} {:>12} {:>9}\n", "state", state_width, "mode",
                           width, "natural[Hz]", "damped[Hz]", "damping");
  for (const auto& [state, modes] : all) {
    for (const auto& mode : modes.oscillatory) {
      std::cout << fmt::format("{:<{}} {:<{}} {:>12.3f} {:>12.3f} {:>9.4f}\n", state, state_width,
                               mode.dominant_dof, width, mode.natural_frequency_Hz,
                               mode.damped_frequency_Hz, mode.damping_ratio);
    }
    for (const auto& mode : modes.real) {
      std::cout << fmt::format("{:<{}} {:<{}} first-order, time constant {:.4g} s\n", state,
                               state_width, "damper", width, mode.time_constant_s);
    }
  }
}

}  // namespace

void register_modes(CLI::App& app) {
  auto flags = std::make_shared<ModesFlags>();
  CLI::App* command = app.add_subcommand(
      "modes",
      "Eigenfrequencies and damping ratios of the linear slip and stick models (quarter or half "
      "car)");
  command->add_option("model", flags->model_file, "Model file (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--state", flags->state,
                   "slip or stick (default: both; a half car's strut axles, none for passive "
                   "axles)")
      ->check(CLI::IsMember({"slip", "stick"}));
  command->add_option("--set", flags->overrides,
                      "Override a model key, e.g. --set top_mount_stiffness_N_per_m=707e3");
  command->add_flag("--json", flags->json, "Print the modes as JSON");
  command->callback([flags] { run(*flags); });
}

}  // namespace ridefit::cli
