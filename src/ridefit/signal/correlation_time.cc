#include "ridefit/signal/correlation_time.h"

#include <algorithm>

namespace ridefit::signal {

double correlation_time_samples(std::span<const double> r) {
  const std::size_t n = r.size();
  if (n < 4) return 1.0;
  double mean = 0.0;
  for (double v : r) mean += v;
  mean /= static_cast<double>(n);
  double c0 = 0.0;
  for (double v : r) c0 += (v - mean) * (v - mean);
  if (!(c0 > 0.0)) return 1.0;
  auto rho = [&](std::size_t lag) {
    double c = 0.0;
    for (std::size_t k = lag; k < n; ++k) c += (r[k] - mean) * (r[k - lag] - mean);
    return c / c0;
  };
  // Γ_m = ρ_2m + ρ_2m+1, summed while positive; τ = −1 + 2·ΣΓ.
  double sum = 0.0;
  for (std::size_t m = 0; 2 * m + 1 < n / 2; ++m) {
    const double pair = (m == 0 ? 1.0 : rho(2 * m)) + rho(2 * m + 1);
    if (!(pair > 0.0)) break;
    sum += pair;
  }
  return std::clamp(2.0 * sum - 1.0, 1.0, static_cast<double>(n));
}

double pooled_correlation_time_samples(std::span<const double> series,
                                       std::span<const std::size_t> lengths) {
  double weighted = 0.0;
  std::size_t first = 0;
  for (const std::size_t n : lengths) {
    if (first + n > series.size()) break;
    weighted += correlation_time_samples(series.subspan(first, n)) * static_cast<double>(n);
    first += n;
  }
  return first > 0 ? std::max(weighted / static_cast<double>(first), 1.0) : 1.0;
}

}  // namespace ridefit::signal
