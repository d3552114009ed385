#include "ridefit/study/quarter_car_metrics.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/comfort/tyre_load_metrics.h"
#include "ridefit/comfort/weighting_filter.h"
#include "ridefit/common/errors.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::study {

std::vector<std::pair<std::string, double>> QuarterCarMetrics::named() const {
  return {{"body_acc_wk_rms_m_per_s2", body_acc_wk_rms_m_per_s2},
          {"body_acc_rms_m_per_s2", body_acc_rms_m_per_s2},
          {"wheel_acc_rms_m_per_s2", wheel_acc_rms_m_per_s2},
          {"travel_rms_m", travel_rms_m},
          {"travel_peak_m", travel_peak_m},
          {"tyre_force_rms_N", tyre_force_rms_N},
          {"dynamic_load_ratio", dynamic_load_ratio},
          {"stuck_share", stuck_share}};
}

QuarterCarMetrics quarter_car_metrics(const simulate::QuarterCarResponse& response,
                                      const model::QuarterCarParameters<double>& parameters,
                                      double settle_s) {
  const auto& t = response.time_s;
  if (t.size() < 2) throw InputError("quarter-car metrics: a run needs 2 samples");
  const double fs = 1.0 / (t[1] - t[0]);
  const auto first =
      static_cast<std::ptrdiff_t>(std::lower_bound(t.begin(), t.end(), settle_s) - t.begin());
  if (static_cast<std::ptrdiff_t>(t.size()) - first < 2) {
    throw InputError(
        fmt::format("quarter-car metrics: nothing left after the first {} s", settle_s));
  }
  auto tail = [&](const std::vector<double>& values) {
    return std::span<const double>(values.data() + first,
                                   values.size() - static_cast<std::size_t>(first));
  };
  QuarterCarMetrics m;
  const std::vector<double> weighted =
      comfort::apply_weighting(comfort::Weighting::kWk, response.body_acc_m_per_s2, fs);
  m.body_acc_wk_rms_m_per_s2 = signal::rms(tail(weighted));
  m.body_acc_rms_m_per_s2 = signal::rms(tail(response.body_acc_m_per_s2));
  m.wheel_acc_rms_m_per_s2 = signal::rms(tail(response.wheel_acc_m_per_s2));
  m.travel_rms_m = signal::rms(tail(response.travel_m));
  for (double z : tail(response.travel_m)) m.travel_peak_m = std::max(m.travel_peak_m, std::abs(z));
  m.tyre_force_rms_N = signal::rms(tail(response.tyre_force_N));
  m.dynamic_load_ratio = m.tyre_force_rms_N / comfort::static_tyre_load_N(parameters);
  const auto stuck = tail(response.stuck);
  double stuck_samples = 0.0;
  for (double s : stuck) stuck_samples += s;
  m.stuck_share = stuck_samples / static_cast<double>(stuck.size());
  return m;
}

}  // namespace ridefit::study
