#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "ridefit/optimisation/tuning_files.h"
#include "ridefit/optimisation/tuning_outcome.h"

namespace ridefit::optimisation {

// Where a run's outputs went, as the result names them: each "" when it was not written.
struct WrittenFiles {
  std::string model;         // only beside a feasible optimum
  std::string tradeoff_csv;  // only when there is a curve
  std::string journal;
  std::string plot;
};

// The files of `files` a run with `outcome` writes: the model only beside a feasible optimum,
// the trade-off CSV only when there is a curve.
WrittenFiles written_files(const TuningFiles& files, const TuningOutcome& outcome,
                           const std::string& plot);

// The whole result as one tree (status, variables, objective, constraint margins, load cases,
// friction, the cost of ignoring it, the trade-off, the files): what --json prints and the YAML
// result file holds.
nlohmann::json tuning_result(const TuningProblem& problem, const TuningOutcome& outcome,
                             const WrittenFiles& written, double wall_time_s);

// Writes the trade-off CSV and the optimised model (where `written` names them) and the result
// as YAML to `result_file` (unless ""), each atomically. `origin` says what produced them (e.g.
// "ridefit optimise study.yaml"): the result's first line is a comment "# ORIGIN", the model's
// "Optimised by ORIGIN from MODEL".
void write_tuning_result(const TuningProblem& problem, const TuningOutcome& outcome,
                         const WrittenFiles& written, const nlohmann::json& result,
                         const std::string& result_file, const std::string& origin);

}  // namespace ridefit::optimisation
