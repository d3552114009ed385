#include "ridefit/io/mat_file.h"

#include <fmt/core.h>
#include <matio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string_view>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/path_type.h"
#include "ridefit/version.h"

namespace ridefit::io {
namespace {

// matio is C: every handle it returns is owned by one of these.
struct MatCloser {
  void operator()(mat_t* mat) const { Mat_Close(mat); }
};
struct VarFreer {
  void operator()(matvar_t* var) const { Mat_VarFree(var); }
};
using MatFile = std::unique_ptr<mat_t, MatCloser>;
using MatVar = std::unique_ptr<matvar_t, VarFreer>;

// matio prints its errors on stderr by default; ridefit reports them in its own message instead.
thread_local std::string last_matio_message;
void keep_matio_message(int level, char* message) {
  if (level <= MATIO_LOG_LEVEL_CRITICAL && message != nullptr) last_matio_message = message;
}
void quiet_matio() {
  static std::once_flag once;
  std::call_once(once, [] { Mat_LogInitFunc("ridefit", keep_matio_message); });
  last_matio_message.clear();
}
std::string matio_reason() {
  return last_matio_message.empty() ? "" : " (matio: " + last_matio_message + ")";
}

const char* const kHowToGiveUnits =
    "give it as a field of a `units` struct (units.body_acc = 'm/s^2') or as an entry "
    "body_acc[m/s^2] of a `description` variable";

// Saturates instead of wrapping: a damaged header's dimensions must not multiply to a small n.
std::size_t element_count(const matvar_t& var) {
  std::size_t n = 1;
  for (int d = 0; d < var.rank; ++d) {
    if (var.dims[d] == 0) return 0;
    if (n > std::numeric_limits<std::size_t>::max() / var.dims[d]) {
      n = std::numeric_limits<std::size_t>::max();
    } else {
      n *= var.dims[d];
    }
  }
  return n;
}

// matio fills `data` from the file's own sizes; a damaged file can claim more elements than
// it holds, so every read of `data` is checked against the bytes matio allocated first.
bool data_fits(const matvar_t& var, std::size_t element_size) {
  if (var.data == nullptr || element_size == 0 || var.data_size < 0 ||
      static_cast<std::size_t>(var.data_size) != element_size) {
    return false;
  }
  std::size_t n = 1;
  for (int d = 0; d < var.rank; ++d) {
    if (var.dims[d] != 0 && n > var.nbytes / var.dims[d]) return false;  // overflow
    n *= var.dims[d];
  }
  return n <= var.nbytes / element_size;
}

std::string shape_of(const matvar_t& var) {
  std::string shape;
  for (int d = 0; d < var.rank; ++d) {
    if (d > 0) shape += 'x';
    shape += std::to_string(var.dims[d]);
  }
  return shape;
}

// The dimensions other than the longest are all 1: a row or a column vector.
bool is_vector(const matvar_t& var) {
  std::size_t longer = 0;
  for (int d = 0; d < var.rank; ++d) longer += var.dims[d] > 1 ? 1 : 0;
  return longer <= 1;
}

bool is_numeric(matio_classes c) {
  switch (c) {
    case MAT_C_DOUBLE:
    case MAT_C_SINGLE:
    case MAT_C_INT8:
    case MAT_C_UINT8:
    case MAT_C_INT16:
    case MAT_C_UINT16:
    case MAT_C_INT32:
    case MAT_C_UINT32:
    case MAT_C_INT64:
    case MAT_C_UINT64:
      return true;
    default:
      return false;
  }
}

std::string_view class_name(matio_classes c) {
  switch (c) {
    case MAT_C_CELL:
      return "a cell array";
    case MAT_C_STRUCT:
      return "a struct";
    case MAT_C_OBJECT:
      return "an object";
    case MAT_C_CHAR:
      return "a char array";
    case MAT_C_SPARSE:
      return "a sparse matrix";
    case MAT_C_FUNCTION:
      return "a function handle";
    case MAT_C_OPAQUE:
      return "an opaque object";
    default:
      return "numeric";
  }
}

template <typename T>
std::optional<std::vector<double>> as_doubles(const matvar_t& var) {
  if (!data_fits(var, sizeof(T))) return std::nullopt;
  const T* typed = static_cast<const T*>(var.data);
  std::vector<double> values(element_count(var));
  for (std::size_t k = 0; k < values.size(); ++k) values[k] = static_cast<double>(typed[k]);
  return values;
}

// std::nullopt for a type ridefit does not read or data that does not fit its dimensions.
std::optional<std::vector<double>> numeric_values(const matvar_t& var) {
  switch (var.data_type) {
    case MAT_T_DOUBLE:
      return as_doubles<double>(var);
    case MAT_T_SINGLE:
      return as_doubles<float>(var);
    case MAT_T_INT8:
      return as_doubles<std::int8_t>(var);
    case MAT_T_UINT8:
      return as_doubles<std::uint8_t>(var);
    case MAT_T_INT16:
      return as_doubles<std::int16_t>(var);
    case MAT_T_UINT16:
      return as_doubles<std::uint16_t>(var);
    case MAT_T_INT32:
      return as_doubles<std::int32_t>(var);
    case MAT_T_UINT32:
      return as_doubles<std::uint32_t>(var);
    case MAT_T_INT64:
      return as_doubles<std::int64_t>(var);
    case MAT_T_UINT64:
      return as_doubles<std::uint64_t>(var);
    default:
      return std::nullopt;
  }
}

// The rows of a char array (MATLAB stores it column-major), trailing blanks removed; non-ASCII
// characters become '?' (units and channel names are ASCII).
std::vector<std::string> char_rows(const matvar_t& var) {
  const std::size_t rows = var.rank >= 1 ? var.dims[0] : 0;
  const std::size_t n = element_count(var);
  const std::size_t cols = rows == 0 ? 0 : n / rows;
  const std::size_t size = var.data_size > 0 ? static_cast<std::size_t>(var.data_size) : 0;
  if ((size != 1 && size != 2 && size != 4) || !data_fits(var, size)) return {};
  std::vector<std::string> lines(rows);
  for (std::size_t c = 0; c < cols; ++c) {
    for (std::size_t r = 0; r < rows; ++r) {
      const std::size_t k = r + c * rows;
      std::uint32_t code = 0;
      if (var.data_size == 1) code = static_cast<const std::uint8_t*>(var.data)[k];
      if (var.data_size == 2) code = static_cast<const std::uint16_t*>(var.data)[k];
      if (var.data_size == 4) code = static_cast<const std::uint32_t*>(var.data)[k];
      lines[r] += code < 128 ? static_cast<char>(code) : '?';
    }
  }
  for (auto& line : lines) {
    while (!line.empty() && (line.back() == ' ' || line.back() == '\0')) line.pop_back();
  }
  return lines;
}

std::string trimmed(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r\n");
  return std::string(s.substr(first, last - first + 1));
}

// What one file says: its channels (in the file's order) and the unit each source gives.
struct Channel {
  std::string label;  // as messages name it: "body_acc" or "data.body_acc"
  std::string name;
  std::vector<double> values;
};
struct UnitSource {
  std::string label;  // "units.body_acc" or "description entry 'body_acc[g]'"
  std::string unit;
};

class MatReader {
 public:
  explicit MatReader(const std::filesystem::path& path) : path_(path), file_(path.string()) {}

