#pragma once

// One job of `ridefit batch` run (batch_job_result.cc): its outcome or why it failed, as bytes
// that go from the rank that ran it to rank 0, which writes it.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "batch_jobs.h"
#include "command_outcome.h"

namespace ridefit::cli {

struct BatchJobResult {
  std::string status = "not run";  // "ok", "failed" or "not run"
  std::string message;             // why it failed
  nlohmann::json summary;          // the command's --json summary; null when it failed first
  std::vector<OutcomeFile> files;  // what goes into the job's folder (result.json among them)
  double wall_time_s = 0.0;        // the job's time on its rank (in the batch summary only)
};

// Runs the job: a job that throws (a record that cannot be read, a fit that does not converge)
// or does not explain its data is a failed result with the message, so the other jobs go on.
BatchJobResult run_batch_job(const BatchJob& job);

// Exact: the files' bytes and the summary's numbers (round-trip) as they were.
std::string encode(const BatchJobResult& result);
BatchJobResult decode_batch_job_result(const std::string& bytes);

}  // namespace ridefit::cli
