// parallel_for: every index once, and the same error whatever the interleaving.
#include "ridefit/common/parallel_for.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

namespace ridefit::common {
namespace {

TEST(ParallelFor, RunsEveryIndexOnceAndRethrowsTheFirstFailure) {
  for (unsigned threads : {1u, 2u}) {
    std::vector<int> hits(100, 0);
    std::atomic<int> calls{0};
    parallel_for(
        hits.size(), threads, [&](std::size_t i) { ++hits[i]; }, [&](std::size_t) { ++calls; });
    for (int h : hits) EXPECT_EQ(h, 1);
    EXPECT_EQ(calls.load(), 100);
    // The lowest failing index is reported, whatever the interleaving.
    try {
      parallel_for(50, threads, [](std::size_t i) {
        if (i == 7 || i == 3 || i == 40) throw std::runtime_error(std::to_string(i));
      });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "3");
    }
  }
}

}  // namespace
}  // namespace ridefit::common
