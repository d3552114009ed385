#pragma once

namespace ridefit::road {

// A band of spatial frequencies n in cycles/m (wavelengths 1/n). The default is ISO 8608's
// reporting band, wavelengths from 91 m down to 0.35 m: longer waves are grade, not
// vibration, and shorter ones are swallowed by the tyre's contact patch.
struct SpatialBand {
  double low_cycles_per_m = 0.011;
  double high_cycles_per_m = 2.83;
};

// A displacement power spectral density that is a straight line on log-log axes:
//
//   G(n) = G(n_ref)·(n/n_ref)^(−w)     [m^3 = m^2 per cycle/m], n in cycles/m
//
// one-sided, so that the variance of the profile is the integral of G over n > 0.
// ISO 8608 uses n_ref = 0.1 cycles/m and w = 2; the Cr·n^(−α) roads of seed 001 use
// n_ref = 1 cycle/m, G(n_ref) = Cr and w = α (see power_law_road.h).
struct PowerLawSpectrum {
  double reference_cycles_per_m = 0.1;
  double psd_at_reference_m3 = 16e-6;
  double exponent = 2.0;  // w (ISO 8608 "waviness"), α in seed 001

  double psd_m3(double cycles_per_m) const;
  // ∫ G(n) dn over the band (closed form): the variance of a profile with this spectrum.
  double band_variance_m2(const SpatialBand& band) const;
  double band_rms_m(const SpatialBand& band) const;
};

}  // namespace ridefit::road
