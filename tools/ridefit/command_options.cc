#include "command_options.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdlib>

#include "ridefit/io/input_error.h"

namespace ridefit::cli {

void SolverFlags::add_to(CLI::App& command) {
  command.add_option("--method", method, "Integrator: cvode (adaptive BDF) or rk4 (fixed step)")
      ->check(CLI::IsMember({"cvode", "rk4"}))
      ->capture_default_str();
  command.add_option("--rtol", relative_tolerance, "CVODE relative tolerance")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--step", fixed_step_s, "RK4 fixed step [s]")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
}

simulate::IntegratorOptions SolverFlags::options() const {
  simulate::IntegratorOptions options;
  options.method = method == "rk4" ? simulate::Method::kArkodeRk4 : simulate::Method::kCvodeBdf;
  options.relative_tolerance = relative_tolerance;
  options.fixed_step_s = fixed_step_s;
  return options;
}

std::map<std::string, double> parse_overrides(const std::vector<std::string>& entries) {
  std::map<std::string, double> overrides;
  for (const auto& entry : entries) {
    const auto eq = entry.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == entry.size()) {
      throw InputError(
          fmt::format("--set '{}': expected KEY=NUMBER, e.g. coulomb_force_N=30", entry));
    }
    const std::string key = entry.substr(0, eq);
    const std::string text = entry.substr(eq + 1);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) {
      throw InputError(fmt::format("--set '{}': '{}' is not a finite number", entry, text));
    }
    overrides[key] = value;
  }
  return overrides;
}

nlohmann::json to_json(const simulate::SolverStatistics& statistics) {
  return {{"method", statistics.method},
          {"steps", statistics.steps},
          {"rhs_evaluations", statistics.rhs_evaluations},
          {"jacobian_evaluations", statistics.jacobian_evaluations},
          {"error_test_failures", statistics.error_test_failures},
          {"nonlinear_convergence_failures", statistics.nonlinear_convergence_failures}};
}

}  // namespace ridefit::cli
