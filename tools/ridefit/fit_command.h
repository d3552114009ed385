#pragma once

// What `ridefit fit`'s subcommands share (fit_command.cc): each kind of fit registers itself
// under `fit` from its own file, and both end with the same verdict and --keep flag.

#include <CLI/CLI.hpp>

#include <string>

namespace ridefit::cli {

void register_fit_hysteresis(CLI::App& fit);  // fit_hysteresis_command.cc
void register_fit_psd(CLI::App& fit);         // fit_psd_command.cc

// --max-nrmse, the threshold of the verdict (`what` names the NRMSE, e.g. "NRMSE"), and --keep:
// write the fitted model even when it does not explain the data.
void add_verdict_options(CLI::App& command, const std::string& what, double& max_nrmse_percent,
                         bool& keep);

// RunError (exit 1) when the fitted model does not explain the data: `note` says why, and
// `withheld` adds that the model was not written and how to have it written.
void require_explained(bool explains_data, const std::string& note, bool withheld);

}  // namespace ridefit::cli
