#include "ridefit/road/iso8608_classification.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/road/power_law_spectrum.h"
#include "ridefit/signal/psd_confidence.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::road {

Iso8608Class iso8608_class_of(double reference_psd_m3) {
  constexpr int kLast = static_cast<int>(Iso8608Class::kH);
  for (int c = 0; c < kLast; ++c) {
    const auto road_class = static_cast<Iso8608Class>(c);
    if (reference_psd_m3 < 2.0 * iso8608_reference_psd_m3(road_class)) return road_class;
  }
  return Iso8608Class::kH;
}

Iso8608Classification classify_iso8608(const RoadProfile& profile,
                                       const Iso8608ClassificationOptions& options) {
  check_road_profile(profile, 4);
  const double length = profile_length_m(profile);
  const double spacing = options.spacing_m > 0.0 ? options.spacing_m : nominal_spacing_m(profile);
  if (!std::isfinite(options.spacing_m) || options.spacing_m < 0.0) {
    throw InputError(
        fmt::format("ISO 8608 classification: spacing {} m is invalid", options.spacing_m));
  }
  const double segment =
      options.segment_length_m > 0.0 ? options.segment_length_m : std::min(100.0, length / 4.0);
  if (!std::isfinite(options.segment_length_m) || options.segment_length_m < 0.0) {
    throw InputError(fmt::format("ISO 8608 classification: PSD segment length {} m is invalid",
                                 options.segment_length_m));
  }
  if (segment > length) {
    throw InputError(fmt::format(
        "ISO 8608 classification: the PSD segment ({} m) is longer than the profile ({} m)",
        segment, length));
  }
  if (segment < 8.0 * spacing) {
    throw InputError(fmt::format(
        "ISO 8608 classification: a PSD segment of {} m holds under 8 samples at {} m spacing; "
        "the profile ({} m) is too short or too coarse",
        segment, spacing, length));
  }
  const RoadProfile grid = is_uniform(profile, spacing) ? profile : uniform(profile, spacing);

  signal::WelchOptions welch;
  welch.segment_length_s = segment;  // "seconds" are metres at a sample rate of 1/spacing
  welch.overlap_fraction = 0.5;
  welch.detrend = signal::Detrend::kLinear;
  const signal::PowerSpectralDensity psd =
      signal::welch_psd(grid.elevation_m, 1.0 / spacing, welch);
  const signal::PsdConfidenceInterval interval =
      signal::psd_confidence_interval(psd, options.confidence);

  Iso8608Classification result;
  result.spatial_frequency_cycles_per_m = psd.frequency_Hz;
  result.psd_m3 = psd.psd;
  result.psd_lower_m3 = interval.lower;
  result.psd_upper_m3 = interval.upper;
  result.confidence = options.confidence;
  result.spacing_m = spacing;
  result.segment_length_m = static_cast<double>(psd.segment_length_samples) * spacing;

  const SpatialBand iso_band;
  result.band_low_cycles_per_m = std::max(iso_band.low_cycles_per_m, 1.0 / result.segment_length_m);
  result.band_high_cycles_per_m = std::min(iso_band.high_cycles_per_m, 0.5 / spacing);

  // log G(n) = log G(n0) − w·log(n/n0): sums for the fixed and the free fit.
  const double n0 = kIso8608ReferenceCyclesPerM;
  double sum_u = 0.0, sum_v = 0.0, sum_uu = 0.0, sum_uv = 0.0, sum_fixed = 0.0;
  std::size_t count = 0;
  for (std::size_t k = 1; k < psd.psd.size(); ++k) {
    const double n = psd.frequency_Hz[k];
    const double tolerance = 1e-9 * n;
    if (n < result.band_low_cycles_per_m - tolerance) continue;
    if (n > result.band_high_cycles_per_m + tolerance) continue;
    if (!(psd.psd[k] > 0.0)) continue;
    const double u = std::log(n / n0);
    const double v = std::log(psd.psd[k]);
    sum_u += u;
    sum_v += v;
    sum_uu += u * u;
    sum_uv += u * v;
    sum_fixed += v + 2.0 * u;
    ++count;
  }
  if (count < 2) {
    throw InputError(fmt::format(
        "ISO 8608 classification: only {} PSD bins between {:g} and {:g} cycles/m; the profile "
        "({} m at {} m spacing, {} m segments) does not resolve ISO 8608's 0.011–2.83 "
        "cycles/m band",
        count, result.band_low_cycles_per_m, result.band_high_cycles_per_m, length, spacing,
        result.segment_length_m));
  }
  const auto m = static_cast<double>(count);
  result.fit_bins = count;
  result.reference_psd_m3 = std::exp(sum_fixed / m);
  result.road_class = iso8608_class_of(result.reference_psd_m3);
  const double slope = (m * sum_uv - sum_u * sum_v) / (m * sum_uu - sum_u * sum_u);
  result.waviness = -slope;
  result.free_fit_reference_psd_m3 = std::exp((sum_v - slope * sum_u) / m);
  return result;
}

}  // namespace ridefit::road
