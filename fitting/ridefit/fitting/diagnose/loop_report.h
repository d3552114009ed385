#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

#include "ridefit/fitting/diagnose/diagnosis.h"
#include "ridefit/fitting/diagnose/loop_diagnosis.h"

namespace ridefit::fitting::diagnose {

// The report (markdown) of a diagnosis on strut rig loops: the records fitted and judged, the
// verdict, the gap (force NRMSE) before and after, each fit's parameters, per-record statistics
// and loop-shape regions, the rounds and, when a disagreement is left unexplained, its shape in
// named terms (residual_shape.h). `model_name` is the baseline's file; `figure_file`
// the figure beside the report ("" = none).
void write_loop_report(std::ostream& out, const std::string& model_name,
                       const DiagnosisResult& result, const LoopDiagnosisData& data,
                       const std::string& figure_file);

// Its JSON summary: verdict, named effects, gaps, regions before and the unexplained ones with
// their shape (`residual_shape`), parameters and rounds.
nlohmann::json loop_summary_json(const DiagnosisResult& result);

}  // namespace ridefit::fitting::diagnose
