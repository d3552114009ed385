#include "ridefit/signal/hann_window.h"

#include <cmath>
#include <numbers>

namespace ridefit::signal {

std::vector<double> periodic_hann_window(std::size_t length) {
  std::vector<double> window(length);
  const double step = 2.0 * std::numbers::pi / static_cast<double>(length);
  for (std::size_t n = 0; n < length; ++n) {
    window[n] = 0.5 - 0.5 * std::cos(step * static_cast<double>(n));
  }
  return window;
}

}  // namespace ridefit::signal
