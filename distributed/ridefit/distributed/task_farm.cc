#include "ridefit/distributed/task_farm.h"

#include <fmt/core.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "ridefit/common/errors.h"
#include "ridefit/common/parallel_for.h"

#ifdef RIDEFIT_HAVE_MPI
#include <mpi.h>
#endif

namespace ridefit::distributed {
namespace {

// The fault tests' hook: RIDEFIT_TEST_FAULT=throw:N makes task N (from 0) throw a RunError,
// die:N ends its process at once (as a crashed rank would). Unset in every real run.
std::function<std::string(std::size_t)> with_injected_fault(
    const std::function<std::string(std::size_t)>& run) {
  const char* spec = std::getenv("RIDEFIT_TEST_FAULT");
  if (spec == nullptr) return run;
  const std::string text = spec;
  const auto colon = text.find(':');
  if (colon == std::string::npos) return run;
  const std::string what = text.substr(0, colon);
  const std::size_t task = std::stoul(text.substr(colon + 1));
  return [run, what, task](std::size_t i) {
    if (i == task && what == "throw") throw RunError("injected failure (RIDEFIT_TEST_FAULT)");
    if (i == task && what == "die") std::_Exit(9);
    return run(i);
  };
}

#ifdef RIDEFIT_HAVE_MPI

// What a failed task threw, carried between ranks as a kind and a message.
struct Failure {
  int rank = 0;
  std::size_t task = 0;
  int kind = 0;  // 2 InputError, 1 RunError, 0 anything else
  std::string message;
};

Failure failure_of(std::exception_ptr error, int rank, std::size_t task) {
  Failure f{rank, task, 0, {}};
  try {
    std::rethrow_exception(error);
  } catch (const InputError& e) {
    f.kind = 2;
    f.message = e.what();
  } catch (const RunError& e) {
    f.kind = 1;
    f.message = e.what();
  } catch (const std::exception& e) {
    f.message = e.what();
  } catch (...) {
    f.message = "unknown exception";
  }
  return f;
}

[[noreturn]] void throw_as(int kind, const std::string& message) {
  if (kind == 2) throw InputError(message);
  if (kind == 1) throw RunError(message);
  throw std::runtime_error(message);
}

[[noreturn]] void rethrow(const Failure& f) {
  throw_as(f.kind, fmt::format("rank {}, run {}: {}", f.rank, f.task + 1, f.message));
}

// Runs tasks [first, first + n) on `threads` threads into results[first …]; on failure, the
// lowest failing task and its exception.
std::optional<std::pair<std::size_t, std::exception_ptr>> run_chunk(
    std::size_t first, std::size_t n, unsigned threads,
    const std::function<std::string(std::size_t)>& run, std::vector<std::string>& results,
    const std::function<void(std::size_t)>& finished_one) {
  std::mutex lock;
  std::size_t lowest = std::numeric_limits<std::size_t>::max();
  try {
    common::parallel_for(
        n, threads,
        [&](std::size_t k) {
          try {
            results[first + k] = run(first + k);
          } catch (...) {
            const std::lock_guard<std::mutex> guard(lock);
            lowest = std::min(lowest, first + k);
            throw;
          }
        },
        [&](std::size_t k) {
          if (finished_one) finished_one(first + k);
        });
  } catch (...) {
    return std::make_pair(lowest, std::current_exception());
  }
  return std::nullopt;
}

std::size_t chunk_size(const TaskFarmOptions& options, std::size_t count, int ranks) {
  if (options.chunk > 0) return options.chunk;
  return std::clamp<std::size_t>(count / (16 * static_cast<std::size_t>(ranks)), 1, 64);
}

enum Tag : int { kRequest = 1, kWork = 2, kFailed = 3 };

// Byte buffers: fixed-width integers and length-prefixed strings, in the machine's order
// (every rank of a run is the same program on the same kind of machine).
void put(std::string& out, std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), 8); }
void put(std::string& out, const std::string& s) {
  put(out, static_cast<std::uint64_t>(s.size()));
  out += s;
}
std::uint64_t take_u64(const std::string& in, std::size_t& at) {
  std::uint64_t v = 0;
  std::memcpy(&v, in.data() + at, 8);
  at += 8;
  return v;
}
std::string take_string(const std::string& in, std::size_t& at) {
  const std::size_t n = take_u64(in, at);
  std::string s = in.substr(at, n);
  at += n;
  return s;
}

