#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/diagnosis_options.h"
#include "ridefit/fitting/diagnose/disagreement_map.h"
#include "ridefit/fitting/diagnose/effect_selection.h"
#include "ridefit/fitting/diagnose/loop_disagreement.h"
#include "ridefit/fitting/diagnose/residual_shape.h"
#include "ridefit/fitting/diagnose/spectral_shape.h"
#include "ridefit/fitting/psd_fit.h"

namespace ridefit::fitting::diagnose {

// The records a diagnosis uses: fits see only `training`; every score, map and figure is taken
// on `held_out` (a second record, or the second half of the only one), so a model cannot win by
// fitting the noise of the data it is judged on.
struct DiagnosisData {
  PsdMeasurement training;
  PsdMeasurement held_out;
};

// Splits one record at its middle into training (first half) and held-out data (second half).
// The second half's simulation starts at rest at its own first sample, as the first one does.
DiagnosisData split_record(const PsdMeasurement& record);

struct DiagnosisResult {
  DataKind kind = DataKind::kVehicleSpectra;
  DiagnosisModel baseline;  // with the baseline's free parameters fitted
  std::vector<FittedValue> baseline_parameters;
  double baseline_held_out_cost = 0.0;
  // The gap on the held-out data before (fitted baseline) and after (final model): RMS dB over
  // the band and the channels for spectra (DisagreementMap::gap_dB), NRMSE in % for loops
  // (LoopDisagreementMap::gap_percent).
  double gap_before = 0.0;
  double gap_after = 0.0;
  std::vector<DiagnosisRound> rounds;
  std::vector<std::string> named;  // accepted effect ids, in order
  // Effects the records could not identify (Selection::not_identifiable).
  std::vector<std::string> not_identifiable;
  DiagnosisModel final_model;  // the baseline with the named effects, refitted
  std::vector<FittedValue> final_parameters;
  // "missing effect found: …", "no missing effect found", or the unexplained disagreement, with
  // the named set's probability among the explanations.
  std::string verdict;
  // Every explanation fitted (nothing missing, each effect, the pairs), weighed, most probable
  // first (explanation_evidence.h).
  std::vector<Explanation> explanations;
  // What would separate the named set from its strongest rival, when the data cannot tell them
  // apart ("" otherwise): where their predictions of the judging data differ most.
  std::string separation;
  // Where the final fit put the values the baseline's data sheet was unsure of
  // (DiagnosisOptions::baseline_tolerances, LoopDiagnosisOptions::baseline_tolerances): a
  // finding in itself ("spring −7 % ± 2 %").
  struct SheetValue {
    std::string name;
    double sheet = 0.0;      // the baseline's value (a prior's mean, or the bounds' centre)
    double tolerance = 0.0;  // one standard deviation as a share of it
    double fitted = 0.0;
    std::optional<double> standard_error;
  };
  std::vector<SheetValue> sheet_values;

  // Vehicle spectra: the maps of the held-out data against the fitted baseline and the final
  // model, the simulations behind them (measured time base), the significant regions left that
  // no effect explained.
  DisagreementMap before;
  DisagreementMap after;
  std::vector<double> before_body, before_wheel, after_body, after_wheel;
  std::vector<DisagreementRegion> unexplained;
  // When such regions remain: the final map's measured-over-simulated ratio in named shapes
  // (spectral_shape.h), a suggestion for a new effect.
  SpectralShape spectral_shape;

  // Strut loops: the same for the held-out records' forces.
  LoopDisagreementMap loops_before;
  LoopDisagreementMap loops_after;
  std::vector<std::vector<double>> before_force_N, after_force_N;
  std::vector<LoopRegion> unexplained_loops;
  // When no region is left but the residual's shape takes a significant force off the judging
  // records (a moving mass, a lag: forces no travel or velocity bin shows): that force's RMS as a
  // share of the measured force's; 0 otherwise. Unexplained too.
  double unexplained_shape_share = 0.0;
  // When such regions remain: the force the final model lacks, in named terms of travel, velocity
  // and acceleration (residual_shape.h), a suggestion for a new effect.
  ResidualShape residual_shape;
};

// The verdict's report of a force outside the library: nothing named, a disagreement left
// unexplained, and an explanation outside the library weighed (add_outside_library).
bool reports_outside_library(const DiagnosisResult& result);
// The probability the verdict gives what it reports: the named effects' (named_probability), or,
// when it reports a force outside the library, that explanation's (outside_probability).
double reported_probability(const DiagnosisResult& result);
// The verdict's words on the evidence (evidence_words, outside_evidence_words), with the result's
// separation.
std::string verdict_evidence(const DiagnosisResult& result);

// The kind-independent part of a result: the baseline's and the final fit's models and
// parameters, the rounds and the named effects (the maps and the verdict are the caller's).
DiagnosisResult result_of(const Selection& selection, DataKind kind);

// Fits the baseline, maps its disagreement with the held-out data, then tries each applicable
// effect of the library (in parallel): adds it, refits every free parameter on the training
// data, and scores it on the held-out data and by BIC. The best significant one is accepted and
// the search repeats from it, up to selection.max_effects rounds. `progress` (may be empty)
// receives one line per finished step. InputError for an unknown effect id or a bad free parameter.
DiagnosisResult diagnose(const DiagnosisModel& baseline, const DiagnosisData& data,
                         const DiagnosisOptions& options,
                         const std::function<void(const std::string&)>& progress = {});

}  // namespace ridefit::fitting::diagnose
