#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "ridefit/fitting/diagnose/diagnosis.h"

namespace ridefit::fitting::diagnose {

// The parts of a diagnosis report (markdown) and of its JSON summary that both data kinds share;
// spectra_report.h and loop_report.h write the rest.

// A markdown table of parameters with their standard errors ("—" where the data cannot tell).
void write_parameters(std::ostream& out, const std::vector<FittedValue>& values);

// Each round's ranked effects, the skipped and failed ones with why, and the accepted one.
// `cost_words` says what the held-out cost is, `gap_unit` the unit of the gap column.
void write_rounds(std::ostream& out, const DiagnosisResult& result, const std::string& cost_words,
                  const std::string& gap_unit);

// "The data sheet against the records": where the final fit put each of the baseline's uncertain
// values, with its move from the sheet; `how` says how the fits held them. Nothing when empty.
void write_sheet_values(std::ostream& out, const std::vector<DiagnosisResult::SheetValue>& values,
                        const std::string& how);

// "How sure": every explanation fitted, most probable first, with its BIC and probability, and
// what separates the named set from its rival when the data cannot tell them apart.
void write_explanations(std::ostream& out, const DiagnosisResult& result);

// The explanations as [{"effects": […], "probability": p, "bic": …, "free_parameters": k}, …].
nlohmann::json explanations_json(const std::vector<Explanation>& explanations);

nlohmann::json values_json(const std::vector<FittedValue>& values);

nlohmann::json sheet_values_json(const std::vector<DiagnosisResult::SheetValue>& values);

// The rounds with each effect's scores; `gap_key` names the gap (e.g. "gap_dB").
nlohmann::json rounds_json(const DiagnosisResult& result, const std::string& gap_key);

}  // namespace ridefit::fitting::diagnose
