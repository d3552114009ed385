#pragma once

#include <vector>

#include "ridefit/io/yaml_map.h"

namespace ridefit::io {

// Values spaced over a range, read from a study file's mapping:
//   {from: 10000, to: 40000, count: 7, spacing: linear}   # or log (from, to > 0)
// The ends are exact. InputError naming the key for a count outside 1 … 10000, an unknown
// spacing, a log range through zero, or an unknown key.
std::vector<double> read_value_range(const YamlMap& range);

}  // namespace ridefit::io
