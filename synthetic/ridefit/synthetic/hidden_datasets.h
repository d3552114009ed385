#pragma once

#include <filesystem>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "ridefit/synthetic/hidden_dataset_spec.h"
#include "ridefit/synthetic/hidden_truth_model.h"

namespace ridefit::synthetic {

// Writing hidden-effect datasets (hidden_dataset_spec.h): per dataset its records and its truth
// file. A vehicle dataset's records are the truth simulated by CVODE over the road (record k >= 2
// over another realisation, road_realisation.h), its accelerations through the sensor model
// (study/sensor_model.h): `time[s],road[m],body_acc[m/s^2],wheel_acc[m/s^2]`. A strut rig
// dataset's are the truth's strut under the multisine (record 1 in sine phase, record k >= 2 with
// seeded random phases), its force by CVODE plus Gaussian load-cell noise (rig_csv.h). Noise of
// record k comes from record_generator; `seed_offset` is added to every dataset's seed.

// Told of each record written: its path in the final folder, its last instant and its rate.
using RecordWritten =
    std::function<void(const std::filesystem::path& file, double end_s, double sample_rate_Hz)>;

// Every file the datasets write, in order: records, then the truth file, per dataset.
std::vector<std::string> hidden_dataset_files(const std::vector<HiddenDataset>& datasets);

// The noise generator of record k (1-based): seeded with (seed + seed_offset) · 1000 + k.
std::mt19937_64 record_generator(const HiddenDataset& d, long seed_offset, int record);

// Writes dataset `d` of truth `truth` into `out_dir` (the folder being staged); paths in its truth
// file are relative to `dir`, the folder `out_dir` becomes. RunError when an integrator fails.
void write_hidden_dataset(const HiddenDataset& d, const HiddenTruthModel& truth,
                          const std::filesystem::path& dir, const std::filesystem::path& out_dir,
                          long seed_offset, const RecordWritten& written);

// NAME_baseline.yaml for a dataset with a `baseline:` (hidden_dataset_spec.h): its model file
// with the values the data sheet gets wrong (drawn, datasheet_values.h, or the spec's shares).
void write_datasheet_baseline(const HiddenDataset& d, const std::filesystem::path& out_dir);

// The two kinds, as write_hidden_dataset dispatches them.
void write_rig_dataset(const HiddenDataset& d, const model::StrutTestParameters<double>& strut,
                       const std::filesystem::path& dir, const std::filesystem::path& out_dir,
                       long seed_offset, const RecordWritten& written);
void write_vehicle_dataset(const HiddenDataset& d, const model::QuarterCar& car,
                           const std::filesystem::path& dir, const std::filesystem::path& out_dir,
                           long seed_offset, const RecordWritten& written);

}  // namespace ridefit::synthetic
