#pragma once

#include <optional>

#include "ridefit/io/csv_table.h"
#include "ridefit/study/recording_analysis.h"

namespace ridefit::study {

// The PSDs of an analysis as a CSV table over `frequency[Hz]`: per channel the averaged PSD and
// its band (`NAME_psd`, `NAME_psd_lower`, `NAME_psd_upper`); at levels each recording's own PSD
// instead (`NAME_psd_runN_PARAMETER_LEVEL`: the run number keeps names unique when runs share a
// level), since an average over different levels means nothing. InputError naming the channel
// when its PSD unit is one a CSV header cannot carry (io::unit_to_si does not read it).
io::CsvTable recording_psd_table(const RecordingAnalysis& analysis,
                                 const std::optional<ParameterLevels>& levels);

}  // namespace ridefit::study
