#include "ridefit/road/power_law_road.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::road {
namespace {

constexpr double kMaxBandRms_m = 10.0;

}  // namespace

void PowerLawRoadParameters::validate() const {
  if (!(roughness_coefficient_m3 > 0.0) || !std::isfinite(roughness_coefficient_m3)) {
    throw InputError(fmt::format("key 'roughness_coefficient_m3' is {}, expected a value > 0",
                                 roughness_coefficient_m3));
  }
  // Measured roads lie around 1.5–3.5; outside 0.5–5 the number is almost surely a typo.
  if (!(waviness >= 0.5 && waviness <= 5.0)) {
    throw InputError(fmt::format("key 'waviness' is {}, expected a value in [0.5, 5]", waviness));
  }
  random.validate();
  // The closed-form RMS catches a mistyped Cr (4.8e7 for 4.8e-7) before the profile overflows.
  const double rms_m = spectrum().band_rms_m(random.band);
  if (!(rms_m <= kMaxBandRms_m)) {
    throw InputError(fmt::format(
        "key 'roughness_coefficient_m3' is {:g}: with waviness {:g} the road's RMS elevation "
        "over the band {:g}–{:g} cycles/m is {:g} m, expected at most {:g} m (ISO 8608 class H, "
        "the roughest, is 0.49 m over the default band)",
        roughness_coefficient_m3, waviness, random.band.low_cycles_per_m,
        random.band.high_cycles_per_m, rms_m, kMaxBandRms_m));
  }
}

SpatialProfileRoad make_power_law_road(const PowerLawRoadParameters& parameters) {
  parameters.validate();
  const PowerLawSpectrum spectrum = parameters.spectrum();
  return make_random_road([spectrum](double n) { return spectrum.psd_m3(n); }, parameters.random);
}

}  // namespace ridefit::road
