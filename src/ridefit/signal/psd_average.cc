#include "ridefit/signal/psd_average.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/spectrum_check.h"

namespace ridefit::signal {
namespace {

constexpr const char* kCaller = "PSD average";

void check_same(const std::string& name, const std::string& first_name, const char* quantity,
                std::size_t value, std::size_t first_value) {
  if (value == first_value) return;
  throw InputError(fmt::format(
      "{}: {} has {} {} but {} has {}; all records must share sample rate, segment length, "
      "overlap and smoothing",
      kCaller, name, quantity, value, first_name, first_value));
}

}  // namespace

PowerSpectralDensity average_psd(std::span<const PowerSpectralDensity> spectra,
                                 std::span<const std::string> names) {
  if (spectra.empty()) {
    throw InputError(fmt::format("{}: no spectra were given; give at least one", kCaller));
  }
  if (!names.empty() && names.size() != spectra.size()) {
    throw InputError(fmt::format("{}: {} names for {} spectra; give one name per spectrum or none",
                                 kCaller, names.size(), spectra.size()));
  }
  const auto name_of = [&](std::size_t r) {
    return names.empty() ? fmt::format("spectrum {}", r) : names[r];
  };

  const PowerSpectralDensity& first = spectra.front();
  const std::string first_name = name_of(0);
  for (std::size_t r = 0; r < spectra.size(); ++r) {
    const PowerSpectralDensity& s = spectra[r];
    const std::string name = name_of(r);
    check_psd_statistics(kCaller, name, s);
    if (std::abs(s.sample_rate_Hz - first.sample_rate_Hz) > 1e-9 * first.sample_rate_Hz) {
      throw InputError(fmt::format(
          "{}: {} has sample rate {} Hz but {} has {} Hz; all records must share sample rate, "
          "segment length, overlap and smoothing (resample first)",
          kCaller, name, s.sample_rate_Hz, first_name, first.sample_rate_Hz));
    }
    check_same(name, first_name, "segment length (samples)", s.segment_length_samples,
               first.segment_length_samples);
    // Equal rate and segment length imply equal bins unless the struct was edited by hand.
    check_same(name, first_name, "bin count", s.psd.size(), first.psd.size());
    check_same(name, first_name, "hop (samples)", s.hop_samples, first.hop_samples);
    check_same(name, first_name, "smoothing width (bins)", s.smoothing_bins, first.smoothing_bins);
  }

  PowerSpectralDensity result = first;
  result.segment_count = 0;
  std::fill(result.psd.begin(), result.psd.end(), 0.0);
  std::fill(result.degrees_of_freedom.begin(), result.degrees_of_freedom.end(), 0.0);
  for (const PowerSpectralDensity& s : spectra) {
    result.segment_count += s.segment_count;
    for (std::size_t k = 0; k < s.psd.size(); ++k) {
      result.psd[k] += s.degrees_of_freedom[k] * s.psd[k];
      result.degrees_of_freedom[k] += s.degrees_of_freedom[k];
    }
  }
  for (std::size_t k = 0; k < result.psd.size(); ++k) {
    result.psd[k] /= result.degrees_of_freedom[k];
  }
  return result;
}

}  // namespace ridefit::signal
