#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ridefit/optimisation/tuning_study.h"

namespace ridefit::optimisation {

// Every file a study reads: the study, the model, the fitted model (when its friction comes
// from a fit) and every load case's road. No output may replace one of them, and a journal
// resumes only the study whose files these are (study_fingerprint).
std::vector<std::filesystem::path> study_inputs(const TuningStudy& study);

// What a tuning run writes. With a result file NAME.yaml, the optimised model NAME_model.yaml and
// (when the study has a trade-off) the curve NAME_tradeoff.csv go beside it; each is "" when not
// written.
struct TuningFiles {
  std::string result;
  std::string model;
  std::string tradeoff_csv;
  std::filesystem::path journal;
};

// The files of a run of `study` with result file `result` ("" for none) and journal `journal`
// ("" for the default: NAME.journal beside the result, else STUDY.journal in the working
// directory, STUDY being the study file's stem).
TuningFiles tuning_files(const TuningStudy& study, const std::string& result,
                         const std::filesystem::path& journal);

}  // namespace ridefit::optimisation