void send(const std::string& bytes, int to, int tag) {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD);
}

// A message of any size from anyone; with `poll`, sleeps between probes instead of MPI's busy
// wait, so rank 0's scheduler thread leaves its core to the thread computing beside it.
std::string receive(int& from, int& tag, bool poll) {
  MPI_Status status;
  if (poll) {
    // Backing off from 20 µs to 1 ms: a request waits at most about 1 ms (a chunk is tens of
    // ms), and an idle scheduler wakes a thousand times a second, not tens of thousands.
    int arrived = 0;
    auto pause = std::chrono::microseconds(20);
    while (true) {
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
      if (arrived) break;
      std::this_thread::sleep_for(pause);
      pause = std::min(2 * pause, std::chrono::microseconds(1000));
    }
  } else {
    MPI_Probe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &status);
  }
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  MPI_Recv(bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  from = status.MPI_SOURCE;
  tag = status.MPI_TAG;
  return bytes;
}

std::string work_message(std::size_t first, std::size_t n) {
  std::string out;
  put(out, static_cast<std::uint64_t>(first));
  put(out, static_cast<std::uint64_t>(n));
  return out;
}

// A worker rank: asks for chunks (handing back the last one's results) until told to stop.
void work(const MpiSession& session, std::size_t count, unsigned threads,
          const std::function<std::string(std::size_t)>& run) {
  std::vector<std::string> results(count);
  std::string request = work_message(0, 0);
  while (true) {
    send(request, 0, kRequest);
    int from = 0;
    int tag = 0;
    const std::string reply = receive(from, tag, false);
    std::size_t at = 0;
    const std::size_t first = take_u64(reply, at);
    const std::size_t n = take_u64(reply, at);
    if (n == 0) return;
    const auto failed = run_chunk(first, n, threads, run, results, {});
    if (failed) {
      const Failure f = failure_of(failed->second, session.rank(), failed->first);
      std::string message;
      put(message, static_cast<std::uint64_t>(f.task));
      put(message, static_cast<std::uint64_t>(f.kind));
      put(message, f.message);
      send(message, 0, kFailed);
      receive(from, tag, false);  // the stop
      return;
    }
    request = work_message(first, n);
    for (std::size_t i = first; i < first + n; ++i) {
      put(request, results[i]);
      results[i].clear();
    }
  }
}

// Rank 0: the scheduler (on its own thread when rank 0 computes too) and rank 0's own chunks.
std::vector<std::string> lead(const MpiSession& session, std::size_t count, unsigned threads,
                              const std::function<std::string(std::size_t)>& run,
                              const TaskFarmOptions& options) {
  const std::size_t chunk = chunk_size(options, count, session.size());
  std::vector<std::string> results(count);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::mutex lock;  // failures, progress
  std::vector<Failure> failures;
  std::size_t done = 0;
  const auto finished = [&](std::size_t task) {
    const std::lock_guard<std::mutex> guard(lock);
    ++done;
    if (options.on_result) options.on_result(task, results[task]);
    if (options.progress) options.progress(done, count);
  };
  const auto take = [&]() -> std::pair<std::size_t, std::size_t> {
    if (failed) return {count, 0};
    const std::size_t first = next.fetch_add(chunk);
    if (first >= count) return {count, 0};
    return {first, std::min(chunk, count - first)};
  };

  TaskFarmStatistics statistics;  // the scheduler's own (one thread)
  const auto schedule = [&](bool poll) {
    int working = session.size() - 1;
    while (working > 0) {
      int from = 0;
      int tag = 0;
      const std::string message = receive(from, tag, poll);
      statistics.bytes_received += message.size();
      std::size_t at = 0;
      if (tag == kFailed) {
        Failure f;
        f.rank = from;
        f.task = take_u64(message, at);
        f.kind = static_cast<int>(take_u64(message, at));
        f.message = take_string(message, at);
        {
          const std::lock_guard<std::mutex> guard(lock);
          failures.push_back(f);
        }
        failed = true;
      } else {
        const std::size_t first = take_u64(message, at);
        const std::size_t n = take_u64(message, at);
        for (std::size_t i = first; i < first + n; ++i) {
          results[i] = take_string(message, at);
          finished(i);
        }
      }
      const auto [first, n] = take();
      const std::string reply = work_message(first, n);
      send(reply, from, kWork);
      statistics.bytes_sent += reply.size();
      if (n > 0) ++statistics.chunks_handed_out;
      if (n == 0) --working;
    }
  };

  if (session.threads_may_call_mpi()) {
    std::thread scheduler(schedule, true);
    while (true) {
      const auto [first, n] = take();
      if (n == 0) break;
      const auto fault = run_chunk(first, n, threads, run, results, finished);
      statistics.tasks_on_rank0 += n;
      if (fault) {
        const std::lock_guard<std::mutex> guard(lock);
        failures.push_back(failure_of(fault->second, 0, fault->first));
        failed = true;
      }
    }
    scheduler.join();
  } else {
    schedule(false);  // rank 0 only schedules
  }
  if (options.statistics) *options.statistics = statistics;
  if (!failures.empty()) {
    rethrow(*std::min_element(failures.begin(), failures.end(),
                              [](const Failure& a, const Failure& b) { return a.task < b.task; }));
  }
  return results;
}

