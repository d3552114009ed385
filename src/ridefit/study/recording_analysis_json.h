#pragma once

#include <nlohmann/json.hpp>

#include <optional>

#include "ridefit/study/recording_analysis.h"

namespace ridefit::study {

// An analysis as JSON: the band, per recording every channel's named metrics (with the
// weighting, its comfort reactions and tyre-load, travel and impact values where they apply),
// the averaged spectra, and with levels the correlations (`relative_increase` null where the
// lowest level's value is zero). Keys follow design.md's names.
nlohmann::json to_json(const RecordingAnalysis& analysis, const RecordingAnalysisOptions& options,
                       const std::optional<ParameterLevels>& levels);

}  // namespace ridefit::study
