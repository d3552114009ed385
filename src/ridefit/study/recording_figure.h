#pragma once

#include <optional>

#include "ridefit/io/gnuplot_figure.h"
#include "ridefit/study/recording_analysis.h"

namespace ridefit::study {

// The figure of an analysis: a PSD panel per channel, averaged with its confidence band; at
// levels, each recording's PSD labelled by its level instead, and beside each channel the
// trend of its headline metric (weighted RMS, else dynamic tyre load, else RMS) against the
// levels with its least-squares line.
io::Figure recording_figure(const RecordingAnalysis& analysis,
                            const RecordingAnalysisOptions& options,
                            const std::optional<ParameterLevels>& levels);

}  // namespace ridefit::study
