#pragma once

#include <cstddef>
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
// What one stage's searches cost: every stage waits for its longest search.
struct StageShare {
  std::size_t searches = 0;
  double wall_time_s = 0;
  double longest_search_s = 0;
};

// What the searches cost and what rank 0 exchanged over the study's stages: the figures behind
// the scaling estimate (`optimise --json`, `ranks`).
struct SearchShare {
  std::vector<StageShare> stages;
  std::size_t searches = 0;
  std::size_t searches_on_rank0 = 0;
  std::size_t evaluations = 0;      // computed in the searches (not found in the journal)
  double search_time_s = 0;         // summed over the searches, each timed on its rank
  std::size_t bytes_received = 0;   // by rank 0: requests with runs and evaluations
  std::size_t bytes_sent = 0;       // by rank 0: assignments of searches
  std::size_t bytes_broadcast = 0;  // by rank 0: every run, to every other rank
};

class RankSearchRunner final : public optimisation::SearchRunner {
 public:
  RankSearchRunner(const distributed::MpiSession& session, unsigned threads,
                   optimisation::EvaluationJournal* journal)
      : session_(session), threads_(threads), journal_(journal) {}
  std::vector<optimisation::OptimisationRun> run(
      optimisation::TuningProblem& problem,
      const std::vector<optimisation::SearchTask>& tasks) override;
  const SearchShare& share() const { return share_; }

 private:
  const distributed::MpiSession& session_;
  unsigned threads_;
  optimisation::EvaluationJournal* journal_;  // rank 0's; null elsewhere
  SearchShare share_;
};

// Rank 0's journal evaluations made known to the problems of every rank (collective).
void share_journal(const distributed::MpiSession& session, optimisation::TuningProblem& problem,
                   const optimisation::EvaluationJournal* journal);

}  // namespace ridefit::cli
