#include "ridefit/comfort/vibration_metrics.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "ridefit/common/errors.h"
#include "ridefit/signal/sample_check.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::comfort {
namespace {

void validate(std::span<const double> weighted, double sample_rate_Hz, std::string_view what) {
  if (!std::isfinite(sample_rate_Hz) || sample_rate_Hz <= 0.0) {
    throw InputError(
        fmt::format("{}: sample rate {} Hz is invalid; it must be a positive, finite number of Hz",
                    what, sample_rate_Hz));
  }
  if (weighted.empty()) {
    throw InputError(
        fmt::format("{}: the weighted signal is empty; it needs at least 1 sample", what));
  }
  signal::require_finite_samples(weighted, what, sample_rate_Hz);
}

std::size_t window_samples(std::size_t size, double sample_rate_Hz, double integration_time_s) {
  if (!std::isfinite(integration_time_s) || integration_time_s <= 0.0) {
    throw InputError(fmt::format(
        "running RMS: integration time {} s is invalid; it must be a positive number of seconds "
        "(ISO 2631-1 recommends 1 s)",
        integration_time_s));
  }
  const double samples = std::round(integration_time_s * sample_rate_Hz);
  if (samples < 1.0) {
    throw InputError(fmt::format(
        "running RMS: integration time {} s is shorter than one sample at {} Hz; use at least "
        "{} s",
        integration_time_s, sample_rate_Hz, 1.0 / sample_rate_Hz));
  }
  if (samples > static_cast<double>(size)) {
    throw InputError(fmt::format(
        "running RMS: the record ({} samples, {} s) is shorter than the integration time {} s "
        "({} samples); use a longer record or an integration time of at most {} s",
        size, static_cast<double>(size) / sample_rate_Hz, integration_time_s, samples,
        static_cast<double>(size) / sample_rate_Hz));
  }
  return static_cast<std::size_t>(samples);
}

// Running RMS of a validated record. The window's sum of squares is updated by adding the new
// and subtracting the leaving sample, and recomputed from scratch every window length so that
// round-off from the subtractions cannot accumulate over a long record (nor go negative).
std::vector<double> running_rms_unchecked(std::span<const double> x, double sample_rate_Hz,
                                          double integration_time_s) {
  const std::size_t n = window_samples(x.size(), sample_rate_Hz, integration_time_s);
  const double inv_n = 1.0 / static_cast<double>(n);
  std::vector<double> out(x.size() - n + 1);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += x[i] * x[i];
  out[0] = std::sqrt(sum * inv_n);
  for (std::size_t i = 1; i < out.size(); ++i) {
    if (i % n == 0) {
      sum = 0.0;
      for (std::size_t j = i; j < i + n; ++j) sum += x[j] * x[j];
    } else {
      const double enter = x[i + n - 1], leave = x[i - 1];
      sum = std::max(0.0, sum + enter * enter - leave * leave);
    }
    out[i] = std::sqrt(sum * inv_n);
  }
  return out;
}

double vdv_unchecked(std::span<const double> x, double sample_rate_Hz) {
  double sum = 0.0;
  for (double v : x) {
    const double v2 = v * v;
    sum += v2 * v2;
  }
  return std::pow(sum / sample_rate_Hz, 0.25);
}

double peak_unchecked(std::span<const double> x) {
  double peak = 0.0;
  for (double v : x) peak = std::max(peak, std::abs(v));
  return peak;
}

}  // namespace

double weighted_rms(std::span<const double> weighted, double sample_rate_Hz) {
  validate(weighted, sample_rate_Hz, "weighted RMS");
  return signal::rms(weighted);
}

std::vector<double> running_rms(std::span<const double> weighted, double sample_rate_Hz,
                                double integration_time_s) {
  validate(weighted, sample_rate_Hz, "running RMS");
  return running_rms_unchecked(weighted, sample_rate_Hz, integration_time_s);
}

double maximum_transient_vibration_value(std::span<const double> weighted, double sample_rate_Hz,
                                         double integration_time_s) {
  const std::vector<double> running = running_rms(weighted, sample_rate_Hz, integration_time_s);
  return *std::max_element(running.begin(), running.end());
}

double vibration_dose_value(std::span<const double> weighted, double sample_rate_Hz) {
  validate(weighted, sample_rate_Hz, "vibration dose value");
  return vdv_unchecked(weighted, sample_rate_Hz);
}

double crest_factor(std::span<const double> weighted, double sample_rate_Hz) {
  validate(weighted, sample_rate_Hz, "crest factor");
  const double rms = signal::rms(weighted);
  return rms > 0.0 ? peak_unchecked(weighted) / rms : 0.0;
}

VibrationMetrics vibration_metrics(std::span<const double> weighted, double sample_rate_Hz,
                                   double integration_time_s) {
  validate(weighted, sample_rate_Hz, "vibration metrics");
  VibrationMetrics m;
  m.duration_s = static_cast<double>(weighted.size()) / sample_rate_Hz;
  m.weighted_rms_m_per_s2 = signal::rms(weighted);
  m.peak_m_per_s2 = peak_unchecked(weighted);
  m.crest_factor = m.weighted_rms_m_per_s2 > 0.0 ? m.peak_m_per_s2 / m.weighted_rms_m_per_s2 : 0.0;
  const std::vector<double> running =
      running_rms_unchecked(weighted, sample_rate_Hz, integration_time_s);
  m.mtvv_m_per_s2 = *std::max_element(running.begin(), running.end());
  m.vdv_m_per_s1_75 = vdv_unchecked(weighted, sample_rate_Hz);
  m.integration_time_s = integration_time_s;
  return m;
}

}  // namespace ridefit::comfort
