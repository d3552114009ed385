#pragma once

#include <filesystem>
#include <memory>

#include "ridefit/road/road_input.h"

namespace ridefit::synthetic {

// Record k of a dataset driven over `excitation`: record 1 is the file's road itself; for a
// random road (iso8608, power_law) record k >= 2 is another realisation, its seed the file's
// (default 1) + k − 1. The loader reads files, so the changed excitation is written to `scratch`
// (a temporary the interrupt handler removes; gone when this returns) and loaded from there.
// InputError from the excitation's loader.
std::unique_ptr<road::RoadInput> load_road_realisation(const std::filesystem::path& excitation,
                                                       int record,
                                                       const std::filesystem::path& scratch);

}  // namespace ridefit::synthetic
