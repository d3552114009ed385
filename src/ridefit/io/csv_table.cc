#include "ridefit/io/csv_table.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/path_type.h"

namespace ridefit::io {
namespace {

struct KnownUnit {
  std::string_view unit;
  double factor_to_si;
  std::string_view si_unit;
};

// The units a CSV header may carry: the channels of design.md (time, displacements,
// accelerations incl. pitch, forces, the `stuck` flag), element rates, and the spectra the
// tools write. Factors are exact by definition (g is the standard gravity of ISO 80000-3).
constexpr double kG = 9.80665;
constexpr double kDeg = 0.017453292519943295;  // π/180
constexpr std::array<KnownUnit, 42> kUnits{{
    {"s", 1.0, "s"},
    {"ms", 1e-3, "s"},
    {"m", 1.0, "m"},
    {"mm", 1e-3, "m"},
    {"m/s", 1.0, "m/s"},
    {"mm/s", 1e-3, "m/s"},
    {"m/s^2", 1.0, "m/s^2"},
    {"g", kG, "m/s^2"},
    {"N", 1.0, "N"},
    {"kN", 1e3, "N"},
    {"N/m", 1.0, "N/m"},
    {"N/mm", 1e3, "N/m"},
    {"Ns/m", 1.0, "Ns/m"},
    {"Hz", 1.0, "Hz"},
    {"rad", 1.0, "rad"},
    {"deg", kDeg, "rad"},
    {"rad/s", 1.0, "rad/s"},
    {"deg/s", kDeg, "rad/s"},
    {"rad/s^2", 1.0, "rad/s^2"},
    {"deg/s^2", kDeg, "rad/s^2"},
    {"A", 1.0, "A"},
    {"mA", 1e-3, "A"},
    {"V", 1.0, "V"},
    {"mV", 1e-3, "V"},
    {"1", 1.0, "1"},
    {"-", 1.0, "1"},
    // Power spectral densities (one-sided): acceleration, displacement, angular
    // acceleration over frequency; road displacement over spatial frequency (m^3).
    {"(m/s^2)^2/Hz", 1.0, "(m/s^2)^2/Hz"},
    {"g^2/Hz", kG* kG, "(m/s^2)^2/Hz"},
    {"m^2/Hz", 1.0, "m^2/Hz"},
    {"mm^2/Hz", 1e-6, "m^2/Hz"},
    {"(rad/s^2)^2/Hz", 1.0, "(rad/s^2)^2/Hz"},
    {"m^3", 1.0, "m^3"},
    {"cycles/m", 1.0, "cycles/m"},
    {"N^2/Hz", 1.0, "N^2/Hz"},
    {"(m/s)^2/Hz", 1.0, "(m/s)^2/Hz"},
    {"rad^2/Hz", 1.0, "rad^2/Hz"},
    {"(rad/s)^2/Hz", 1.0, "(rad/s)^2/Hz"},
    {"1/Hz", 1.0, "1/Hz"},
    {"(Ns/m)^2/Hz", 1.0, "(Ns/m)^2/Hz"},
    {"(N/m)^2/Hz", 1.0, "(N/m)^2/Hz"},
    {"s^2/Hz", 1.0, "s^2/Hz"},
    {"Hz^2/Hz", 1.0, "Hz^2/Hz"},
}};

std::optional<UnitConversion> find_unit(std::string_view unit) {
  for (const auto& known : kUnits) {
    if (known.unit == unit) {
      return UnitConversion{known.factor_to_si, std::string(known.si_unit)};
    }
  }
  return std::nullopt;
}

std::string accepted_units() {
  std::string list;
  for (const auto& known : kUnits) {
    list += (list.empty() ? "" : ", ") + std::string(known.unit);
  }
  return list;
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> cells;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = line.find(',', begin);
    if (comma == std::string_view::npos) {
      cells.push_back(trim(line.substr(begin)));
      return cells;
    }
    cells.push_back(trim(line.substr(begin, comma - begin)));
    begin = comma + 1;
  }
}

// Parses a whole cell as a number; a leading '+' is accepted (from_chars rejects it).
std::optional<double> parse_number(std::string_view cell) {
  if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
  if (cell.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), value);
  if (end != cell.data() + cell.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    // Overflow (→ ±inf, rejected later) or underflow (→ a subnormal or 0, fine): strtod says.
    return std::strtod(std::string(cell).c_str(), nullptr);
  }
  if (error != std::errc()) return std::nullopt;
  return value;
}

struct Header {
  std::string name;
  std::string unit;
};

