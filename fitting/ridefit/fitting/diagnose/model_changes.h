#pragma once

#include <string>
#include <utility>
#include <vector>

#include "ridefit/model/quarter_car.h"
#include "ridefit/model/strut_test.h"

namespace ridefit::fitting::diagnose {

// What a diagnosis changed or fitted in the baseline, as model-file values for
// io::write_model_with_values: numbers with 6 significant digits, as the report shows them, so
// model.yaml and report.md agree.

// Vehicle spectra: the quarter-car keys whose values differ, the damper state (model::to_string)
// when an effect changed the topology, and the tyre lift-off and sensor-order switches.
std::vector<std::pair<std::string, std::string>> changed_model_values(
    const model::QuarterCar& before, const model::QuarterCar& after);

// Strut loops: the changed parameters that are model keys, and the rig-only ones (gas force,
// load-cell offset and chain, which no model file holds) in words, "name: value, …".
struct StrutChanges {
  std::vector<std::pair<std::string, std::string>> model_values;
  std::string rig_only;
};
StrutChanges changed_strut_values(const model::StrutTestParameters<double>& before,
                                  const model::StrutTestParameters<double>& after);

}  // namespace ridefit::fitting::diagnose
