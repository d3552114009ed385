#include "ridefit/synthetic/hidden_datasets.h"

#include <fmt/core.h>

#include <cstdint>
#include <ostream>
#include <utility>

#include "ridefit/common/errors.h"
#include "ridefit/io/atomic_file.h"
#include "ridefit/io/model_values_file.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/model/quarter_car_parameter_table.h"
#include "ridefit/synthetic/datasheet_values.h"

namespace ridefit::synthetic {

std::vector<std::string> hidden_dataset_files(const std::vector<HiddenDataset>& datasets) {
  std::vector<std::string> files;
  for (const HiddenDataset& d : datasets) {
    for (int k = 1; k <= d.records; ++k) files.push_back(record_file_name(d, k));
    files.push_back(d.name + "_truth.yaml");
    if (!d.baseline_model.empty()) files.push_back(baseline_file_name(d));
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
  if (!d.baseline_model.empty()) write_datasheet_baseline(d, out_dir);
}

void write_datasheet_baseline(const HiddenDataset& d, const std::filesystem::path& out_dir) {
  const model::QuarterCar car = io::load_quarter_car(d.baseline_model).make_model();
  std::vector<std::pair<std::string, double>> values;
  std::string how;
  if (d.baseline_errors.empty()) {
    values = datasheet_values(car, static_cast<std::uint64_t>(d.baseline_datasheet_seed));
    how = fmt::format(
        "by errors drawn with datasheet_seed {} (synthetic/datasheet_values.h: masses ±3 %, tyre "
        "and spring ±8 %, damping ±12 %, top mount ±15 %, Fc ±25 %, σ0 a factor 2)",
        d.baseline_datasheet_seed);
  } else {
    for (const auto& [name, share] : d.baseline_errors) {
      const auto index = model::quarter_car_parameter_index(name);
      if (!index) {
        throw InputError(fmt::format("{}: baseline errors: '{}' is not a quarter-car parameter",
                                     d.location, name));
      }
      values.emplace_back(name,
                          model::quarter_car_parameter(car.parameters(), *index) * (1.0 + share));
    }
    how = "by the spec's errors";
  }
  const std::string comment = fmt::format(
      "The baseline for diagnosing {0}.csv as an engineer's data sheet gives it (ridefit "
      "generate-hidden): the values of {1}, off {2}; diagnose with --tolerances datasheet.",
      d.name, d.baseline_model.filename().string(), how);
  const std::string text = io::model_with_values_text(d.baseline_model, values, comment);
  io::write_atomically(out_dir / baseline_file_name(d), [&](std::ostream& out) { out << text; });
}

}  // namespace ridefit::synthetic
