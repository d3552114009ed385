#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>

#include "ridefit/synthetic/hidden_dataset_spec.h"

namespace ridefit::synthetic {

// The truth file of a hidden dataset (NAME_truth.yaml), which a diagnosis must never read.

// What every truth file starts with: dataset, kind (rig datasets), model (relative to `dir`, the
// output folder), damper_state (if given), set, effects.
YAML::Node truth_header(const HiddenDataset& d, const std::filesystem::path& dir);

// Writes `truth` as `out_dir`/NAME_truth.yaml below a comment saying not to read it.
void write_truth_file(const HiddenDataset& d, const YAML::Node& truth,
                      const std::filesystem::path& out_dir);

}  // namespace ridefit::synthetic
