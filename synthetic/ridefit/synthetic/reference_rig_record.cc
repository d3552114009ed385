#include "ridefit/synthetic/reference_rig_record.h"

#include <utility>

#include "ridefit/simulate/strut_test_reference.h"

namespace ridefit::synthetic {

std::vector<double> sample_times(std::size_t samples, double rate_Hz) {
  std::vector<double> t(samples);
  for (std::size_t k = 0; k < samples; ++k) t[k] = static_cast<double>(k) / rate_Hz;
  return t;
}

fitting::HysteresisRecord reference_rig_record(std::vector<double> time_s,
                                               const std::function<double(double)>& displacement_m,
                                               const model::StrutTestParameters<double>& strut,
                                               const std::function<double(double)>& command,
                                               const std::string& source) {
  fitting::HysteresisRecord r;
  r.source = source;
  r.time_s = std::move(time_s);
  for (double t : r.time_s) r.displacement_m.push_back(displacement_m(t));
  if (command) {
    for (double t : r.time_s) r.command.push_back(command(t));
    r.command_unit = std::string(1, 'A');  // not = "A": GCC 12's false -Wrestrict on it
  }
  r.force_N = simulate::reference_strut_test_force(r.time_s, displacement_m, strut, command);
  return r;
}

}  // namespace ridefit::synthetic
