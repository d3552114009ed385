#include "command_options.h"

#include <fmt/core.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "ridefit/common/errors.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/simulate/simulation_options.h"

namespace ridefit::cli {

CLI::Validator positive_number(const std::string& unit) {
  return CLI::Validator(
      [unit](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (end == text.c_str() || *end != '\0' || !std::isfinite(value) || !(value > 0.0)) {
          return fmt::format("expected a finite number > 0{}, got '{}'",
                             unit.empty() ? "" : " (" + unit + ")", text);
        }
        return "";
      },
      "NUMBER > 0");
}

CLI::Option* add_tolerance_option(CLI::App& command, const std::string& name, double& value,
                                  const std::string& what) {
  return command.add_option(name, value, what + ", in (0, 0.1]")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !(v > 0.0 && v <= 0.1)) {
              return fmt::format("expected a relative tolerance in (0, 0.1], got '{}'", text);
            }
            return "";
          },
          "RTOL"))
      ->capture_default_str();
}

CLI::Option* add_noise_psd_option(CLI::App& command, const std::string& channel, double& value) {
  return command
      .add_option(
          "--" + channel + "-noise-psd", value,
          "White sensor-noise floor of " + channel +
              "_acc [(m/s^2)^2/Hz, one-sided PSD level], added to the simulated PSD "
              "before it is compared with the measured one; 0 = none; default: estimated "
              "from the record (a power law plus a constant fitted to its PSD above the band)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !std::isfinite(v) || !(v >= 0.0)) {
              return fmt::format("expected a noise PSD level >= 0 in (m/s^2)^2/Hz, got '{}'", text);
            }
            return "";
          },
          "(m/s^2)^2/Hz >= 0"));
}

std::optional<double> noise_psd_of(double value) {
  return std::isnan(value) ? std::nullopt : std::optional<double>(value);
}

ProgressReporter::ProgressReporter(std::string what, double end_time_s)
    : what_(std::move(what)),
      end_time_s_(end_time_s),
      start_wall_s_(
          std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
              .count()),
      tty_(isatty(fileno(stderr)) != 0) {}

void ProgressReporter::operator()(double time_s) {
  const int decile = static_cast<int>(10.0 * time_s / end_time_s_);
  if (decile == last_decile_) return;
  last_decile_ = decile;
  const double now =
      std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
  if (now - start_wall_s_ < 1.0) return;
  printed_ = true;
  std::cerr << fmt::format("{}{}: {:3d} % of {:g} s simulated{}", tty_ ? "\r" : "", what_,
                           10 * decile, end_time_s_, tty_ ? "" : "\n")
            << std::flush;
}

void ProgressReporter::finish() {
  if (printed_ && tty_) std::cerr << "\n";
}

void SolverFlags::add_to(CLI::App& command) {
  command
      .add_option("--method", method,
                  "Integrator: esdirk (ridefit's adaptive L-stable ESDIRK, the default), cvode "
                  "(SUNDIALS' adaptive BDF, the reference) or rk4 (fixed step, the seed's ode4)")
      ->check(CLI::IsMember({"esdirk", "cvode", "rk4"}))
      ->capture_default_str();
  add_tolerance_option(command, "--rtol", relative_tolerance,
                       "Relative tolerance of esdirk and cvode: each state's local error is kept "
                       "below rtol times its size plus rtol times its typical size (1 mm, "
                       "10 mm/s, Fc)");
  command.add_option("--step", fixed_step_s, "RK4 fixed step [s]")
      ->check(positive_number("s"))
      ->capture_default_str();
}

simulate::IntegratorOptions SolverFlags::options() const {
  simulate::IntegratorOptions options;
  options.method = method == "rk4"     ? simulate::Method::kArkodeRk4
                   : method == "cvode" ? simulate::Method::kCvodeBdf
                                       : simulate::Method::kEsdirk;
  options.relative_tolerance = relative_tolerance;
  options.fixed_step_s = fixed_step_s;
  return options;
}

void check_output_rate(double rate_Hz, double duration_s) {
  try {
    simulate::check_output_rate(rate_Hz, duration_s);
  } catch (const InputError& e) {
    throw InputError(fmt::format("--rate {}", e.what()));
  }
}

