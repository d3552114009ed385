#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/diagnose/loop_diagnosis_options.h"
#include "ridefit/fitting/hysteresis_record.h"
#include "ridefit/simulate/strut_test_response.h"

namespace ridefit::fitting::diagnose {

// The diagnosis of strut rig tests: the same selection as for spectra (effect_selection.h), with
// the hysteresis fit (hysteresis_fit.h) on force residuals and the loop map
// (loop_disagreement.h); the gap is the held-out NRMSE in %.

// Fits see only `training`; scores, maps and figures use `held_out`.
struct LoopDiagnosisData {
  std::vector<HysteresisRecord> training;
  std::vector<HysteresisRecord> held_out;
  // Per held-out record, the samples that ran before it (empty when it starts a test): the
  // model is run through them first and judged from the held-out record's first sample on, so a
  // half cut from mid-stroke is not judged on the model's start from rest.
  std::vector<HysteresisRecord> held_out_lead_in;
};

// One record: its first half is fitted and its second half judges (the first half is the
// second's lead-in). Several: they alternate, the 1st, 3rd, … are fitted and the 2nd, 4th, …
// judge, each simulated from rest at its own first sample.
LoopDiagnosisData split_loops(const std::vector<HysteresisRecord>& records);

// The rig files' tests (a file of several tests, by its segment or test column, gives a record
// per test, each cut to its motion: five currents in one file are fitted on the 1st, 3rd, 5th and
// judged on the others, as separate files would be), split by split_loops. InputError naming the
// record for a part with fewer than 40 samples to fit or judge; the loader's own otherwise.
LoopDiagnosisData load_loop_diagnosis_data(const std::vector<std::filesystem::path>& files);

// Fits the baseline strut (`baseline.strut`), maps its loops against the held-out records, tries
// each effect that applies to loops, accepts the significant best, up to selection.max_effects
// rounds. The result's spectral fields stay empty; its loop fields and gap (NRMSE %) are filled.
// InputError for an unknown effect id or free parameter.
DiagnosisResult diagnose_loops(const DiagnosisModel& baseline, const LoopDiagnosisData& data,
                               const LoopDiagnosisOptions& options,
                               const std::function<void(const std::string&)>& progress = {});

}  // namespace ridefit::fitting::diagnose