Header parse_header_cell(std::string_view cell, std::size_t index, const std::string& file) {
  const std::size_t open = cell.find('[');
  if (cell.empty() || open == std::string_view::npos || cell.back() != ']' || open == 0) {
    throw InputError(fmt::format(
        "{}: row 1, column {} '{}': header must read name[unit], e.g. road[m] or stuck[1]", file,
        index + 1, cell));
  }
  Header header{std::string(trim(cell.substr(0, open))),
                std::string(trim(cell.substr(open + 1, cell.size() - open - 2)))};
  if (header.name.empty() || header.unit.empty()) {
    throw InputError(fmt::format(
        "{}: row 1, column {} '{}': header must read name[unit], e.g. road[m] or stuck[1]", file,
        index + 1, cell));
  }
  return header;
}

// The units as `path`'s header row wrote them (road[mm], where the column holds SI, road[m]),
// for messages: read back from the file, since a column keeps only its SI unit. Empty when
// the table was not read from a file or the header does not match `columns` (any more).
std::vector<std::string> file_units(const std::filesystem::path& path,
                                    const std::vector<CsvColumn>& columns) {
  std::ifstream in(path);
  std::string line;
  if (path.empty() || !in || !std::getline(in, line)) return {};
  if (!line.empty() && line.back() == '\r') line.pop_back();
  std::string_view header_line = line;
  if (header_line.starts_with("\xEF\xBB\xBF")) header_line.remove_prefix(3);  // UTF-8 BOM
  const std::vector<std::string_view> cells = split(header_line);
  if (cells.size() != columns.size()) return {};
  std::vector<std::string> units;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::size_t open = cells[c].find('[');
    if (open == std::string_view::npos || cells[c].back() != ']') return {};
    const std::string_view unit = trim(cells[c].substr(open + 1, cells[c].size() - open - 2));
    const auto conversion = find_unit(unit);
    if (trim(cells[c].substr(0, open)) != columns[c].name || !conversion ||
        conversion->si_unit != columns[c].unit) {
      return {};
    }
    units.emplace_back(unit);
  }
  return units;
}

}  // namespace

UnitConversion unit_to_si(const std::string& unit) {
  if (auto found = find_unit(unit)) return *found;
  throw InputError(fmt::format("unknown unit '{}'; accepted units: {}", unit, accepted_units()));
}

CsvTable CsvTable::read(const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!path_exists(path)) throw InputError(fmt::format("{}: file not found", file));
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open for reading", file));

  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  // Trailing blank lines are an editor's habit, not missing data; blank lines inside are not.
  while (!lines.empty() && trim(lines.back()).empty()) lines.pop_back();
  if (lines.empty()) {
    throw InputError(fmt::format(
        "{}: the file is empty; expected a header row like time[s],road[m] and data rows", file));
  }
  std::string_view header_line = lines.front();
  if (header_line.starts_with("\xEF\xBB\xBF")) header_line.remove_prefix(3);  // UTF-8 BOM

  CsvTable table(path);
  const std::vector<std::string_view> header_cells = split(header_line);
  std::vector<double> factors;
  for (std::size_t c = 0; c < header_cells.size(); ++c) {
    Header header = parse_header_cell(header_cells[c], c, file);
    const auto conversion = find_unit(header.unit);
    if (!conversion) {
      throw InputError(
          fmt::format("{}: row 1, column {} '{}': unknown unit '{}'; accepted units: {}", file,
                      c + 1, header.name, header.unit, accepted_units()));
    }
    for (std::size_t previous = 0; previous < table.columns_.size(); ++previous) {
      if (table.columns_[previous].name == header.name) {
        throw InputError(
            fmt::format("{}: row 1, column {}: duplicate column name '{}' (also column {})", file,
                        c + 1, header.name, previous + 1));
      }
    }
    factors.push_back(conversion->factor_to_si);
    table.columns_.push_back(CsvColumn{std::move(header.name), conversion->si_unit, {}});
  }
  if (lines.size() == 1) {
    throw InputError(fmt::format("{}: no data rows after the header (row 1)", file));
  }
  for (auto& column : table.columns_) column.values.reserve(lines.size() - 1);

  for (std::size_t r = 1; r < lines.size(); ++r) {
    const std::size_t row = r + 1;  // line number in the file
    const std::vector<std::string_view> cells = split(lines[r]);
    if (cells.size() != table.columns_.size()) {
      if (trim(lines[r]).empty()) {
        throw InputError(fmt::format("{}: row {} is empty; expected {} values", file, row,
                                     table.columns_.size()));
      }
      const std::size_t c = std::min(cells.size(), table.columns_.size());
      throw InputError(fmt::format(
          "{}: row {} has {} cells, expected {} (one per header column); {} at column {}{}", file,
          row, cells.size(), table.columns_.size(),
          cells.size() < table.columns_.size() ? "first missing cell" : "first extra cell", c + 1,
          c < table.columns_.size() ? fmt::format(" '{}'", table.columns_[c].name) : ""));
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const std::optional<double> value = parse_number(cells[c]);
      if (!value) {
        throw InputError(fmt::format("{}: row {}, column {} '{}': '{}' is not a number", file, row,
                                     c + 1, table.columns_[c].name, cells[c]));
      }
      if (!std::isfinite(*value)) {
        throw InputError(fmt::format("{}: row {}, column {} '{}': '{}' is not a finite number",
                                     file, row, c + 1, table.columns_[c].name, cells[c]));
      }
      table.columns_[c].values.push_back(*value * factors[c]);
    }
  }
  return table;
}

