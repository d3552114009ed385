#include "ridefit/signal/uniform_sample_rate.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ridefit/common/errors.h"

namespace ridefit::signal {

double uniform_sample_rate_Hz(std::span<const double> time_s, const std::string& source,
                              double tolerance) {
  if (time_s.size() < 2) {
    throw InputError(
        fmt::format("{}: {} time sample(s); a signal needs at least 2", source, time_s.size()));
  }
  std::vector<double> steps(time_s.size() - 1);
  for (std::size_t i = 0; i + 1 < time_s.size(); ++i) steps[i] = time_s[i + 1] - time_s[i];
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  if (!(median > 0.0) || !std::isfinite(median)) {
    throw InputError(fmt::format("{}: time does not increase (median step {} s)", source, median));
  }
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (!(std::abs(steps[i] - median) <= tolerance * median)) {
      throw InputError(fmt::format(
          "{}: row {}: time step {:.6g} s differs from the median step {:.6g} s by more than "
          "{:g} %; spectra and filters need uniform sampling: resample the data to {:.6g} Hz",
          source, i + 3, steps[i], median, 100.0 * tolerance, 1.0 / median));
    }
  }
  // The mean step over the record: exact for uniform data, and unbiased by rounding jitter.
  return static_cast<double>(steps.size()) / (time_s.back() - time_s.front());
}

}  // namespace ridefit::signal
