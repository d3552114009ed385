#pragma once

#include <map>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/disagreement_map.h"
#include "ridefit/fitting/diagnose/effect_selection.h"
#include "ridefit/fitting/psd_fit_options.h"

namespace ridefit::fitting::diagnose {

// InputError for an unknown effect id (naming the library's) or one given twice.
void check_effect_ids(const std::vector<std::string>& ids);

// The uncertainty of a vehicle's data sheet, one standard deviation as a share of each value:
// masses 3 %, tyre and spring rates 8 %, damping 12 %, top mount 15 %, Coulomb force 25 %
// (the tolerances an engineer's baseline carries; issue "A diagnosis that holds when the
// engineer's model is off"). The diagnosis frees those its baseline has (a rigid top mount,
// no friction: left out).
std::map<std::string, double> datasheet_tolerances();

// How a diagnosis of vehicle spectra runs (diagnosis.h). Plain fields with defaults, checked as
// a whole by validate().
struct DiagnosisOptions {
  // The baseline's parameters every fit frees (quarter-car keys); empty = the default: the
  // damping, and the Coulomb force when the baseline has Dahl friction (a locked damper: the
  // sprung mass).
  std::vector<std::string> baseline_free;
  // The baseline's values an engineer is unsure of, each with the share of its value that is
  // one standard deviation of the data sheet's uncertainty (0.08: ±8 %). Every fit, the
  // baseline's and each effect's, frees them too, with a Gaussian prior at the baseline's value
  // (PsdFitOptions::priors): an effect cannot win by absorbing a wrong mass, and the refitted
  // baseline's move from the sheet is reported. datasheet_tolerances() is the usual set; empty
  // (the default): none, the baseline's values are held but for those of `baseline_free`. (Not
  // the default yet: on a 20 s class A record the seed case's stiffer small-amplitude top mount
  // is then taken up by the baseline's top mount, +35 %, and nothing is named.)
  std::map<std::string, double> baseline_tolerances;
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
  // or is given twice, a tolerance on an unknown parameter or not in (0, 10], an unknown effect
  // id, fit options PsdFitOptions::validate(false) refuses,
  // a tolerance outside (0, 0.1], fewer than 1 screening iteration, bad map or selection
  // options, or thresholds that are not > 0. Called by diagnose().
  void validate() const;
};

}  // namespace ridefit::fitting::diagnose