// Rank 0's results, or the exception it threw, sent to every rank; every rank returns the
// results or throws that exception.
std::vector<std::string> share_outcome(const MpiSession& session,
                                       const std::function<std::vector<std::string>()>& lead_run,
                                       TaskFarmStatistics* statistics) {
  std::string bytes;
  if (session.root()) {
    try {
      const std::vector<std::string> results = lead_run();
      put(bytes, static_cast<std::uint64_t>(0));
      put(bytes, static_cast<std::uint64_t>(results.size()));
      for (const auto& r : results) put(bytes, r);
    } catch (...) {
      const Failure f = failure_of(std::current_exception(), 0, 0);
      bytes.clear();
      put(bytes, static_cast<std::uint64_t>(1));
      put(bytes, static_cast<std::uint64_t>(f.kind));
      put(bytes, f.message);
    }
    if (bytes.size() > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
      throw std::runtime_error("task farm: the results exceed 2 GiB, too many to share");
    }
  } else {
    lead_run();  // a worker: runs its chunks
  }
  std::uint64_t size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  bytes.resize(size);
  MPI_Bcast(bytes.data(), static_cast<int>(size), MPI_BYTE, 0, MPI_COMM_WORLD);
  if (session.root() && statistics != nullptr) statistics->bytes_broadcast = size;
  std::size_t at = 0;
  if (take_u64(bytes, at) != 0) {
    const int kind = static_cast<int>(take_u64(bytes, at));
    throw_as(kind, take_string(bytes, at));
  }
  std::vector<std::string> results(take_u64(bytes, at));
  for (auto& r : results) r = take_string(bytes, at);
  return results;
}

#endif  // RIDEFIT_HAVE_MPI

}  // namespace

std::vector<std::string> run_task_farm(const MpiSession& session, std::size_t count,
                                       const std::function<std::string(std::size_t)>& task,
                                       const TaskFarmOptions& options) {
  const std::function<std::string(std::size_t)> run = with_injected_fault(task);
  const unsigned threads =
      options.threads > 0 ? options.threads : default_threads_per_rank(session);
#ifdef RIDEFIT_HAVE_MPI
  if (session.active() && session.size() > 1) {
    if (options.results_on_every_rank) {
      return share_outcome(
          session,
          [&]() -> std::vector<std::string> {
            if (session.root()) return lead(session, count, threads, run, options);
            work(session, count, threads, run);
            return {};
          },
          options.statistics);
    }
    if (session.root()) return lead(session, count, threads, run, options);
    work(session, count, threads, run);
    return {};
  }
#endif
  if (options.statistics) *options.statistics = {.tasks_on_rank0 = count};
  std::vector<std::string> results(count);
  std::size_t done = 0;
  common::parallel_for(
      count, threads, [&](std::size_t i) { results[i] = run(i); },
      [&](std::size_t i) {
        ++done;
        if (options.on_result) options.on_result(i, results[i]);
        if (options.progress) options.progress(done, count);
      });
  return results;
}

}  // namespace ridefit::distributed
