#include "ridefit/comfort/tyre_load_metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/sample_check.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::comfort {

double static_tyre_load_N(const model::QuarterCarParameters<double>& parameters) {
  return parameters.static_tyre_load_N();
}

TyreLoadMetrics tyre_load_metrics(std::span<const double> dynamic_tyre_force_N,
                                  double static_load_N) {
  constexpr const char* kCaller = "tyre load metrics";
  signal::check_samples(kCaller, dynamic_tyre_force_N, 1);
  if (!std::isfinite(static_load_N) || static_load_N <= 0.0) {
    throw InputError(
        fmt::format("{}: static tyre load {} N is invalid; it must be positive and finite, e.g. "
                    "(sprung + unsprung mass)·g",
                    kCaller, static_load_N));
  }
  TyreLoadMetrics result;
  result.static_load_N = static_load_N;
  result.dynamic_load_rms_N = signal::rms(dynamic_tyre_force_N);
  result.relative_dynamic_load = result.dynamic_load_rms_N / static_load_N;
  const auto lifted = std::count_if(dynamic_tyre_force_N.begin(), dynamic_tyre_force_N.end(),
                                    [&](double f) { return static_load_N + f <= 0.0; });
  result.lift_off_share =
      static_cast<double>(lifted) / static_cast<double>(dynamic_tyre_force_N.size());
  result.min_total_load_N =
      static_load_N + *std::min_element(dynamic_tyre_force_N.begin(), dynamic_tyre_force_N.end());
  return result;
}

}  // namespace ridefit::comfort
