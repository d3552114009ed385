#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ridefit/io/csv_table.h"

namespace ridefit::io {

// The command of a controlled (semi-active) damper in a record: its coil current (a `current`
// column in A or mA) or valve voltage (`voltage`, V or mV), in SI.
struct CommandColumn {
  std::vector<double> values;
  std::string unit;  // "A" or "V"
  std::string name;  // "current" or "voltage"
};

// The table's command column, or none when it has neither a current nor a voltage column.
// InputError naming `source` when it has both (a damper has one command) or the unit is not the
// column's electrical one.
std::optional<CommandColumn> read_command_column(const CsvTable& table, const std::string& source);

}  // namespace ridefit::io
