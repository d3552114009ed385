#pragma once

#include <filesystem>
#include <memory>
#include <optional>

#include "ridefit/road/power_law_spectrum.h"
#include "ridefit/road/random_profile.h"
#include "ridefit/road/road_input.h"

namespace ridefit::road {

// Loads an excitation file (YAML) into a road. A required `type` selects the road; every
// other key carries its unit in its name. Keys with a default may be left out.
//
//   type: log_sweep            # log_sweep.h
//   start_frequency_Hz: 0.1    # default 0.1
//   end_frequency_Hz: 30       # default 30
//   initial_amplitude_m: 0.01  # required
//   end_amplitude_m: 1.0e-4    # default initial_amplitude_m/100
//   duration_s: 60             # default 60
//
//   type: iso8608              # iso8608.h
//   class: A                   # A … H
//   speed_km_per_h: 50         # or speed_m_per_s: exactly one of the two (every driven road)
//   duration_s: 60
//   seed: 1                    # default 1; integer >= 0
//   band_low_cycles_per_m: 0.011   # default 0.011 (also power_law)
//   band_high_cycles_per_m: 2.83   # default 2.83
//   sample_spacing_m: 0.05         # default 0.05
//   fade_in_m: 5                   # default 5
//
//   type: power_law            # power_law_road.h, seed 001: S(n) = Cr·n^(−α)
//   roughness_coefficient_m3: 4.8e-7   # Cr, PSD at 1 cycle/m
//   waviness: 2.1                      # α
//   speed…, duration_s, seed, band_…, sample_spacing_m, fade_in_m as for iso8608
//
//   type: cleat                # cleat.h
//   shape: semicircular        # or rectangular
//   height_m: 0.02
//   length_m: 0.04
//   start_distance_m: 2        # default 2
//   tyre_contact_length_m: 0.1 # default 0.1
//   speed…; duration_s         # default: until 3 s after the cleat
//
//   type: profile              # profile_road.h
//   file: profile.csv          # distance[m|mm],elevation[m|mm]; relative to this YAML file
//   speed…; offset_m: 0        # default 0
//
//   type: measured             # measured_road.h
//   file: drive.csv            # with a time column; relative to this YAML file
//   channel: road              # default road
//
// Unknown keys, missing keys, wrong types, out-of-range values and both or neither speed
// keys are InputErrors naming the file and the key. Beyond each road's own ranges, the limits
// of road_limits.h apply: speed <= 150 m/s (540 km/h), sweep frequencies <= 500 Hz, at most
// 2e7 road samples (or steps of max_step_s()) per run, runs of at least 1 ms.
std::unique_ptr<RoadInput> load_excitation(const std::filesystem::path& yaml_file);

// The same excitation driven at another speed (a study's speed axis). InputError for an
// excitation that is not driven at a speed (log_sweep, measured).
std::unique_ptr<RoadInput> load_excitation(const std::filesystem::path& yaml_file,
                                           double speed_m_per_s);

// The spatial spectrum of a random road excitation (iso8608, power_law) with its band, speed
// (the file's, or `speed_m_per_s`) and duration: what a frequency-domain evaluation needs.
// Empty for other types. The file is fully checked first (as load_excitation does).
struct RoadSpectrum {
  PowerLawSpectrum spectrum;
  SpatialBand band;
  double speed_m_per_s = 0.0;
  double duration_s = 0.0;
};
std::optional<RoadSpectrum> load_road_spectrum(const std::filesystem::path& yaml_file,
                                               std::optional<double> speed_m_per_s = {});

}  // namespace ridefit::road
