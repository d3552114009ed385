#pragma once

#include <cstddef>
#include <functional>

namespace ridefit::common {

// Runs body(i) for i = 0 … count−1 on `threads` threads (0 = every core), each thread taking the
// next index from a shared counter, so uneven runs balance themselves. `done` (may be empty) is
// called after each finished index, under a lock (one call at a time). When bodies throw, the
// exception of the lowest failing index is rethrown once all threads have stopped (indices
// above it are skipped, those below it all run), so the error does not depend on timing.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                  const std::function<void(std::size_t index)>& done = {});

}  // namespace ridefit::common
