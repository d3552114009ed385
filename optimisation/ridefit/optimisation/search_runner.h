#pragma once

#include <functional>
#include <vector>

#include "ridefit/optimisation/tuning_problem.h"

namespace ridefit::optimisation {

struct OptimisationRun;

// One independent search of a tuning study (a start, or the polish of an optimum), run on its
// own branch of the problem (TuningProblem::branch), so that what it finds depends on nothing
// but its own path and the evaluations known before the stage began.
using SearchTask = std::function<OptimisationRun(TuningProblem& branch)>;

// Runs the independent searches of one stage and returns their runs in task order; afterwards
// `problem` knows every evaluation they computed (TuningProblem::learn), in task order. How
// the tasks are spread (threads here, ranks in the CLI's runner over MPI) must not change any
// run, so a study gives the same result on any number of threads or ranks.
class SearchRunner {
 public:
  virtual ~SearchRunner() = default;
  virtual std::vector<OptimisationRun> run(TuningProblem& problem,
                                           const std::vector<SearchTask>& tasks) = 0;
};

// The searches on `threads` threads of this process (0: every core). With fewer searches than
// threads, each search's load cases run in parallel instead (the study's evaluation threads).
class LocalSearchRunner final : public SearchRunner {
 public:
  explicit LocalSearchRunner(unsigned threads) : threads_(threads) {}
  std::vector<OptimisationRun> run(TuningProblem& problem,
                                   const std::vector<SearchTask>& tasks) override;

 private:
  unsigned threads_;
};

// The threads each search's load cases get when `tasks` searches share `threads` threads
// (0: every core): all of the study's when a search has the threads to itself, else one.
unsigned case_threads_for(const TuningProblem& problem, std::size_t tasks, unsigned threads);

}  // namespace ridefit::optimisation
