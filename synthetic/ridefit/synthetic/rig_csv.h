#pragma once

#include <filesystem>

#include "ridefit/fitting/hysteresis_record.h"

namespace ridefit::synthetic {

// How a rig CSV prints its numbers. kFixed: the lab files' resolution, time to 0.1 ms,
// displacement to 1 nm, force to 1 mN, a current to 10 µA. kSixSignificant: six significant
// digits in every column (the hidden-effect datasets).
enum class RigCsvDigits { kFixed, kSixSignificant };

// Writes `record` as `time[s],displacement[mm],force[N]` (plus `current[A]` or `voltage[V]` when it
// carries a command), the file that fitting::load_hysteresis_record reads; atomically
// (io/atomic_file.h).
void write_rig_csv(const std::filesystem::path& path, const fitting::HysteresisRecord& record,
                   RigCsvDigits digits);

}  // namespace ridefit::synthetic