void add_force_flag(CLI::App& command, bool& force) {
  command.add_flag("--force", force,
                   "Write into an existing -o folder that holds files ridefit did not write "
                   "there (files of the same name are replaced; inputs never are)");
}

void parse_arguments(CLI::App& command, std::vector<std::string> arguments) {
  for (const auto& argument : arguments) {
    if (argument.rfind("--", 0) != 0 || command.get_option_no_throw(argument) != nullptr) continue;
    std::string known;
    for (const CLI::Option* option : command.get_options()) {
      for (std::string name : option->get_lnames()) {
        if (name == "help") continue;
        std::replace(name.begin(), name.end(), '-', '_');
        if (!known.empty()) known += ", ";
        known += name;
      }
    }
    std::string name = argument.substr(2);
    std::replace(name.begin(), name.end(), '-', '_');
    throw InputError(fmt::format(
        "key 'options.{}': not an option of this command (its options: {})", name, known));
  }
  std::reverse(arguments.begin(), arguments.end());  // CLI11 takes them last first
  command.parse(arguments);
}

std::vector<std::pair<std::string, std::string>> parse_key_values(
    const std::vector<std::string>& entries) {
  std::vector<std::pair<std::string, std::string>> pairs;
  for (const auto& entry : entries) {
    const auto eq = entry.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == entry.size()) {
      throw InputError(fmt::format(
          "--set '{}': expected KEY=VALUE, e.g. coulomb_force_N=30 or front.damping_Ns_per_m=1500",
          entry));
    }
    pairs.emplace_back(entry.substr(0, eq), entry.substr(eq + 1));
  }
  return pairs;
}

std::map<std::string, double> parse_overrides(const std::vector<std::string>& entries) {
  std::map<std::string, double> overrides;
  for (const auto& [key, text] : parse_key_values(entries)) {
    const std::string entry = key + "=" + text;
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) {
      throw InputError(fmt::format("--set '{}': '{}' is not a finite number", entry, text));
    }
    overrides[key] = value;
  }
  return overrides;
}

std::map<std::string, double> parse_value_shares(const std::vector<std::string>& entries,
                                                 const std::string& flag) {
  std::map<std::string, double> shares;
  for (const auto& entry : entries) {
    const auto equals = entry.find('=');
    const std::string key = entry.substr(0, equals);
    if (equals == std::string::npos || !model::quarter_car_parameter_index(key)) {
      throw InputError(fmt::format(
          "{}: '{}' is not KEY=SHARE with a quarter-car key (e.g. spring_stiffness_N_per_m=0.08)",
          flag, entry));
    }
    const std::string text = entry.substr(equals + 1);
    char* end = nullptr;
    const double share = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !(share > 0.0 && share <= 10.0)) {
      throw InputError(
          fmt::format("{}: {} is '{}'; expected a share of its value in (0, 10] (0.08 = ±8 %)",
                      flag, key, text));
    }
    shares[key] = share;
  }
  return shares;
}

io::QuarterCarFile load_quarter_car_with_set(const std::string& model_file,
                                             const std::vector<std::string>& set_entries,
                                             const std::string& damper_state,
                                             const std::string& state_flag) {
  io::ModelOverrides overrides;
  overrides.origin = "given on the command line as --set";
  overrides.damper_state = damper_state;
  for (const auto& [key, value] : parse_overrides(set_entries)) {
    if (key == "damper_state" || key == "model") {
      throw InputError(fmt::format(
          "--set {}: not a number key; {}", key,
          state_flag.empty() ? std::string("this command chooses the damper's topology itself")
                             : fmt::format("use {} for the topology", state_flag)));
    }
    overrides.set(key, value);
  }
  return io::load_quarter_car(model_file, overrides);
}

io::ModelOverrides half_car_set(const std::vector<std::string>& set_entries) {
  io::ModelOverrides overrides;
  overrides.origin = "given on the command line as --set";
  overrides.keys = parse_key_values(set_entries);
  return overrides;
}

}  // namespace ridefit::cli
