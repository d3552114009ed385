#include "ridefit/common/parallel_for.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace ridefit::common {

void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                  const std::function<void(std::size_t)>& done) {
  std::atomic<std::size_t> next{0};
  // The lowest failing index: indices above it are skipped, those below still run, so the
  // error reported is the same however the threads interleave.
  std::atomic<std::size_t> first_failure{count};
  std::mutex mutex;
  std::exception_ptr failure;
  auto worker = [&] {
    for (std::size_t i = next++; i < count && i < first_failure; i = next++) {
      try {
        body(i);
        if (done) {
          const std::lock_guard<std::mutex> lock(mutex);
          done(i);
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (i < first_failure) {
          first_failure = i;
          failure = std::current_exception();
        }
      }
    }
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const auto pool_size = static_cast<unsigned>(
      std::min<std::size_t>(threads ? threads : cores, std::max<std::size_t>(count, 1)));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < pool_size; ++t) pool.emplace_back(worker);
  worker();
  for (auto& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace ridefit::common
