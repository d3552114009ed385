#include "ridefit/road/power_law_spectrum.h"

#include <cmath>

namespace ridefit::road {

double PowerLawSpectrum::psd_m3(double cycles_per_m) const {
  return psd_at_reference_m3 * std::pow(cycles_per_m / reference_cycles_per_m, -exponent);
}

double PowerLawSpectrum::band_variance_m2(const SpatialBand& band) const {
  // With u = n/n_ref: ∫ G dn = G_ref·n_ref·∫ u^(−w) du.
  const double u_low = band.low_cycles_per_m / reference_cycles_per_m;
  const double u_high = band.high_cycles_per_m / reference_cycles_per_m;
  const double one_minus_w = 1.0 - exponent;
  const double integral =
      std::abs(one_minus_w) < 1e-12
          ? std::log(u_high / u_low)
          : (std::pow(u_high, one_minus_w) - std::pow(u_low, one_minus_w)) / one_minus_w;
  return psd_at_reference_m3 * reference_cycles_per_m * integral;
}

double PowerLawSpectrum::band_rms_m(const SpatialBand& band) const {
  return std::sqrt(band_variance_m2(band));
}

}  // namespace ridefit::road
