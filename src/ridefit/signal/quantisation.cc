#include "ridefit/signal/quantisation.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {
namespace {

// RMS of the quantisation's forward-difference velocity under the forward-backward low-pass
// (cut-off 0: unfiltered), by the midpoint rule over (0, fs/2).
double velocity_noise_rms(double step, double fs, double cutoff_Hz) {
  const int bins = 4000;
  const double df = 0.5 * fs / bins, density = step * step / (6.0 * fs);
  double variance = 0.0;
  for (int k = 0; k < bins; ++k) {
    const double f = (k + 0.5) * df;
    const double s = 2.0 * fs * std::sin(std::numbers::pi * f / fs);
    double gain = 1.0;
    if (cutoff_Hz > 0.0) {
      const double h2 = 1.0 / (1.0 + std::pow(f / cutoff_Hz, 4));
      gain = h2 * h2;
    }
    variance += density * s * s * gain * df;
  }
  return std::sqrt(variance);
}

}  // namespace

double quantisation_step(std::span<const double> series) {
  std::vector<double> v(series.begin(), series.end());
  std::sort(v.begin(), v.end());
  if (v.empty() || !std::isfinite(v.front()) || !std::isfinite(v.back())) return 0.0;
  const double range = v.back() - v.front();
  if (!(range > 0.0)) return 0.0;
  std::vector<double> gaps;
  for (std::size_t k = 1; k < v.size(); ++k) {
    const double gap = v[k] - v[k - 1];
    if (gap > 1e-12 * range) gaps.push_back(gap);
  }
  if (gaps.size() < 7) return 0.0;
  const double smallest = *std::min_element(gaps.begin(), gaps.end());
  std::vector<double> near;
  for (double g : gaps) {
    if (g <= 1.5 * smallest) near.push_back(g);
  }
  std::nth_element(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(near.size() / 2),
                   near.end());
  double step = near[near.size() / 2];
  // Refined by least squares over ever larger multiples: a record moving many steps per sample
  // has gaps of tens of steps, which judge the step only once it is known to a fraction of a
  // per cent (printing to a coarser format rounds each gap by up to one print digit).
  for (const double most : {2.0, 8.0, 64.0, 1e9}) {
    double gm = 0.0, mm = 0.0;
    for (double g : gaps) {
      const double m = std::round(g / step);
      if (m >= 1.0 && m <= most) gm += g * m, mm += m * m;
    }
    if (mm > 0.0) step = gm / mm;
  }
  std::size_t on_lattice = 0;
  for (double g : gaps) {
    const double m = std::max(1.0, std::round(g / step));
    if (std::abs(g - m * step) <= 0.1 * step) ++on_lattice;
  }
  return static_cast<double>(on_lattice) >= 0.95 * static_cast<double>(gaps.size()) ? step : 0.0;
}

QuantisationLowPass choose_quantisation_low_pass(std::span<const double> time_s,
                                                 std::span<const double> series) {
  QuantisationLowPass out;
  const std::size_t n = std::min(time_s.size(), series.size());
  if (n < 64) {
    out.reason = fmt::format("{} samples: too short to examine", n);
    return out;
  }
  out.step = quantisation_step(series.first(n));
  if (out.step == 0.0) {
    out.reason = "not quantised (its values lie on no common step)";
    return out;
  }
  const double mean_step = (time_s[n - 1] - time_s[0]) / static_cast<double>(n - 1);
  double shortest = mean_step, longest = mean_step;
  for (std::size_t k = 1; k < n; ++k) {
    shortest = std::min(shortest, time_s[k] - time_s[k - 1]);
    longest = std::max(longest, time_s[k] - time_s[k - 1]);
  }
  const double fs = 1.0 / mean_step;
  out.velocity_noise_rms_before = velocity_noise_rms(out.step, fs, 0.0);
  out.velocity_noise_rms_after = out.velocity_noise_rms_before;
  if (shortest < 0.75 * mean_step || longest > 1.25 * mean_step) {
    out.reason = fmt::format(
        "its time steps run from {:.3g} to {:.3g} s around a mean of {:.3g} s: too uneven for a "
        "filter of the mean step",
        shortest, longest, mean_step);
    return out;
  }
  std::vector<double> velocity(n - 1);
  for (std::size_t k = 0; k + 1 < n; ++k) velocity[k] = (series[k + 1] - series[k]) * fs;
  const PowerSpectralDensity psd = welch_psd(velocity, fs);
  const double density = out.step * out.step / (6.0 * fs);
  // Tail sums from the top: above the content, the record's velocity power is the steps' alone
  // (a sine whose period is a whole number of samples puts it in lines, not a flat floor: the
  // sums hold either way).
  const std::size_t bins = psd.psd.size();
  std::vector<double> record_tail(bins + 1, 0.0), floor_tail(bins + 1, 0.0);
  for (std::size_t k = bins; k-- > 1;) {
    const double s = 2.0 * fs * std::sin(std::numbers::pi * psd.frequency_Hz[k] / fs);
    record_tail[k] = record_tail[k + 1] + psd.psd[k];
    floor_tail[k] = floor_tail[k + 1] + density * s * s;
  }
  out.content_up_to_Hz = 0.5 * fs;
  for (std::size_t k = 1; k < bins; ++k) {
    if (record_tail[k] <= 2.0 * floor_tail[k]) {
      out.content_up_to_Hz = psd.frequency_Hz[k];
      break;
    }
  }
  const double cutoff = 10.0 * std::max(out.content_up_to_Hz, psd.frequency_resolution_Hz);
  if (cutoff >= 0.4 * fs) {
    out.reason = fmt::format(
        "its content stands above the quantisation floor up to {:.4g} Hz, near half the "
        "{:.4g} Hz sample rate: nothing to remove",
        out.content_up_to_Hz, fs);
    return out;
  }
  out.cutoff_Hz = cutoff;
  out.velocity_noise_rms_after = velocity_noise_rms(out.step, fs, cutoff);
  return out;
}

}  // namespace ridefit::signal