  CsvTable read() {
    if (!path_exists(path_)) throw InputError(fmt::format("{}: file not found", file_));
    quiet_matio();
    MatFile mat(Mat_Open(file_.c_str(), MAT_ACC_RDONLY));
    if (!mat) {
      throw InputError(fmt::format(
          "{}: not a MATLAB .mat file (v5 or v7.3) that can be read; save it with MATLAB's "
          "save -v7 or -v7.3, or scipy.io.savemat, or give a .csv file",
          file_));
    }
    if (Mat_GetVersion(mat.get()) == MAT_FT_MAT4) {
      throw InputError(fmt::format(
          "{}: a MAT v4 file, which holds no struct for the units; save it as v5 or v7.3 "
          "(MATLAB's save -v7 or -v7.3, scipy.io.savemat(..., format='5'))",
          file_));
    }
    // zlib inflates at most about 1032:1; a variable claiming more elements than that is a
    // damaged header, refused before matio allocates for it.
    std::error_code ec;
    const std::uintmax_t file_bytes = std::filesystem::file_size(path_, ec);
    const std::size_t most_elements = ec ? 0 : 1100 * static_cast<std::size_t>(file_bytes) + 4096;
    std::vector<std::string> names;
    while (MatVar info{Mat_VarReadNextInfo(mat.get())}) {
      if (most_elements != 0 && element_count(*info) > most_elements) {
        throw InputError(fmt::format(
            "{}: variable '{}' claims {} values, more than a file of {} bytes holds; the file "
            "is damaged",
            file_, info->name == nullptr ? "" : info->name, shape_of(*info), file_bytes));
      }
      // A damaged file can make matio return the same variable forever: names are unique.
      if (info->name == nullptr ||
          std::find(names.begin(), names.end(), info->name) != names.end()) {
        throw InputError(
            fmt::format("{}: variable '{}' appears twice or has no name; the file is damaged",
                        file_, info->name == nullptr ? "" : info->name));
      }
      names.emplace_back(info->name);
    }
    std::vector<MatVar> top;
    for (const auto& name : names) {
      MatVar var(Mat_VarRead(mat.get(), name.c_str()));
      if (!var) {
        throw InputError(
            fmt::format("{}: variable '{}' cannot be read{}", file_, name, matio_reason()));
      }
      top.push_back(std::move(var));
    }
    collect(top);
    return table();
  }

