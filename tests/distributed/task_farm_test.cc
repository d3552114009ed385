// The task farm in one process (no mpirun): results in task order, the lowest failing task's
// exception unchanged, the injected fault of the rank tests. Over ranks: tests/mpi/.
#include "ridefit/distributed/task_farm.h"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <atomic>
#include <string>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::distributed {
namespace {

int argc = 1;
char name[] = "task_farm_test";
char* args[] = {name, nullptr};
char** argv = args;

TEST(TaskFarm, OneProcessReturnsEveryResultInTaskOrder) {
  const MpiSession session(argc, argv);
  EXPECT_TRUE(session.root());
  EXPECT_EQ(session.size(), 1);
  std::atomic<int> calls{0};
  std::size_t reported = 0;
  TaskFarmOptions options;
  options.threads = 2;
  options.progress = [&](std::size_t done, std::size_t total) {
    EXPECT_EQ(total, 100u);
    reported = done;
  };
  const auto results = run_task_farm(
      session, 100,
      [&](std::size_t i) {
        ++calls;
        return std::to_string(i * i);
      },
      options);
  ASSERT_EQ(results.size(), 100u);
  for (std::size_t i = 0; i < results.size(); ++i) EXPECT_EQ(results[i], std::to_string(i * i));
  EXPECT_EQ(calls.load(), 100);
  EXPECT_EQ(reported, 100u);
}

TEST(TaskFarm, OneProcessRethrowsTheLowestFailingTaskUnchanged) {
  const MpiSession session(argc, argv);
  TaskFarmOptions options;
  options.threads = 2;
  try {
    run_task_farm(
        session, 50,
        [](std::size_t i) -> std::string {
          if (i == 7 || i == 31) throw InputError("bad value in run " + std::to_string(i));
          return {};
        },
        options);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "bad value in run 7");
  }
}

TEST(TaskFarm, OneProcessHandsOverEachResultAsItFinishes) {
  const MpiSession session(argc, argv);
  std::vector<std::string> seen(40);
  std::size_t calls = 0;
  TaskFarmOptions options;
  options.threads = 2;
  options.results_on_every_rank = true;  // one rank: the same results
  options.on_result = [&](std::size_t task, const std::string& result) {
    ++calls;  // one call at a time: no lock needed
    seen.at(task) = result;
  };
  const auto results = run_task_farm(
      session, 40, [](std::size_t i) { return std::to_string(i) + "r"; }, options);
  EXPECT_EQ(calls, 40u);
  EXPECT_EQ(seen, results);
  EXPECT_EQ(results[39], "39r");
  EXPECT_EQ(broadcast_from_root(session, "unchanged"), "unchanged");
}

TEST(TaskFarm, OneProcessCountsEveryTaskOnRankZeroAndNothingSent) {
  const MpiSession session(argc, argv);
  TaskFarmStatistics statistics{.chunks_handed_out = 5, .bytes_broadcast = 9};  // overwritten
  TaskFarmOptions options;
  options.threads = 2;
  options.statistics = &statistics;
  run_task_farm(session, 13, [](std::size_t i) { return std::to_string(i); }, options);
  EXPECT_EQ(statistics.tasks_on_rank0, 13u);
  EXPECT_EQ(statistics.chunks_handed_out, 0u);
  EXPECT_EQ(statistics.bytes_received + statistics.bytes_sent + statistics.bytes_broadcast, 0u);
}

TEST(TaskFarm, InjectedFaultThrowsARunErrorAtItsTask) {
  const MpiSession session(argc, argv);
  setenv("RIDEFIT_TEST_FAULT", "throw:3", 1);
  EXPECT_THROW(run_task_farm(session, 10, [](std::size_t) { return std::string("x"); }), RunError);
  EXPECT_NO_THROW(run_task_farm(session, 3, [](std::size_t) { return std::string("x"); }));
  unsetenv("RIDEFIT_TEST_FAULT");
}

}  // namespace
}  // namespace ridefit::distributed
