#include "ridefit/signal/detrend.h"

#include <fmt/format.h>

#include <cstddef>

#include "ridefit/common/errors.h"

namespace ridefit::signal {

void detrend_in_place(std::span<double> samples, Detrend detrend) {
  if (detrend == Detrend::kNone || samples.empty()) return;
  const double n = static_cast<double>(samples.size());
  double sum = 0.0;
  for (double x : samples) sum += x;
  const double mean = sum / n;
  if (detrend == Detrend::kMean) {
    for (double& x : samples) x -= mean;
    return;
  }
  // Least-squares line about the centred abscissa t = i − (n−1)/2, so that the intercept is
  // the mean and the slope decouples: slope = Σ t·x / Σ t², Σ t² = n(n²−1)/12.
  const double centre = 0.5 * (n - 1.0);
  double sum_tx = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    sum_tx += (static_cast<double>(i) - centre) * samples[i];
  }
  const double sum_tt = n * (n * n - 1.0) / 12.0;
  const double slope = sum_tt > 0.0 ? sum_tx / sum_tt : 0.0;  // one sample: no slope
  for (std::size_t i = 0; i < samples.size(); ++i) {
    samples[i] -= mean + slope * (static_cast<double>(i) - centre);
  }
}

const char* to_string(Detrend detrend) {
  switch (detrend) {
    case Detrend::kNone:
      return "none";
    case Detrend::kMean:
      return "mean";
    case Detrend::kLinear:
      return "linear";
  }
  return "unknown";
}

Detrend parse_detrend(std::string_view name) {
  if (name == "none") return Detrend::kNone;
  if (name == "mean") return Detrend::kMean;
  if (name == "linear") return Detrend::kLinear;
  throw InputError(fmt::format("unknown detrend '{}'; use one of: none, mean, linear", name));
}

}  // namespace ridefit::signal