 private:
  // Top-level channels, or the fields of the one struct that holds them.
  void collect(const std::vector<MatVar>& top) {
    std::vector<const matvar_t*> structs;
    std::string first_other;  // the first top-level variable that is no struct
    for (const auto& var : top) {
      const std::string name = var->name;
      if (name == "units" || name == "description") continue;
      if (var->class_type == MAT_C_STRUCT) {
        structs.push_back(var.get());
      } else if (first_other.empty()) {
        first_other = name;
      }
    }
    if (!first_other.empty() && !structs.empty()) {
      throw InputError(fmt::format(
          "{}: struct '{}' beside the top-level variable '{}'; keep every channel either at the "
          "top level or as the fields of one struct",
          file_, structs.front()->name, first_other));
    }
    if (first_other.empty() && structs.size() > 1) {
      throw InputError(
          fmt::format("{}: {} structs ('{}', '{}', ...); the channels must be the fields of one "
                      "struct (or top-level variables)",
                      file_, structs.size(), structs[0]->name, structs[1]->name));
    }
    for (const auto& var : top) {
      const std::string name = var->name;
      if (name == "units") {
        add_units_struct(*var, "units");
      } else if (name == "description") {
        add_description(*var, "description");
      } else if (var->class_type != MAT_C_STRUCT) {
        add_channel(*var, name, name);
      }
    }
    if (structs.size() == 1) read_struct(*structs.front());
    if (channels_.empty()) {
      throw InputError(fmt::format(
          "{}: no channels; expected real numeric vectors named like CSV columns (time, "
          "body_acc, ...) at the top level or as the fields of one struct",
          file_));
    }
  }

  void read_struct(const matvar_t& s) {
    const std::string prefix = std::string(s.name) + ".";
    if (element_count(s) != 1) {
      throw InputError(fmt::format("{}: struct '{}' is {}; expected a 1x1 struct of channels",
                                   file_, s.name, shape_of(s)));
    }
    const unsigned n = Mat_VarGetNumberOfFields(const_cast<matvar_t*>(&s));
    char* const* fields = Mat_VarGetStructFieldnames(&s);
    for (unsigned f = 0; f < n; ++f) {
      if (fields == nullptr || fields[f] == nullptr) {
        throw InputError(fmt::format("{}: a field of '{}' cannot be read", file_, s.name));
      }
      const std::string field = fields[f];
      matvar_t* value = Mat_VarGetStructFieldByIndex(const_cast<matvar_t*>(&s), f, 0);
      if (value == nullptr) {
        throw InputError(fmt::format("{}: field '{}{}' cannot be read", file_, prefix, field));
      }
      if (field == "units") {
        add_units_struct(*value, prefix + "units");
      } else if (field == "description") {
        add_description(*value, prefix + "description");
      } else {
        add_channel(*value, field, prefix + field);
      }
    }
  }

  void add_channel(const matvar_t& var, const std::string& name, const std::string& label) {
    const auto fail = [&](const std::string& what) {
      throw InputError(fmt::format("{}: variable '{}': {}", file_, label, what));
    };
    if (var.class_type == MAT_C_SPARSE) fail("is a sparse matrix; store it full (full(x))");
    if (!is_numeric(var.class_type)) {
      fail(
          fmt::format("is {}; a channel is a real numeric vector (units and description are "
                      "the only other variables read)",
                      class_name(var.class_type)));
    }
    if (var.isComplex) fail("is complex; a channel is a real numeric vector");
    if (element_count(var) == 0) fail(fmt::format("is empty ({})", shape_of(var)));
    if (!is_vector(var)) fail(fmt::format("is a {} matrix; a channel is a vector", shape_of(var)));
    std::optional<std::vector<double>> values = numeric_values(var);
    if (!values) fail("holds data that cannot be read (an unknown type, or a damaged file)");
    for (std::size_t k = 0; k < values->size(); ++k) {
      if (!std::isfinite((*values)[k])) {
        fail(fmt::format("row {} is {}; every value must be finite", k + 1, (*values)[k]));
      }
    }
    for (const auto& channel : channels_) {
      if (channel.name == name) fail(fmt::format("duplicates channel '{}'", channel.label));
    }
    channels_.push_back(Channel{label, name, std::move(*values)});
  }

