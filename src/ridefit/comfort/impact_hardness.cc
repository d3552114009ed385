#include "ridefit/comfort/impact_hardness.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/signal/sample_check.h"
#include "ridefit/signal/statistics.h"

namespace ridefit::comfort {
namespace {

constexpr const char* kCaller = "impact hardness";

struct Extremum {
  std::size_t index;
  bool is_max;
};

void check_fraction(double fraction, const char* name) {
  if (!(fraction > 0.0 && fraction < 1.0)) {
    throw InputError(
        fmt::format("{}: {} is {}; it must lie in (0, 1), a fraction of the "
                    "record's peak |a|",
                    kCaller, name, fraction));
  }
}

// Alternating maxima and minima from `start` on, with swings of more than `delta`.
std::vector<Extremum> zigzag_extrema(std::span<const double> a, std::size_t start, double delta) {
  std::vector<Extremum> extrema;
  std::size_t hi = start;
  std::size_t lo = start;
  int direction = 0;  // 0: none confirmed yet; +1: seeking a maximum; −1: seeking a minimum
  for (std::size_t i = start; i < a.size(); ++i) {
    if (a[i] > a[hi]) hi = i;
    if (a[i] < a[lo]) lo = i;
    if (direction >= 0 && a[i] < a[hi] - delta) {
      extrema.push_back({hi, true});
      direction = -1;
      lo = i;
    } else if (direction <= 0 && a[i] > a[lo] + delta) {
      extrema.push_back({lo, false});
      direction = +1;
      hi = i;
    }
  }
  return extrema;
}

}  // namespace

ImpactHardness impact_hardness(std::span<const double> acceleration, double sample_rate_Hz,
                               const ImpactHardnessOptions& options) {
  signal::check_samples(kCaller, acceleration, 3);
  signal::check_sample_rate(kCaller, sample_rate_Hz);
  check_fraction(options.onset_fraction, "onset_fraction");
  check_fraction(options.prominence_fraction, "prominence_fraction");
  const auto time_of = [&](std::size_t i) { return static_cast<double>(i) / sample_rate_Hz; };

  double peak = 0.0;
  for (double v : acceleration) peak = std::max(peak, std::abs(v));
  if (peak == 0.0) {
    throw InputError(
        fmt::format("{}: the record is zero everywhere; there is no obstacle response", kCaller));
  }
  const double threshold = options.onset_fraction * peak;
  const auto onset =
      static_cast<std::size_t>(std::find_if(acceleration.begin(), acceleration.end(),
                                            [&](double v) { return std::abs(v) >= threshold; }) -
                               acceleration.begin());
  if (onset == 0) {
    throw InputError(fmt::format(
        "{}: the first sample, |a| = {:g}, already reaches the onset threshold "
        "onset_fraction·max|a| = {:g}; the record must start before the obstacle with a quiet "
        "lead-in (or raise onset_fraction above the lead-in's noise)",
        kCaller, std::abs(acceleration[0]), threshold));
  }

  const double delta = options.prominence_fraction * peak;
  const auto extrema = zigzag_extrema(acceleration, onset, delta);
  // The first peak of the wanted sign after position `from` in `extrema`.
  const auto next_peak = [&](std::size_t from, bool positive) -> std::optional<std::size_t> {
    for (std::size_t e = from; e < extrema.size(); ++e) {
      const double v = acceleration[extrema[e].index];
      if (positive && extrema[e].is_max && v >= delta) return e;
      if (!positive && !extrema[e].is_max && v <= -delta) return e;
    }
    return std::nullopt;
  };
  const auto peak_at = [&](std::size_t e) {
    const std::size_t i = extrema[e].index;
    return SignalPeak{i, time_of(i), acceleration[i]};
  };
  const auto missing = [&](const char* what, const char* after, double after_s) {
    return InputError(fmt::format(
        "{}: no obstacle response: no {} (a peak reaching ±{:g} = prominence_fraction·max|a| "
        "with swings of more than that on both sides) after the {} at t = {:g} s; the record "
        "may end too early or hold no single obstacle",
        kCaller, what, delta, after, after_s));
  };

  const auto p1 = next_peak(0, true);
  if (!p1) throw missing("first positive peak", "onset", time_of(onset));
  const auto n1 = next_peak(*p1 + 1, false);
  if (!n1) {
    throw missing("first negative peak", "first positive peak", time_of(extrema[*p1].index));
  }
  const auto p2 = next_peak(*n1 + 1, true);
  const auto n2 = p2 ? next_peak(*p2 + 1, false) : std::nullopt;
  if (!n2) {
    throw missing("second negative peak (after a positive one)", "first negative peak",
                  time_of(extrema[*n1].index));
  }

  ImpactHardness result;
  result.onset_index = onset;
  result.onset_time_s = time_of(onset);
  result.first_positive_peak = peak_at(*p1);
  result.first_negative_peak = peak_at(*n1);
  result.second_negative_peak = peak_at(*n2);
  result.peak_to_peak = result.first_positive_peak.value - result.first_negative_peak.value;
  result.rms =
      signal::rms(acceleration.subspan(onset, result.second_negative_peak.index - onset + 1));
  return result;
}

}  // namespace ridefit::comfort
