#pragma once

#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/disagreement_map.h"
#include "ridefit/fitting/diagnose/effect_selection.h"
#include "ridefit/fitting/psd_fit_options.h"

namespace ridefit::fitting::diagnose {

// InputError for an unknown effect id (naming the library's) or one given twice.
void check_effect_ids(const std::vector<std::string>& ids);

// How a diagnosis of vehicle spectra runs (diagnosis.h). Plain fields with defaults, checked as
// a whole by validate().
struct DiagnosisOptions {
  // The baseline's parameters every fit frees (quarter-car keys); empty = the default: the
  // damping, and the Coulomb force when the baseline has Dahl friction (a locked damper: the
  // sprung mass).
  std::vector<std::string> baseline_free;
  std::vector<std::string> effects;  // ids to try; empty = the whole library
  PsdFitOptions fit;  // band, segments, iterations (free and relative_tolerance are set here)
  // Integration tolerances (the adaptive ESDIRK's rtol, PsdFitOptions::relative_tolerance):
  // effects are screened (fitted and ranked) at screening_relative_tolerance; the baseline and
  // the named effects are then refitted at final_relative_tolerance, whose figures the report,
  // the map and the model show. Screening compares effects with one another on the same terms;
  // the reported fit is the one whose numbers are quoted.
  double screening_relative_tolerance = 1e-3;
  double final_relative_tolerance = 1e-4;
  int screening_iterations = 25;  // at most, per screening fit
  DisagreementOptions map;        // the map's settings; its band follows `fit`
  SelectionOptions selection;     // significance, rounds, threads (gap_unit and refine set here)
  // A disagreement region left after the last accepted effect counts as unexplained when it is
  // inside the excitation band (not above it), its mean size is at least unexplained_dB and it
  // spans at least unexplained_width_Hz (or unexplained_wide_dB over unexplained_wide_width_Hz);
  // or when it is a peak shift (RegionEvidence::kPeakShift:
  // a channel's peak further from the measured one than the estimates resolve) in the band.
  // The maps compare the simulated PSD plus the record's sensor-noise floor (fit's
  // body_noise_psd / wheel_noise_psd, or estimated from the held-out record).
  double unexplained_dB = 1.5;
  double unexplained_width_Hz = 1.0;
  // Or, wider and shallower (what the pooled band tests find): a mean size of at least
  // unexplained_wide_dB over at least unexplained_wide_width_Hz.
  double unexplained_wide_dB = 1.0;
  double unexplained_wide_width_Hz = 2.0;

  // InputError naming the option for: a baseline parameter that is not a quarter-car parameter
  // or is given twice, an unknown effect id, fit options PsdFitOptions::validate(false) refuses,
  // a tolerance outside (0, 0.1], fewer than 1 screening iteration, bad map or selection
  // options, or thresholds that are not > 0. Called by diagnose().
  void validate() const;
};

}  // namespace ridefit::fitting::diagnose
