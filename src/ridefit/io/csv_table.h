#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ridefit::io {

// One column of a time-series CSV, in SI units.
struct CsvColumn {
  std::string name;  // e.g. "body_acc"
  std::string unit;  // the SI unit after conversion, e.g. "m/s^2"
  std::vector<double> values;
};

// A CSV file with one header row whose every column reads `name[unit]`
// (e.g. `time[s],road[mm],body_acc[g]`). Reading converts every column to SI; an unknown
// unit, a missing unit, a non-numeric cell, a ragged row or an empty table is an
// InputError that names the file, the row and the column.
class CsvTable {
 public:
  static CsvTable read(const std::filesystem::path& path);

  CsvTable() = default;
  // `first_data_row`: how messages number the first value of a column (2 in a CSV file, under
  // its header; 1 in a .mat file, as MATLAB indexes).
  explicit CsvTable(std::filesystem::path source, std::size_t first_data_row = 2)
      : source_(std::move(source)), first_data_row_(first_data_row) {}

  // Converts `values` from `unit` to SI. The unit must be one read() accepts (the list is in
  // csv_table.cc), so every written file reads back; otherwise, and for a duplicate name or a
  // length that differs from the other columns, std::invalid_argument (a programming error).
  void add(std::string name, std::string unit, std::vector<double> values);
  bool has(const std::string& name) const;
  // Throws InputError naming the file and the columns that do exist.
  const CsvColumn& column(const std::string& name) const;
  const std::vector<CsvColumn>& columns() const { return columns_; }
  std::size_t rows() const { return columns_.empty() ? 0 : columns_.front().values.size(); }
  const std::filesystem::path& source() const { return source_; }

  // A `time` column that must be strictly increasing (checked, the row is named).
  const std::vector<double>& time_s() const;
  // Any column that must be strictly increasing (e.g. `distance` of a road profile). Rows are
  // numbered as lines of a CSV file (the header is row 1, the first data row is row 2), or
  // from `first_data_row`.
  const std::vector<double>& strictly_increasing(const std::string& name) const;

  // Writes atomically (temporary file, then rename): a failed write leaves no file.
  void write(const std::filesystem::path& path) const;

 private:
  std::filesystem::path source_;
  std::vector<CsvColumn> columns_;
  std::size_t first_data_row_ = 2;
};

// Converts `value` in `unit` to SI for the quantity kind implied by the unit; returns the
// factor and offset-free SI unit. Throws InputError for an unknown unit.
struct UnitConversion {
  double factor_to_si = 1.0;
  std::string si_unit;
};
UnitConversion unit_to_si(const std::string& unit);

// The unit of a one-sided PSD of a channel in `si_unit`: "m/s^2" → "(m/s^2)^2/Hz", "m" →
// "m^2/Hz", "1" → "1/Hz". Every channel unit's PSD unit is one that read() accepts.
std::string psd_unit_of(const std::string& si_unit);

}  // namespace ridefit::io
