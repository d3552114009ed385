#include "ridefit/fitting/diagnose/diagnosis_options.h"

#include <fmt/core.h>

#include <cmath>
#include <set>

#include "ridefit/common/errors.h"
#include "ridefit/fitting/diagnose/effect.h"
#include "ridefit/model/quarter_car_parameter_table.h"

namespace ridefit::fitting::diagnose {
namespace {

void require_positive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("{} {}: expected a finite value > 0", what, value));
  }
}

void require_tolerance(double value, const char* what) {
  if (!(value > 0.0 && value <= 0.1)) {
    throw InputError(fmt::format("{} {}: expected a value in (0, 0.1]", what, value));
  }
}

}  // namespace

void check_effect_ids(const std::vector<std::string>& ids) {
  std::set<std::string> seen;
  for (const auto& id : ids) {
    find_effect(id);  // InputError naming the library's ids for an unknown one
    if (!seen.insert(id).second) {
      throw InputError(fmt::format("effects: '{}' is given twice", id));
    }
  }
}

std::map<std::string, double> datasheet_tolerances() {
  namespace rows = model::quarter_car_rows;
  return {{rows::sprung_mass_kg.key_string(), 0.03},
          {rows::unsprung_mass_kg.key_string(), 0.03},
          {rows::tyre_stiffness_N_per_m.key_string(), 0.08},
          {rows::spring_stiffness_N_per_m.key_string(), 0.08},
          {rows::damping_Ns_per_m.key_string(), 0.12},
          {rows::top_mount_stiffness_N_per_m.key_string(), 0.15},
          {rows::coulomb_force_N.key_string(), 0.25}};
}

void DiagnosisOptions::validate() const {
  for (const auto& [name, share] : baseline_tolerances) {
    if (!model::quarter_car_parameter_index(name)) {
      throw InputError(
          fmt::format("baseline tolerances: '{}' is not a quarter-car parameter", name));
    }
    if (!(share > 0.0 && share <= 10.0) || !std::isfinite(share)) {
      throw InputError(fmt::format(
          "baseline tolerance of {}: {} of its value; expected a share in (0, 10]", name, share));
    }
  }
  std::set<std::string> freed;
  for (const auto& name : baseline_free) {
    if (!model::quarter_car_parameter_index(name)) {
      throw InputError(
          fmt::format("baseline free parameters: '{}' is not a quarter-car parameter", name));
    }
    if (!freed.insert(name).second) {
      throw InputError(fmt::format("baseline free parameters: '{}' is given twice", name));
    }
  }
  check_effect_ids(effects);
  fit.validate(false);  // its free parameters and tolerance are the diagnosis's own
  require_tolerance(screening_relative_tolerance, "screening relative tolerance");
  require_tolerance(final_relative_tolerance, "final relative tolerance");
  if (screening_iterations < 1) {
    throw InputError(
        fmt::format("screening iteration limit {}: expected at least 1", screening_iterations));
  }
  DisagreementOptions band_map = map;  // diagnose() gives the map the fit's band
  band_map.band_low_Hz = fit.band_low_Hz;
  band_map.band_high_Hz = fit.band_high_Hz;
  band_map.validate();
  selection.validate();
  require_positive(unexplained_dB, "unexplained size (dB)");
  require_positive(unexplained_width_Hz, "unexplained width (Hz)");
  require_positive(unexplained_wide_dB, "unexplained wide size (dB)");
  require_positive(unexplained_wide_width_Hz, "unexplained wide width (Hz)");
}

}  // namespace ridefit::fitting::diagnose
