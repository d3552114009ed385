#include "ridefit/signal/band_power.h"

#include <algorithm>
#include <cmath>

#include "ridefit/signal/spectrum_check.h"

namespace ridefit::signal {

double band_power(std::span<const double> frequency_Hz, std::span<const double> psd, double low_Hz,
                  double high_Hz) {
  check_spectrum_band("band power", frequency_Hz, psd, low_Hz, high_Hz);
  // Linear interpolation of the PSD inside interval [f_i, f_i+1].
  const auto value_at = [&](std::size_t i, double f) {
    const double t = (f - frequency_Hz[i]) / (frequency_Hz[i + 1] - frequency_Hz[i]);
    return psd[i] + t * (psd[i + 1] - psd[i]);
  };
  double power = 0.0;
  for (std::size_t i = 0; i + 1 < frequency_Hz.size(); ++i) {
    const double a = std::max(frequency_Hz[i], low_Hz);
    const double b = std::min(frequency_Hz[i + 1], high_Hz);
    if (b <= a) continue;
    power += 0.5 * (b - a) * (value_at(i, a) + value_at(i, b));
  }
  return power;
}

double band_power(const PowerSpectralDensity& spectrum, double low_Hz, double high_Hz) {
  return band_power(spectrum.frequency_Hz, spectrum.psd, low_Hz, high_Hz);
}

double band_rms(std::span<const double> frequency_Hz, std::span<const double> psd, double low_Hz,
                double high_Hz) {
  return std::sqrt(band_power(frequency_Hz, psd, low_Hz, high_Hz));
}

double band_rms(const PowerSpectralDensity& spectrum, double low_Hz, double high_Hz) {
  return band_rms(spectrum.frequency_Hz, spectrum.psd, low_Hz, high_Hz);
}

}  // namespace ridefit::signal
