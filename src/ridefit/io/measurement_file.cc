#include "ridefit/io/measurement_file.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "ridefit/io/mat_file.h"

namespace ridefit::io {

bool is_mat_file(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".mat";
}

CsvTable read_measurement_table(const std::filesystem::path& path) {
  return is_mat_file(path) ? read_mat_table(path) : CsvTable::read(path);
}

void write_measurement_table(const CsvTable& table, const std::filesystem::path& path) {
  if (is_mat_file(path)) {
    write_mat_table(table, path);
  } else {
    table.write(path);
  }
}

}  // namespace ridefit::io
