#include "distributed_tuning.h"

#include <string>
#include <utility>

#include "ridefit/distributed/task_farm.h"
#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/run_bytes.h"

namespace ridefit::cli {

namespace opt = optimisation;

std::vector<opt::OptimisationRun> RankSearchRunner::run(opt::TuningProblem& problem,
                                                        const std::vector<opt::SearchTask>& tasks) {
  const unsigned rank_threads =
      threads_ > 0 ? threads_ : distributed::default_threads_per_rank(session_);
  const std::size_t ranks = static_cast<std::size_t>(session_.size());
  const unsigned case_threads =
      opt::case_threads_for(problem, (tasks.size() + ranks - 1) / ranks, rank_threads);
  distributed::TaskFarmOptions options;
  options.threads = rank_threads;
  options.chunk = rank_threads;  // a search is long: each rank holds one per thread
  options.results_on_every_rank = true;
  if (journal_ != nullptr) {
    // Rank 0's own searches appended as they evaluated; the others' come with their runs.
    options.on_result = [this](std::size_t, const std::string& bytes) {
      for (const auto& record : opt::run_from_bytes(bytes).second) journal_->append(record);
    };
  }
  const std::vector<std::string> results = distributed::run_task_farm(
      session_, tasks.size(),
      [&](std::size_t i) {
        opt::TuningProblem branch = problem.branch(case_threads);
        const opt::OptimisationRun run = tasks[i](branch);
        return opt::run_to_bytes(run, branch.take_computed());
      },
      options);
  std::vector<opt::OptimisationRun> runs;
  runs.reserve(results.size());
  for (const auto& bytes : results) {
    auto [run, computed] = opt::run_from_bytes(bytes);
    problem.learn(computed);
    runs.push_back(std::move(run));
  }
  return runs;
}

void share_journal(const distributed::MpiSession& session, opt::TuningProblem& problem,
                   const opt::EvaluationJournal* journal) {
  const std::string bytes = distributed::broadcast_from_root(
      session, journal != nullptr ? opt::records_to_bytes(journal->records()) : std::string());
  if (!session.root()) problem.learn(opt::records_from_bytes(bytes));
}

}  // namespace ridefit::cli
