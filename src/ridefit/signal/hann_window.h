#pragma once

#include <cstddef>
#include <vector>

namespace ridefit::signal {

// The periodic Hann window of `length` samples, w[n] = 0.5 − 0.5·cos(2πn/L), n = 0 … L−1: the
// (L+1)-point symmetric window without its last sample, so that copies shifted by L/2 sum to a
// constant (the window Welch segments use). An empty vector for length 0.
std::vector<double> periodic_hann_window(std::size_t length);

}  // namespace ridefit::signal
