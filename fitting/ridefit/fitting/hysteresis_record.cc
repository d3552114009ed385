#include "ridefit/fitting/hysteresis_record.h"

#include <fmt/core.h>

#include <algorithm>

#include "ridefit/common/errors.h"
#include "ridefit/io/command_column.h"
#include "ridefit/io/csv_table.h"
#include "ridefit/io/measurement_file.h"
#include "ridefit/signal/signal_presence.h"

namespace ridefit::fitting {

HysteresisRecord load_hysteresis_record(const std::filesystem::path& csv_file) {
  const io::CsvTable table = io::read_measurement_table(csv_file);
  HysteresisRecord record;
  record.source = csv_file.string();
  record.time_s = table.time_s();
  const io::CsvColumn& displacement = table.column("displacement");
  const io::CsvColumn& force = table.column("force");
  if (displacement.unit != "m") {
    throw InputError(fmt::format("{}: column displacement is in {}, expected a length (m, mm)",
                                 csv_file.string(), displacement.unit));
  }
  if (force.unit != "N") {
    throw InputError(fmt::format("{}: column force is in {}, expected a force (N, kN)",
                                 csv_file.string(), force.unit));
  }
  record.displacement_m = displacement.values;
  record.force_N = force.values;
  if (auto command = io::read_command_column(table, csv_file.string())) {
    record.command = std::move(command->values);
    record.command_unit = command->unit;
  }
  if (record.time_s.size() < 20) {
    throw InputError(fmt::format("{}: {} samples; a hysteresis fit needs at least 20",
                                 csv_file.string(), record.time_s.size()));
  }
  // A rig that did not move, or a load cell that read nothing, gives a fit of round-off.
  signal::require_signal(record.displacement_m, record.source, "displacement", "m");
  signal::require_signal(record.force_N, record.source, "force", "N");
  return record;
}

}  // namespace ridefit::fitting
