#pragma once

#include <vector>

#include "ridefit/distributed/mpi_session.h"
#include "ridefit/optimisation/evaluation_journal.h"
#include "ridefit/optimisation/search_runner.h"

namespace ridefit::cli {

// A tuning study's searches spread over the ranks of `session`. Every rank runs the study's
// steps alike and calls run() with the same searches; rank 0 hands them out as ranks ask
// (each rank `threads` at a time, 0 = its share of the cores), every rank gets every run back
// bit for bit, so every rank goes on from the same state and the outcome is that of one
// process. Rank 0 alone owns the journal: its own searches append as they evaluate, the other
// ranks' evaluations are appended as each of their searches ends.
class RankSearchRunner final : public optimisation::SearchRunner {
 public:
  RankSearchRunner(const distributed::MpiSession& session, unsigned threads,
                   optimisation::EvaluationJournal* journal)
      : session_(session), threads_(threads), journal_(journal) {}
  std::vector<optimisation::OptimisationRun> run(
      optimisation::TuningProblem& problem,
      const std::vector<optimisation::SearchTask>& tasks) override;

 private:
  const distributed::MpiSession& session_;
  unsigned threads_;
  optimisation::EvaluationJournal* journal_;  // rank 0's; null elsewhere
};

// Rank 0's journal evaluations made known to the problems of every rank (collective).
void share_journal(const distributed::MpiSession& session, optimisation::TuningProblem& problem,
                   const optimisation::EvaluationJournal* journal);

}  // namespace ridefit::cli
