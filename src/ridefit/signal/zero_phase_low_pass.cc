#include "ridefit/signal/zero_phase_low_pass.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "ridefit/common/errors.h"
#include "ridefit/signal/biquad_cascade.h"

namespace ridefit::signal {
namespace {

// One pass from steady state at the first value: the filter's DC gain is 1, so filtering
// x − x₀ from rest and adding x₀ back is the response of a filter that has sat at x₀ forever.
void steady_state_pass(const BiquadCascade& filter, std::vector<double>& x) {
  const double start = x.front();
  for (double& v : x) v -= start;
  filter.filter_in_place(x);
  for (double& v : x) v += start;
}

}  // namespace

std::vector<double> zero_phase_low_pass(std::span<const double> signal, double sample_rate_Hz,
                                        double cutoff_Hz) {
  const std::size_t n = signal.size();
  if (n < 4) {
    throw InputError(fmt::format("zero-phase low-pass: {} samples, expected at least 4", n));
  }
  if (!(std::isfinite(sample_rate_Hz) && sample_rate_Hz > 0.0)) {
    throw InputError(
        fmt::format("zero-phase low-pass: sample rate {} Hz, expected a positive, finite rate",
                    sample_rate_Hz));
  }
  if (!(cutoff_Hz > 0.0 && cutoff_Hz < 0.5 * sample_rate_Hz)) {
    throw InputError(
        fmt::format("zero-phase low-pass: cut-off {} Hz, expected a value in (0, {} Hz), below "
                    "half the sample rate",
                    cutoff_Hz, 0.5 * sample_rate_Hz));
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(signal[k])) {
      throw InputError(fmt::format("zero-phase low-pass: sample {} is {}", k, signal[k]));
    }
  }
  // H(s) = ω²/(s² + √2·ω·s + ω²), pre-warped at the cut-off.
  const double w = 2.0 * std::numbers::pi * cutoff_Hz;
  const AnalogueSection butterworth{
      {w * w, 0.0, 0.0}, {w * w, std::numbers::sqrt2 * w, 1.0}, cutoff_Hz};
  const BiquadCascade filter = BiquadCascade::from_analogue({&butterworth, 1}, sample_rate_Hz);
  const std::size_t pad =
      std::min(n - 1, static_cast<std::size_t>(std::ceil(6.0 * sample_rate_Hz / cutoff_Hz)));
  std::vector<double> x;
  x.reserve(n + 2 * pad);
  for (std::size_t k = pad; k >= 1; --k) x.push_back(2.0 * signal[0] - signal[k]);
  x.insert(x.end(), signal.begin(), signal.end());
  for (std::size_t k = 1; k <= pad; ++k) x.push_back(2.0 * signal[n - 1] - signal[n - 1 - k]);
  steady_state_pass(filter, x);
  std::reverse(x.begin(), x.end());
  steady_state_pass(filter, x);
  std::reverse(x.begin(), x.end());
  return {x.begin() + static_cast<std::ptrdiff_t>(pad),
          x.begin() + static_cast<std::ptrdiff_t>(pad + n)};
}

}  // namespace ridefit::signal
