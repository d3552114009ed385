#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ridefit/optimisation/evaluation_journal.h"
#include "ridefit/optimisation/nlopt_tuner.h"

namespace ridefit::optimisation {

// A search's run and the evaluations it computed, as bytes and back (common/byte_buffer.h:
// exact): how a search run on another rank comes home, so that every rank holds the same run.
std::string run_to_bytes(const OptimisationRun& run, const std::vector<JournalRecord>& computed);
std::pair<OptimisationRun, std::vector<JournalRecord>> run_from_bytes(const std::string& bytes);

// Journal records alone (a resumed journal sent from rank 0 to the others).
std::string records_to_bytes(const std::vector<JournalRecord>& records);
std::vector<JournalRecord> records_from_bytes(const std::string& bytes);

}  // namespace ridefit::optimisation
