#pragma once

#include <optional>
#include <ostream>

#include "ridefit/study/recording_analysis.h"

namespace ridefit::study {

// The tables a person reads after an analysis: per recording, each channel's values with its
// ISO 2631-1 comfort reading, then its tyre-load, travel and impact lines; the averaged spectra
// when several recordings were averaged (not at levels: an average over different levels means
// nothing); the correlations with the levels.
void write_recording_report(std::ostream& out, const RecordingAnalysis& analysis,
                            const std::optional<ParameterLevels>& levels);

}  // namespace ridefit::study
