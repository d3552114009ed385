#include "ridefit/synthetic/hidden_datasets.h"

namespace ridefit::synthetic {

std::vector<std::string> hidden_dataset_files(const std::vector<HiddenDataset>& datasets) {
  std::vector<std::string> files;
  for (const HiddenDataset& d : datasets) {
    for (int k = 1; k <= d.records; ++k) files.push_back(record_file_name(d, k));
    files.push_back(d.name + "_truth.yaml");
  }
  return files;
}

std::mt19937_64 record_generator(const HiddenDataset& d, long seed_offset, int record) {
  return std::mt19937_64(static_cast<unsigned long>(d.seed + seed_offset) * 1000u +
                         static_cast<unsigned long>(record));
}

void write_hidden_dataset(const HiddenDataset& d, const HiddenTruthModel& truth,
                          const std::filesystem::path& dir, const std::filesystem::path& out_dir,
                          long seed_offset, const RecordWritten& written) {
  if (d.strut_rig) {
    write_rig_dataset(d, truth.strut, dir, out_dir, seed_offset, written);
  } else {
    write_vehicle_dataset(d, truth.car, dir, out_dir, seed_offset, written);
  }
}

}  // namespace ridefit::synthetic
