#include "ridefit/signal/excitation_band.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "ridefit/common/errors.h"
#include "ridefit/signal/welch_psd.h"

namespace ridefit::signal {

ExcitationBand excitation_band(std::span<const double> input, std::span<const double> residual,
                               double sample_rate_Hz, double input_share) {
  if (input.size() != residual.size()) {
    throw InputError(
        fmt::format("excitation band: input has {} samples, residual {}; expected "
                    "the same samples",
                    input.size(), residual.size()));
  }
  if (input.size() < 128) {
    throw InputError(fmt::format(
        "excitation band: {} samples; expected at least 128 for two spectra", input.size()));
  }
  if (!(input_share > 0.0 && input_share <= 1.0)) {
    throw InputError(
        fmt::format("excitation band: input share {}; expected a share in (0, 1]", input_share));
  }
  WelchOptions options;
  options.segment_length_samples = std::max<std::size_t>(64, input.size() / 8);
  const PowerSpectralDensity in = welch_psd(input, sample_rate_Hz, options);
  const PowerSpectralDensity out = welch_psd(residual, sample_rate_Hz, options);
  double total_in = 0.0, total_out = 0.0;
  for (std::size_t k = 0; k < in.psd.size(); ++k) {
    total_in += in.psd[k];
    total_out += out.psd[k];
  }
  ExcitationBand band;
  band.band_Hz = in.frequency_Hz.back();
  double below_in = 0.0, below_out = 0.0;
  for (std::size_t k = 0; k < in.psd.size(); ++k) {
    below_in += in.psd[k];
    below_out += out.psd[k];
    if (below_in >= input_share * total_in) {
      band.band_Hz = in.frequency_Hz[k];
      break;
    }
  }
  band.residual_in_band_share = total_out > 0.0 ? std::min(below_out / total_out, 1.0) : 1.0;
  return band;
}

}  // namespace ridefit::signal
