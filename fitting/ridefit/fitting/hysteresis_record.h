#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ridefit::fitting {

// One strut test: the displacement imposed and the force measured, in SI.
struct HysteresisRecord {
  std::string source;
  std::vector<double> time_s;
  std::vector<double> displacement_m;  // extension positive
  std::vector<double> force_N;         // tension positive
  // A controlled damper's command at the same samples (empty for a passive one), in its SI unit:
  // "A" for a `current` column (A or mA in the file), "V" for a `voltage` column (V or mV).
  std::vector<double> command;
  std::string command_unit;
};

// Reads `time[...]`, `displacement[...]`, `force[...]` columns in any supported units, and an
// optional command column `current[A|mA]` or `voltage[V|mV]`. InputError (naming file, row,
// column) for a missing column, a time that does not increase, fewer than 20 samples, a
// displacement that never moves or a force that never changes (signal/signal_presence.h: nothing
// to identify), both a current and a voltage column, or a command in the wrong kind of unit.
HysteresisRecord load_hysteresis_record(const std::filesystem::path& csv_file);

}  // namespace ridefit::fitting
