#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

#include "ridefit/simulate/integrator.h"

namespace ridefit::cli {

// Solver flags shared by every command that integrates: --method, --rtol, --step.
struct SolverFlags {
  std::string method = "cvode";
  double relative_tolerance = 1e-6;
  double fixed_step_s = 1e-4;

  void add_to(CLI::App& command);
  simulate::IntegratorOptions options() const;
};

// `--set key=value` overrides of numeric model keys; a malformed entry is an InputError.
std::map<std::string, double> parse_overrides(const std::vector<std::string>& entries);

nlohmann::json to_json(const simulate::SolverStatistics& statistics);

}  // namespace ridefit::cli