  void add_unit(const std::string& channel, const std::string& unit, const std::string& label) {
    if (unit.empty()) {
      throw InputError(fmt::format("{}: {} is empty; expected a unit such as m/s^2", file_, label));
    }
    auto [it, inserted] = units_.emplace(channel, UnitSource{label, unit});
    if (!inserted && it->second.unit != unit) {
      throw InputError(fmt::format("{}: {} says '{}' but {} says '{}'; give one unit per channel",
                                   file_, it->second.label, it->second.unit, label, unit));
    }
  }

  void add_units_struct(const matvar_t& var, const std::string& label) {
    if (var.class_type != MAT_C_STRUCT || element_count(var) != 1) {
      throw InputError(fmt::format(
          "{}: '{}' must be a 1x1 struct whose fields are channel names holding a unit string "
          "(units.body_acc = 'm/s^2')",
          file_, label));
    }
    const unsigned n = Mat_VarGetNumberOfFields(const_cast<matvar_t*>(&var));
    char* const* fields = Mat_VarGetStructFieldnames(&var);
    for (unsigned f = 0; f < n; ++f) {
      if (fields == nullptr || fields[f] == nullptr) {
        throw InputError(fmt::format("{}: a field of '{}' cannot be read", file_, label));
      }
      const std::string field = fields[f];
      const matvar_t* value = Mat_VarGetStructFieldByIndex(const_cast<matvar_t*>(&var), f, 0);
      const std::string entry = label + "." + field;
      if (value == nullptr || value->class_type != MAT_C_CHAR || char_rows(*value).size() > 1) {
        throw InputError(fmt::format("{}: {} must be a unit string such as 'm/s^2'", file_, entry));
      }
      const std::vector<std::string> rows = char_rows(*value);
      add_unit(field, rows.empty() ? "" : trimmed(rows.front()), entry);
    }
  }

  void add_description_text(const std::string& text, const std::string& label) {
    std::string entry;
    const auto flush = [&] {
      const std::string cell = trimmed(entry);
      entry.clear();
      if (cell.empty()) return;
      const std::size_t open = cell.find('[');
      if (open == std::string::npos || open == 0 || cell.back() != ']') {
        throw InputError(fmt::format("{}: {} entry '{}' must read name[unit], e.g. body_acc[m/s^2]",
                                     file_, label, cell));
      }
      add_unit(trimmed(cell.substr(0, open)),
               trimmed(cell.substr(open + 1, cell.size() - open - 2)),
               fmt::format("{} entry '{}'", label, cell));
    };
    for (const char c : text) {
      if (c == ',' || c == ';' || std::isspace(static_cast<unsigned char>(c))) {
        flush();
      } else {
        entry += c;
      }
    }
    flush();
  }

  void add_description(const matvar_t& var, const std::string& label) {
    if (var.class_type == MAT_C_CHAR) {
      for (const auto& row : char_rows(var)) add_description_text(row, label);
      return;
    }
    if (var.class_type == MAT_C_CELL) {
      const std::size_t n = element_count(var);
      for (std::size_t k = 0; k < n; ++k) {
        const matvar_t* cell = Mat_VarGetCell(const_cast<matvar_t*>(&var), static_cast<int>(k));
        if (cell == nullptr || cell->class_type != MAT_C_CHAR) {
          throw InputError(
              fmt::format("{}: {} cell {} is not a string; expected name[unit] "
                          "entries such as body_acc[m/s^2]",
                          file_, label, k + 1));
        }
        for (const auto& row : char_rows(*cell)) add_description_text(row, label);
      }
      return;
    }
    throw InputError(fmt::format(
        "{}: '{}' is {}; expected a string or a cell array of name[unit] entries such as "
        "body_acc[m/s^2]",
        file_, label, class_name(var.class_type)));
  }

