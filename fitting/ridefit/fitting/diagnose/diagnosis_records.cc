#include "ridefit/fitting/diagnose/diagnosis_records.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>
#include <string>

#include "ridefit/common/errors.h"

namespace ridefit::fitting::diagnose {
namespace {

// The excitation must cover the record and not be much longer (a road for another record).
void check_excitation_length(const PsdMeasurement& m, const std::filesystem::path& excitation) {
  const double record_s = m.time_s.back() - m.time_s.front();
  const double excitation_s = m.road->duration_s();
  if (excitation_s > record_s + std::max(1.0, 0.02 * record_s)) {
    throw InputError(fmt::format(
        "{}: the excitation lasts {:.6g} s but the record {} only {:.6g} s; give the excitation "
        "that drove this record",
        excitation.string(), excitation_s, m.source, record_s));
  }
}

}  // namespace

DiagnosisData load_diagnosis_data(const std::vector<std::filesystem::path>& records,
                                  const std::vector<std::filesystem::path>& excitations) {
  if (records.empty() || records.size() > 2 ||
      (excitations.size() > 1 && excitations.size() != records.size())) {
    throw std::invalid_argument(
        "load_diagnosis_data: one or two records, and no excitation, "
        "one for all records or one per record");
  }
  std::vector<PsdMeasurement> measurements;
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::filesystem::path excitation = excitations.empty()       ? std::filesystem::path()
                                             : excitations.size() == 1 ? excitations[0]
                                                                       : excitations[i];
    measurements.push_back(load_psd_measurement(records[i], excitation));
    if (!excitation.empty()) check_excitation_length(measurements.back(), excitation);
  }
  if (measurements.size() == 1) return split_record(measurements[0]);
  const PsdMeasurement& fitted = measurements[0];
  const PsdMeasurement& judging = measurements[1];
  if (fitted.body_acc_m_per_s2.empty() != judging.body_acc_m_per_s2.empty() ||
      fitted.wheel_acc_m_per_s2.empty() != judging.wheel_acc_m_per_s2.empty()) {
    throw InputError(
        fmt::format("{} and {} hold different channels (body_acc, wheel_acc); the "
                    "held-out record must show what the fitted one shows",
                    records[0].string(), records[1].string()));
  }
  return DiagnosisData{fitted, judging};
}

}  // namespace ridefit::fitting::diagnose
