#include "distributed_tuning.h"

#include <algorithm>
#include <chrono>
#include <string>
#include <utility>

#include "ridefit/common/byte_buffer.h"
#include "ridefit/distributed/task_farm.h"
#include "ridefit/optimisation/nlopt_tuner.h"
#include "ridefit/optimisation/run_bytes.h"

namespace ridefit::cli {

namespace opt = optimisation;

namespace {

// A search's result as sent: the seconds it took on its rank, then its run and evaluations.
std::string timed_result(double seconds, const std::string& run_bytes) {
  common::ByteWriter writer;
  writer.put(seconds);
  writer.put(run_bytes);
  return writer.take();
}

std::pair<double, std::string> untimed(const std::string& bytes) {
  common::ByteReader reader(bytes);
  const double seconds = reader.get<double>();
  return {seconds, reader.get_string()};
}

}  // namespace

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
      for (const auto& record : opt::run_from_bytes(untimed(bytes).second).second) {
        journal_->append(record);
      }
    };
  }
  distributed::TaskFarmStatistics farm;
  options.statistics = &farm;
  const auto started = std::chrono::steady_clock::now();
  const std::vector<std::string> results = distributed::run_task_farm(
      session_, tasks.size(),
      [&](std::size_t i) {
        const auto search_started = std::chrono::steady_clock::now();
        opt::TuningProblem branch = problem.branch(case_threads);
        const opt::OptimisationRun run = tasks[i](branch);
        std::string bytes = opt::run_to_bytes(run, branch.take_computed());
        return timed_result(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - search_started)
                .count(),
            bytes);
      },
      options);
  StageShare stage{
      .searches = tasks.size(),
      .wall_time_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()};
  share_.searches += tasks.size();
  share_.searches_on_rank0 += farm.tasks_on_rank0;
  share_.bytes_received += farm.bytes_received;
  share_.bytes_sent += farm.bytes_sent;
  share_.bytes_broadcast += farm.bytes_broadcast;
  std::vector<opt::OptimisationRun> runs;
  runs.reserve(results.size());
  for (const auto& bytes : results) {
    auto [seconds, run_bytes] = untimed(bytes);
    share_.search_time_s += seconds;
    stage.longest_search_s = std::max(stage.longest_search_s, seconds);
    auto [run, computed] = opt::run_from_bytes(run_bytes);
    share_.evaluations += computed.size();
    problem.learn(computed);
    runs.push_back(std::move(run));
  }
  share_.stages.push_back(stage);
  return runs;
}

void share_journal(const distributed::MpiSession& session, opt::TuningProblem& problem,
                   const opt::EvaluationJournal* journal) {
  const std::string bytes = distributed::broadcast_from_root(
      session, journal != nullptr ? opt::records_to_bytes(journal->records()) : std::string());
  if (!session.root()) problem.learn(opt::records_from_bytes(bytes));
}

}  // namespace ridefit::cli
