#include "ridefit/signal/noise_floor.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {
namespace {

// Nonnegative weighted least squares of p ≈ a·g + n over the bins: the unconstrained solution
// of the 2×2 normal equations, or the better one-parameter fit when it leaves the quadrant.
void fit_power_law_and_floor(const std::vector<double>& p, const std::vector<double>& g,
                             const std::vector<double>& weight, double& a, double& n) {
  double sgg = 0.0, sg = 0.0, s1 = 0.0, sgp = 0.0, sp = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    sgg += weight[k] * g[k] * g[k];
    sg += weight[k] * g[k];
    s1 += weight[k];
    sgp += weight[k] * g[k] * p[k];
    sp += weight[k] * p[k];
  }
  const double det = sgg * s1 - sg * sg;
  a = det > 0.0 ? (sgp * s1 - sg * sp) / det : -1.0;
  n = det > 0.0 ? (sgg * sp - sg * sgp) / det : -1.0;
  if (a >= 0.0 && n >= 0.0) return;
  auto cost = [&](double aa, double nn) {
    double c = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const double r = p[k] - aa * g[k] - nn;
      c += weight[k] * r * r;
    }
    return c;
  };
  const double a_only = std::max(0.0, sgp / sgg), n_only = std::max(0.0, sp / s1);
  if (cost(a_only, 0.0) < cost(0.0, n_only)) {
    a = a_only;
    n = 0.0;
  } else {
    a = 0.0;
    n = n_only;
  }
}

}  // namespace

double estimate_white_noise_floor(std::span<const double> series, double sample_rate_Hz,
                                  double above_Hz) {
  if (series.size() < 64) {
    throw InputError(
        fmt::format("noise floor: {} samples; the estimate needs at least 64", series.size()));
  }
  if (!(sample_rate_Hz > 0.0) || !std::isfinite(sample_rate_Hz)) {
    throw InputError(
        fmt::format("noise floor: sample rate {} Hz, expected a finite value > 0", sample_rate_Hz));
  }
  if (!(above_Hz >= 0.0) || !(above_Hz < 0.45 * sample_rate_Hz)) {
    throw InputError(fmt::format(
        "noise floor: the band's top {} Hz leaves no room below the Nyquist frequency {} Hz to "
        "see the sensor noise (it must be below {} Hz); give the floor instead",
        above_Hz, 0.5 * sample_rate_Hz, 0.45 * sample_rate_Hz));
  }
  WelchOptions welch;
  welch.segment_length_samples = std::max<std::size_t>(
      16, std::min(static_cast<std::size_t>(std::lround(sample_rate_Hz)), series.size() / 8));
  const PowerSpectralDensity psd = welch_psd(series, sample_rate_Hz, welch);
  std::vector<double> f, p;
  for (std::size_t k = 1; k + 1 < psd.frequency_Hz.size(); ++k) {  // neither DC nor Nyquist
    if (psd.frequency_Hz[k] > above_Hz) {
      f.push_back(psd.frequency_Hz[k]);
      p.push_back(psd.psd[k]);
    }
  }
  if (f.size() < 8) {
    throw InputError(fmt::format("noise floor: {} PSD bins above {} Hz; the estimate needs 8",
                                 f.size(), above_Hz));
  }
  const double reference_Hz = std::max(above_Hz, f.front());
  // The starting weights: a 5-bin running median as the level (one bin's χ² scatter must not
  // weigh itself).
  std::vector<double> level(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) {
    const std::size_t lo = k >= 2 ? k - 2 : 0, hi = std::min(p.size(), k + 3);
    std::vector<double> window(p.begin() + static_cast<std::ptrdiff_t>(lo),
                               p.begin() + static_cast<std::ptrdiff_t>(hi));
    std::nth_element(window.begin(),
                     window.begin() + static_cast<std::ptrdiff_t>(window.size() / 2), window.end());
    level[k] = std::max(window[window.size() / 2], 1e-300);
  }
  double best_cost = std::numeric_limits<double>::infinity(), best_floor = 0.0;
  std::vector<double> g(p.size()), weight(p.size());
  for (double exponent = 0.5; exponent <= 8.0; exponent += 0.5) {
    for (std::size_t k = 0; k < p.size(); ++k) g[k] = std::pow(f[k] / reference_Hz, -exponent);
    std::vector<double> model = level;
    double a = 0.0, n = 0.0;
    for (int iteration = 0; iteration < 4; ++iteration) {
      for (std::size_t k = 0; k < p.size(); ++k) weight[k] = 1.0 / (model[k] * model[k]);
      fit_power_law_and_floor(p, g, weight, a, n);
      for (std::size_t k = 0; k < p.size(); ++k) model[k] = std::max(a * g[k] + n, 1e-300);
    }
    double cost = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const double r = p[k] / model[k] - 1.0;
      cost += r * r;
    }
    if (cost < best_cost) {
      best_cost = cost;
      best_floor = n;
    }
  }
  return best_floor;
}

}  // namespace ridefit::signal
