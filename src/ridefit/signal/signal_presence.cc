#include "ridefit/signal/signal_presence.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::signal {

double no_signal_floor(const std::string& si_unit, std::span<const double> values) {
  double largest = 0.0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  double floor = 0.0;
  if (si_unit == "m/s^2") {
    floor = 1e-6;
  } else if (si_unit == "m") {
    floor = 1e-8;
  } else if (si_unit == "N") {
    floor = 1e-4;
  }
  return std::max(floor, 1e-9 * largest);
}

void require_signal(std::span<const double> values, const std::string& source,
                    const std::string& channel, const std::string& si_unit) {
  if (values.empty()) return;
  double mean = 0.0;
  for (double v : values) mean += v;
  mean /= static_cast<double>(values.size());
  double sum = 0.0;
  for (double v : values) sum += (v - mean) * (v - mean);
  const double deviation = std::sqrt(sum / static_cast<double>(values.size()));
  if (!std::isfinite(deviation)) return;  // non-finite samples are the readers' to report
  const double floor = no_signal_floor(si_unit, values);
  if (deviation > floor) return;
  throw InputError(fmt::format(
      "{}: channel {} carries no signal: {} (standard deviation {:.3g} {} about its mean "
      "{:.6g} {}, at or below the floor of {:.3g} {}); check the sensor and the logger, or leave "
      "the channel out",
      source, channel, deviation == 0.0 && mean == 0.0 ? "every sample is zero" : "it is constant",
      deviation, si_unit, mean, si_unit, floor, si_unit));
}

}  // namespace ridefit::signal
