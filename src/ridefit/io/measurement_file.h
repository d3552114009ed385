#pragma once

#include <filesystem>

#include "ridefit/io/csv_table.h"

namespace ridefit::io {

// A measurement (time series with units) in either format ridefit reads: a MATLAB file when the
// name ends in .mat (any case; mat_file.h), a `name[unit]` CSV file otherwise (csv_table.h).
// Both give the same table, in SI units.
CsvTable read_measurement_table(const std::filesystem::path& path);

// Writes `table` the same way: MAT v5 for .mat, CSV otherwise; atomically either way.
void write_measurement_table(const CsvTable& table, const std::filesystem::path& path);

bool is_mat_file(const std::filesystem::path& path);

}  // namespace ridefit::io
