#include "ridefit/fitting/diagnose/loop_diagnosis_options.h"

#include <fmt/core.h>

#include <cmath>
#include <set>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/diagnosis_options.h"
#include "ridefit/fitting/strut_parameters.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {

std::map<std::string, double> strut_datasheet_tolerances() {
  namespace rows = model::quarter_car_rows;
  return {{rows::damping_Ns_per_m.key_string(), 0.12},
          {rows::top_mount_stiffness_N_per_m.key_string(), 0.15},
          {rows::coulomb_force_N.key_string(), 0.25},
          {rows::dahl_sigma0_N_per_m.key_string(), 1.0}};
}

void LoopDiagnosisOptions::validate() const {
  for (const auto& [name, share] : baseline_tolerances) {
    strut_parameter_index(name);  // InputError naming the strut parameters for an unknown one
    if (!(share > 0.0 && share <= 10.0)) {
      throw InputError(fmt::format(
          "baseline tolerance of {}: {} of its value; expected a share in (0, 10]", name, share));
    }
  }
  std::set<std::size_t> freed;
  for (const auto& name : baseline_free) {
    // InputError naming the strut parameters for an unknown one.
    if (!freed.insert(strut_parameter_index(name)).second) {
      throw InputError(fmt::format("baseline free parameters: '{}' is given twice", name));
    }
  }
  check_effect_ids(effects);
  if (max_iterations < 0) {  // 0: evaluate the start only
    throw InputError(fmt::format("iteration limit {}: expected at least 0", max_iterations));
  }
  if (!(solver.relative_tolerance > 0.0 && solver.relative_tolerance <= 0.1)) {
    throw InputError(fmt::format("relative tolerance {}: expected a value in (0, 0.1]",
                                 solver.relative_tolerance));
  }
  if (!(solver.max_steps_per_s > 0.0)) {
    throw InputError(
        fmt::format("step limit {} per s: expected a value > 0", solver.max_steps_per_s));
  }
  map.validate();
  selection.validate();
  if (!(unexplained_share > 0.0 && unexplained_share < 1.0)) {
    throw InputError(
        fmt::format("unexplained share {}: expected a value in (0, 1)", unexplained_share));
  }
}

}  // namespace ridefit::fitting::diagnose
