#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ridefit/distributed/mpi_session.h"

namespace ridefit::distributed {

// What rank 0's scheduler exchanged in a run over ranks (in one process: every task on rank 0,
// nothing exchanged): the figures behind the scaling estimate.
struct TaskFarmStatistics {
  std::size_t chunks_handed_out = 0;  // to the other ranks
  std::size_t bytes_received = 0;     // requests with results, and failures
  std::size_t bytes_sent = 0;         // chunk assignments and stops
  std::size_t tasks_on_rank0 = 0;
  std::size_t bytes_broadcast = 0;  // results_on_every_rank: every result, to every other rank
};

struct TaskFarmOptions {
  // Threads per rank running its tasks (0 = default_threads_per_rank).
  unsigned threads = 0;
  // Tasks handed out at a time (0 = chosen from the count: about 16 chunks per rank, at most
  // 64 tasks, so slow tasks do not stall the end and fast ones do not flood rank 0).
  std::size_t chunk = 0;
  // Called on rank 0 (one call at a time) as tasks finish: (done, total).
  std::function<void(std::size_t, std::size_t)> progress;
  // Called on rank 0 (one call at a time, in the order tasks finish, from whichever thread
  // received the result) with each finished task's result: for what must be kept as it comes
  // (a journal, a summary so far), so that a run that fails or is killed keeps it.
  std::function<void(std::size_t task, const std::string& result)> on_result;
  // Every rank returns every result (rank 0 sends them to all once all are in), and a failure
  // is thrown on every rank alike: for runs in which every rank goes on from the results.
  bool results_on_every_rank = false;
  // Filled on rank 0 when given.
  TaskFarmStatistics* statistics = nullptr;
};

// Runs tasks 0 … count−1, where run(i) returns task i's result as bytes, over the ranks of the
// session: rank 0 hands out chunks of tasks as ranks ask for them (dynamic scheduling) and, when
// MPI allows a second thread to call it, runs chunks itself between requests; every rank runs
// a chunk on its threads. Returns on rank 0 every task's result in task order, and nothing on
// the other ranks; so for any number of ranks rank 0 holds the same bytes as one process.
//
// Every rank must call it with the same count. A task that throws stops the handing out of new
// chunks: the ranks finish what they hold and stop, and rank 0 throws the exception of the
// lowest failing task it knows of, as InputError, RunError or std::runtime_error as thrown,
// its message prefixed with the rank and the task ("rank 2, run 17: …") when more than one
// rank runs. The other ranks return an empty result (or, with results_on_every_rank, rank 0's
// results or its exception). Without MPI (one rank) it is
// common::parallel_for with the exception unchanged.
std::vector<std::string> run_task_farm(const MpiSession& session, std::size_t count,
                                       const std::function<std::string(std::size_t)>& run,
                                       const TaskFarmOptions& options = {});

}  // namespace ridefit::distributed
