#include "ridefit/io/command_column.h"

#include <fmt/core.h>

#include "ridefit/common/errors.h"

namespace ridefit::io {

std::optional<CommandColumn> read_command_column(const CsvTable& table, const std::string& source) {
  const bool current = table.has("current");
  const bool voltage = table.has("voltage");
  if (current && voltage) {
    throw InputError(fmt::format(
        "{}: both a current and a voltage column; a controlled damper has one command, keep the "
        "one the damper's law is written in",
        source));
  }
  if (!current && !voltage) return std::nullopt;
  // Built whole: GCC 12 warns falsely (-Wrestrict) on assigning short literals to the members.
  CommandColumn command{
      {}, std::string(current ? "A" : "V"), std::string(current ? "current" : "voltage")};
  const CsvColumn& column = table.column(command.name);
  if (column.unit != command.unit) {
    throw InputError(fmt::format("{}: column {} is in {}, expected {} ({}, m{})", source,
                                 command.name, column.unit, current ? "a current" : "a voltage",
                                 command.unit, command.unit));
  }
  command.values = column.values;
  return command;
}

}  // namespace ridefit::io
