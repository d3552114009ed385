#include "ridefit/road/iso8608.h"

#include <fmt/core.h>

#include <cmath>

#include "ridefit/common/errors.h"

namespace ridefit::road {

Iso8608Class parse_iso8608_class(const std::string& text) {
  if (text.size() == 1 && text[0] >= 'A' && text[0] <= 'H') {
    return static_cast<Iso8608Class>(text[0] - 'A');
  }
  throw InputError(
      fmt::format("ISO 8608 class '{}', expected one of: A, B, C, D, E, F, G, H", text));
}

char to_char(Iso8608Class road_class) {
  return static_cast<char>('A' + static_cast<int>(road_class));
}

double iso8608_reference_psd_m3(Iso8608Class road_class) {
  // 16e-6 m^3 · 4^index: A 16e-6, B 64e-6, …, H 262144e-6.
  return 16e-6 * std::ldexp(1.0, 2 * static_cast<int>(road_class));
}

PowerLawSpectrum iso8608_spectrum(Iso8608Class road_class) {
  return {kIso8608ReferenceCyclesPerM, iso8608_reference_psd_m3(road_class), 2.0};
}

SpatialProfileRoad make_iso8608_road(const Iso8608RoadParameters& parameters) {
  const PowerLawSpectrum spectrum = iso8608_spectrum(parameters.road_class);
  return make_random_road([spectrum](double n) { return spectrum.psd_m3(n); }, parameters.random);
}

}  // namespace ridefit::road