  CsvTable table() const {
    std::string names;
    for (const auto& channel : channels_) {
      if (!names.empty()) names += ", ";
      names += channel.name;
    }
    for (const auto& unit : units_) {  // (Clang 14 cannot capture a structured binding)
      const bool known = std::any_of(channels_.begin(), channels_.end(),
                                     [&](const Channel& c) { return c.name == unit.first; });
      if (!known) {
        throw InputError(fmt::format("{}: {} names no channel; the channels are: {}", file_,
                                     unit.second.label, names));
      }
    }
    CsvTable table(path_, 1);
    const Channel& first = channels_.front();
    for (const auto& channel : channels_) {
      if (channel.values.size() != first.values.size()) {
        throw InputError(fmt::format(
            "{}: variable '{}' has {} samples but '{}' has {}; every "
            "channel must have the same length",
            file_, channel.label, channel.values.size(), first.label, first.values.size()));
      }
      const auto unit = units_.find(channel.name);
      if (unit == units_.end()) {
        throw InputError(fmt::format("{}: variable '{}' has no unit; {}", file_, channel.label,
                                     kHowToGiveUnits));
      }
      try {
        unit_to_si(unit->second.unit);
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: variable '{}' ({}): {}", file_, channel.label,
                                     unit->second.label, e.what()));
      }
      table.add(channel.name, unit->second.unit, channel.values);
    }
    return table;
  }

  std::filesystem::path path_;
  std::string file_;
  std::vector<Channel> channels_;
  std::map<std::string, UnitSource> units_;
};

bool is_matlab_name(const std::string& name) {
  if (name.empty() || name.size() > 63 || !std::isalpha(static_cast<unsigned char>(name[0]))) {
    return false;
  }
  return std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  });
}

void write_variable(mat_t* mat, matvar_t* var, const std::string& file) {
  if (var == nullptr || Mat_VarWrite(mat, var, MAT_COMPRESSION_ZLIB) != 0) {
    throw RunError(fmt::format("{}: writing the .mat file failed{}", file, matio_reason()));
  }
}

}  // namespace

CsvTable read_mat_table(const std::filesystem::path& path) { return MatReader(path).read(); }

void write_mat_table(const CsvTable& table, const std::filesystem::path& path) {
  const std::string file = path.string();
  for (const auto& c : table.columns()) {
    if (!is_matlab_name(c.name) || c.name == "units") {
      throw InputError(fmt::format(
          "{}: channel '{}' cannot be a MATLAB variable name (a letter, then letters, digits "
          "or underscores, at most 63); write a .csv instead",
          file, c.name));
    }
    for (std::size_t k = 0; k < c.values.size(); ++k) {
      if (!std::isfinite(c.values[k])) {
        throw RunError(
            fmt::format("{}: column '{}' row {} is {}; refusing to write a non-finite "
                        "value",
                        file, c.name, k + 1, c.values[k]));
      }
    }
  }
  quiet_matio();
  write_file_atomically(path, [&](const std::filesystem::path& temporary) {
    const std::string header = "MATLAB 5.0 MAT-file, written by ridefit " RIDEFIT_VERSION;
    MatFile mat(Mat_CreateVer(temporary.string().c_str(), header.c_str(), MAT_FT_MAT5));
    if (!mat) {
      throw InputError(fmt::format("{}: cannot open for writing{}", file, matio_reason()));
    }
    std::vector<const char*> fields;
    for (const auto& c : table.columns()) {
      size_t dims[2] = {c.values.size(), 1};
      // matio does not write through the pointer; it only lacks const.
      const MatVar var(Mat_VarCreate(c.name.c_str(), MAT_C_DOUBLE, MAT_T_DOUBLE, 2, dims,
                                     const_cast<double*>(c.values.data()), MAT_F_DONT_COPY_DATA));
      write_variable(mat.get(), var.get(), file);
      fields.push_back(c.name.c_str());
    }
    fields.push_back(nullptr);
    size_t one[2] = {1, 1};
    const MatVar units(Mat_VarCreateStruct2("units", 2, one, fields.data()));
    for (const auto& c : table.columns()) {
      // UTF-16 code units, as MATLAB writes char (matio 1.5.23 cannot read back a compressed
      // struct whose char fields are 8-bit: it crashes).
      std::vector<std::uint16_t> unit(c.unit.begin(), c.unit.end());
      size_t dims[2] = {1, unit.size()};
      // Copied (no MAT_F_DONT_COPY_DATA): the struct owns and frees its fields.
      MatVar field(
          Mat_VarCreate(c.name.c_str(), MAT_C_CHAR, MAT_T_UINT16, 2, dims, unit.data(), 0));
      if (!field) {
        throw RunError(fmt::format("{}: writing the .mat file failed{}", file, matio_reason()));
      }
      // The struct takes the field; it returns the one it replaces (none here).
      const MatVar replaced(
          Mat_VarSetStructFieldByName(units.get(), c.name.c_str(), 0, field.release()));
    }
    write_variable(mat.get(), units.get(), file);
    if (Mat_Close(mat.release()) != 0) {
      throw RunError(fmt::format("{}: closing the .mat file failed{}", file, matio_reason()));
    }
  });
}

}  // namespace ridefit::io
