// ridefit fit hysteresis|psd: the `fit` command and what its subcommands share.
#include "fit_command.h"

#include "ridefit/common/errors.h"
#include "subcommands.h"

namespace ridefit::cli {

void register_fit(CLI::App& app) {
  CLI::App* fit = app.add_subcommand("fit", "Identify model parameters from lab data (Ceres)");
  fit->require_subcommand(1);
  register_fit_hysteresis(*fit);
  register_fit_psd(*fit);
}

void add_verdict_options(CLI::App& command, const std::string& what, double& max_nrmse_percent,
                         bool& keep) {
  command
      .add_option("--max-nrmse", max_nrmse_percent,
                  what + " [%] above which the model is reported as not explaining the data")
      ->check(CLI::Range(0.0, 1000.0).description("in (0, 1000]"));
  command.add_flag("--keep", keep,
                   "Write the fitted model even when it does not explain the data (exit 1 all the "
                   "same)");
}

void require_explained(bool explains_data, const std::string& note, bool withheld) {
  if (explains_data) return;
  throw RunError(note + (withheld ? "; no fitted model was written (--keep writes it)" : ""));
}

}  // namespace ridefit::cli
