#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/io/quarter_car_file.h"
#include "ridefit/simulate/integrator.h"

namespace ridefit::cli {

// Solver flags shared by every command that integrates: --method, --rtol, --step.
struct SolverFlags {
  std::string method = "esdirk";
  double relative_tolerance = 1e-5;
  double fixed_step_s = 1e-4;

  void add_to(CLI::App& command);
  simulate::IntegratorOptions options() const;
};

// A finite number > 0, with a message that says so (CLI11's own range check prints a
// 309-digit upper bound). `unit` is shown in the message, e.g. "Hz".
CLI::Validator positive_number(const std::string& unit);

// An integrator tolerance flag (--rtol and kin): a number in (0, 0.1], the range every adaptive
// integrator accepts, with `what` saying whose tolerance it is; the default is shown.
CLI::Option* add_tolerance_option(CLI::App& command, const std::string& name, double& value,
                                  const std::string& what);

// The white sensor-noise floor of one acceleration channel (`channel`: "body" or "wheel"):
// --body-noise-psd / --wheel-noise-psd, a one-sided PSD level in (m/s^2)^2/Hz, >= 0 (0: no
// floor); not given, it is estimated from the record (signal/noise_floor.h). `value` stays NaN
// when the flag is absent; noise_psd_of turns it into the fit option.
CLI::Option* add_noise_psd_option(CLI::App& command, const std::string& channel, double& value);
std::optional<double> noise_psd_of(double value);

// Reports progress on stderr for runs that take longer than a second: nothing for short
// runs, then a line per 10 % of simulated time (rewritten in place on a terminal).
class ProgressReporter {
 public:
  ProgressReporter(std::string what, double end_time_s);
  void operator()(double time_s);
  void finish();

 private:
  std::string what_;
  double end_time_s_;
  double start_wall_s_;
  int last_decile_ = -1;
  bool printed_ = false;
  bool tty_;
};

// simulate::check_output_rate with its InputError naming --rate.
void check_output_rate(double rate_Hz, double duration_s);

// --force of a command that writes an output folder (io::RunOutputs::add_folder).
void add_force_flag(CLI::App& command, bool& force);

// Parses `arguments` (in command-line order, without the program and command names) with
// `command`'s options, as `ridefit batch` does for a job's: InputError naming an option the
// command does not have (as the job file's key, options.NAME), CLI::ParseError when one is wrong.
void parse_arguments(CLI::App& command, std::vector<std::string> arguments);

// `--set key=value` entries as (key, value text); a malformed entry is an InputError.
std::vector<std::pair<std::string, std::string>> parse_key_values(
    const std::vector<std::string>& entries);

// `--set key=value` overrides of numeric model keys; a malformed entry is an InputError.
std::map<std::string, double> parse_overrides(const std::vector<std::string>& entries);

// KEY=SHARE entries of `flag` (a data sheet's tolerances: --prior, --tolerances): quarter-car keys
// with a share of their value in (0, 10]; InputError naming the flag and the entry otherwise.
std::map<std::string, double> parse_value_shares(const std::vector<std::string>& entries,
                                                 const std::string& flag);

// io::load_quarter_car with `--set` entries: the library's messages about an override name the
// flag here. `state_flag` is the command's flag for the topology (e.g. "--damper-state"), or ""
// when the command sets it itself; --set damper_state (or model) points to it.
io::QuarterCarFile load_quarter_car_with_set(const std::string& model_file,
                                             const std::vector<std::string>& set_entries,
                                             const std::string& damper_state,
                                             const std::string& state_flag);

// The `--set` entries as overrides of a half-car file (values as typed; the file's reader
// checks them), naming the flag in every message they cause.
io::ModelOverrides half_car_set(const std::vector<std::string>& set_entries);

}  // namespace ridefit::cli
