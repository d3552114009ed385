#pragma once

#include <filesystem>

#include "ridefit/io/csv_table.h"

namespace ridefit::io {

// MATLAB .mat measurement files (MAT v5, compressed or not, and v7.3, through matio).
//
// Channels: real numeric vectors (row or column; double, single, integer or logical, converted
// to double) of equal length, named like the CSV columns (`time`, `body_acc`, ...), either
//   - as top-level variables, or
//   - as the fields of one 1x1 struct, when the file's top level holds nothing else but that
//     struct, `units` and `description` (e.g. `data.time`, `data.body_acc`).
// Units, one per channel, from either or both of (they must agree)
//   - a `units` struct whose fields are channel names holding a unit string
//     (`units.body_acc = 'g'`), or
//   - a `description` variable listing `name[unit]` entries as in a CSV header: a string
//     (`'time[s],body_acc[g]'`, separated by commas, semicolons or white space), a char matrix
//     (one entry per row) or a cell array of strings.
// Either may sit beside the channels (at the top level or inside the struct). Every other
// variable is an error, so a typo cannot pass silently. The values are converted to SI as
// CsvTable::read does. Anything else (complex, sparse, char, cell or struct channels, matrices,
// empty or non-finite values, unequal lengths, a missing or unknown unit, a unit naming no
// channel, a v4 file, a damaged file or one matio cannot read) is an InputError that names the
// file and the variable. In messages a sample is numbered as MATLAB indexes it (from 1).
CsvTable read_mat_table(const std::filesystem::path& path);

// Writes `table` as a compressed MAT v5 file (MATLAB, Octave and scipy.io.loadmat read it):
// one column vector per channel in its SI unit and a `units` struct. Atomic (temporary file,
// then rename); a non-finite value is a RunError, as for CsvTable::write; a channel name that
// cannot name a MATLAB variable is an InputError.
void write_mat_table(const CsvTable& table, const std::filesystem::path& path);

}  // namespace ridefit::io
