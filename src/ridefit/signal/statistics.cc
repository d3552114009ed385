#include "ridefit/signal/statistics.h"

#include <cmath>

namespace ridefit::signal {

double rms(std::span<const double> values) {
  if (values.empty()) return 0.0;
  double sum = 0.0;
  for (double v : values) sum += v * v;
  return std::sqrt(sum / static_cast<double>(values.size()));
}

}  // namespace ridefit::signal
