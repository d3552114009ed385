#pragma once

#include <cstddef>
#include <vector>

#include "ridefit/road/iso8608.h"
#include "ridefit/road/road_profile.h"

namespace ridefit::road {

struct Iso8608ClassificationOptions {
  // Welch segment length in m; 0 = min(100 m, profile length / 4).
  double segment_length_m = 0.0;
  // Resampling spacing in m; 0 = the profile's median spacing.
  double spacing_m = 0.0;
  double confidence = 0.9;  // of the PSD's χ² interval
};

// The displacement PSD of a profile and its ISO 8608 roughness.
struct Iso8608Classification {
  std::vector<double> spatial_frequency_cycles_per_m;  // n, bins k/segment, k = 0 … L/2
  std::vector<double> psd_m3;                          // Gd(n), one-sided, m^2/(cycles/m)
  std::vector<double> psd_lower_m3;                    // χ² confidence interval per bin
  std::vector<double> psd_upper_m3;
  double confidence = 0.9;
  double segment_length_m = 0.0;
  double spacing_m = 0.0;
  // The fitting band: ISO 8608's 0.011–2.83 cycles/m, narrowed to what the profile resolves
  // (n >= 1/segment, n <= 1/(2·spacing)); fit_bins bins lie in it.
  double band_low_cycles_per_m = 0.0;
  double band_high_cycles_per_m = 0.0;
  std::size_t fit_bins = 0;
  // Gd(n0) at n0 = 0.1 cycles/m with the waviness fixed at w = 2 (the standard's fit):
  // least squares in log PSD.
  double reference_psd_m3 = 0.0;
  Iso8608Class road_class = Iso8608Class::kA;
  // Free-waviness fit: a straight line in log-log, Gd(n) = G·(n/n0)^(−w).
  double free_fit_reference_psd_m3 = 0.0;
  double waviness = 0.0;
};

// The class whose range holds Gd(n0): class c spans [ref(c)/2, 2·ref(c)) around its
// geometric mean ref(c) = iso8608_reference_psd_m3(c) (A below 32e-6 m^3, H from 65536e-6).
Iso8608Class iso8608_class_of(double reference_psd_m3);

// Resamples the profile to a uniform spacing (linear interpolation), estimates its PSD by
// Welch (periodic Hann segments, 50 % overlap, linear detrend per segment) and fits it.
// Throws InputError for a bad profile (check_road_profile), a profile shorter than one
// segment, or a band with fewer than 2 bins (the profile resolves none of 0.011–2.83 cycles/m).
Iso8608Classification classify_iso8608(const RoadProfile& profile,
                                       const Iso8608ClassificationOptions& options = {});

}  // namespace ridefit::road
