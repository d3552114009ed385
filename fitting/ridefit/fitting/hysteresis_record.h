#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ridefit::fitting {

// One strut test: the displacement imposed and the force measured, in SI.
struct HysteresisRecord {
  std::string source;
  std::vector<double> time_s;
  std::vector<double> displacement_m;  // extension positive
  std::vector<double> force_N;         // tension positive
};

// Reads `time[...]`, `displacement[...]`, `force[...]` columns in any supported units. InputError
// (naming file, row, column) for a missing column, a time that does not increase, fewer than 20
// samples, or a displacement that never moves (nothing to identify).
HysteresisRecord load_hysteresis_record(const std::filesystem::path& csv_file);

}  // namespace ridefit::fitting
