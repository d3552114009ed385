#include "ridefit/synthetic/hidden_truth_model.h"

#include <fmt/core.h>

#include <random>
#include <vector>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/io/quarter_car_file.h"
#include "ridefit/road/excitation_file.h"

namespace ridefit::synthetic {

HiddenTruthModel load_truth_model(const HiddenDataset& d) {
  if (d.strut_rig) {
    const io::QuarterCarFile file = io::load_quarter_car(d.model);
    model::StrutTestParameters<double> strut = fitting::strut_on_rig(file.make_model());
    for (const auto& [key, value] : d.set) {
      try {
        fitting::strut_parameter(strut, fitting::strut_parameter_index(key)) = value;
      } catch (const InputError& e) {
        throw InputError(fmt::format("{}: {}", d.set_location, e.what()));
      }
    }
    return {file.make_model(), strut};
  }
  io::ModelOverrides overrides;
  overrides.origin = fmt::format("given in {} as", d.set_location);
  overrides.damper_state = d.damper_state;
  for (const auto& [key, value] : d.set) overrides.set(key, value);
  const model::QuarterCar car = io::load_quarter_car(d.model, overrides).make_model();
  road::load_excitation(d.excitation);
  // The sensor model checks its band against the rate only when it measures.
  std::mt19937_64 rng(0);
  study::measure(std::vector<double>(8, 0.0), d.sample_rate_Hz, d.sensor, rng);
  return {car, {}};
}

}  // namespace ridefit::synthetic
