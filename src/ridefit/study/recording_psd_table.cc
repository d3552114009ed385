#include "ridefit/study/recording_psd_table.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"

namespace ridefit::study {

io::CsvTable recording_psd_table(const RecordingAnalysis& analysis,
                                 const std::optional<ParameterLevels>& levels) {
  io::CsvTable table;
  table.add("frequency", "Hz", analysis.spectra.front().psd.frequency_Hz);
  for (std::size_t c = 0; c < analysis.spectra.size(); ++c) {
    const auto& s = analysis.spectra[c];
    try {
      io::unit_to_si(s.psd_unit);
    } catch (const InputError&) {
      throw InputError(fmt::format("channel {} is in a unit whose PSD unit ({}) a CSV cannot carry",
                                   s.name, s.psd_unit));
    }
    if (!levels) {
      table.add(s.name + "_psd", s.psd_unit, s.psd.psd);
      table.add(s.name + "_psd_lower", s.psd_unit, s.interval.lower);
      table.add(s.name + "_psd_upper", s.psd_unit, s.interval.upper);
      continue;
    }
    for (std::size_t r = 0; r < analysis.recordings.size(); ++r) {
      table.add(
          fmt::format("{}_psd_run{}_{}_{:g}", s.name, r + 1, levels->parameter, levels->values[r]),
          s.psd_unit, analysis.recordings[r].channels[c].psd.psd);
    }
  }
  return table;
}

}  // namespace ridefit::study
