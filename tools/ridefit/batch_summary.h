#pragma once

// The summary of `ridefit batch` (batch_summary.cc): one row per job in job order, written as
// DIR/summary.csv and DIR/summary.json after every finished job, so a run that is killed keeps
// the summary so far.

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "batch_job_result.h"
#include "batch_jobs.h"

namespace ridefit::cli {

// Every job's row: name, command, records, status (ok, failed, not run), the fitted values with
// their standard errors (a fit) or the named effects and the gap before and after (a
// diagnosis), the NRMSE, the job's wall time and the message of a failed job. `results` holds one
// result per job (status "not run" for a job not finished).
nlohmann::json batch_summary_json(const std::filesystem::path& job_file,
                                  const std::vector<BatchJob>& jobs,
                                  const std::vector<BatchJobResult>& results);

// Writes summary.json and summary.csv (the same rows; values as `name=value±se` in one
// column) into `dir`, each atomically.
void write_batch_summary(const std::filesystem::path& dir, const nlohmann::json& summary);

}  // namespace ridefit::cli
