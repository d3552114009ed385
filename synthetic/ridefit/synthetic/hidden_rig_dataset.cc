// A strut rig dataset of hidden_datasets.h.
#include <cmath>
#include <numbers>

#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/synthetic/hidden_datasets.h"
#include "ridefit/synthetic/load_cell.h"
#include "ridefit/synthetic/multisine.h"
#include "ridefit/synthetic/reference_rig_record.h"
#include "ridefit/synthetic/rig_csv.h"
#include "ridefit/synthetic/truth_file.h"

namespace ridefit::synthetic {

void write_rig_dataset(const HiddenDataset& d, const model::StrutTestParameters<double>& strut,
                       const std::filesystem::path& dir, const std::filesystem::path& out_dir,
                       long seed_offset, const RecordWritten& written) {
  YAML::Node truth = truth_header(d, dir);
  for (std::size_t p = 0; p < fitting::kStrutParameters.size(); ++p) {
    truth["strut"][std::string(fitting::kStrutParameters[p].name())] =
        fitting::strut_parameter(strut, p);
  }
  truth["sample_rate_Hz"] = d.sample_rate_Hz;
  truth["noise_N"] = d.noise_N;
  const auto samples = static_cast<std::size_t>(std::floor(d.duration_s * d.sample_rate_Hz)) + 1;
  for (int k = 1; k <= d.records; ++k) {
    std::mt19937_64 rng = record_generator(d, seed_offset, k);
    Multisine displacement{d.rig_amplitudes_m, d.rig_frequencies_Hz,
                           std::vector<double>(d.rig_amplitudes_m.size(), 0.0)};
    if (k > 1) {
      std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi);
      for (double& p : displacement.phase_rad) p = phase(rng);
    }
    // CVODE at rtol 1e-10 on the exact multisine: not the ESDIRK the diagnosis fits with.
    fitting::HysteresisRecord record =
        reference_rig_record(sample_times(samples, d.sample_rate_Hz), displacement, strut);
    record.force_N = read_load_cell(record.force_N, LoadCell{d.noise_N, 0.0}, rng);
    const std::string file = record_file_name(d, k);
    write_rig_csv(out_dir / file, record, RigCsvDigits::kSixSignificant);
    truth["records"].push_back(file);
    if (written) written(dir / file, record.time_s.back(), d.sample_rate_Hz);
  }
  write_truth_file(d, truth, out_dir);
}

}  // namespace ridefit::synthetic
