#pragma once

#include <cstddef>
#include <functional>

namespace ridefit::study {

// Runs body(i) for i = 0 … count−1 on `threads` threads (0 = every core), each thread taking the
// next index from a shared counter, so uneven runs balance themselves. `done` (may be empty) is
// called after each finished index, under a lock (one call at a time). The first exception
// thrown by a body is rethrown once all threads have stopped; the indices not yet started are
// skipped then.
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& body,
                  const std::function<void(std::size_t index)>& done = {});

}  // namespace ridefit::study
