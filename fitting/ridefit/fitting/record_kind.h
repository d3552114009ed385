#pragma once

#include <filesystem>

namespace ridefit::fitting {

// True when the CSV header (or the .mat file) names a displacement column: a strut rig test
// (hysteresis_record.h, whose loader then names any column it misses), not a vehicle measurement
// (psd_fit.h). Decides which diagnosis a record gets.
bool is_rig_record(const std::filesystem::path& csv_file);

}  // namespace ridefit::fitting
