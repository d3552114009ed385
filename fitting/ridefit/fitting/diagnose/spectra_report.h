#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "ridefit/fitting/diagnose/diagnosis.h"

namespace ridefit::fitting::diagnose {

// The report (markdown) of a diagnosis on vehicle spectra: the data and settings it used (band,
// segments, the sensor-noise floors, given or estimated, from `options`), the verdict, the gap
// before and after, each fit's parameters, channels and disagreement regions, and the rounds.
// `model_name` is the baseline's file; `figure_file` the figure beside the report ("" = none).
void write_spectra_report(std::ostream& out, const std::string& model_name,
                          const DiagnosisOptions& options, const DiagnosisResult& result,
                          const DiagnosisData& data, const std::string& figure_file);

// Its JSON summary: verdict, named effects, gaps, channels and regions before and after, the
// unexplained regions, parameters and rounds.
nlohmann::json spectra_summary_json(const DiagnosisResult& result);

}  // namespace ridefit::fitting::diagnose
