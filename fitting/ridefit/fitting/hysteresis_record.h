#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ridefit/signal/quantisation.h"

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
  // The rig's own velocity at the same samples (a `velocity[m/s]` column), empty when the record
  // has none: the model then runs on it rather than on a derivative of quantised displacement.
  std::vector<double> velocity_m_per_s{};
  // The displacement's quantisation (quantised_displacement.h): empty until the record is
  // examined, which the loaders do; low-passed only when asked.
  std::optional<signal::QuantisationLowPass> displacement_low_pass{};
  bool displacement_low_passed = false;
};

// Reads `time[...]`, `displacement[...]`, `force[...]` columns in any supported units, an
// optional command column `current[A|mA]` or `voltage[V|mV]` and an optional `velocity[m/s]`;
// other columns are ignored. A quantised displacement is examined (quantised_displacement.h).
// InputError (naming file, row, column) for a missing column, a time that does not increase, fewer
// than 20 samples, a displacement that never moves or a force that never changes
// (signal/signal_presence.h: nothing to identify), both a current and a voltage column, or a
// command in the wrong kind of unit.
HysteresisRecord load_hysteresis_record(const std::filesystem::path& csv_file);

// The tests a rig file holds. Without a `segment` (or `test`) column: the whole file, as
// load_hysteresis_record. With one: a record per test (the column's whole numbers, each test's
// rows together; the time may run on across the pauses between them), named "FILE (segment N)",
// each cut to the part where the actuator moves (moving_rows) so that it starts from its own rest
// state and the rest samples are not fitted. InputError, naming file, row and column, for a test
// number that is not whole, a test whose rows are split, and a test that moves through less than
// one cycle. Each test's quantised displacement is low-passed on its own
// (quantised_displacement.h).
std::vector<HysteresisRecord> load_hysteresis_tests(const std::filesystem::path& file);

// The tests of each file (load_hysteresis_tests), in order. With `per_file_option` (the caller's
// words for per-file values, "--per-file coulomb_force_N") a file of several tests is an
// InputError that starts with them: per-file values are written one model per file.
std::vector<HysteresisRecord> load_rig_files(const std::vector<std::filesystem::path>& files,
                                             const std::string& per_file_option = "");

// Rows [first, last) of `r`, named `source`: every per-sample column (command, measured velocity)
// cut alike, the displacement's treatment kept.
HysteresisRecord rows_of(const HysteresisRecord& r, std::size_t first, std::size_t last,
                         std::string source);

// The rows [first, last) where the actuator moves: the rest before the motion starts and after it
// ends cut off (the displacement within 1 % of the stroke of its first or last value, back to
// where it left rest by more than a few quantisation steps), one rest sample kept on each side.
// The whole record when it never rests.
std::pair<std::size_t, std::size_t> moving_rows(const HysteresisRecord& record);

}  // namespace ridefit::fitting
