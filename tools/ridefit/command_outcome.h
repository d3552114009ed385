#pragma once

// What a fit or a diagnosis produced, in memory, before anything is written: the single
// command writes it to its -o paths and prints it; `ridefit batch` runs the same code as a job
// (on any rank), sends it to rank 0 as bytes and writes it into the job's folder there. So a
// batch job gives the numbers the single command gives.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "command_options.h"

namespace ridefit::cli {

// A file of the outcome by its name in an output folder (e.g. "model.yaml") and its text.
struct OutcomeFile {
  std::string name;
  std::string text;
};

struct CommandOutcome {
  // What the command's --json prints (without the paths it wrote).
  nlohmann::json summary;
  // What it writes: a fitted model per output (none when the fit does not explain the data and
  // --keep is not given), a diagnosis' report and model.
  std::vector<OutcomeFile> files;
  // Why the run failed after producing its results (the model does not explain the data: the
  // command's exit 1); empty on success.
  std::string failure;
};

// A job of `ridefit batch`: the command's run with its arguments parsed (CLI::ParseError, or
// InputError, when they are wrong). Calling it runs the fit or diagnosis (InputError / RunError
// as the command throws them).
using CommandJob = std::function<CommandOutcome()>;

// A command's job from its flags: `add_options(app, flags)` adds the command's inputs and
// settings, `arguments` are parsed into the flags, and the job returns `outcome(flags)`.
template <class Flags, class AddOptions, class Outcome>
CommandJob command_job(std::vector<std::string> arguments, AddOptions add_options,
                       Outcome outcome) {
  auto flags = std::make_shared<Flags>();
  CLI::App command;
  add_options(command, *flags);
  parse_arguments(command, std::move(arguments));
  return [flags, outcome] { return outcome(*flags); };
}

// The batchable commands' jobs, each made in its command's file from `arguments` as that
// command's command line takes them (inputs and options, no output flags): the same option
// names, checks and defaults. A job runs on one thread (the batch runs jobs side by side).
CommandJob fit_hysteresis_job(std::vector<std::string> arguments);  // DATA... --model M ...
CommandJob fit_psd_job(std::vector<std::string> arguments);         // MEAS --model M ...
CommandJob diagnose_job(std::vector<std::string> arguments);        // MODEL RECORDS... ...

}  // namespace ridefit::cli