void CsvTable::add(std::string name, std::string unit, std::vector<double> values) {
  if (has(name)) throw std::invalid_argument("CsvTable::add: duplicate column " + name);
  if (!columns_.empty() && values.size() != rows()) {
    throw std::invalid_argument(fmt::format("CsvTable::add: column {} has {} values, expected {}",
                                            name, values.size(), rows()));
  }
  const std::optional<UnitConversion> found = find_unit(unit);
  // A unit read() would reject makes a file ridefit cannot read back: a programming error.
  if (!found) {
    throw std::invalid_argument(fmt::format(
        "CsvTable::add: column {} has unit '{}', which is not one of: {} (extend kUnits in "
        "csv_table.cc)",
        name, unit, accepted_units()));
  }
  const UnitConversion& conversion = *found;
  if (conversion.factor_to_si != 1.0) {
    for (double& v : values) v *= conversion.factor_to_si;
  }
  columns_.push_back(CsvColumn{std::move(name), conversion.si_unit, std::move(values)});
}

bool CsvTable::has(const std::string& name) const {
  for (const auto& column : columns_) {
    if (column.name == name) return true;
  }
  return false;
}

const CsvColumn& CsvTable::column(const std::string& name) const {
  for (const auto& column : columns_) {
    if (column.name == name) return column;
  }
  const std::vector<std::string> units = file_units(source_, columns_);
  std::string names;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    names += (names.empty() ? "" : ", ") + columns_[c].name + "[" +
             (units.empty() ? columns_[c].unit : units[c]) + "]";
  }
  throw InputError(fmt::format("{}: no column '{}'; the columns are: {}", source_.string(), name,
                               names.empty() ? "(none)" : names));
}

const std::vector<double>& CsvTable::strictly_increasing(const std::string& name) const {
  const CsvColumn& c = column(name);
  for (std::size_t k = 1; k < c.values.size(); ++k) {
    if (!(c.values[k] > c.values[k - 1])) {
      throw InputError(fmt::format(
          "{}: row {}, column '{}': {} {} is not greater than the previous row's {} {}; '{}' "
          "must be strictly increasing",
          source_.string(), k + first_data_row_, name, c.values[k], c.unit, c.values[k - 1], c.unit,
          name));
    }
  }
  return c.values;
}

const std::vector<double>& CsvTable::time_s() const { return strictly_increasing("time"); }

void CsvTable::write(const std::filesystem::path& path) const {
  // NaN would be written as "nan", which read() rejects: a silent NaN must not leave here.
  for (const auto& c : columns_) {
    for (std::size_t k = 0; k < c.values.size(); ++k) {
      if (!std::isfinite(c.values[k])) {
        throw RunError(
            fmt::format("{}: column '{}' row {} is {}; refusing to write a non-finite "
                        "value",
                        path.string(), c.name, k + 2, c.values[k]));
      }
    }
  }
  write_atomically(path, [this](std::ostream& out) {
    std::string buffer;
    for (std::size_t c = 0; c < columns_.size(); ++c) {
      buffer += fmt::format("{}{}[{}]", c == 0 ? "" : ",", columns_[c].name, columns_[c].unit);
    }
    buffer += '\n';
    for (std::size_t k = 0; k < rows(); ++k) {
      for (std::size_t c = 0; c < columns_.size(); ++c) {
        // "{}" is the shortest text that reads back to the same double.
        fmt::format_to(std::back_inserter(buffer), "{}{}", c == 0 ? "" : ",",
                       columns_[c].values[k]);
      }
      buffer += '\n';
      if (buffer.size() > (1u << 16)) {
        out << buffer;
        buffer.clear();
      }
    }
    out << buffer;
  });
}

std::string psd_unit_of(const std::string& si_unit) {
  if (si_unit == "1") return "1/Hz";
  const bool compound = si_unit.find('/') != std::string::npos;
  return (compound ? "(" + si_unit + ")" : si_unit) + "^2/Hz";
}

}  // namespace ridefit::io
