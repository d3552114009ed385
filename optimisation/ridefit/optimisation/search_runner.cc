#include "ridefit/optimisation/search_runner.h"

#include <algorithm>
#include <thread>

#include "ridefit/common/parallel_for.h"
#include "ridefit/optimisation/nlopt_tuner.h"

namespace ridefit::optimisation {

unsigned case_threads_for(const TuningProblem& problem, std::size_t tasks, unsigned threads) {
  const unsigned available =
      threads > 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  return tasks >= available ? 1 : problem.study().evaluation.threads;
}

std::vector<OptimisationRun> LocalSearchRunner::run(TuningProblem& problem,
                                                    const std::vector<SearchTask>& tasks) {
  const unsigned case_threads = case_threads_for(problem, tasks.size(), threads_);
  std::vector<OptimisationRun> runs(tasks.size());
  std::vector<std::vector<JournalRecord>> computed(tasks.size());
  common::parallel_for(tasks.size(), tasks.size() > 1 ? threads_ : 1, [&](std::size_t i) {
    TuningProblem branch = problem.branch(case_threads);
    runs[i] = tasks[i](branch);
    computed[i] = branch.take_computed();
  });
  for (const auto& records : computed) problem.learn(records);
  return runs;
}

}  // namespace ridefit::optimisation
